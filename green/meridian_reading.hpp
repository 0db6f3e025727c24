// What a sensor reads on the meridian, per sensor model, as fem/sensor_reading.hpp gives it in 3D: the nodes
// held as the support and the weights w over their reactions (reading = w·R). A disc of the base: its point
// value at the axis, the limit of two small discs' means (meridian.hpp), and with a diameter its mean. A
// post: the force on it over its cross-section. A new sensor model adds its weights here and in 3D.
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "skinfem/fem/sensor_reading.hpp"
#include "skinfem/green/meridian.hpp"

namespace skinfem {

struct MeridianReading {
  std::vector<int> held;  // the base's nodes (m.base), then a post's (m.post)
  // held × readings: the σ_x reading's weights (mode 1), and the σ_z reading's (mode 0), the same but on a
  // post's foot. A disc: column 0 the point value at the axis, column 1 the disc mean (with a diameter).
  Eigen::MatrixXd w, w_z;
};

// Throws std::invalid_argument when the mesh is not cut for the sensor (a post's outline and height, or no
// post for a disc).
MeridianReading meridian_reading(const MeridianMesh& m, const ReadingSite& sensor);

}  // namespace skinfem
