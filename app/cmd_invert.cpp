// skinfem invert — where the holes are: a scan's sensor signals (scan.csv's columns u_mm, sensor,
// varsigma_z_kPa, varsigma_x_kPa, and case if present), measured or simulated, deconvolved over the scene's
// own single-hole responses by non-negative least squares, with the contact's offset from the sensors
// (unknown to ±1 mm, the paper says) fitted on a 0.1 mm grid; beside it the paper's naive inversion, each
// sensor alone at the nominal offset (pipeline/inversion.hpp, docs/perception.md).
//
//   $ skinfem invert out/texture_row/scan.csv scenes/candelier2011.json --out out/invert
//   invert candelier2011: 12 features, contact offset 0.000 mm; ...
//
// Writes DIR/features.csv (position_mm,diameter_mm,amplitude,snr: positions on the plate at u = 0, one row
// per feature), DIR/dictionary.csv (x_mm,site_mm,R_z_kPa,R_x_kPa: the response of a sensor at `site` to the
// scene's hole at x, both in the contact's frame; what the fit is made of, for another solver to read) and
// DIR/summary.json (contact_offset_mm; contact_offset_refined_mm, between grid points from the residuals'
// parabola; the residual per offset tried, the features, the naive single-sensor features, the dictionary's
// size, wall_s per stage, peak_rss_mb).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

#include "app/commands.hpp"
#include "app/common.hpp"
#include "app/stages.hpp"
#include "skinfem/pipeline/inversion.hpp"

namespace skinfem::app {

namespace {
std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, ',')) out.push_back(cell);
  if (!line.empty() && line.back() == ',') out.push_back("");
  return out;
}

// The signals of `case_name` for the scene's sensors; SceneError (one line, the file, the row, the value)
// for anything else.
validation::ScanSignals read_signals(const std::string& path, const Scene& scene,
                                     const std::string& case_name) {
  std::ifstream in(path);
  if (!in) throw SceneError(path + ": cannot read the signals file");
  std::string line;
  if (!std::getline(in, line))
    throw SceneError(path + ": empty; expected a header u_mm,sensor,varsigma_z_kPa,varsigma_x_kPa");
  if (!line.empty() && line.back() == '\r') line.pop_back();
  const std::vector<std::string> header = split_csv(line);
  std::map<std::string, int> col;
  for (size_t k = 0; k < header.size(); ++k) col[header[k]] = static_cast<int>(k);
  for (const char* need : {"u_mm", "sensor", "varsigma_z_kPa", "varsigma_x_kPa"})
    if (!col.count(need))
      throw SceneError(path + ": header has no column " + need +
                       "; expected u_mm,sensor,varsigma_z_kPa,varsigma_x_kPa");
  const int ns = static_cast<int>(scene.sensors.positions.size());
  std::vector<double> us;
  std::map<long long, std::map<int, std::pair<double, double>>> rows;  // u in nm → sensor → (z, x)
  int row = 1;
  while (std::getline(in, line)) {
    ++row;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    const std::vector<std::string> cells = split_csv(line);
    if (cells.size() != header.size())
      throw SceneError(path + ": row " + std::to_string(row) + " has " + std::to_string(cells.size()) +
                       " cells for " + std::to_string(header.size()) + " columns");
    if (col.count("case") && cells[col["case"]] != case_name) continue;
    const auto number = [&](const char* name) {
      const std::string& s = cells[col[name]];
      char* end = nullptr;
      const double v = std::strtod(s.c_str(), &end);
      if (s.empty() || *end != '\0' || !std::isfinite(v))
        throw SceneError(path + ": row " + std::to_string(row) + ": " + name + " = " + s +
                         ": must be a finite number");
      return v;
    };
    const double u = number("u_mm"), sensor = number("sensor");
    if (sensor != std::round(sensor) || sensor < 1 || sensor > ns)
      throw SceneError(path + ": row " + std::to_string(row) + ": sensor = " + cells[col["sensor"]] +
                       ": the scene has sensors 1 to " + std::to_string(ns));
    auto& at_u = rows[std::llround(u * 1e6)];
    if (at_u.count(static_cast<int>(sensor) - 1))
      throw SceneError(path + ": row " + std::to_string(row) + ": sensor " + cells[col["sensor"]] +
                       " at u = " + cells[col["u_mm"]] + " mm is given twice");
    at_u[static_cast<int>(sensor) - 1] = {number("varsigma_z_kPa"), number("varsigma_x_kPa")};
  }
  if (rows.size() < 2)
    throw SceneError(path + ": " + std::to_string(rows.size()) + " scan positions" +
                     (col.count("case") ? " of case " + case_name : std::string()) +
                     "; at least 2 are needed");
  validation::ScanSignals sig;
  for (const Vec2& p : scene.sensors.positions) sig.sensors.push_back(p[0]);
  sig.y.resize(static_cast<int>(rows.size()), 2 * ns);
  int i = 0;
  for (const auto& [key, sensors] : rows) {
    if (static_cast<int>(sensors.size()) != ns)
      throw SceneError(path + ": u = " + std::to_string(key * 1e-6) + " mm has " +
                       std::to_string(sensors.size()) + " sensors; the scene has " + std::to_string(ns));
    sig.u.push_back(key * 1e-6);
    for (const auto& [k, v] : sensors) sig.y(i, 2 * k) = v.first, sig.y(i, 2 * k + 1) = v.second;
    ++i;
  }
  const double step = (sig.u.back() - sig.u.front()) / (sig.u.size() - 1);
  for (size_t k = 1; k < sig.u.size(); ++k)
    if (std::abs(sig.u[k] - sig.u[k - 1] - step) > 1e-6 * std::max(1.0, step) + 2e-6)
      throw SceneError(path + ": u_mm is not evenly spaced (" + std::to_string(sig.u[k - 1]) + " then " +
                       std::to_string(sig.u[k]) + " mm); the inversion needs a uniform scan");
  return sig;
}
// The fit's dense design matrix per offset (two in flight, 200 MB each).
constexpr double kMaxDesign = 2.5e7;
}  // namespace

