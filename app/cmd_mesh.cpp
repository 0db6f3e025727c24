// skinfem mesh — meshes the scene's skin with graded 10-node tetrahedra and reports their quality.
//
//   $ skinfem mesh scenes/candelier2011.json --out out
//   mesh: 9,412 nodes, 5,870 tets, min dihedral 14.2°, max radius-edge 1.9, volume error 2e-7, 0.8 s
//
// Writes DIR/mesh.vtu (quadratic tets, point data boundary_marker: 1 base, 2 top, 4 side, 16 the symmetry
// cut, 32 a post sensor's wall and top, OR-ed),
// DIR/boundary.vtu (the marked boundary faces) and DIR/summary.json (counts, quality, volume, wall_s).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include "app/commands.hpp"
#include "app/common.hpp"
#include "app/stages.hpp"
#include "skinfem/mesh/build.hpp"
#include "skinfem/mesh/quality.hpp"
#include "skinfem/mesh/shape.hpp"
#include "skinfem/mesh/vtu.hpp"
#include "skinfem/pipeline/resources.hpp"

namespace skinfem::app {

namespace {
// The skin's exact volume where its shape is known: the generated layer's, less its post sensors' cavities.
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

nlohmann::json quality_json(const MeshQuality& q, const Scene& scene) {
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
  if (const auto exact = exact_volume(scene)) {
    j["exact_volume_mm3"] = *exact;
    j["volume_rel_error"] = q.volume_mm3 / *exact - 1;
  }
  return j;
}

nlohmann::json mesh_stage(const Scene& scene, const TetMesh& mesh, double mesh_s, const std::string& out_dir,
                          std::string* lines) {
  const MeshQuality q = assess_quality(mesh);

  prepare_output_dir(out_dir);
  write_vtu(out_dir + "/mesh.vtu", mesh);
  write_boundary_vtu(out_dir + "/boundary.vtu", mesh);
  nlohmann::json summary = quality_json(q, scene);
  summary["scene"] = scene_json(scene);
  summary["straightened_elements"] = mesh.straightened;
  summary["wall_s"] = mesh_s;
  summary["peak_rss_mb"] = peak_rss_mb();
  write_json(out_dir + "/summary.json", summary);

  say(lines, "mesh %s: %d nodes (%d vertices), %d tets; dihedral %.1f–%.1f°, max radius-edge %.2f, ",
      scene.name.c_str(), q.nodes, q.vertices, q.elements, q.min_dihedral_deg, q.max_dihedral_deg,
      q.max_radius_edge);
  say(lines, "min det J ratio %.3f; volume %.4f mm³", q.min_jacobian_ratio, q.volume_mm3);
  if (const auto exact = exact_volume(scene))
    say(lines, " (exact %.4f, rel. error %.1e)", *exact, q.volume_mm3 / *exact - 1);
  if (mesh.straightened > 0)
    say(lines, "; %d elements folded by their curved edges were given straight ones", mesh.straightened);
  say(lines, "; %.2f s\n  wrote %s/mesh.vtu, boundary.vtu, summary.json\n", mesh_s, out_dir.c_str());
  return summary;
}

int run_mesh(const Scene& scene, const std::string& out_dir) {
  check_output_dir(out_dir);
  Stopwatch clock;
  MeshEstimate estimate;
  const TetMesh mesh = guarded_mesh(scene, MeshPart::whole, &estimate);
  nlohmann::json summary = mesh_stage(scene, mesh, clock.seconds(), out_dir);
  if (estimate.known) {
    summary["estimated_tets"] = estimate.tets;
    summary["estimated_over_actual_tets"] = estimate.tets / mesh.num_tets();
    write_json(out_dir + "/summary.json", summary);
  }
  return 0;
}

}  // namespace skinfem::app
