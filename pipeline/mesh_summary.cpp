#include "skinfem/pipeline/mesh_summary.hpp"

#include <cmath>

#include "skinfem/mesh/shape.hpp"
#include "skinfem/pipeline/clock.hpp"
#include "skinfem/pipeline/scene_json.hpp"

namespace skinfem::pipeline {

namespace {
std::optional<double> exact_volume(const Scene& scene) {
  const SkinShape shape(scene.geometry);
  if (!shape.exact()) return std::nullopt;
  double v = shape.volume();
  if (scene.sensors.model == SensorModel::post) {
    const PostSensor& p = scene.sensors.post;
    v -= static_cast<double>(scene.sensors.positions.size()) * M_PI * 0.25 * p.diameter * p.diameter *
         p.height;
  }
  return v;
}
}  // namespace

MeshSummary mesh_summary(const Scene& scene, const TetMesh& mesh, double mesh_seconds) {
  return {assess_quality(mesh), exact_volume(scene), mesh.straightened, mesh_seconds};
}

nlohmann::json mesh_json(const Scene& scene, const MeshSummary& s) {
  const MeshQuality& q = s.quality;
  nlohmann::json j = {{"nodes", q.nodes},
                      {"vertices", q.vertices},
                      {"elements", q.elements},
                      {"boundary_faces", q.boundary_faces},
                      {"min_dihedral_deg", q.min_dihedral_deg},
                      {"max_dihedral_deg", q.max_dihedral_deg},
                      {"max_radius_edge", q.max_radius_edge},
                      {"min_edge_mm", q.min_edge_mm},
                      {"max_edge_mm", q.max_edge_mm},
                      {"min_jacobian_ratio", q.min_jacobian_ratio},
                      {"volume_mm3", q.volume_mm3}};
  if (s.exact_volume_mm3) {
    j["exact_volume_mm3"] = *s.exact_volume_mm3;
    j["volume_rel_error"] = q.volume_mm3 / *s.exact_volume_mm3 - 1;
  }
  j["scene"] = scene_json(scene);
  j["straightened_elements"] = s.straightened;
  j["wall_s"] = s.seconds;
  j["peak_rss_mb"] = peak_rss_mb();
  return j;
}

}  // namespace skinfem::pipeline
