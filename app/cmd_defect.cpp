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
// DIR/defect.pvd with DIR/frames/<case>_NNN.vtp (the contact pressure at each position, at most 201 per
// case evenly spaced, NNN the position: a ParaView animation, part 0 static, part 1 sliding) and
// DIR/summary.json (positions, wall_s per stage, time per position, peak |ς| per sensor and case,
// complementarity, max_roughness: the largest second difference along u over its curve's peak
// (validation::roughness), peak_rss_mb). The computation and summary.json are pipeline/defect.hpp's; this
// file writes and prints them.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "app/animation.hpp"
#include "app/commands.hpp"
#include "app/common.hpp"
#include "app/report_page.hpp"
#include "app/stages.hpp"
#include "skinfem/contact/holes/sweep.hpp"
#include "skinfem/contact/pressure_map.hpp"
#include "skinfem/pipeline/contact_setup.hpp"
#include "skinfem/pipeline/defect.hpp"
#include "skinfem/pipeline/finite_defect.hpp"
#include "skinfem/validation/text.hpp"

namespace skinfem::app {

using validation::fmt;

void write_defect(const Scene& scene, const DefectRun& run, nlohmann::json& summary,
                  const std::string& out_dir, bool write_frames) {
  const ContactSetup& setup = *run.setup;
  const HoleSweep& sweep = *scene.contact->sweep;
  const auto& results = run.sweeps;
  const auto& frames = run.frames;
  Stopwatch clock;
  // The frames pipeline::written_frame picks (the run may keep more); defect.csv keeps every position.
  std::vector<AnimationFrame> written;
  std::vector<std::pair<size_t, size_t>> kept;  // per written frame: its case and its place in run.frames
  for (size_t ci = 0; ci < run.cases.size() && write_frames; ++ci)
    for (size_t k = 0; k < frames[ci].size(); ++k) {
      const int i = run.frame_positions[ci][k];
      if (!pipeline::written_frame(i, sweep.positions)) continue;
      char file[64];
      std::snprintf(file, sizeof file, "%s_%03d.vtp", run.cases[ci].c_str(), i);
      written.push_back({file, results[ci].centers[i][0], static_cast<int>(ci)});
      kept.push_back({ci, k});
    }
  const std::string pvd = write_animation_frames(out_dir, written, [&](size_t w, const std::string& path) {
    const auto [ci, k] = kept[w];
    const Vec2& c = results[ci].centers[run.frame_positions[ci][k]];
    contact::write_pressure_vtp(path, setup.mesh(), *setup.solver, frames[ci][k],
                                {Hole{c, sweep.hole_diameter, 0.0, sweep.hole_depth}});
  });
  std::ostringstream csv;
  csv.precision(10);
  csv << "case,u_mm,sensor,varsigma_z_kPa,varsigma_x_kPa\n";
  const int ns = static_cast<int>(scene.sensors.positions.size());
  for (size_t ci = 0; ci < run.cases.size(); ++ci) {
    const auto& res = results[ci];
    for (size_t i = 0; i < res.centers.size(); ++i)
      for (int k = 0; k < ns; ++k)
        csv << run.cases[ci] << "," << res.centers[i][0] << "," << k + 1 << ","
            << 1e3 * res.varsigma(i, 2 * k) << "," << 1e3 * res.varsigma(i, 2 * k + 1) << "\n";
  }
  write_text_atomic(out_dir + "/defect.csv", csv.str());
  if (write_frames) {
    write_text_atomic(out_dir + "/defect.pvd", pvd);
  } else {                    // nothing of an earlier run's animation stays
    std::error_code ignored;  // frames/ holds no .vtp now; a file of the user's there keeps it
    std::filesystem::remove(out_dir + "/defect.pvd");
    std::filesystem::remove(out_dir + "/frames", ignored);
  }
  add_write_seconds(summary, clock.seconds());
  write_json(out_dir + "/summary.json", summary);
  const Timings& wall = run.wall;

  std::printf("defect %s: %zu cases x %d positions; %d DOFs, %d multipliers (%d solved%s)\n",
              scene.name.c_str(), run.cases.size(), sweep.positions, setup.model->solver().free_dofs(),
              setup.solver->zone().size(), setup.condensed->zone.size(),
              setup.whole ? " on the half y >= 0, mirror-symmetric" : "");
  std::printf("  mesh %.2f s, assemble %.2f s, factor %.2f s, condense %.2f s; sweeps", wall.at("mesh"),
              wall.at("assemble"), wall.at("factor"), wall.at("condense"));
  for (size_t ci = 0; ci < run.cases.size(); ++ci)
    std::printf(" %s %.2f s (%.2f ms/position)", run.cases[ci].c_str(), results[ci].seconds,
                1e3 * results[ci].seconds / sweep.positions);
  std::printf("; total %.1f s, peak %.0f MB\n", summary.at("wall_total_s").get<double>(), peak_rss_mb());
  for (size_t ci = 0; ci < run.cases.size(); ++ci) {
    const int col = run.max_roughness_column[ci];
    std::printf("  %s: largest second difference along u %.1f %% of its curve's peak (#%d varsigma_%c)\n",
                run.cases[ci].c_str(), 100 * run.max_roughness[ci], col / 2 + 1, col % 2 ? 'x' : 'z');
    std::printf("  %s: peak |varsigma_z| per sensor (kPa):", run.cases[ci].c_str());
    for (int k = 0; k < ns; ++k)
      std::printf(" %.2f", 1e3 * results[ci].varsigma.col(2 * k).cwiseAbs().maxCoeff());
    std::printf("\n");
  }
  if (summary.contains("largest_sliding")) {
    const nlohmann::json& b = summary["largest_sliding"];
    std::string scales;
    for (const auto& l : b["levels"])
      scales += (scales.empty() ? "" : ", ") + fmt("%g", l["mesh_scale"].get<double>());
    std::printf("  largest sliding |varsigma_z|: %.4f kPa +- %.4f (%.1f %%; %s, mesh scales %s",
                b["value_kPa"].get<double>(), b["error_kPa"].get<double>(),
                100 * b["relative_error"].get<double>(), b["how"].get<std::string>().c_str(), scales.c_str());
    if (b["asymptotic"].get<bool>()) std::printf(", observed order %.2f", b["observed_order"].get<double>());
    std::printf(")\n");
  }
  std::printf("  wrote %s/defect.csv, %ssummary.json\n", out_dir.c_str(),
              write_frames ? "defect.pvd (+ frames/), " : "");
}

namespace {
int finite_defect_stage(const Scene& scene, const std::string& out_dir,
                        const std::vector<double>& error_scales) {
  // The coarser levels first, each freed before the next: the scene's own level sets the peak memory.
  std::vector<pipeline::ChainLevel> coarse = pipeline::finite_sliding_levels(scene, error_scales);
  const pipeline::FiniteDefectRun run = pipeline::finite_defect_run(
      scene, {FrictionMode::static_residual, FrictionMode::coupled}, std::move(coarse));
  nlohmann::json summary = pipeline::finite_defect_json(scene, run);
  Stopwatch clock;
  prepare_output_dir(out_dir);
  std::ostringstream csv;
  csv.precision(10);
  csv << "case,u_mm,sensor,varsigma_z_kPa,varsigma_x_kPa\n";
  const int ns = static_cast<int>(scene.sensors.positions.size());
  for (const pipeline::FiniteDefectCase& c : run.cases)
    for (size_t i = 0; i < c.sweep.centers.size(); ++i)
      for (int k = 0; k < ns; ++k)
        csv << c.name << "," << c.sweep.centers[i][0] << "," << k + 1 << ","
            << 1e3 * c.sweep.varsigma(i, 2 * k) << "," << 1e3 * c.sweep.varsigma(i, 2 * k + 1) << "\n";
  write_text_atomic(out_dir + "/defect.csv", csv.str());
  add_write_seconds(summary, clock.seconds());
  write_json(out_dir + "/summary.json", summary);
  const pipeline::FiniteContactRun& first = run.cases.front().state;
  std::printf("defect %s, neo-Hookean skin: %zu x %d positions about the deformed states; %d DOFs%s\n",
              scene.name.c_str(), run.cases.size(), scene.contact->sweep->positions, first.dofs,
              first.mirrored ? " on the half y >= 0, mirror-symmetric" : "");
  for (const pipeline::FiniteDefectCase& c : run.cases) {
    const Timings& wall = run.wall;
    const std::string& n = c.name;
    const double ratio = summary["cases"][n]["ratio"].get<double>();
    char friction[96];
    if (c.state.tau_MPa > 0)
      std::snprintf(friction, sizeof friction, "shear strength %.4g kPa%s", 1e3 * c.state.tau_MPa,
                    ratio > 0 ? (", friction ratio " + validation::fmt("%.3g", ratio)).c_str() : "");
    else
      std::snprintf(friction, sizeof friction, "friction ratio %.3g", ratio);
    std::printf("  %s (%s): mesh %.2f s, Newton %.2f s, tangent %.2f s, sweep %.2f s (%.2f ms/position)\n",
                n.c_str(), friction, wall.at("mesh_" + n), wall.at("newton_" + n), wall.at("tangent_" + n),
                c.sweep.seconds, 1e3 * c.sweep.seconds / scene.contact->sweep->positions);
    std::printf(
        "    the tangent's own hole-free contact against the finite one: %.1e of the largest pressure; the "
        "holes act on material up to %.4f mm from their centres\n",
        c.baseline_rel, c.largest_material_shift_mm);
    const int col = c.max_roughness_column;
    std::printf("    largest second difference along u %.1f %% of its curve's peak (#%d varsigma_%c)\n",
                100 * c.max_roughness, col / 2 + 1, col % 2 ? 'x' : 'z');
    std::printf("    peak |varsigma_z| per sensor (kPa):");
    for (int k = 0; k < ns; ++k)
      std::printf(" %.2f", 1e3 * c.sweep.varsigma.col(2 * k).cwiseAbs().maxCoeff());
    std::printf("\n");
  }
  if (summary.contains("error_bars"))
    for (const auto& b : summary["error_bars"])
      std::printf("  %s: %s %s (%s)\n", b["what"].get<std::string>().c_str(),
                  with_error(b["value"].get<double>(), b["error"].get<double>()).c_str(),
                  b["unit"].get<std::string>().c_str(), b["method"].get<std::string>().c_str());
  std::printf(
      "  peak %.0f MB%s\n", peak_rss_mb(),
      summary.contains("left_out") ? ("; left out: " + summary["left_out"].get<std::string>()).c_str() : "");
  std::printf("  wrote %s/defect.csv, summary.json\n", out_dir.c_str());
  return 0;
}
}  // namespace

int run_defect(const Scene& scene, const std::string& out_dir, const std::vector<double>& error_scales) {
  pipeline::check_error_scales(error_scales);
  require_sweep(scene);
  check_output_dir(out_dir);
  if (scene.material.model == MaterialModel::neo_hookean)
    return finite_defect_stage(scene, out_dir, error_scales);
  // The coarser levels first, each freed before the next: the scene's own level sets the peak memory.
  std::vector<pipeline::ChainLevel> coarse = pipeline::largest_sliding_levels(scene, error_scales);
  const DefectRun run =
      defect_run(scene, contact_setup(scene), std::move(coarse), pipeline::DefectFrames::written);
  nlohmann::json summary = defect_json(scene, run);
  write_defect(scene, run, summary, out_dir);
  return 0;
}

}  // namespace skinfem::app
