// skinfem report — the main job: the whole chain on one mesh and one factorization, and the paper's
// convolution model checked against it assumption by assumption (validation/crosscheck.hpp).
//
//   $ skinfem report scenes/candelier2011.json
//   report candelier2011: 101342 DOFs, one factorization for the chain and 2 coarser for the error bars;
//   50.3 s, peak 1407 MB
//
// A scene mirror-symmetric about y = 0, contact included (pipeline/symmetry.hpp), is solved on its half y ≥ 0
// and every output is written for the whole skin (mesh.vtu, maps, pressure, fields).
//
// Stages, each writing its own folder under DIR (default out/<scene name>): mesh/ (mesh.vtu, boundary.vtu),
// green/ (green.csv, green_maps.vtp), kfit/ (kfit.json, and k_sweep.csv: the exact layer's k as each reading
// of the calibration protocol changes, validation/k_sweep.hpp), and with a contact: contact/ (pressure.vtp,
// fields.vtu, sensors.csv, modes.csv), defect/ (defect.csv, defect.pvd + frames/) and crosscheck/
// (readings.csv, defect.csv, pressure.csv, attribution.csv: case,variant,sensor,component,amplitude_ratio,
// peak_shift_mm,shape_error). Then figures/*.png (scripts/figures.py, matplotlib) and DIR/report.json (the
// headline numbers with units, wall seconds per stage, peak memory) and DIR/index.html (figures, tables,
// links to every VTK file).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <sstream>

#include "app/chain_study.hpp"
#include "app/commands.hpp"
#include "app/common.hpp"
#include "app/stages.hpp"
#include "green/kfit.hpp"
#include "mesh/mirror.hpp"
#include "pipeline/symmetry.hpp"
#include "validation/crosscheck.hpp"
#include "validation/k_sweep.hpp"

