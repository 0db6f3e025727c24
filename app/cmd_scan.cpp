// skinfem scan — a textured plate (contact.texture: listed holes, a lattice, grooves, random holes) moved
// along the sliding direction over the skin from contact.scan.from to .to by .step; at every position the
// full contact with every hole over the zone resolved on its exact disc and the contact set free, static
// (residual traction) and sliding (the scene's friction law), and beside it the paper's linear prediction
// Σ_k ς_k(u) from the holes one at a time (docs/contact.md, "Textures and scans").
//
//   $ skinfem scan scenes/texture_row.json --out out/texture_row
//   scan texture_row: 2 cases x 401 positions, 20 holes; ...
//
// A scene without a texture but with a contact.sweep along the sliding direction (the default scene) scans
// the sweep's hole, resolved, along its path: the paper's single-hole experiment.
//
// Writes DIR/scan.csv (case,u_mm,sensor,varsigma_z_kPa,varsigma_x_kPa,superposed_z_kPa,superposed_x_kPa;
// u = the plate's displacement), DIR/holes.csv (x_mm,y_mm,diameter_mm,depth_mm,length_mm: the plate's holes
// at u = 0, random ones included; a groove's width in diameter_mm, its length across the sliding direction in
// length_mm, 0 for a disc), DIR/scan.pvd with DIR/frames/<case>_NNNNN.vtp (the contact pressure and
// the holes at each position, at most 201 per case evenly spaced) and DIR/summary.json (per case the peaks
// per sensor, the superposition's largest difference, time per position; wall_s per stage, peak_rss_mb).
// The computation and summary.json are pipeline/scan.hpp's; this file writes and prints them.
#include <cstdio>
#include <sstream>

#include "app/animation.hpp"
#include "app/commands.hpp"
#include "app/common.hpp"
#include "app/stages.hpp"
#include "skinfem/contact/pressure_map.hpp"
#include "skinfem/pipeline/contact_setup.hpp"
#include "skinfem/pipeline/scan.hpp"

