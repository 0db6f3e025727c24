// skinfem defect — the paper's §IV: a hole in the indenter swept along a path through the contact, a
// full contact solve at every position, static (residual traction, static_ratio/μ of the sliding one) and
// sliding (coupled, with the scene's friction law: Coulomb μp, a shear strength τ0 or both; docs/contact.md).
// ς = sensor reading with the hole − without, for every sensor and position. A hole path on y = 0 in a
// mirror-symmetric scene is solved on the half y ≥ 0 (pipeline/symmetry.hpp), frames written whole.
//
//   $ skinfem defect scenes/candelier2011.json --out out/defect
//   defect candelier2011: 2 × 201 positions, 0.9 ms per position; ...
//
// Writes DIR/defect.csv (case,u_mm,sensor,varsigma_z_kPa,varsigma_x_kPa; u = the hole centre's x),
// DIR/defect.pvd with DIR/frames/<case>_NNN.vtp (the contact pressure at each position: a ParaView
// animation, part 0 static, part 1 sliding) and DIR/summary.json (positions, wall_s per stage, time per
// position, peak |ς| per sensor and case, complementarity, max_roughness: the largest second difference
// along u over its curve's peak (validation::roughness), peak_rss_mb).
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "app/commands.hpp"
#include "app/common.hpp"
#include "app/stages.hpp"
#include "contact/hole_sweep.hpp"
#include "contact/pressure_map.hpp"
#include "pipeline/contact_setup.hpp"
#include "validation/hole_budget.hpp"

