// Figures of merit of one solved load case, shared by `skinfem solve` and the refinement study.
#pragma once

#include <optional>
#include <string>

#include "skinfem/fem/elastic_model.hpp"
#include "skinfem/scene/scene.hpp"

namespace skinfem {

struct LoadMetrics {
  double force_balance_rel = 0;  // |Σ reactions (base, posts, a held side) + applied force| / |applied|
  Vec2 centre{0, 0};             // the first punch's centre, else the first patch's
  // Base traction below the centre (a sensor's point value there, BaseTraction::point_value) over
  // Boussinesq's 3F/(2πh²), h the skin's thickness there (its mesh for an imported skin); only for a normal
  // load (a punch, or a patch along ±z) whose centre has base below it (not a post's foot).
  std::optional<double> center_ratio;
};

// Why a scene's load has no center_ratio (no normal load; its centre over a post, where no base is below),
// or empty.
std::string center_ratio_unavailable(const Scene& scene);

LoadMetrics load_metrics(const Scene& scene, const TetMesh& mesh, const LoadCaseResult& result,
                         const BaseTraction& base);

}  // namespace skinfem
