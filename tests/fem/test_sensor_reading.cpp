// The sensor-reading seam (fem/sensor_reading.hpp): a uniform base traction read exactly (closed form: the
// disc mean of a constant), the forward reading against the traction-field route of fem/base_traction.hpp
// (a second method), and the weight block's layout.
#include <gtest/gtest.h>

#include <cmath>

#include "skinfem/fem/base_traction.hpp"
#include "skinfem/fem/elastic_model.hpp"
#include "skinfem/fem/sensor_reading.hpp"
#include "skinfem/mesh/build.hpp"

namespace skinfem {
namespace {

Scene layer_scene() {
  Scene s;
  s.geometry.kind = GeometryKind::flat;
  s.geometry.flat = {1.5, 3.0};
  s.sensors.positions = {{0, 0}, {-1, 0.4}};
  s.sensors.disc_diameter = 0.2;
  s.mesh.h_min = 0.25;
  s.mesh.h_max = 0.75;
  s.mesh.growth = 1.5;
  return s;
}

const TetMesh& layer() {
  static const TetMesh m = build_mesh(layer_scene());
  return m;
}

// Nodal reactions of a uniform traction t on the flat base: on a straight P2 triangle of area A, ∫φ = 0 at
// the corners and A/3 at the mid-edge nodes.
Eigen::VectorXd uniform_reactions(const TetMesh& m, const Eigen::Vector3d& t) {
  Eigen::VectorXd R = Eigen::VectorXd::Zero(3 * m.num_nodes());
  for (int f = 0; f < m.faces.rows(); ++f) {
    if (m.face_marker[f] != kBase) continue;
    const Eigen::Vector3d a = m.nodes.row(m.faces(f, 0)), b = m.nodes.row(m.faces(f, 1)),
                          c = m.nodes.row(m.faces(f, 2));
    const double area = 0.5 * (b - a).cross(c - a).norm();
    for (int k = 3; k < 6; ++k) R.segment<3>(3 * m.faces(f, k)) += area / 3 * t;
  }
  return R;
}

TEST(SensorReading, UniformTractionIsReadExactly) {
  // σ_z = t_z, σ_x = −t_x (docs/theory.md §Conventions), for the point value and the disc mean alike: the
  // base mass matrix maps R back to the constant field exactly, and the reading's weights sum to one.
  const Eigen::Vector3d t(0.3, -0.2, 0.7);  // MPa
  const Eigen::VectorXd R = uniform_reactions(layer(), t);
  for (bool point : {true, false}) {
    const SensorReadings readings(layer(), reading_sites(layer_scene().sensors, point));
    for (int k = 0; k < readings.size(); ++k) {
      const SensorReading v = readings.read(k, R);
      EXPECT_NEAR(v.sigma_z, t.z(), 1e-12) << "site " << k << " point " << point;
      EXPECT_NEAR(v.sigma_x, -t.x(), 1e-12) << "site " << k << " point " << point;
    }
  }
}

TEST(SensorReading, ForwardReadingMatchesTheTractionField) {
  // A slanted traction patch's reactions, read through the weights and through the interpolated traction
  // field's disc quadrature (BaseTraction): equal in exact arithmetic, the base mass matrix well conditioned.
  const TetMesh& m = layer();
  const ElasticModel model(m, layer_scene().material, SideCondition::free, std::vector<Punch>{});
  const TractionPatch slanted{{0.2, 0.1}, 0.5, {1, 0.5, -1}, 1.0};
  const Eigen::VectorXd R = model.solve(model.patch_load(slanted), {}).reactions;
  const BaseTraction field(m, R);
  const Scene s = layer_scene();
  const SensorReadings readings(m, reading_sites(s.sensors));
  for (int k = 0; k < readings.size(); ++k) {
    const Vec2& p = s.sensors.positions[k];
    const SensorReading a = readings.read(k, R), b = field.disc_mean(p[0], p[1], s.sensors.disc_diameter);
    EXPECT_NEAR(a.sigma_z, b.sigma_z, 1e-12 * std::abs(b.sigma_z)) << k;
    EXPECT_NEAR(a.sigma_x, b.sigma_x, 1e-12 * std::abs(b.sigma_x)) << k;
  }
}

TEST(SensorReading, WeightBlockLayout) {
  const SensorReadings readings(layer(), reading_sites(layer_scene().sensors));
  const Eigen::MatrixXd W = readings.weight_block();
  ASSERT_EQ(W.cols(), 2 * readings.size());
  for (int k = 0; k < readings.size(); ++k) {
    EXPECT_EQ((W.col(2 * k) - readings.weights(k, 'z')).norm(), 0.0);
    EXPECT_EQ((W.col(2 * k + 1) - readings.weights(k, 'x')).norm(), 0.0);
  }
  EXPECT_THROW(SensorReadings(layer(), {disc_site({2.95, 0}, 0.2)}).weights(0, 'z'), std::out_of_range);
}

}  // namespace
}  // namespace skinfem