namespace skinfem::app {

DefectStage defect_stage(const Scene& scene, const ContactSetup& setup, const std::string& out_dir) {
  const HoleSweep& sweep = *scene.contact->sweep;
  nlohmann::json wall = setup.wall;
  const std::vector<std::pair<std::string, FrictionMode>> cases{{"static", FrictionMode::static_residual},
                                                                {"sliding", FrictionMode::coupled}};
  std::vector<contact::SweepResult> results;
  std::vector<std::vector<contact::ContactResult>> frames(cases.size());
  for (const auto& c : cases) check_zone(scene, setup, setup.solver->solve(c.second));
  for (size_t ci = 0; ci < cases.size(); ++ci) {
    const auto& [name, mode] = cases[ci];
    Stopwatch clock;
    results.push_back(contact::hole_sweep(
        *setup.solver, setup.mesh(), sweep, mode, [&](int i, const contact::ContactResult& r) {
          frames[ci].push_back(r);
          if ((i + 1) % 50 == 0 || i + 1 == sweep.positions) {
            char buf[128];
            std::snprintf(buf, sizeof buf, "sweep %s: %d/%d positions (%.1f s)", name.c_str(), i + 1,
                          sweep.positions, clock.seconds());
            progress(buf);
          }
        }));
    wall["sweep_" + name] = clock.seconds();
  }

  Stopwatch clock;
  prepare_output_dir(out_dir + "/frames");
  std::ostringstream pvd;
  pvd << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
  for (size_t ci = 0; ci < cases.size(); ++ci)
    for (size_t i = 0; i < frames[ci].size(); ++i) {
      char file[64];
      std::snprintf(file, sizeof file, "%s_%03zu.vtp", cases[ci].first.c_str(), i);
      contact::write_pressure_vtp(out_dir + "/frames/" + file, setup.mesh(), *setup.solver, frames[ci][i]);
      pvd << "<DataSet timestep=\"" << results[ci].centers[i][0] << "\" part=\"" << ci << "\" file=\"frames/"
          << file << "\"/>\n";
    }
  pvd << "</Collection>\n</VTKFile>\n";
  std::ostringstream csv;
  csv.precision(10);
  csv << "case,u_mm,sensor,varsigma_z_kPa,varsigma_x_kPa\n";
  const int ns = static_cast<int>(scene.sensors.positions.size());
  nlohmann::json summary;
  for (size_t ci = 0; ci < cases.size(); ++ci) {
    const auto& res = results[ci];
    for (size_t i = 0; i < res.centers.size(); ++i)
      for (int k = 0; k < ns; ++k)
        csv << cases[ci].first << "," << res.centers[i][0] << "," << k + 1 << ","
            << 1e3 * res.varsigma(i, 2 * k) << "," << 1e3 * res.varsigma(i, 2 * k + 1) << "\n";
    nlohmann::json c;
    c["friction"] = contact::to_string(res.mode);
    c["ratio"] = setup.solver->ratio(res.mode);
    c["shear_kPa"] = 1e3 * setup.solver->shear(res.mode);
    c["seconds"] = res.seconds;
    c["ms_per_position"] = 1e3 * res.seconds / sweep.positions;
    c["max_complementarity"] = res.max_complementarity;
    double pivots = 0;
    for (int p : res.pivots) pivots += p;
    c["mean_pivots"] = pivots / res.pivots.size();
    // The jaggedness of each curve (validation::roughness), and the worst.
    double rough = 0;
    int rough_col = 0;
    for (int col = 0; col < 2 * ns; ++col)
      if (const double r = validation::roughness(res.varsigma.col(col)); r > rough)
        rough = r, rough_col = col;
    c["max_roughness"] = rough;
    c["max_roughness_curve"] =
        "#" + std::to_string(rough_col / 2 + 1) + (rough_col % 2 ? " varsigma_x" : " varsigma_z");
    for (int k = 0; k < ns; ++k) {
      Eigen::Index iz, ix;
      const double z = res.varsigma.col(2 * k).cwiseAbs().maxCoeff(&iz);
      const double x = res.varsigma.col(2 * k + 1).cwiseAbs().maxCoeff(&ix);
      c["sensors"].push_back({{"sensor", k + 1},
                              {"peak_abs_varsigma_z_kPa", 1e3 * z},
                              {"u_at_peak_z_mm", res.centers[iz][0]},
                              {"peak_abs_varsigma_x_kPa", 1e3 * x},
                              {"u_at_peak_x_mm", res.centers[ix][0]}});
    }
    summary["cases"][cases[ci].first] = c;
  }
  write_text_atomic(out_dir + "/defect.csv", csv.str());
  write_text_atomic(out_dir + "/defect.pvd", pvd.str());
  wall["write"] = clock.seconds();

  summary["scene"] = scene_json(scene);
  summary["friction_law"] = contact::to_string(scene.contact->law);
  summary["positions"] = sweep.positions;
  summary["hole_diameter_mm"] = sweep.hole_diameter;
  summary["from_mm"] = {sweep.from[0], sweep.from[1]};
  summary["to_mm"] = {sweep.to[0], sweep.to[1]};
  summary["dofs"] = setup.model->solver().free_dofs();
  summary["multipliers"] = setup.solver->zone().size();
  summary["multipliers_solved"] = setup.condensed->zone.size();
  summary["block_solves"] = setup.condensed->block_solves;
  summary["wall_s"] = wall;
  summary["wall_total_s"] = total_seconds(wall);
  summary["peak_rss_mb"] = peak_rss_mb();
  write_json(out_dir + "/summary.json", summary);

  std::printf("defect %s: %zu cases x %d positions; %d DOFs, %d multipliers (%d solved%s)\n",
              scene.name.c_str(), cases.size(), sweep.positions, setup.model->solver().free_dofs(),
              setup.solver->zone().size(), setup.condensed->zone.size(),
              setup.whole ? " on the half y >= 0, mirror-symmetric" : "");
  std::printf("  mesh %.2f s, assemble %.2f s, factor %.2f s, condense %.2f s; sweeps",
              wall["mesh"].get<double>(), wall["assemble"].get<double>(), wall["factor"].get<double>(),
              wall["condense"].get<double>());
  for (size_t ci = 0; ci < cases.size(); ++ci)
    std::printf(" %s %.2f s (%.2f ms/position)", cases[ci].first.c_str(), results[ci].seconds,
                1e3 * results[ci].seconds / sweep.positions);
  std::printf("; total %.1f s, peak %.0f MB\n", total_seconds(wall), peak_rss_mb());
  for (size_t ci = 0; ci < cases.size(); ++ci) {
    const auto& c = summary["cases"][cases[ci].first];
    std::printf("  %s: largest second difference along u %.1f %% of its curve's peak (%s)\n",
                cases[ci].first.c_str(), 100 * c["max_roughness"].get<double>(),
                c["max_roughness_curve"].get<std::string>().c_str());
    std::printf("  %s: peak |varsigma_z| per sensor (kPa):", cases[ci].first.c_str());
    for (int k = 0; k < ns; ++k)
      std::printf(" %.2f", 1e3 * results[ci].varsigma.col(2 * k).cwiseAbs().maxCoeff());
    std::printf("\n");
  }
  std::printf("  wrote %s/defect.csv, defect.pvd (+ frames/), summary.json\n", out_dir.c_str());
  return {summary, std::move(results), std::move(frames)};
}

int run_defect(const Scene& scene, const std::string& out_dir) {
  if (!scene.contact || !scene.contact->sweep)
    throw SceneError(scene.source_path +
                     ": contact.sweep: missing; skinfem defect needs a \"contact\" section with a \"sweep\"");
  check_output_dir(out_dir);
  defect_stage(scene, *contact_setup(scene), out_dir);
  return 0;
}

}  // namespace skinfem::app
