// Figures of merit of one solved load case, shared by `skinfem solve` and the refinement study.
#pragma once

#include <optional>

#include "fem/elastic_model.hpp"
#include "scene/scene.hpp"

namespace skinfem {

struct LoadMetrics {
  double force_balance_rel = 0;  // |∫ base traction + applied force| / |applied force|
  Vec2 centre{0, 0};             // the first punch's centre, else the first patch's
  // Base traction below the centre (a sensor's point value there, BaseTraction::point_value) over
  // Boussinesq's 3F/(2πh²), h the skin's thickness there (its mesh for an imported skin); only for a normal
  // load (a punch, or a patch along ±z).
  std::optional<double> center_ratio;
};

LoadMetrics load_metrics(const Scene& scene, const TetMesh& mesh, const LoadCaseResult& result,
                         const BaseTraction& base);

}  // namespace skinfem
