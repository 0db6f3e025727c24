#include "validation/load_metrics.hpp"

#include <cmath>

#include "fem/face_index.hpp"

namespace skinfem {

LoadMetrics load_metrics(const Scene& scene, const TetMesh& mesh, const LoadCaseResult& r,
                         const BaseTraction& base) {
  LoadMetrics m;
  const Eigen::Vector3d applied(r.applied_force_N[0], r.applied_force_N[1], r.applied_force_N[2]);
  m.force_balance_rel = (base.total_force() + applied).norm() / applied.norm();
  double normal_force = 0;
  if (!scene.loads.punches.empty()) {
    m.centre = scene.loads.punches[0].center;
    normal_force = r.punches[0].force_N;
  } else if (!scene.loads.patches.empty()) {
    m.centre = scene.loads.patches[0].center;
    if (std::abs(scene.loads.patches[0].direction[2]) > 0.99) normal_force = scene.loads.patches[0].force;
  }
  if (normal_force != 0) {
    const double h = skin_thickness(scene.geometry, mesh, m.centre[0], m.centre[1]);
    m.center_ratio =
        base.point_value(m.centre[0], m.centre[1], h).sigma_z / (3 * normal_force / (2 * M_PI * h * h));
  }
  return m;
}

}  // namespace skinfem
