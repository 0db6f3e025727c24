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
// DIR/dictionary.key (the case and the scene's text it was built for, and its DOFs), and DIR/summary.json
// (contact_offset_mm; contact_offset_refined_mm, between grid points from the residuals' parabola; the
// residual per offset tried, the features, the naive single-sensor features, the dictionary's size, wall_s
// per stage, peak_rss_mb).
//
// --dictionary DIR reuses the dictionary an earlier invert wrote in DIR instead of building it (19 of the
// 19.5 s on the default scene): refused in one line when its key differs from this run's (another scene or
// case: the first line that differs), or when its step, hole positions or virtual sensors do not fit the
// signals and --offset-range.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
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
// The fit's size per offset: Aᵀb passes over hole positions × samples design entries, and the normal
// equations hold positions² (200 MB per offset in flight at the bound).
constexpr double kMaxDesign = 2.5e7;

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError(path + ": cannot read it");
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// What a dictionary is built from besides the step and the offsets (which dictionary_mismatch checks): the
// case and the scene's text, with an imported surface's size and time (its bytes would make the key as large
// as the mesh). Written as DIR/dictionary.key; a reuse compares it line by line.
std::string dictionary_key(const Scene& scene, const std::string& case_name) {
  std::string key = "skinfem invert dictionary\ncase " + case_name + "\n";
  if (scene.geometry.kind == GeometryKind::surface) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const auto size = fs::file_size(scene.geometry.surface.path, ec);
    const auto time = fs::last_write_time(scene.geometry.surface.path, ec).time_since_epoch().count();
    key += "surface " + scene.geometry.surface.path + " " + std::to_string(size) + " bytes, written " +
           std::to_string(time) + "\n";
  }
  return key + "scene:\n" + read_text(scene.source_path);
}

struct StoredDictionary {
  validation::HoleResponses responses;
  int dofs = 0;
};

// The key as written: the DOFs the dictionary was solved on on its second line.
std::string keyed(const std::string& key, int dofs) {
  const size_t first = key.find('\n') + 1;
  return key.substr(0, first) + "dofs " + std::to_string(dofs) + "\n" + key.substr(first);
}

// DIR/dictionary.csv as `skinfem invert` wrote it (rows by hole position, then by site), after DIR/
// dictionary.key has been checked against this run's: SceneError naming the first line that differs.
StoredDictionary read_dictionary(const std::string& dir, const std::string& key, const Scene& scene) {
  StoredDictionary d;
  std::string stored = read_text(dir + "/dictionary.key");
  const size_t first = stored.find('\n') + 1, second = stored.find('\n', first);
  if (first == 0 || second == std::string::npos || stored.compare(first, 5, "dofs ") != 0)
    throw SceneError("--dictionary " + dir + ": its dictionary.key is not one skinfem invert wrote");
  d.dofs = std::atoi(stored.c_str() + first + 5);
  stored.erase(first, second + 1 - first);
  std::istringstream a(stored), b(key);
  std::string la, lb;
  // Lines numbered as in the file, whose line 2 (the DOFs) was taken out.
  for (int line = 1;; ++line) {
    const bool more_a = static_cast<bool>(std::getline(a, la)),
               more_b = static_cast<bool>(std::getline(b, lb));
    if (!more_a && !more_b) break;
    if (more_a != more_b || la != lb)
      throw SceneError("--dictionary " + dir + ": built for another scene or case: line " +
                       std::to_string(line + (line >= 2)) + " of its dictionary.key reads '" +
                       (more_a ? la : "") + "', this run's '" + (more_b ? lb : "") + "'");
  }
  const std::string path = dir + "/dictionary.csv";
  std::ifstream in(path);
  std::string line;
  if (!in || !std::getline(in, line) || line != "x_mm,site_mm,R_z_kPa,R_x_kPa")
    throw SceneError(path + ": cannot read it, or its header is not x_mm,site_mm,R_z_kPa,R_x_kPa");
  std::vector<std::array<double, 4>> rows;
  for (int row = 2; std::getline(in, line); ++row) {
    const std::vector<std::string> cells = split_csv(line);
    std::array<double, 4> v{};
    char* end = nullptr;
    for (size_t c = 0; c < 4; ++c) {
      v[c] = c < cells.size() ? std::strtod(cells[c].c_str(), &end) : NAN;
      if (cells.size() != 4 || cells[c].empty() || *end != '\0' || !std::isfinite(v[c]))
        throw SceneError(path + ": row " + std::to_string(row) + ": expected four finite numbers");
    }
    rows.push_back(v);
  }
  validation::HoleResponses& r = d.responses;
  r.diameter = scene.contact->sweep->hole_diameter;
  for (size_t k = 0; k < rows.size() && rows[k][0] == rows[0][0]; ++k) r.sites.push_back(rows[k][1]);
  const size_t n = r.sites.size();
  if (n == 0 || rows.size() % n != 0 || rows.size() < 2 * n)
    throw SceneError(path + ": " + std::to_string(rows.size()) + " rows are not whole hole positions of " +
                     std::to_string(n) + " sites");
  r.x0 = rows[0][0];
  r.dx = rows[n][0] - rows[0][0];
  r.R.resize(static_cast<Eigen::Index>(rows.size() / n), static_cast<Eigen::Index>(2 * n));
  for (size_t i = 0; i < rows.size(); ++i) {
    const size_t m = i / n, k = i % n;
    if (std::abs(rows[i][0] - (r.x0 + m * r.dx)) > 1e-6 || rows[i][1] != r.sites[k])
      throw SceneError(path + ": row " + std::to_string(i + 2) + " is out of order (x_mm " +
                       std::to_string(rows[i][0]) + ", site_mm " + std::to_string(rows[i][1]) + ")");
    r.R(m, 2 * k) = rows[i][2];
    r.R(m, 2 * k + 1) = rows[i][3];
  }
  return d;
}
}  // namespace

