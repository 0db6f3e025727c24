#include "skinfem/pipeline/preloaded_skin.hpp"

#include <cstdio>

#include "skinfem/fem/finite_strain.hpp"
#include "skinfem/fem/supports.hpp"
#include "skinfem/pipeline/adjoint_setup.hpp"
#include "skinfem/pipeline/progress.hpp"
#include "skinfem/pipeline/resources.hpp"
#include "skinfem/pipeline/symmetry.hpp"

namespace skinfem::pipeline {

std::string Preload::said() const {
  if (patches == 0) return "linearized at rest (no loads.patches: the linear skin's Green tensor)";
  char buf[240];
  std::snprintf(buf, sizeof buf,
                "linearized about the state of its %d traction patch%s (force (%.4g, %.4g, %.4g) N, largest "
                "displacement %.4g mm; %zu Newton steps)",
                patches, patches == 1 ? "" : "es", force_N.x(), force_N.y(), force_N.z(), max_displacement_mm,
                steps.size());
  return buf;
}

void check_preload(const Scene& scene) {
  if (!scene.loads.punches.empty())
    throw SceneError(scene.source_path +
                     ": loads.punches: with material.model \"neo_hookean\" the Green "
                     "tensor's preload is loads.patches alone (" +
                     std::to_string(scene.loads.punches.size()) + " punches given)");
  require_rigid_posts(scene);
}

MeshPart preload_mesh_part(const Scene& scene) {
  for (const TractionPatch& p : scene.loads.patches)
    if (p.center[1] != 0 || p.direction[1] != 0) return MeshPart::whole;
  return green_mesh_part(scene);
}

std::shared_ptr<Skin> preloaded_skin(const Scene& scene, MeshPart part, Preload* preload) {
  check_preload(scene);
  Stopwatch clock;
  auto skin = std::make_shared<Skin>();
  skin->mesh = guarded_mesh(scene, part);
  const TetMesh& mesh = skin->mesh;
  check_sensors_on_skin(scene, mesh);
  skin->wall["mesh"] = clock.seconds();

  clock = Stopwatch();
  const double mu = Lame::from(scene.material.E, scene.material.nu).mu;
  const Supports held = skin_supports(mesh, scene.geometry.side, {});
  Eigen::VectorXd f = Eigen::VectorXd::Zero(3 * mesh.num_nodes());
  for (const TractionPatch& patch : scene.loads.patches) f += patch_load(mesh, patch);
  Preload p;
  p.patches = static_cast<int>(scene.loads.patches.size());
  MixedSolution state{Eigen::VectorXd::Zero(3 * mesh.num_nodes()), Eigen::VectorXd::Zero(mesh.num_vertices)};
  if (p.patches > 0) {
    progress("Newton on the neo-Hookean skin under its " + std::to_string(p.patches) + " patch(es)");
    FiniteStrainResult fs = solve_finite_strain(mesh, mu, held.fixed, f);
    state = fs.solution;
    p.steps = std::move(fs.steps);
    p.rejected_steps = fs.rejected_steps;
  }
  for (const TractionPatch& patch : scene.loads.patches)
    for (int c = 0; c < 3; ++c) p.force_N[c] += patch.force * patch.direction[c];
  for (int i = 0; i < mesh.num_nodes(); ++i)
    p.max_displacement_mm = std::max(p.max_displacement_mm, state.u.segment<3>(3 * i).norm());
  skin->wall["newton"] = clock.seconds();

  clock = Stopwatch();
  progress("the tangent at the preloaded state: assembling and factoring (" +
           std::to_string(mesh.num_nodes()) + " nodes)");
  FiniteStrainSystem system = assemble_finite_strain(mesh, mu, state.u, state.p);
  skin->wall["assemble"] = clock.seconds();
  skin->model = std::make_unique<ElasticModel>(mesh, std::move(system.tangent), mu, scene.geometry.side);
  skin->wall["factor"] = skin->model->solver().factor_seconds();
  if (preload) *preload = std::move(p);
  return skin;
}

}  // namespace skinfem::pipeline
