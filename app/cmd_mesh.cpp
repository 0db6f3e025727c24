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
#include "skinfem/mesh/vtu.hpp"
#include "skinfem/pipeline/mesh_summary.hpp"
#include "skinfem/pipeline/resources.hpp"

namespace skinfem::app {

void write_mesh(const Scene& scene, const TetMesh& mesh, const pipeline::MeshSummary& s,
                const nlohmann::json& summary, const std::string& out_dir, std::string* lines) {
  const MeshQuality& q = s.quality;
  prepare_output_dir(out_dir);
  write_vtu(out_dir + "/mesh.vtu", mesh);
  write_boundary_vtu(out_dir + "/boundary.vtu", mesh);
  write_json(out_dir + "/summary.json", summary);

  say(lines, "mesh %s: %d nodes (%d vertices), %d tets; dihedral %.1f–%.1f°, max radius-edge %.2f, ",
      scene.name.c_str(), q.nodes, q.vertices, q.elements, q.min_dihedral_deg, q.max_dihedral_deg,
      q.max_radius_edge);
  say(lines, "min det J ratio %.3f; volume %.4f mm³", q.min_jacobian_ratio, q.volume_mm3);
  if (const auto exact = s.exact_volume_mm3)
    say(lines, " (exact %.4f, rel. error %.1e)", *exact, q.volume_mm3 / *exact - 1);
  if (s.straightened > 0)
    say(lines, "; %d elements folded by their curved edges were given straight ones", s.straightened);
  say(lines, "; %.2f s\n  wrote %s/mesh.vtu, boundary.vtu, summary.json\n", s.seconds, out_dir.c_str());
}

int run_mesh(const Scene& scene, const std::string& out_dir) {
  check_output_dir(out_dir);
  Stopwatch clock;
  MeshEstimate estimate;
  const TetMesh mesh = guarded_mesh(scene, MeshPart::whole, &estimate);
  const pipeline::MeshSummary s = pipeline::mesh_summary(scene, mesh, clock.seconds());
  nlohmann::json summary = pipeline::mesh_json(scene, s);
  if (estimate.known) {
    summary["estimated_tets"] = estimate.tets;
    summary["estimated_over_actual_tets"] = estimate.tets / mesh.num_tets();
  }
  write_mesh(scene, mesh, s, summary, out_dir);
  return 0;
}

}  // namespace skinfem::app