namespace skinfem::app {

namespace {
// The paper's measured excess of the front sensors' hole signals over its model (§IV: "up to 4 times").
constexpr double kPaperFrontExcess = 4.0;

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

void write_crosscheck(const validation::Crosscheck& x, const Sensors& sensors, const std::string& dir) {
  prepare_output_dir(dir);
  const char* cases[2] = {"static", "sliding"};
  const int ns = static_cast<int>(sensors.positions.size());
  std::ostringstream r, d, p, a;
  for (auto* s : {&r, &d, &p, &a}) s->precision(10);
  r << "case,variant,sensor,x_mm,sigma_z_kPa,sigma_x_kPa\n";
  for (size_t v = 0; v < x.readings.size(); ++v)
    for (int c = 0; c < 2; ++c)
      for (int k = 0; k < ns; ++k)
        r << cases[c] << "," << x.reading_variants[v].name << "," << k + 1 << "," << sensors.positions[k][0]
          << "," << 1e3 * x.readings[v][c][2 * k] << "," << 1e3 * x.readings[v][c][2 * k + 1] << "\n";
  d << "case,variant,u_mm,sensor,varsigma_z_kPa,varsigma_x_kPa\n";
  for (size_t v = 0; v < x.signals.size(); ++v)
    for (int c = 0; c < 2; ++c)
      for (size_t i = 0; i < x.u.size(); ++i)
        for (int k = 0; k < ns; ++k)
          d << cases[c] << "," << x.signal_variants[v].name << "," << x.u[i] << "," << k + 1 << ","
            << 1e3 * x.signals[v][c](i, 2 * k) << "," << 1e3 * x.signals[v][c](i, 2 * k + 1) << "\n";
  p << "x_mm,p_hertz_halfspace_kPa,p_layer_exact_kPa,p_fe_frictionless_kPa,p_fe_coupled_kPa,q_fe_coupled_"
       "kPa\n";
  for (const auto& row : x.pressure_profile) {
    p << row[0];
    for (int j = 1; j < 6; ++j) {
      p << ",";
      if (std::isfinite(row[j])) p << 1e3 * row[j];
    }
    p << "\n";
  }
  a << "case,variant,sensor,component,amplitude_ratio,peak_shift_mm,shape_error\n";
  for (size_t v = 0; v < x.metrics.size(); ++v)
    for (int c = 0; c < 2; ++c)
      for (int k = 0; k < ns; ++k)
        for (int b = 0; b < 2; ++b) {
          const auto& m = x.metrics[v][c][k][b];
          a << cases[c] << "," << x.signal_variants[v].name << "," << k + 1 << "," << (b ? "x" : "z") << ","
            << m.amplitude_ratio << "," << m.peak_shift_mm << "," << m.shape_error << "\n";
        }
  write_text_atomic(dir + "/readings.csv", r.str());
  write_text_atomic(dir + "/defect.csv", d.str());
  write_text_atomic(dir + "/pressure.csv", p.str());
  write_text_atomic(dir + "/attribution.csv", a.str());
}

int variant_index(const std::vector<validation::Variant>& v, const std::string& name) {
  for (size_t i = 0; i < v.size(); ++i)
    if (v[i].name == name) return static_cast<int>(i);
  return -1;
}

// Does coupling explain the front sensors' excess? FE coupled against FE uncoupled sliding signals on the
// sensors at or ahead of the contact centre along x.
// front: the sensors ahead along the sliding direction (validation::front_sensors).
nlohmann::json front_sensor_answer(const validation::Crosscheck& x, const std::vector<int>& front_sensors,
                                   const Vec2& direction) {
  const int unc = variant_index(x.signal_variants, "uncoupled"),
            paper = variant_index(x.signal_variants, "paper_model");
  nlohmann::json j;
  double lo[2] = {1e300, 1e300}, hi[2] = {0, 0}, plo[2] = {1e300, 1e300}, phi[2] = {0, 0};
  std::string front;
  for (const int k : front_sensors) {
    front += (front.empty() ? "#" : ", #") + std::to_string(k + 1);
    for (int b = 0; b < 2; ++b) {
      // FE coupled / FE uncoupled is 1 / (uncoupled / FE).
      const double coupling = 1 / x.metrics[unc][1][k][b].amplitude_ratio;
      lo[b] = std::min(lo[b], coupling);
      hi[b] = std::max(hi[b], coupling);
      if (paper >= 0) {
        const double fe_over_model = 1 / x.metrics[paper][1][k][b].amplitude_ratio;
        plo[b] = std::min(plo[b], fe_over_model);
        phi[b] = std::max(phi[b], fe_over_model);
      }
    }
  }
  if (front.empty()) {
    j["front_sensors"] = "";
    j["answer"] = "No sensor lies ahead of the contact centre along the sliding direction (" +
                  fmt("%.3g", direction[0]) + ", " + fmt("%.3g", direction[1]) +
                  "): the front sensors' excess cannot be examined on this scene";
    return j;
  }
  j["front_sensors"] = front;
  j["coupling_amplitude_factor_z"] = {lo[0], hi[0]};
  j["coupling_amplitude_factor_x"] = {lo[1], hi[1]};
  const double best = std::max(hi[0], hi[1]);
  std::string text = "Coupled against uncoupled friction, the front sensors' (" + front +
                     ") sliding hole-signal amplitudes change by x" + fmt("%.2f", lo[0]) + "-" +
                     fmt("%.2f", hi[0]) + " (varsigma_z) and x" + fmt("%.2f", lo[1]) + "-" +
                     fmt("%.2f", hi[1]) + " (varsigma_x); the paper measured up to x" +
                     fmt("%.0f", kPaperFrontExcess) + " over its model, so coupling " +
                     (best >= kPaperFrontExcess ? std::string("is large enough to explain it")
                                                : "explains at most x" + fmt("%.2f", best) + " of it");
  if (paper >= 0) {
    j["fe_over_paper_model_amplitude_z"] = {plo[0], phi[0]};
    j["fe_over_paper_model_amplitude_x"] = {plo[1], phi[1]};
    text += "; full FE over the paper's model on these sensors: x" + fmt("%.3g", plo[0]) + "-" +
            fmt("%.3g", phi[0]) + " (z), x" + fmt("%.3g", plo[1]) + "-" + fmt("%.3g", phi[1]) + " (x)";
  }
  j["answer"] = text;
  return j;
}

// Which single change of the calibration protocol gives the paper's k: the exact layer's k under each
// reading (validation/k_sweep.hpp), written to DIR/k_sweep.csv, and the readings within ±0.01 of it.
// mesh_rows: the FE k of sensor #1 per mesh scale (parameter mesh_scale), the sweep's mesh-resolution axis.
nlohmann::json k_paper_answer(const Scene& scene, double h,
                              const std::vector<validation::KSweepPoint>& mesh_rows, const std::string& dir) {
  validation::KProtocol base;
  base.h = h;
  base.nu = scene.material.nu;
  base.punch_diameter = scene.calibration.punch_diameter;
  auto pts = validation::k_sweep(base);
  pts.insert(pts.end(), mesh_rows.begin(), mesh_rows.end());
  std::ostringstream csv;
  csv.precision(10);
  csv << "parameter,value,k_central,k_lsq_line\n";
  for (const auto& p : pts)
    csv << p.parameter << "," << p.value << "," << p.k_central << "," << p.k_lsq_line << "\n";
  write_text_atomic(dir + "/k_sweep.csv", csv.str());
  const char* loads[3] = {"point", "uniform disc", "punch"};
  nlohmann::json j;
  std::string near, cross;
  for (const auto& p : pts)
    for (const char* crit : {"k_central", "k_lsq_line"}) {
      const double k = std::string(crit) == "k_central" ? p.k_central : p.k_lsq_line;
      if (std::abs(k - green::kPaperK) <= 0.01) {
        const std::string what = p.parameter == "load"
                                     ? std::string("load ") + loads[static_cast<int>(p.value)]
                                     : p.parameter + " = " + fmt("%.3g", p.value);
        near += (near.empty() ? "" : "; ") + what + ": " + crit + " " + fmt("%.4f", k);
        j["within_0.01"].push_back(
            {{"parameter", p.parameter}, {"value", p.value}, {"criterion", crit}, {"k", k}});
      }
    }
  for (const char* param : {"nu", "punch_diameter_mm", "disc_diameter_mm", "h_mm"})
    for (const char* crit : {"k_central", "k_lsq_line"})
      for (double v : validation::crossings(pts, param, crit, green::kPaperK)) {
        cross += (cross.empty() ? "" : "; ") + std::string(crit) + " = " + fmt("%.2f", green::kPaperK) +
                 " at " + param + " = " + fmt("%.3g", v);
        j["crossings"].push_back({{"parameter", param}, {"criterion", crit}, {"value", v}});
      }
  j["answer"] = "Exact layer (h " + fmt("%.3g", h) + " mm) with one protocol reading changed at a time" +
                (mesh_rows.empty() ? std::string() : ", and the FE mesh scale") + ": " +
                (near.empty() ? std::string("no reading in the sweep gives k within 0.01 of ") +
                                    fmt("%.2f", green::kPaperK)
                              : "within 0.01 of " + fmt("%.2f", green::kPaperK) + ": " + near) +
                (cross.empty() ? std::string("; no parameter's range crosses it") : "; crossings: " + cross);
  return j;
}

// The chain's quantities with their error bars (pipeline/chain_level.hpp), in display units.
nlohmann::json error_bars(const std::vector<ChainError>& errors, const std::vector<double>& coarse_scales) {
  struct Display {
    const char* name;
    const char* what;
    const char* unit;
    double factor;
  };
  const Display table[] = {
      {"k_central", "k, central criterion (sensor #1)", "", 1},
      {"k_lsq_line", "k, line fit (sensor #1)", "", 1},
      {"contact_radius", "contact radius (coupled friction)", "mm", 1},
      {"contact_p0", "central pressure (coupled friction)", "kPa", 1e3},
      {"indentation", "indentation (coupled friction)", "um", 1e3},
      {"hole_signal", "largest sliding |varsigma_z| over sensors and hole positions", "kPa", 1e3}};
  std::string levels;
  for (double s : coarse_scales) levels += fmt("%g", s) + ", ";
  levels += "1";
  nlohmann::json j = nlohmann::json::array();
  for (const ChainError& e : errors)
    for (const Display& d : table)
      if (e.name == d.name)
        j.push_back(
            {{"quantity", e.name},
             {"what", d.what},
             {"unit", d.unit},
             {"value", d.factor * e.value},
             {"error", d.factor * e.error},
             {"relative_error", e.error / std::abs(e.value)},
             {"method", e.asymptotic ? "|value - Richardson limit| over mesh scales " + levels +
                                           ", observed order " + fmt("%.2f", e.order)
                                     : "last change between mesh scales " + fmt("%g", coarse_scales.back()) +
                                           " and 1; no asymptotic regime over " + levels + " (" + e.why_not +
                                           "), so an order of magnitude only"}});
  return j;
}

// "value ± error" with the value rounded to the error's second significant digit.
std::string with_error(double value, double error) {
  if (!(error > 0)) return fmt("%.6g", value);
  const int decimals = std::max(0, 1 - static_cast<int>(std::floor(std::log10(error))));
  char buf[96];
  std::snprintf(buf, sizeof buf, "%.*f +- %.*f", decimals, value, decimals, error);
  return buf;
}

std::string html_escape(const std::string& s) {
  std::string o;
  for (char c : s) o += c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '&' ? "&amp;" : std::string(1, c);
  return o;
}

void write_index(const std::string& dir, const Scene& scene, const nlohmann::json& report,
                 const validation::Crosscheck* x) {
  namespace fs = std::filesystem;
  std::ostringstream h;
  h << "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>skinfem report: "
    << html_escape(scene.name)
    << "</"
       "title><style>body{font-family:sans-serif;max-width:1100px;margin:auto}table{border-collapse:collapse}"
       "td,th{border:1px solid #bbb;padding:2px "
       "6px;text-align:right}img{max-width:100%}</style></head><body>\n";
  h << "<h1>skinfem report: " << html_escape(scene.name) << "</h1>\n<p>Units: mm, N, MPa (stresses in kPa). "
    << report["dofs"].get<int>() << " DOFs, one factorization for the chain"
    << (report.contains("error_bars") ? " (and one per coarser level for the error bars)" : "") << "; total "
    << fmt("%.1f", report["wall_total_s"].get<double>()) << " s, peak memory "
    << fmt("%.0f", report["peak_rss_mb"].get<double>()) << " MB.</p>\n";
  if (report.contains("error_bars")) {
    h << "<h2>Headline numbers and their discretization error</h2><table><tr><th>quantity</th><th>value</th>"
         "<th>error</th><th>unit</th><th>how the error is estimated</th></tr>\n";
    for (const auto& e : report["error_bars"])
      h << "<tr><td style=\"text-align:left\">" << html_escape(e["what"].get<std::string>()) << "</td><td>"
        << html_escape(with_error(e["value"].get<double>(), e["error"].get<double>())) << "</td><td>"
        << e["unit"].get<std::string>() << "</td><td style=\"text-align:left\">"
        << html_escape(e["method"].get<std::string>()) << "</td></tr>\n";
    h << "</table>\n";
  }
  if (report.contains("chain_study")) {
    const auto& cs = report["chain_study"];
    std::vector<std::string> stages;
    for (const auto& [stage, t] : cs["levels"].back()["wall_s"].items()) stages.push_back(stage);
    h << "<h2>Speed against error: the levels behind the error bars</h2><table><tr><th>mesh scale</th>"
         "<th>DOFs</th>";
    for (const auto& st : stages) h << "<th>" << st << " s</th>";
    h << "<th>peak MB</th>";
    for (const auto& [q, v] : cs["levels"].back()["values"].items()) h << "<th>" << q << "</th>";
    h << "</tr>\n";
    for (const auto& l : cs["levels"]) {
      h << "<tr><td>" << fmt("%g", l["scale"].get<double>()) << "</td><td>" << l["dofs"].get<int>()
        << "</td>";
      for (const auto& st : stages)
        h << "<td>" << (l["wall_s"].contains(st) ? fmt("%.2f", l["wall_s"][st].get<double>()) : "")
          << "</td>";
      h << "<td>" << fmt("%.0f", l["peak_rss_mb"].get<double>()) << "</td>";
      for (const auto& [q, v] : l["values"].items()) h << "<td>" << fmt("%.6g", v.get<double>()) << "</td>";
      h << "</tr>\n";
    }
    h << "<tr><td style=\"text-align:left\" colspan=\"2\">time &prop; DOFs<sup>e</sup>, e =</td>";
    for (const auto& st : stages)
      h << "<td>"
        << (cs["time_vs_dofs_exponent"].contains(st)
                ? fmt("%.2f", cs["time_vs_dofs_exponent"][st].get<double>())
                : "")
        << "</td>";
    h << "</tr></table><p>Values in mm and MPa; the scene's own level is scale 1 (its memory is the whole "
         "report's). Errors per level: <a href=\"study/chain_study.csv\">study/chain_study.csv</a>, Pareto "
         "plot below.</p>\n";
  }
  h << "<h2>Time per stage</h2><table><tr><th>stage</th><th>seconds</th></tr>\n";
  for (const auto& [stage, s] : report["wall_s"].items())
    h << "<tr><td style=\"text-align:left\">" << stage << "</td><td>" << fmt("%.2f", s.get<double>())
      << "</td></tr>\n";
  h << "</table>\n";
  h << "<h2>k</h2><p>" << html_escape(report["kfit"]["verdict"].get<std::string>()) << "</p>\n<p>"
    << html_escape(report["k_paper"]["answer"].get<std::string>())
    << " (<a href=\"kfit/k_sweep.csv\">kfit/k_sweep.csv</a>)</p>\n";
  if (report.contains("front_sensors") && report["front_sensors"].contains("answer"))
    h << "<h2>Does friction-pressure coupling explain the front sensors?</h2><p>"
      << html_escape(report["front_sensors"]["answer"].get<std::string>()) << "</p>\n";
  if (report.contains("hole_budget") && report["hole_budget"].contains("hypotheses")) {
    const auto& b = report["hole_budget"];
    const std::vector<int> front =
        validation::front_sensors(scene.sensors, contact_center(scene), scene.contact->direction);
    const auto range = [&](const nlohmann::json& ratios, bool in_front) {
      double lo = 1e300, hi = 0;
      for (size_t k = 0; k < ratios.size(); ++k)
        if ((std::find(front.begin(), front.end(), static_cast<int>(k)) != front.end()) == in_front)
          lo = std::min(lo, ratios[k].get<double>()), hi = std::max(hi, ratios[k].get<double>());
      return hi > 0 ? fmt("%.2f", lo) + "–" + fmt("%.2f", hi) : std::string("–");
    };
    h << "<h2>Why is a hole so loud? The hole-signal budget</h2><p>"
      << html_escape(b["answer"].get<std::string>())
      << " Sliding amplitude of full FE over the paper's model per hypothesis; a fact is judged from the "
         "numbers "
         "(hover or open a row for the sentence). Detection: "
      << fmt("%.0f", b["noise"]["k_sigma"].get<double>()) << " standard deviations of a "
      << b["noise"]["passages"].get<int>() << "-passage mean, "
      << fmt("%.3f", b["noise"]["threshold_z_kPa"].get<double>()) << " kPa (ςz) and "
      << fmt("%.3f", b["noise"]["threshold_x_kPa"].get<double>())
      << " kPa (ςx).</p>\n<table><tr><th>hypothesis</th><th>τ0 kPa</th><th>K MPa/mm</th><th>back "
         "z</th><th>back "
         "x</th><th>front "
         "z</th><th>front x</th><th>F1</th><th>F2</th><th>F3</th><th>F4</th><th>F5</th></tr>\n";
    for (const auto& y : b["hypotheses"]) {
      const auto& r = y["amplitude_ratio"]["sliding"];
      h << "<tr><td style=\"text-align:left\" title=\"" << html_escape(y["what"].get<std::string>()) << "\">"
        << y["name"].get<std::string>() << "</td><td>" << fmt("%.1f", y["tau0_kPa"].get<double>())
        << "</td><td>"
        << (y["interface_K_MPa_per_mm"].get<double>() > 0
                ? fmt("%.4g", y["interface_K_MPa_per_mm"].get<double>())
                : std::string("hard"))
        << "</td><td>" << range(r["z"], false) << "</td><td>" << range(r["x"], false) << "</td><td>"
        << range(r["z"], true) << "</td><td>" << range(r["x"], true) << "</td>";
      for (const auto& [fact, v] : y["facts"].items())
        h << "<td title=\"" << html_escape(v["why"].get<std::string>()) << "\">"
          << (v["met"].get<bool>() ? "yes" : "no") << "</td>";
      h << "</tr>\n";
    }
    h << "</table>\n";
    for (const auto& y : b["hypotheses"]) {
      h << "<details><summary>" << y["name"].get<std::string>() << ": "
        << html_escape(y["what"].get<std::string>()) << "</summary><ul>\n";
      for (const auto& [fact, v] : y["facts"].items())
        h << "<li>" << fact << (v["met"].get<bool>() ? " met: " : " not met: ")
          << html_escape(v["why"].get<std::string>()) << "</li>\n";
      h << "</ul></details>\n";
    }
    h << "<p>Per sensor: <a href=\"crosscheck/hole_budget.csv\">crosscheck/hole_budget.csv</a>; signals: <a "
         "href=\"crosscheck/hole_budget_signals.csv\">crosscheck/hole_budget_signals.csv</a>.</p>\n";
  }
  if (x) {
    const int ns = static_cast<int>(scene.sensors.positions.size());
    h << "<h2>Mean sensor stresses (kPa), each variant swaps one assumption into full FE</h2>\n";
    for (int c = 0; c < 2; ++c) {
      h << "<h3>" << (c ? "sliding" : "static") << " (p_x = "
        << (x->shear[c] != 0 ? fmt("%.3g kPa", 1e3 * x->shear[c]) + (x->ratio[c] != 0 ? " + " : "") : "")
        << (x->ratio[c] != 0 || x->shear[c] == 0 ? fmt("%.3g p_z", x->ratio[c]) : "")
        << ")</h3><table><tr><th>variant</th>";
      for (int k = 0; k < ns; ++k) h << "<th>#" << k + 1 << " σz</th><th>σx</th>";
      h << "</tr>\n";
      for (size_t v = 0; v < x->readings.size(); ++v) {
        h << "<tr><td style=\"text-align:left\" title=\"" << html_escape(x->reading_variants[v].what) << "\">"
          << x->reading_variants[v].name << "</td>";
        for (int k = 0; k < 2 * ns; ++k) h << "<td>" << fmt("%.2f", 1e3 * x->readings[v][c][k]) << "</td>";
        h << "</tr>\n";
      }
      h << "</table>\n";
    }
    h << "<h2>Hole signals: amplitude of each variant over full FE (sliding), "
         "attribution</h2>\n<table><tr><th>sensor</th>"
         "<th>FE max|ςz| kPa</th>";
    for (size_t v = 1; v < x->signals.size(); ++v) h << "<th>" << x->signal_variants[v].name << " z</th>";
    h << "<th>FE max|ςx| kPa</th>";
    for (size_t v = 1; v < x->signals.size(); ++v) h << "<th>" << x->signal_variants[v].name << " x</th>";
    h << "</tr>\n";
    for (int k = 0; k < ns; ++k) {
      h << "<tr><td>#" << k + 1 << "</td>";
      for (int b = 0; b < 2; ++b) {
        h << "<td>" << fmt("%.4f", 1e3 * x->signals[0][1].col(2 * k + b).cwiseAbs().maxCoeff()) << "</td>";
        for (size_t v = 1; v < x->signals.size(); ++v)
          h << "<td>" << fmt("%.3g", x->metrics[v][1][k][b].amplitude_ratio) << "</td>";
      }
      h << "</tr>\n";
    }
    h << "</table><p>Variants:</p><ul>\n";
    for (const auto& v : x->signal_variants)
      h << "<li><b>" << v.name << "</b>: " << html_escape(v.what) << "</li>\n";
    h << "</ul><p>Peak shifts and shape errors of every variant, case and sensor: <a "
         "href=\"crosscheck/attribution.csv\">"
         "crosscheck/attribution.csv</a>.</p>\n";
  }
  h << "<h2>Figures</h2>\n";
  if (fs::is_directory(dir + "/figures"))
    for (const auto& e : fs::directory_iterator(dir + "/figures"))
      if (e.path().extension() == ".png")
        h << "<h3>" << e.path().stem().string() << "</h3><img src=\"figures/" << e.path().filename().string()
          << "\">\n";
  h << "<h2>Files</h2><ul>\n";
  for (const char* f :
       {"mesh/mesh.vtu", "mesh/boundary.vtu", "green/green_maps.vtp", "green/green.csv", "kfit/kfit.json",
        "contact/pressure.vtp", "contact/fields.vtu", "contact/modes.csv", "defect/defect.pvd",
        "defect/defect.csv", "crosscheck/readings.csv", "crosscheck/defect.csv", "crosscheck/pressure.csv",
        "crosscheck/attribution.csv", "crosscheck/hole_budget.csv", "crosscheck/hole_budget_signals.csv",
        "study/chain_study.csv", "report.json"})
    if (fs::exists(dir + "/" + f)) h << "<li><a href=\"" << f << "\">" << f << "</a></li>\n";
  h << "</ul></body></html>\n";
  write_text_atomic(dir + "/index.html", h.str());
}
}  // namespace

int run_report(const Scene& scene, const std::string& out_dir, const std::vector<double>& error_scales) {
  if (error_scales.size() == 1)
    throw SceneError("--error-scales: one coarser level given; Richardson needs two (e.g. 2,1.41)");
  for (double e : error_scales)
    if (!(e > 1))
      throw SceneError("--error-scales: " + fmt("%g", e) +
                       ": the error levels are coarser than the scene, so each scale must be > 1");
  check_output_dir(out_dir);
  Stopwatch total;
  nlohmann::json report, wall;
  auto skin = skin_setup(scene, contact_mesh_part(scene));
  wall = skin->wall;
  report["dofs"] = skin->model->solver().free_dofs();
  // A half skin is shown, and its quality and volume checked, as the whole it stands for.
  const bool half = is_half_y(skin->mesh);
  const TetMesh mirrored = half ? mirror_half(skin->mesh) : TetMesh{};
  report["mesh"] =
      mesh_stage(scene, half ? mirrored : skin->mesh, skin->wall["mesh"].get<double>(), out_dir + "/mesh");

  Stopwatch clock;
  auto adjoints = adjoint_setup(scene, skin);
  wall["green_adjoints"] = adjoints->wall["adjoint_solves"];
  clock = Stopwatch();
  const SensorGreens greens = sensor_greens(scene, *adjoints);
  report["green"] = green_stage(scene, greens, adjoints.get(), out_dir + "/green");
  report["kfit"] = kfit_stage(scene, greens, out_dir + "/kfit", "punch");
  wall["green_kfit_profiles"] = clock.seconds();

  std::shared_ptr<ContactSetup> contact;
  std::optional<DefectRun> defect;
  std::optional<validation::Crosscheck> x;
  if (scene.contact) {
    contact = contact_setup(scene, skin);
    wall["condense"] = contact->wall["condense"];
    clock = Stopwatch();
    report["contact"] = contact_stage(scene, contact, out_dir + "/contact", scene.contact->friction);
    wall["contact"] = clock.seconds();
    if (scene.contact->sweep) {
      clock = Stopwatch();
      defect = defect_stage(scene, contact, out_dir + "/defect");
      wall["defect"] = clock.seconds();
      clock = Stopwatch();
      progress("crosscheck: the paper's model against FE, one assumption at a time");
      validation::CrosscheckInput in;
      in.mesh = &contact->mesh();
      in.solver = contact->solver.get();
      in.fe = adjoints->fe.get();
      in.sensors = scene.sensors;
      for (const auto& s : scene.sensors.positions)
        in.thickness.push_back(thickness_at(scene, skin->mesh, s));
      in.E = scene.material.E;
      in.nu = scene.material.nu;
      in.force = scene.contact->force.value_or(report["contact"]["force_N"].get<double>());
      in.center = contact_center(scene);
      in.center_thickness = thickness_at(scene, skin->mesh, in.center);
      in.equivalent_radius = equivalent_sphere_radius(scene);
      in.k_paper = green::kPaperK;
      in.k_best = report["kfit"]["k_lsq_line"].get<double>();
      in.sweeps = &defect->sweeps;
      in.frames = &defect->frames;
      in.sweep = *scene.contact->sweep;
      x = validation::crosscheck(in);
      write_crosscheck(*x, scene.sensors, out_dir + "/crosscheck");
      report["front_sensors"] = front_sensor_answer(
          *x, validation::front_sensors(scene.sensors, in.center, scene.contact->direction),
          scene.contact->direction);
      wall["crosscheck"] = clock.seconds();
      clock = Stopwatch();
      report["hole_budget"] = hole_budget_stage(scene, *contact, *x, out_dir + "/crosscheck");
      wall["hole_budget"] = clock.seconds();
    }
  }

  // Error bars: the chain's headline quantities on this mesh and on coarser ones (every mesh size scaled),
  // Richardson through the three finest. The coarse levels come after this level's memory is released.
  std::vector<validation::KSweepPoint> mesh_rows;
  if (!error_scales.empty()) {
    clock = Stopwatch();
    std::vector<ChainLevel> levels{chain_values(scene, *adjoints, contact.get())};
    contact.reset();
    adjoints.reset();
    skin.reset();
    std::vector<double> scales = error_scales;
    std::sort(scales.begin(), scales.end(), std::greater<>());
    for (size_t i = 0; i < scales.size(); ++i) {
      progress("error bars: level " + std::to_string(i + 1) + " of " + std::to_string(scales.size()) +
               " (mesh sizes x" + fmt("%g", scales[i]) + ")");
      levels.insert(levels.end() - 1, chain_level(scene, scales[i]));
    }
    report["chain_study"] = write_chain_study(scene, levels, out_dir + "/study");
    report["chain_study"].erase("scene");
    report["error_bars"] = error_bars(chain_errors(levels), scales);
    for (const ChainLevel& l : levels) mesh_rows.push_back({"mesh_scale", l.scale, l.value[0], l.value[1]});
    wall["error_levels"] = clock.seconds();
  }
  clock = Stopwatch();
  progress("k sweep: which protocol reading gives the paper's k");
  report["k_paper"] =
      k_paper_answer(scene, report["kfit"]["h_mm"].get<double>(), mesh_rows, out_dir + "/kfit");
  wall["k_sweep"] = clock.seconds();

  clock = Stopwatch();
  const std::string script = figures_script();
  progress("figures: " + script);
  const int rc = run_child({"/usr/bin/python3", script, out_dir});
  report["figures_exit_code"] = rc;
  wall["figures"] = clock.seconds();

  report["scene"] = scene_json(scene);
  report["wall_s"] = wall;
  report["wall_total_s"] = total.seconds();
  report["peak_rss_mb"] = peak_rss_mb();
  report["units"] = {{"length", "mm"}, {"force", "N"}, {"stress", "kPa in tables and CSV, MPa in the model"}};
  write_json(out_dir + "/report.json", report);
  write_index(out_dir, scene, report, x ? &*x : nullptr);
  std::printf("report %s: %d DOFs, one factorization for the chain%s; %.1f s, peak %.0f MB\n",
              scene.name.c_str(), report["dofs"].get<int>(),
              report.contains("error_bars")
                  ? (" and " + std::to_string(error_scales.size()) + " coarser for the error bars").c_str()
                  : "",
              total.seconds(), peak_rss_mb());
  if (report.contains("error_bars"))
    for (const auto& e : report["error_bars"])
      std::printf("  %s: %s%s%s (%s)\n", e["what"].get<std::string>().c_str(),
                  with_error(e["value"].get<double>(), e["error"].get<double>()).c_str(),
                  e["unit"].get<std::string>().empty() ? "" : " ", e["unit"].get<std::string>().c_str(),
                  e["method"].get<std::string>().c_str());
  std::printf("  %s\n", report["k_paper"]["answer"].get<std::string>().c_str());
  if (report.contains("front_sensors") && report["front_sensors"].contains("answer"))
    std::printf("  %s\n", report["front_sensors"]["answer"].get<std::string>().c_str());
  if (rc != 0)
    std::printf("  figures: scripts/figures.py exited with %d; index.html lists the figures written\n", rc);
  std::printf("  wrote %s/index.html, report.json\n", out_dir.c_str());
  return 0;
}

}  // namespace skinfem::app