int run_invert(const Scene& scene, const std::string& signals_path, const std::string& out_dir,
               const pipeline::InversionOptions& options, const std::string& case_name,
               const std::string& dictionary_dir) {
  const validation::ScanSignals signals = read_signals(signals_path, scene, case_name);
  const std::string key = dictionary_key(scene, case_name);
  // The fit's design matrix: a column per hole position the scan can show, a row per sample.
  const double step = signals.u[1] - signals.u[0];
  const double atoms = pipeline::dictionary_positions(scene, step) + signals.u.size() - 1;
  const double samples = 2.0 * signals.u.size() * signals.sensors.size();
  if (atoms * std::max(samples, atoms) > kMaxDesign)
    throw SceneError(
        signals_path + ": " + std::to_string(signals.u.size()) + " positions every " + std::to_string(step) +
        " mm make a fit of " + std::to_string(static_cast<long long>(atoms)) + " hole positions by " +
        std::to_string(static_cast<long long>(samples)) +
        " samples; at most 2.5e7 for positions times the larger of the two: resample the signals "
        "coarser or scan a shorter range");
  check_output_dir(out_dir);
  Stopwatch reading;
  std::optional<StoredDictionary> reused;
  if (!dictionary_dir.empty()) reused = read_dictionary(dictionary_dir, key, scene);
  const double read_s = reading.seconds();
  pipeline::InversionRun run =
      pipeline::inversion_run(scene, signals, options, reused ? &reused->responses : nullptr);
  if (reused) {
    run.wall["dictionary_read"] = read_s;
    run.dofs = reused->dofs;
  }
  nlohmann::json j = pipeline::inversion_json(scene, run, options);
  if (reused) j["dictionary"]["read_from"] = dictionary_dir;
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
  write_text_atomic(out_dir + "/dictionary.key", keyed(key, run.dofs));
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
      "\n  dictionary: %zu virtual sensors x %d hole positions on %d DOFs%s; total %.1f s, invert %.2f s, "
      "peak %.0f MB\n",
      run.responses.sites.size(), static_cast<int>(run.responses.R.rows()), run.dofs,
      reused ? (", read from " + dictionary_dir).c_str() : "", j["wall_total_s"].get<double>(),
      run.wall.at("invert"), peak_rss_mb());
  std::printf("  wrote %s/features.csv, dictionary.csv, dictionary.key, summary.json\n", out_dir.c_str());
  return 0;
}

}  // namespace skinfem::app
