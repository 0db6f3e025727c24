// skinfem solve — Taylor–Hood P2–P1 incompressible elasticity for the scene's loads (punches,
// traction patches) on its skin, bonded to a rigid base.
//
//   $ skinfem solve scenes/flat_layer.json --out out/flat
//   solve flat_layer: 95,211 DOFs; mesh 0.3 s, assemble 0.6 s, factor 2.1 s, solve 0.1 s; ...
//
// Writes DIR/fields.vtu (displacement_mm, pressure_MPa, stress_MPa, von_mises_MPa), DIR/sensors.csv
// (sensor,x_mm,y_mm,sigma_z_kPa,sigma_x_kPa: mean base traction over each sensor disc) and
// DIR/summary.json (dofs, wall_s per stage, peak_rss_mb, residual, applied_force_N,
// base_force_balance_rel, center_ratio, punch force and depth).
#include <cmath>
#include <cstdio>
#include <sstream>

#include "app/commands.hpp"
#include "app/common.hpp"
#include "fem/elastic_model.hpp"
#include "fem/fields.hpp"
#include "mesh/build.hpp"
#include "pipeline/adjoint_setup.hpp"
#include "pipeline/resources.hpp"
#include "validation/load_metrics.hpp"

namespace skinfem::app {

int run_solve(const Scene& scene, const std::string& out_dir, SolverKind solver) {
  if (scene.loads.punches.empty() && scene.loads.patches.empty())
    throw SceneError(scene.source_path + ": loads = {}: solve needs at least one punch or patch");
  check_output_dir(out_dir);
  Stopwatch total;
  nlohmann::json wall;
  Stopwatch clock;
  check_resources(scene, g_max_dofs);
  progress("meshing " + scene.name);
  const TetMesh mesh = build_mesh(scene);
  check_meshed_dofs(scene, mesh, g_max_dofs);
  check_sensors_on_skin(scene, mesh);
  wall["mesh"] = clock.seconds();

  progress("assembling and factoring (" + std::string(to_string(solver)) + ")");
  const ElasticModel model(mesh, scene.material, scene.geometry.side, scene.loads.punches,
                           {solver, 1e-10, {}});
  wall["assemble"] = model.assemble_seconds();
  wall["factor"] = model.solver().factor_seconds();

  clock = Stopwatch();
  Eigen::VectorXd f = Eigen::VectorXd::Zero(3 * mesh.num_nodes());
  for (const auto& patch : scene.loads.patches) f += model.patch_load(patch);
  const LoadCaseResult r = model.solve(f, scene.loads.punches);
  const BaseTraction base(mesh, r.reactions);
  wall["solve"] = clock.seconds();

  const Eigen::Vector3d applied(r.applied_force_N[0], r.applied_force_N[1], r.applied_force_N[2]);
  const LoadMetrics metrics = load_metrics(scene, mesh, r, base);
  const double balance = metrics.force_balance_rel;
  nlohmann::json summary;
  if (metrics.center_ratio) summary["center_ratio"] = *metrics.center_ratio;

  clock = Stopwatch();
  // Every reading before the first file: a run that fails leaves nothing behind.
  std::ostringstream csv;
  csv << "sensor,x_mm,y_mm,sigma_z_kPa,sigma_x_kPa\n";
  csv.precision(10);
  for (size_t i = 0; i < scene.sensors.positions.size(); ++i) {
    const auto& s = scene.sensors.positions[i];
    const SensorReading v = base.disc_mean(s[0], s[1], scene.sensors.disc_diameter);
    csv << i + 1 << "," << s[0] << "," << s[1] << "," << 1e3 * v.sigma_z << "," << 1e3 * v.sigma_x << "\n";
  }
  prepare_output_dir(out_dir);
  write_fields_vtu(out_dir + "/fields.vtu", mesh, model.lame(), r.solution);
  write_text_atomic(out_dir + "/sensors.csv", csv.str());
  wall["write"] = clock.seconds();

  summary["scene"] = scene_json(scene);
  summary["dofs"] = model.solver().free_dofs();
  summary["nodes"] = mesh.num_nodes();
  summary["elements"] = mesh.num_tets();
  summary["solver"] = to_string(solver);
  summary["iterations"] = r.solution.iterations;
  summary["wall_s"] = wall;
  summary["wall_total_s"] = total.seconds();
  summary["peak_rss_mb"] = peak_rss_mb();
  summary["residual"] = r.solution.residual;
  summary["applied_force_N"] = {applied[0], applied[1], applied[2]};
  summary["base_force_N"] = {base.total_force()[0], base.total_force()[1], base.total_force()[2]};
  summary["base_force_balance_rel"] = balance;
  for (const auto& p : r.punches)
    summary["punches"].push_back({{"force_N", p.force_N}, {"depth_mm", p.displacement_mm}});
  write_json(out_dir + "/summary.json", summary);

  std::printf(
      "solve %s: %d DOFs (%s); mesh %.2f s, assemble %.2f s, factor %.2f s, solve %.2f s; peak %.0f MB\n",
      scene.name.c_str(), model.solver().free_dofs(), to_string(solver), wall["mesh"].get<double>(),
      wall["assemble"].get<double>(), wall["factor"].get<double>(), wall["solve"].get<double>(),
      peak_rss_mb());
  std::printf("  residual %.1e, applied force (%.4g, %.4g, %.4g) N, base balance %.1e", r.solution.residual,
              applied[0], applied[1], applied[2], balance);
  if (summary.contains("center_ratio"))
    std::printf(", center_ratio %.5f", summary["center_ratio"].get<double>());
  std::printf("\n  wrote %s/fields.vtu, sensors.csv, summary.json\n", out_dir.c_str());
  return 0;
}

}  // namespace skinfem::app
