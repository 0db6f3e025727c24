#include "skinfem/pipeline/solve.hpp"

#include <algorithm>

#include "skinfem/fem/base_traction.hpp"
#include "skinfem/mesh/build.hpp"
#include "skinfem/pipeline/adjoint_setup.hpp"
#include "skinfem/pipeline/clock.hpp"
#include "skinfem/pipeline/progress.hpp"
#include "skinfem/pipeline/resources.hpp"

namespace skinfem::pipeline {

namespace {

// The finite-strain skin's refusals, before meshing.
void check_finite_strain(const Scene& scene) {
  for (size_t i = 0; i < scene.loads.punches.size(); ++i)
    if (!scene.loads.punches[i].displacement)
      throw SceneError(
          scene.source_path + ": loads.punches[" + std::to_string(i) +
          "].force: with material.model \"neo_hookean\" a punch is driven by its \"displacement\"");
  require_rigid_posts(scene);
}

// Newton on the neo-Hookean skin; the run's result as the linear solve gives it.
void solve_finite_strain_run(const Scene& scene, SolveRun& run) {
  const TetMesh& mesh = *run.mesh;
  Stopwatch clock;
  const Supports held = skin_supports(mesh, scene.geometry.side, scene.loads.punches);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(3 * mesh.num_nodes());
  for (const auto& patch : scene.loads.patches) f += patch_load(mesh, patch);
  Eigen::VectorXd u_fixed = Eigen::VectorXd::Zero(3 * mesh.num_nodes());
  for (size_t k = 0; k < held.punch_nodes.size(); ++k)
    for (int i : held.punch_nodes[k]) u_fixed[3 * i + 2] = -*scene.loads.punches[k].displacement;
  run.wall["assemble"] = clock.seconds();  // the supports and loads; Newton assembles in its iterations

  clock = Stopwatch();
  progress("Newton on the neo-Hookean skin");
  FiniteStrainResult fs = solve_finite_strain(mesh, run.lame.mu, held.fixed, f, u_fixed);
  run.wall["newton"] = clock.seconds();
  run.dofs = static_cast<int>(std::count(held.fixed.begin(), held.fixed.end(), false)) + mesh.num_vertices;

  LoadCaseResult& out = run.result;
  out.solution = fs.solution;
  const Eigen::VectorXd r = fs.internal_force - f;  // at held DOFs: the force the skin puts on its holder
  out.reactions = support_reactions(held, r);
  for (size_t k = 0; k < held.punch_nodes.size(); ++k)
    out.punches.push_back({punch_force(held.punch_nodes[k], r), *scene.loads.punches[k].displacement});
  const Eigen::Vector3d applied = applied_force(held, r, f);
  for (int c = 0; c < 3; ++c) out.applied_force_N[c] = applied[c];
  run.newton_steps = std::move(fs.steps);
  run.rejected_steps = fs.rejected_steps;
}

}  // namespace

SolveRun solve_run(const Scene& scene, SolverKind solver) {
  if (scene.loads.punches.empty() && scene.loads.patches.empty())
    throw SceneError(scene.source_path + ": loads = {}: solve needs at least one punch or patch");
  const bool finite = scene.material.model == MaterialModel::neo_hookean;
  if (finite) check_finite_strain(scene);
  if (finite && solver != SolverKind::direct_ldlt)
    throw SceneError(std::string("--solver ") + to_string(solver) +
                     ": the neo-Hookean skin's Newton factors each tangent; use direct_ldlt");
  SolveRun run;
  run.lame = Lame::from(scene.material.E, scene.material.nu);
  Stopwatch clock;
  run.mesh = std::make_unique<TetMesh>(guarded_mesh(scene));
  const TetMesh& mesh = *run.mesh;
  check_sensors_on_skin(scene, mesh);
  run.wall["mesh"] = clock.seconds();
  if (finite) {
    solve_finite_strain_run(scene, run);
  } else {
    progress("assembling and factoring (" + std::string(to_string(solver)) + ")");
    run.model = std::make_unique<ElasticModel>(mesh, scene.material, scene.geometry.side, scene.loads.punches,
                                               ModelOptions{solver, 1e-10, {}});
    run.wall["assemble"] = run.model->assemble_seconds();
    run.wall["factor"] = run.model->solver().factor_seconds();
    run.dofs = run.model->solver().free_dofs();
    clock = Stopwatch();
    Eigen::VectorXd f = Eigen::VectorXd::Zero(3 * mesh.num_nodes());
    for (const auto& patch : scene.loads.patches) f += run.model->patch_load(patch);
    run.result = run.model->solve(f, scene.loads.punches);
    run.wall["solve"] = clock.seconds();
  }
  const BaseTraction base(mesh, run.result.reactions);
  run.metrics = load_metrics(scene, mesh, run.result, base);
  run.base_force_N = base.total_force();
  const SensorReadings readings(mesh, reading_sites(scene.sensors),
                                run.model ? &run.model->solver() : nullptr);
  for (int i = 0; i < readings.size(); ++i) run.readings.push_back(readings.read(i, run.result.reactions));
  return run;
}

}  // namespace skinfem::pipeline
