#include "skinfem/validation/load_metrics.hpp"

#include <cmath>

#include "skinfem/fem/face_index.hpp"

namespace skinfem {

namespace {
// The first punch's centre, else the first patch's; whether that load is normal.
std::pair<Vec2, bool> first_load(const Scene& scene) {
  if (!scene.loads.punches.empty()) return {scene.loads.punches[0].center, true};
  if (!scene.loads.patches.empty())
    return {scene.loads.patches[0].center, std::abs(scene.loads.patches[0].direction[2]) > 0.99};
  return {{0, 0}, false};
}
}  // namespace

std::string center_ratio_unavailable(const Scene& scene) {
  const auto [centre, normal] = first_load(scene);
  if (!normal) return "the scene's first load is not a punch or a normal patch";
  if (scene.sensors.model == SensorModel::post)
    for (const Vec2& c : scene.sensors.positions)
      if (std::hypot(centre[0] - c[0], centre[1] - c[1]) <= 0.5 * scene.sensors.post.diameter)
        return "the load's centre is over a post's foot, where there is no base to read";
  return "";
}

LoadMetrics load_metrics(const Scene& scene, const TetMesh& mesh, const LoadCaseResult& r,
                         const BaseTraction& base) {
  LoadMetrics m;
  const Eigen::Vector3d applied(r.applied_force_N[0], r.applied_force_N[1], r.applied_force_N[2]);
  // Every support's reaction: the base, posts and a held side.
  Eigen::Vector3d support = Eigen::Vector3d::Zero();
  for (int n = 0; n < mesh.num_nodes(); ++n) support += r.reactions.segment<3>(3 * n);
  m.force_balance_rel = (support + applied).norm() / applied.norm();
  const auto [centre, normal] = first_load(scene);
  m.centre = centre;
  const double normal_force = !normal                        ? 0.0
                              : !scene.loads.punches.empty() ? r.punches[0].force_N
                                                             : scene.loads.patches[0].force;
  if (normal_force != 0 && center_ratio_unavailable(scene).empty()) {
    const double h = skin_thickness(scene.geometry, mesh, m.centre[0], m.centre[1]);
    m.center_ratio =
        base.point_value(m.centre[0], m.centre[1], h).sigma_z / (3 * normal_force / (2 * M_PI * h * h));
  }
  return m;
}

}  // namespace skinfem