namespace skinfem::app {

namespace {
void write_scan(const Scene& scene, const pipeline::ScanRun& run, nlohmann::json& summary,
                const std::string& out_dir) {
  const ContactSetup& setup = *run.setup;
  Stopwatch clock;
  std::vector<AnimationFrame> written;
  std::vector<std::pair<size_t, size_t>> kept;  // per written frame: its case and its place in run.frames
  for (size_t ci = 0; ci < run.cases.size(); ++ci)
    for (size_t k = 0; k < run.frames[ci].size(); ++k) {
      const int i = run.frame_positions[ci][k];
      char file[64];
      std::snprintf(file, sizeof file, "%s_%05d.vtp", run.cases[ci].c_str(), i);
      written.push_back({file, run.scans[ci].u[i], static_cast<int>(ci)});
      kept.push_back({ci, k});
    }
  const std::string pvd = write_animation_frames(out_dir, written, [&](size_t w, const std::string& path) {
    const auto [ci, k] = kept[w];
    contact::write_pressure_vtp(path, setup.mesh(), *setup.solver, run.frames[ci][k], run.frame_holes[ci][k]);
  });
  std::ostringstream csv;
  csv.precision(10);
  csv << "case,u_mm,sensor,varsigma_z_kPa,varsigma_x_kPa"
      << (run.superposed.empty() ? "" : ",superposed_z_kPa,superposed_x_kPa") << "\n";
  const int ns = static_cast<int>(scene.sensors.positions.size());
  for (size_t ci = 0; ci < run.cases.size(); ++ci) {
    const contact::ScanResult& res = run.scans[ci];
    for (size_t i = 0; i < res.u.size(); ++i)
      for (int k = 0; k < ns; ++k) {
        csv << run.cases[ci] << "," << res.u[i] << "," << k + 1 << "," << 1e3 * res.varsigma(i, 2 * k) << ","
            << 1e3 * res.varsigma(i, 2 * k + 1);
        if (!run.superposed.empty())
          csv << "," << 1e3 * run.superposed[ci].varsigma(i, 2 * k) << ","
              << 1e3 * run.superposed[ci].varsigma(i, 2 * k + 1);
        csv << "\n";
      }
  }
  std::ostringstream plate;
  plate.precision(10);
  plate << "x_mm,y_mm,diameter_mm,depth_mm,length_mm\n";
  for (const Hole& h : scene.contact->texture->holes)
    plate << h.center[0] << "," << h.center[1] << "," << h.diameter << "," << h.depth << "," << h.length
          << "\n";
  write_text_atomic(out_dir + "/scan.csv", csv.str());
  write_text_atomic(out_dir + "/holes.csv", plate.str());
  write_text_atomic(out_dir + "/scan.pvd", pvd);
  add_write_seconds(summary, clock.seconds());
  write_json(out_dir + "/summary.json", summary);

  const Timings& wall = run.wall;
  const int n = scene.contact->scan->positions();
  const size_t holes = scene.contact->texture->holes.size();
  std::printf(
      "scan %s: %zu cases x %d positions, %zu hole%s; %d DOFs, %d multipliers (%d solved%s), %d watched "
      "nodes\n",
      scene.name.c_str(), run.cases.size(), n, holes, holes == 1 ? "" : "s",
      setup.model->solver().free_dofs(), setup.solver->zone().size(), setup.condensed->zone.size(),
      setup.whole ? " on the half y >= 0, mirror-symmetric" : "", summary["watched_nodes"].get<int>());
  std::printf("  mesh %.2f s, assemble %.2f s, factor %.2f s, condense %.2f s; scans", wall.at("mesh"),
              wall.at("assemble"), wall.at("factor"), wall.at("condense"));
  for (size_t ci = 0; ci < run.cases.size(); ++ci)
    std::printf(" %s %.2f s (%.2f ms/position)", run.cases[ci].c_str(), run.scans[ci].seconds,
                1e3 * run.scans[ci].seconds / n);
  std::printf("; total %.1f s, peak %.0f MB\n", summary.at("wall_total_s").get<double>(), peak_rss_mb());
  for (size_t ci = 0; ci < run.cases.size(); ++ci) {
    const nlohmann::json& c = summary["cases"][run.cases[ci]];
    const int most = c["most_holes_in_zone"].get<int>();
    std::printf("  %s: up to %d hole%s in the zone at once; peak |varsigma_z| per sensor (kPa):",
                run.cases[ci].c_str(), most, most == 1 ? "" : "s");
    for (int k = 0; k < static_cast<int>(scene.sensors.positions.size()); ++k)
      std::printf(" %.2f", 1e3 * run.scans[ci].varsigma.col(2 * k).cwiseAbs().maxCoeff());
    std::printf("\n");
    if (c.contains("superposition")) {
      const nlohmann::json& s = c["superposition"];
      const int pairs = s["mirror_pair_solves"].get<int>();
      char how[160];
      if (pairs > 0)
        std::snprintf(how, sizeof how,
                      "%d solves, %d of them a hole off y = 0 with its mirror image, whose own interaction "
                      "the difference leaves out",
                      s["single_hole_solves"].get<int>(), pairs);
      else
        std::snprintf(how, sizeof how, "%d single-hole solves", s["single_hole_solves"].get<int>());
      std::printf(
          "  %s: the holes one at a time (%s, %.2f s) differ from the scan by up to %.4f "
          "kPa in varsigma_z (%.1f %% of its largest) and %.4f kPa in varsigma_x (%.1f %%)\n",
          run.cases[ci].c_str(), how, s["seconds"].get<double>(), s["max_diff_z_kPa"].get<double>(),
          100 * s["rel_diff_z"].get<double>(), s["max_diff_x_kPa"].get<double>(),
          100 * s["rel_diff_x"].get<double>());
    }
  }
  std::printf("  wrote %s/scan.csv, holes.csv, scan.pvd (+ frames/), summary.json\n", out_dir.c_str());
}
}  // namespace

int run_scan(const Scene& given, const std::string& out_dir, bool superpose) {
  const Scene scene = pipeline::scanned_scene(given);
  check_output_dir(out_dir);
  // One hole is its own superposition.
  const bool sum = superpose && scene.contact->texture->holes.size() > 1;
  const pipeline::ScanRun run = pipeline::scan_run(scene, contact_setup(scene), sum);
  nlohmann::json summary = pipeline::scan_json(scene, run);
  write_scan(scene, run, summary, out_dir);
  return 0;
}

}  // namespace skinfem::app
