// skinfem solve — Taylor–Hood P2–P1 incompressible elasticity for the scene's loads (punches,
// traction patches) on its skin, bonded to a rigid base: linear, or the neo-Hookean skin at finite strain
// (material.model), solved by Newton in load steps.
//
//   $ skinfem solve scenes/flat_layer.json --out out/flat
//   solve flat_layer: 95,211 DOFs; mesh 0.3 s, assemble 0.6 s, factor 2.1 s, solve 0.1 s; ...
//
// Writes DIR/fields.vtu (displacement_mm, pressure_MPa, stress_MPa: Cauchy's, von_mises_MPa; on the reference
// mesh), DIR/sensors.csv (sensor,x_mm,y_mm,sigma_z_kPa,sigma_x_kPa: mean base traction over each sensor disc)
// and DIR/summary.json (dofs, wall_s per stage, peak_rss_mb, residual, applied_force_N,
// base_force_balance_rel, center_ratio, punch force and depth; for neo_hookean each load step's Newton
// residuals). The computation is pipeline/solve.hpp's; this file writes and prints it.
#include <cstdio>
#include <sstream>

#include "app/commands.hpp"
#include "app/common.hpp"
#include "skinfem/fem/fields.hpp"
#include "skinfem/pipeline/solve.hpp"

namespace skinfem::app {

int run_solve(const Scene& scene, const std::string& out_dir, SolverKind solver) {
  check_output_dir(out_dir);
  Stopwatch total;
  SolveRun run = solve_run(scene, solver);
  const TetMesh& mesh = *run.mesh;
  const LoadCaseResult& r = run.result;
  Timings& wall = run.wall;

  Stopwatch clock;
  std::ostringstream csv;
  csv << "sensor,x_mm,y_mm,sigma_z_kPa,sigma_x_kPa\n";
  csv.precision(10);
  for (size_t i = 0; i < run.readings.size(); ++i) {
    const Vec2& s = scene.sensors.positions[i];
    const SensorReading& v = run.readings[i];
    csv << i + 1 << "," << s[0] << "," << s[1] << "," << 1e3 * v.sigma_z << "," << 1e3 * v.sigma_x << "\n";
  }
  prepare_output_dir(out_dir);
  const bool finite = scene.material.model == MaterialModel::neo_hookean;
  write_fields_vtu(out_dir + "/fields.vtu", mesh, run.lame, r.solution,
                   finite ? StressMeasure::neo_hookean : StressMeasure::small_strain);
  write_text_atomic(out_dir + "/sensors.csv", csv.str());
  wall["write"] = clock.seconds();

  const Eigen::Vector3d applied(r.applied_force_N[0], r.applied_force_N[1], r.applied_force_N[2]);
  const double balance = run.metrics.force_balance_rel;
  nlohmann::json summary;
  if (run.metrics.center_ratio)
    summary["center_ratio"] = *run.metrics.center_ratio;
  else
    summary["center_ratio_unavailable"] = center_ratio_unavailable(scene);
  summary["scene"] = scene_json(scene);
  summary["dofs"] = run.dofs;
  summary["nodes"] = mesh.num_nodes();
  summary["elements"] = mesh.num_tets();
  summary["solver"] = to_string(solver);
  summary["iterations"] = r.solution.iterations;
  summary["wall_s"] = wall;
  summary["wall_total_s"] = total.seconds();
  summary["peak_rss_mb"] = peak_rss_mb();
  summary["residual"] = r.solution.residual;
  summary["applied_force_N"] = {applied[0], applied[1], applied[2]};
  summary["base_force_N"] = {run.base_force_N[0], run.base_force_N[1], run.base_force_N[2]};
  summary["base_force_balance_rel"] = balance;
  for (const auto& p : r.punches)
    summary["punches"].push_back({{"force_N", p.force_N}, {"depth_mm", p.displacement_mm}});
  if (finite) {
    nlohmann::json steps = nlohmann::json::array();
    for (const NewtonStep& s : run.newton_steps)
      steps.push_back(
          {{"load_factor", s.load_factor}, {"residuals", s.residuals}, {"line_steps", s.line_steps}});
    summary["newton"] = {{"steps", steps}, {"rejected_steps", run.rejected_steps}};
  }
  write_json(out_dir + "/summary.json", summary);

  if (finite) {
    std::printf(
        "solve %s: neo-Hookean, %d DOFs; mesh %.2f s, Newton %.2f s (%zu load steps, %d halved); peak %.0f "
        "MB\n",
        scene.name.c_str(), run.dofs, wall.at("mesh"), wall.at("newton"), run.newton_steps.size(),
        run.rejected_steps, peak_rss_mb());
    for (const NewtonStep& s : run.newton_steps) {
      std::printf("  load %.4g: residuals", s.load_factor);
      for (double x : s.residuals) std::printf(" %.1e", x);
      std::printf("\n");
    }
  } else {
    std::printf(
        "solve %s: %d DOFs (%s); mesh %.2f s, assemble %.2f s, factor %.2f s, solve %.2f s; peak %.0f MB\n",
        scene.name.c_str(), run.dofs, to_string(solver), wall.at("mesh"), wall.at("assemble"),
        wall.at("factor"), wall.at("solve"), peak_rss_mb());
  }
  std::printf("  residual %.1e, applied force (%.4g, %.4g, %.4g) N, force balance %.1e", r.solution.residual,
              applied[0], applied[1], applied[2], balance);
  if (run.metrics.center_ratio) std::printf(", center_ratio %.5f", *run.metrics.center_ratio);
  std::printf("\n  wrote %s/fields.vtu, sensors.csv, summary.json\n", out_dir.c_str());
  return 0;
}

}  // namespace skinfem::app