int run_invert(const Scene& scene, const std::string& signals_path, const std::string& out_dir,
               const pipeline::InversionOptions& options, const std::string& case_name) {
  const validation::ScanSignals signals = read_signals(signals_path, scene, case_name);
  // The fit's design matrix: a column per hole position the scan can show, a row per sample.
  const double step = signals.u[1] - signals.u[0];
  const double atoms = pipeline::dictionary_positions(scene, step) + signals.u.size() - 1;
  const double samples = 2.0 * signals.u.size() * signals.sensors.size();
  if (atoms * samples > kMaxDesign)
    throw SceneError(signals_path + ": " + std::to_string(signals.u.size()) + " positions every " +
                     std::to_string(step) + " mm make a fit of " +
                     std::to_string(static_cast<long long>(atoms)) + " hole positions by " +
                     std::to_string(static_cast<long long>(samples)) +
                     " samples; at most 2.5e7 entries: resample the signals coarser or scan a shorter range");
  check_output_dir(out_dir);
  const pipeline::InversionRun run = pipeline::inversion_run(scene, signals, options);
  nlohmann::json j = pipeline::inversion_json(scene, run, options);
  Stopwatch clock;
  prepare_output_dir(out_dir);
  std::ostringstream csv;
  csv.precision(10);
  csv << "position_mm,diameter_mm,amplitude,snr\n";
  for (const validation::Feature& f : run.multi.features)
    csv << f.position_mm << "," << f.diameter_mm << "," << f.amplitude << "," << f.snr << "\n";
  write_text_atomic(out_dir + "/features.csv", csv.str());
  std::ostringstream dictionary;
  dictionary.precision(10);
  dictionary << "x_mm,site_mm,R_z_kPa,R_x_kPa\n";
  const validation::HoleResponses& r = run.responses;
  for (Eigen::Index m = 0; m < r.R.rows(); ++m)
    for (size_t k = 0; k < r.sites.size(); ++k)
      dictionary << r.x0 + m * r.dx << "," << r.sites[k] << "," << r.R(m, 2 * k) << "," << r.R(m, 2 * k + 1)
                 << "\n";
  write_text_atomic(out_dir + "/dictionary.csv", dictionary.str());
  add_write_seconds(j, clock.seconds());
  write_json(out_dir + "/summary.json", j);
  std::printf(
      "invert %s (%s case, %zu positions every %.4g mm): %zu features, contact offset %.3f mm (searched "
      "+-%.3g mm by %.3g; %.3f mm between grid points)\n",
      scene.name.c_str(), case_name.c_str(), signals.u.size(), run.responses.dx, run.multi.features.size(),
      run.multi.offset_mm, options.offset_range, options.offset_step, run.multi.offset_refined_mm);
  for (const validation::Feature& f : run.multi.features)
    std::printf("  at %.3f mm: diameter %.3f mm (SNR %.1f)\n", f.position_mm, f.diameter_mm, f.snr);
  std::printf("  each sensor alone (naive, offset 0): features found per sensor:");
  for (const validation::Inversion& n : run.naive) std::printf(" %zu", n.features.size());
  std::printf(
      "\n  dictionary: %zu virtual sensors x %d hole positions on %d DOFs; total %.1f s, invert %.2f s, peak "
      "%.0f MB\n",
      run.responses.sites.size(), static_cast<int>(run.responses.R.rows()), run.dofs,
      j["wall_total_s"].get<double>(), run.wall.at("invert"), peak_rss_mb());
  std::printf("  wrote %s/features.csv, dictionary.csv, summary.json\n", out_dir.c_str());
  return 0;
}

}  // namespace skinfem::app
