#include "skinfem/pipeline/solve.hpp"

#include "skinfem/fem/base_traction.hpp"
#include "skinfem/mesh/build.hpp"
#include "skinfem/pipeline/adjoint_setup.hpp"
#include "skinfem/pipeline/clock.hpp"
#include "skinfem/pipeline/progress.hpp"
#include "skinfem/pipeline/resources.hpp"

namespace skinfem::pipeline {

SolveRun solve_run(const Scene& scene, SolverKind solver) {
  if (scene.loads.punches.empty() && scene.loads.patches.empty())
    throw SceneError(scene.source_path + ": loads = {}: solve needs at least one punch or patch");
  SolveRun run;
  Stopwatch clock;
  run.mesh = std::make_unique<TetMesh>(guarded_mesh(scene));
  const TetMesh& mesh = *run.mesh;
  check_sensors_on_skin(scene, mesh);
  run.wall["mesh"] = clock.seconds();

  progress("assembling and factoring (" + std::string(to_string(solver)) + ")");
  run.model = std::make_unique<ElasticModel>(mesh, scene.material, scene.geometry.side, scene.loads.punches,
                                             ModelOptions{solver, 1e-10, {}});
  run.wall["assemble"] = run.model->assemble_seconds();
  run.wall["factor"] = run.model->solver().factor_seconds();

  clock = Stopwatch();
  Eigen::VectorXd f = Eigen::VectorXd::Zero(3 * mesh.num_nodes());
  for (const auto& patch : scene.loads.patches) f += run.model->patch_load(patch);
  run.result = run.model->solve(f, scene.loads.punches);
  const BaseTraction base(mesh, run.result.reactions);
  run.wall["solve"] = clock.seconds();
  run.metrics = load_metrics(scene, mesh, run.result, base);
  run.base_force_N = base.total_force();
  const SensorReadings readings(mesh, reading_sites(scene.sensors), &run.model->solver());
  for (int i = 0; i < readings.size(); ++i) run.readings.push_back(readings.read(i, run.result.reactions));
  return run;
}

}  // namespace skinfem::pipeline
