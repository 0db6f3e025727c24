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
// green/ (green.csv, green_maps.vtp, post_design.csv: an isolated post against a disc at the skin's axis and
// a design sweep, app/post_design_stage.cpp), kfit/ (kfit.json, and k_sweep.csv: the exact layer's k as each
// reading of the calibration protocol changes, validation/k_sweep.hpp), and with a contact: contact/
// (pressure.vtp, fields.vtu, sensors.csv, modes.csv), defect/ (defect.csv, defect.pvd + frames/) and
// crosscheck/ (readings.csv, defect.csv, pressure.csv, attribution.csv with columns
// case,variant,sensor,component,amplitude_ratio,peak_shift_mm,shape_error). Then figures/*.png
// (scripts/figures.py, matplotlib) and DIR/report.json (the headline numbers with units, wall seconds per
// stage, peak memory) and DIR/index.html (figures, tables, links to every VTK file).
#include <signal.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <optional>
#include <sstream>
#include <string>
#include <utility>

#include "app/chain_study.hpp"
#include "app/commands.hpp"
#include "app/common.hpp"
#include "app/stages.hpp"
#include "fem/blas_threads.hpp"
#include "green/kfit.hpp"
#include "mesh/mirror.hpp"
#include "pipeline/crosscheck.hpp"
#include "pipeline/symmetry.hpp"
#include "validation/crosscheck.hpp"
#include "validation/k_sweep.hpp"
#include "validation/text.hpp"

namespace skinfem::app {

namespace {
using validation::fmt;

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
       "kPa,p_meridian_frictionless_kPa\n";
  for (const auto& row : x.pressure_profile) {
    p << row[0];
    for (int j = 1; j < 7; ++j) {
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

// report.json's front_sensors entry (validation::front_sensor_answer).
nlohmann::json front_sensor_json(const validation::FrontSensorAnswer& a) {
  nlohmann::json j;
  std::string front;
  for (const int k : a.front) front += (front.empty() ? "#" : ", #") + std::to_string(k + 1);
  j["front_sensors"] = front;
  if (!a.front.empty()) {
    j["coupling_amplitude_factor_z"] = {a.coupling_lo[0], a.coupling_hi[0]};
    j["coupling_amplitude_factor_x"] = {a.coupling_lo[1], a.coupling_hi[1]};
  }
  if (a.model_lo) {
    j["fe_over_paper_model_amplitude_z"] = {(*a.model_lo)[0], (*a.model_hi)[0]};
    j["fe_over_paper_model_amplitude_x"] = {(*a.model_lo)[1], (*a.model_hi)[1]};
  }
  j["answer"] = a.answer;
  return j;
}

// Which single change of the calibration protocol gives the paper's k (validation/k_sweep.hpp), with the
// FE k of sensor #1 per mesh scale (mesh_rows) as one more axis; writes DIR/k_sweep.csv and its report.json
// entry.
validation::KTargetAnswer k_paper_answer(const Scene& scene, double h,
                                         const std::vector<validation::KSweepPoint>& mesh_rows,
                                         const std::string& dir, nlohmann::json& entry) {
  validation::KProtocol base;
  base.h = h;
  base.nu = scene.material.nu;
  base.punch_diameter = scene.calibration.punch_diameter;
  const validation::KTargetAnswer a = validation::k_target_answer(base, mesh_rows, green::kPaperK);
  std::ostringstream csv;
  csv.precision(10);
  csv << "parameter,value,k_central,k_lsq_line\n";
  for (const auto& p : a.points)
    csv << p.parameter << "," << p.value << "," << p.k_central << "," << p.k_lsq_line << "\n";
  write_text_atomic(dir + "/k_sweep.csv", csv.str());
  nlohmann::json j;
  for (const auto& n : a.near)
    j["within_0.01"].push_back(
        {{"parameter", n.parameter}, {"value", n.value}, {"criterion", n.criterion}, {"k", n.k}});
  for (const auto& c : a.crossings)
    j["crossings"].push_back({{"parameter", c.parameter},
                              {"criterion", c.criterion},
                              {"value", c.value},
                              {"linear_interpolation", c.interpolated}});
  j["answer"] = a.answer;
  entry = j;
  return a;
}

// The chain's quantities with their error bars (pipeline/chain_level.hpp), in display units.
struct ErrorBar {
  std::string quantity, what, unit, method;
  double value = 0, error = 0, relative_error = 0;
};

std::vector<ErrorBar> error_bars(const std::vector<ChainError>& errors,
                                 const std::vector<double>& coarse_scales) {
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
  std::vector<ErrorBar> out;
  for (const ChainError& e : errors)
    for (const Display& d : table)
      if (e.name == d.name)
        out.push_back({e.name, d.what, d.unit,
                       e.asymptotic ? "|value - Richardson limit| over mesh scales " + levels +
                                          ", observed order " + fmt("%.2f", e.order)
                                    : "last change between mesh scales " + fmt("%g", coarse_scales.back()) +
                                          " and 1; no asymptotic regime over " + levels + " (" + e.why_not +
                                          "), so an order of magnitude only",
                       d.factor * e.value, d.factor * e.error, e.error / std::abs(e.value)});
  return out;
}

nlohmann::json error_bars_json(const std::vector<ErrorBar>& bars) {
  nlohmann::json j = nlohmann::json::array();
  for (const ErrorBar& e : bars)
    j.push_back({{"quantity", e.quantity},
                 {"what", e.what},
                 {"unit", e.unit},
                 {"value", e.value},
                 {"error", e.error},
                 {"relative_error", e.relative_error},
                 {"method", e.method}});
  return j;
}

// A value and its error, the value rounded to the error's second significant digit (no error: 6 digits).
std::array<std::string, 2> rounded_to_error(double value, double error) {
  if (!(error > 0)) return {fmt("%.6g", value), ""};
  const int decimals = std::max(0, 1 - static_cast<int>(std::floor(std::log10(error))));
  const std::string f = "%." + std::to_string(decimals) + "f";
  return {fmt(f.c_str(), value), fmt(f.c_str(), error)};
}

// "value +- error" (the terminal's ASCII).
std::string with_error(double value, double error) {
  const auto [v, e] = rounded_to_error(value, error);
  return e.empty() ? v : v + " +- " + e;
}

// A word of the terminal's ASCII in the page's notation: um → µm, sigma[_]c → σc and varsigma[_]c → ςc
// for a component c of x, y, z or none; any other word as it is.
std::string page_word(const std::string& w) {
  if (w == "um") return "µm";
  for (const auto& [name, symbol] : {std::pair{"varsigma", "ς"}, std::pair{"sigma", "σ"}}) {
    if (w.rfind(name, 0) != 0) continue;
    std::string c = w.substr(std::strlen(name));
    if (!c.empty() && c[0] == '_') c.erase(0, 1);
    if (c.empty() || (c.size() == 1 && c[0] >= 'x' && c[0] <= 'z')) return symbol + c;
  }
  return w;
}

// Text for the page: escaped, and in the page's notation where the shared sentences write the terminal's
// ASCII (±, µm, ς and σ with their component; words as a regular expression's \w+ delimits them).
std::string html_escape(const std::string& s) {
  std::string o;
  for (char c : s) o += c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '&' ? "&amp;" : std::string(1, c);
  const auto word_char = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  std::string page;
  for (size_t i = 0; i < o.size();) {
    if (o.compare(i, 2, "+-") == 0) {
      page += "±", i += 2;
    } else if (!word_char(o[i])) {
      page += o[i++];
    } else {
      size_t j = i;
      while (j < o.size() && word_char(o[j])) ++j;
      page += page_word(o.substr(i, j - i));
      i = j;
    }
  }
  return page;
}

// The figures in the paper's order (its figures 1-4 first), each with what it plots; a figure not listed
// here keeps its file name as caption and comes last.
std::vector<std::pair<std::string, std::string>> figure_captions(const std::string& scene,
                                                                 const std::optional<HoleBudget>& budget) {
  const std::string on = " Scene " + scene + ".";
  std::vector<std::pair<std::string, std::string>> f{
      {"fig1_calibration",
       "Paper fig. 1: the calibration scans, each sensor's FE Green tensor along y = 0 (zz, zx, xz, xx), "
       "against the half-space rescaled by the paper's k and by the fitted one." +
           on},
      {"fig2_static_sliding",
       "Paper fig. 2: mean sensor stresses σz and σx under the plate, static and sliding; full FE and each "
       "variant that swaps one assumption into it." +
           on},
      {"fig3_varsigma_z",
       "Paper fig. 3: the hole signal ςz(u) of each sensor as the hole in the plate crosses the contact, "
       "sliding then static: full FE, the paper's model, and FE rescaled to the model for #5 and #7." +
           on},
      {"fig4_varsigma_x", "Paper fig. 4: the hole signal ςx(u), as fig. 3." + on},
      {"pressure_profiles",
       "Contact pressure p along y = 0: Hertz on the half-space, the exact bonded layer, FE frictionless "
       "and FE with coupled friction (its tangential traction q dotted)." +
           on},
      {"green_vs_halfspace",
       "Sensor #1's FE Green tensor (g_zz, g_xx) against the half-space rescaled by both k, and the "
       "difference over the FE peak." +
           on},
      {"k_sweep",
       "k of the exact layer as one calibration-protocol reading changes at a time, against the paper's "
       "1.48 ± 0.01, and the FE k per mesh scale." +
           on},
      {"post_design",
       "A post against a disc at the skin's axis (meridian solves): ∫ g dA and half width of g_zz over the "
       "post's height and diameter." +
           on},
      {"pareto", "Cost against accuracy of each stage over the error-bar levels (labels: DOFs)." + on}};
  if (budget)
    for (const validation::HypothesisResult& y : budget->results)
      f.push_back({"budget_" + y.hypothesis.name,
                   "The hole-signal budget under '" + y.hypothesis.name + "' (" + y.hypothesis.what +
                       "): sliding ςz (top) and ςx (bottom) of full FE against the paper's model per sensor, "
                       "titled with their amplitude ratio." +
                       on});
  return f;
}

// What index.html shows, as the stages returned it.
struct IndexInput {
  int dofs = 0;
  double wall_total_s = 0, peak_rss_mb = 0;
  const nlohmann::json* wall = nullptr;  // the report's own seconds per stage
  std::string kfit_verdict, k_paper_answer;
  std::optional<validation::FrontSensorAnswer> front;
  std::optional<HoleBudget> budget;
  std::vector<ErrorBar> error_bars;                 // empty without error bars
  const std::vector<ChainLevel>* levels = nullptr;  // the error bars' levels, coarse to fine
  std::map<std::string, double> exponents;          // time ∝ DOFs^e per stage
  const validation::Crosscheck* x = nullptr;
  const pipeline::PostDesign* post = nullptr;  // what a post changes, when the skin has an axis
  std::string post_answer;
  std::string left_out;  // what a --fast report left out; empty otherwise
};

void write_index(const std::string& dir, const Scene& scene, const IndexInput& in) {
  namespace fs = std::filesystem;
  std::ostringstream h;
  h << "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>skinfem report: "
    << html_escape(scene.name)
    << "</"
       "title><style>body{font-family:sans-serif;max-width:1100px;margin:auto}table{border-collapse:collapse}"
       "td,th{border:1px solid #bbb;padding:2px 6px;text-align:right}"
       // A table wider than the page scrolls inside itself.
       "table{display:block;max-width:100%;overflow-x:auto}td:not([style]){white-space:nowrap}"
       "img{max-width:100%}"
       "figure{margin:1em 0}figcaption{font-size:90%}</style></head><body>\n";
  h << "<h1>skinfem report: " << html_escape(scene.name) << "</h1>\n<p>Units: mm, N, MPa (stresses in kPa). "
    << in.dofs << " DOFs, one factorization for the chain"
    << (in.error_bars.empty() ? "" : " (and one per coarser level for the error bars)") << "; total "
    << fmt("%.1f", in.wall_total_s) << " s, peak memory " << fmt("%.0f", in.peak_rss_mb) << " MB.</p>\n";
  if (!in.left_out.empty())
    h << "<p><b>A fast report</b> (<code>--fast</code>): it leaves out the " << html_escape(in.left_out)
      << ". Run <code>skinfem report</code> without it for them.</p>\n";
  if (!in.error_bars.empty()) {
    h << "<h2>Headline numbers and their discretization error</h2><table><tr><th>quantity</th><th>value</th>"
         "<th>error</th><th>unit</th><th>how the error is estimated</th></tr>\n";
    for (const ErrorBar& e : in.error_bars) {
      const auto [value, error] = rounded_to_error(e.value, e.error);
      h << "<tr><td style=\"text-align:left\">" << html_escape(e.what) << "</td><td>" << value << "</td><td>"
        << (error.empty() ? "" : "± " + error) << "</td><td>" << html_escape(e.unit)
        << "</td><td style=\"text-align:left\">" << html_escape(e.method) << "</td></tr>\n";
    }
    h << "</table>\n";
  }
  if (in.levels) {
    const std::vector<ChainLevel>& levels = *in.levels;
    std::vector<std::string> stages;
    for (const auto& [stage, t] : levels.back().wall.items()) stages.push_back(stage);
    // The quantities in name order, as chain_study.json lists them.
    std::vector<size_t> order(levels.back().names.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(),
              [&](size_t a, size_t b) { return levels.back().names[a] < levels.back().names[b]; });
    h << "<h2>Speed against error: the levels behind the error bars</h2><table><tr><th>mesh scale</th>"
         "<th>DOFs</th>";
    for (const auto& st : stages) h << "<th>" << st << " s</th>";
    h << "<th>peak MB</th>";
    for (size_t i : order) h << "<th>" << levels.back().names[i] << "</th>";
    h << "</tr>\n";
    for (const ChainLevel& l : levels) {
      h << "<tr><td>" << fmt("%g", l.scale) << "</td><td>" << l.dofs << "</td>";
      for (const auto& st : stages)
        h << "<td>" << (l.wall.contains(st) ? fmt("%.2f", l.wall[st].get<double>()) : "") << "</td>";
      h << "<td>" << fmt("%.0f", l.peak_rss_mb) << "</td>";
      for (size_t i : order) h << "<td>" << fmt("%.6g", l.value[i]) << "</td>";
      h << "</tr>\n";
    }
    h << "<tr><td style=\"text-align:left\" colspan=\"2\">time &prop; DOFs<sup>e</sup>, e =</td>";
    for (const auto& st : stages) {
      const auto e = in.exponents.find(st);
      h << "<td>" << (e != in.exponents.end() ? fmt("%.2f", e->second) : "") << "</td>";
    }
    h << "<td colspan=\"" << 1 + order.size() << "\"></td></tr></table><p>Values in mm and MPa. Peak memory "
      << "per level: each coarser level's own; the scene's level (scale 1) is the report's up to its error "
         "bars. Errors per level: <a href=\"study/chain_study.csv\">study/chain_study.csv</a>, Pareto "
         "plot below.</p>\n";
  }
  h << "<h2>Time per stage</h2><table><tr><th>stage</th><th>seconds</th></tr>\n";
  for (const auto& [stage, sec] : in.wall->items())
    h << "<tr><td style=\"text-align:left\">" << stage << "</td><td>" << fmt("%.2f", sec.get<double>())
      << "</td></tr>\n";
  h << "</table>\n";
  h << "<h2>k</h2><p>" << html_escape(in.kfit_verdict) << "</p>\n<p>" << html_escape(in.k_paper_answer)
    << " (<a href=\"kfit/k_sweep.csv\">kfit/k_sweep.csv</a>)</p>\n";
  if (const pipeline::PostDesign* p = in.post) {
    h << "<h2>What a post changes: the paper's sensor against a disc</h2><p>" << html_escape(in.post_answer)
      << " A post reads the force on it over its cross-section.</p>\n"
         "<table><tr><th>sensor</th><th>diameter mm</th><th>height mm</th><th>g_zz peak /mm²</th><th>half "
         "width mm</th><th>∫ g_zz dA</th><th>g_xx peak /mm²</th><th>at mm</th><th>half width mm</th><th>∫ "
         "g_xx dA</th>"
         "<th>mesh change %</th></tr>\n";
    const auto row = [&h](const std::string& name, const pipeline::SensorDesign& d) {
      h << "<tr><td style=\"text-align:left\">" << name << "</td><td>" << fmt("%g", d.diameter) << "</td><td>"
        << fmt("%g", d.height) << "</td><td>" << fmt("%.4g", d.zz.peak) << "</td><td>"
        << fmt("%.3f", d.zz.half_width) << "</td><td>" << fmt("%.3f", d.zz.integral) << "</td><td>"
        << fmt("%.4g", d.xx.peak) << "</td><td>" << fmt("%.2f", d.xx.peak_at) << "</td><td>"
        << fmt("%.3f", d.xx.half_width) << "</td><td>" << fmt("%.3f", d.xx.integral) << "</td><td>"
        << fmt("%.2g", 100 * std::max({d.peak_change, d.half_width_change, d.integral_change}))
        << "</td></tr>\n";
    };
    row("disc", p->disc);
    row("post", p->post);
    h << "</table>\n<p>Design sweep (mesh scale " << fmt("%g", p->sweep_scale)
      << "; height 0 is the disc): ∫ g_zz dA, and its half width in mm.</p><table><tr><th>diameter "
         "mm</th>";
    std::vector<double> heights;
    for (const auto& d : p->sweep)
      if (std::find(heights.begin(), heights.end(), d.height) == heights.end()) heights.push_back(d.height);
    for (double t : heights) h << "<th>t = " << fmt("%g", t) << " mm</th>";
    h << "</tr>\n";
    for (size_t i = 0; i < p->sweep.size(); i += heights.size()) {
      h << "<tr><td>" << fmt("%g", p->sweep[i].diameter) << "</td>";
      for (size_t j = 0; j < heights.size(); ++j)
        h << "<td>" << fmt("%.3f", p->sweep[i + j].zz.integral) << " / "
          << fmt("%.3f", p->sweep[i + j].zz.half_width) << "</td>";
      h << "</tr>\n";
    }
    h << "</table><p>Every design: <a href=\"green/post_design.csv\">green/post_design.csv</a>.</p>\n";
  }
  if (in.front)
    h << "<h2>Does friction-pressure coupling explain the front sensors?</h2><p>"
      << html_escape(in.front->answer) << "</p>\n";
  if (in.budget && !in.budget->results.empty()) {
    const HoleBudget& b = *in.budget;
    const auto scale_sentence = [](const Eigen::VectorXd& s) {
      const auto range = [&](int d) {
        double lo = 1e300, hi = 0;
        for (int k = d; k < s.size(); k += 2) lo = std::min(lo, s[k]), hi = std::max(hi, s[k]);
        return fmt("%.3g", lo) + "–" + fmt("%.3g", hi);
      };
      return " Readings are in the paper's units: each sensor's FE reading over its scale from the paper's "
             "calibration (kfit/kfit.json, paper_calibration), " +
             range(0) + " for ςz and " + range(1) + " for ςx.";
    };
    const std::vector<int> front =
        validation::front_sensors(scene.sensors, contact_center(scene), scene.contact->direction);
    const auto range = [&](const std::vector<std::array<double, 2>>& ratios, int component, bool in_front) {
      double lo = 1e300, hi = 0;
      for (size_t k = 0; k < ratios.size(); ++k)
        if ((std::find(front.begin(), front.end(), static_cast<int>(k)) != front.end()) == in_front)
          lo = std::min(lo, ratios[k][component]), hi = std::max(hi, ratios[k][component]);
      return hi > 0 ? fmt("%.2f", lo) + "–" + fmt("%.2f", hi) : std::string("–");
    };
    const auto sorted_facts = [](std::vector<validation::FactVerdict> facts) {
      std::sort(facts.begin(), facts.end(), [](const auto& a, const auto& c) { return a.fact < c.fact; });
      return facts;
    };
    h << "<h2>Why is a hole so loud? The hole-signal budget</h2><p>" << html_escape(b.answer)
      << " Sliding amplitude of full FE over the paper's model per hypothesis; a fact is judged from the "
         "numbers "
         "(hover or open a row for the sentence). Detection: "
      << fmt("%.0f", b.base.noise.k) << " standard deviations of a " << b.base.noise.passages
      << "-passage mean, " << fmt("%.3f", 1e3 * b.base.noise.threshold(0)) << " kPa (ςz) and "
      << fmt("%.3f", 1e3 * b.base.noise.threshold(1)) << " kPa (ςx). F2: every back sensor's ratio within ["
      << fmt("%.2g", b.base.rules.match_lo) << ", " << fmt("%.2g", b.base.rules.match_hi)
      << "]; F3, the paper's asymmetry: the front's largest ratio at least "
      << fmt("%.2g", b.base.rules.front_min) << " and at least " << fmt("%.2g", b.base.rules.front_over_back)
      << " times the back's largest."
      << (b.base.reading_scale.size() ? scale_sentence(b.base.reading_scale) : "")
      << "</p>\n<table><tr><th>hypothesis</th><th>τ0 kPa</th><th>K MPa/mm</th><th>back "
         "z</th><th>back "
         "x</th><th>front "
         "z</th><th>front x</th><th>F1</th><th>F2</th><th>F3</th><th>F4</th><th>F5</th></tr>\n";
    for (const validation::HypothesisResult& y : b.results) {
      const auto& r = y.ratio[1];
      const Interface& face = y.hypothesis.load.interface;
      h << "<tr><td style=\"text-align:left\" title=\"" << html_escape(y.hypothesis.what) << "\">"
        << y.hypothesis.name << "</td><td>" << fmt("%.1f", 1e3 * y.tau0_MPa) << "</td><td>"
        << (face.law == InterfaceLaw::linear && face.K > 0 ? fmt("%.4g", face.K) : std::string("hard"))
        << "</td><td>" << range(r, 0, false) << "</td><td>" << range(r, 1, false) << "</td><td>"
        << range(r, 0, true) << "</td><td>" << range(r, 1, true) << "</td>";
      for (const auto& f : sorted_facts(y.facts))
        h << "<td title=\"" << html_escape(f.why) << "\">" << (f.met ? "yes" : "no") << "</td>";
      h << "</tr>\n";
    }
    h << "</table>\n";
    for (const validation::HypothesisResult& y : b.results) {
      h << "<details><summary>" << y.hypothesis.name << ": " << html_escape(y.hypothesis.what)
        << "</summary><ul>\n";
      for (const auto& f : sorted_facts(y.facts))
        h << "<li>" << f.fact << (f.met ? " met: " : " not met: ") << html_escape(f.why) << "</li>\n";
      h << "</ul></details>\n";
    }
    h << "<p>Per sensor: <a href=\"crosscheck/hole_budget.csv\">crosscheck/hole_budget.csv</a>; signals: <a "
         "href=\"crosscheck/hole_budget_signals.csv\">crosscheck/hole_budget_signals.csv</a>.</p>\n";
  }
  if (const validation::Crosscheck* x = in.x) {
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
  std::vector<std::string> drawn;  // PNG stems, sorted: the directory's own order is the file system's
  if (fs::is_directory(dir + "/figures"))
    for (const auto& e : fs::directory_iterator(dir + "/figures"))
      if (e.path().extension() == ".png") drawn.push_back(e.path().stem().string());
  std::sort(drawn.begin(), drawn.end());
  auto captions = figure_captions(scene.name, in.budget);
  for (const std::string& stem : drawn)
    if (std::none_of(captions.begin(), captions.end(), [&](const auto& c) { return c.first == stem; }))
      captions.push_back({stem, stem});
  int number = 0;
  for (const auto& [stem, caption] : captions)
    if (std::binary_search(drawn.begin(), drawn.end(), stem)) {
      const std::string file = "figures/" + stem + ".png";
      h << "<figure id=\"" << stem << "\"><a href=\"" << file << "\"><img src=\"" << file << "\" alt=\""
        << html_escape(stem) << "\"></a><figcaption>Figure " << ++number << " (" << stem
        << ".png, click for full size). " << html_escape(caption) << "</figcaption></figure>\n";
    }
  h << "<h2>Files</h2><ul>\n";
  for (const char* f :
       {"mesh/mesh.vtu", "mesh/boundary.vtu", "green/green_maps.vtp", "green/green.csv", "kfit/kfit.json",
        "contact/pressure.vtp", "contact/fields.vtu", "contact/modes.csv", "defect/defect.pvd",
        "green/post_design.csv", "defect/defect.csv", "crosscheck/readings.csv", "crosscheck/defect.csv",
        "crosscheck/pressure.csv", "crosscheck/attribution.csv", "crosscheck/hole_budget.csv",
        "crosscheck/hole_budget_signals.csv", "study/chain_study.csv", "report.json"})
    if (fs::exists(dir + "/" + f)) h << "<li><a href=\"" << f << "\">" << f << "</a></li>\n";
  h << "</ul></body></html>\n";
  write_text_atomic(dir + "/index.html", h.str());
}
}  // namespace

int run_report(const Scene& scene, const std::string& out_dir, const std::vector<double>& error_scales,
               bool fast) {
  pipeline::check_error_scales(error_scales);
  check_output_dir(out_dir);
  Stopwatch total;
  nlohmann::json report, wall;
  // One factorization for every stage: with a contact, bordered by its condensation's columns where that is
  // cheaper (green and kfit solve on its interior block). The hole budget sweeps its interface hypotheses
  // resolved: the path's compliance, whatever the scene's.
  // The meridian's frictionless contact, which checks the 3D one, is solved first: beside the 3D
  // factorization its own would add 35 MB to the report's peak.
  std::optional<pipeline::MeridianContactRun> meridian_check;
  if (scene.contact && pipeline::meridian_contact_unavailable(scene, FrictionMode::none, false).empty())
    meridian_check = pipeline::meridian_contact_run(scene, FrictionMode::none);
  pipeline::ContactSkin factored = pipeline::chain_skin(scene, HolePath::always);
  auto skin = factored.skin;
  wall = skin->wall;
  const int dofs = skin->model->solver().free_dofs();
  report["dofs"] = dofs;
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
  std::optional<MeridianCheck> axis_check;  // the green stage's, which kfit would otherwise solve again
  {
    auto green = green_stage(scene, greens, adjoints.get(), out_dir + "/green");
    report["green"] = std::move(green.summary);
    axis_check = green.result.meridian_check;
  }
  const auto kf = kfit_stage(scene, greens, out_dir + "/kfit", "punch", axis_check ? &*axis_check : nullptr);
  report["kfit"] = kf.summary;
  const pipeline::KfitSensor& headline = kf.result.sensors.at(0);
  wall["green_kfit_profiles"] = clock.seconds();

  IndexInput index;
  index.kfit_verdict = kf.result.verdict;
  std::shared_ptr<ContactSetup> contact;
  std::optional<DefectRun> defect;
  std::optional<validation::Crosscheck> x;
  if (scene.contact) {
    contact = contact_setup(scene, std::move(factored));
    wall["condense"] = contact->wall["condense"];
    clock = Stopwatch();
    double force = 0;  // the chosen mode's; the run is dropped here, its set-up released with `contact`
    std::optional<contact::MeridianContactResult> meridian;  // frictionless, where the skin has one
    {
      const auto run = contact_stage(scene, contact, out_dir + "/contact", scene.contact->friction, "",
                                     meridian_check ? &*meridian_check : nullptr);
      report["contact"] = run.summary;
      force = run.result.result().force_N;
      if (run.result.meridian_check) meridian = run.result.meridian_check->frictionless;
    }
    wall["contact"] = clock.seconds();
    // Its volume solution was the chain's last solve: the rest works on the condensed contact and the
    // adjoints' maps, so the factorization (most of the peak) goes.
    skin->model->release_factorization();
    if (scene.contact->sweep) {
      clock = Stopwatch();
      // Every position's frame: the crosscheck convolves each one's tractions.
      defect = defect_stage(scene, contact, out_dir + "/defect", {}, pipeline::DefectFrames::every, !fast);
      wall["defect"] = clock.seconds();
      clock = Stopwatch();
      x = crosscheck_run(scene, *adjoints, *contact, *defect, scene.contact->force.value_or(force),
                         headline.fe.k_lsq_line, meridian ? &*meridian : nullptr);
      write_crosscheck(*x, scene.sensors, out_dir + "/crosscheck");
      index.front = validation::front_sensor_answer(
          *x, validation::front_sensors(scene.sensors, contact_center(scene), scene.contact->direction),
          scene.contact->direction);
      report["front_sensors"] = front_sensor_json(*index.front);
      wall["crosscheck"] = clock.seconds();
      if (!fast) {
        clock = Stopwatch();
        auto budget = hole_budget_stage(scene, *contact, *x, out_dir + "/crosscheck",
                                        pipeline::paper_reading_scale(kf.result));
        report["hole_budget"] = std::move(budget.summary);
        index.budget = std::move(budget.result);
        wall["hole_budget"] = clock.seconds();
      }
    }
  }

  // The figures whose inputs are final are drawn from here on, beside the stages still to come; those of
  // the later stages (kfit/k_sweep.csv, study/chain_study.csv, green/post_design.csv) at the end.
  const std::string script = figures_script(), late_figures = "k_sweep.png,pareto.png,post_design.png";
  progress("figures: " + script + ", beside the stages to come");
  const int early_figures =
      start_background_child({"/usr/bin/python3", script, out_dir, "--except", late_figures});

  // Error bars: the chain's headline quantities on this mesh and on coarser ones (every mesh size scaled),
  // Richardson through the three finest. The coarse levels come after this level's memory is released.
  std::vector<validation::KSweepPoint> mesh_rows;
  std::vector<ChainLevel> levels;
  if (!error_scales.empty()) {
    clock = Stopwatch();
    const BlasThreads one(1);
    levels.push_back(chain_values(scene, *adjoints, contact.get()));
    // The defect run holds the contact set-up too (its solver, its condensed blocks): without it, the
    // paper's skin with posts kept 1.65 GB resident through the levels and peaked there, 350 MB above its
    // own chain.
    if (defect) defect->setup.reset();
    contact.reset();
    adjoints.reset();
    skin.reset();
    factored.skin.reset();  // without a contact it was never handed on
    release_freed_memory();
    std::vector<double> scales = error_scales;
    std::sort(scales.begin(), scales.end(), std::greater<>());
    for (size_t i = 0; i < scales.size(); ++i) {
      progress("error bars: level " + std::to_string(i + 1) + " of " + std::to_string(scales.size()) +
               " (mesh sizes x" + fmt("%g", scales[i]) + ")");
      levels.insert(levels.end() - 1, chain_level(scene, scales[i]));
    }
    report["chain_study"] = write_chain_study(scene, levels, out_dir + "/study");
    report["chain_study"].erase("scene");
    index.error_bars = error_bars(chain_errors(levels), scales);
    index.levels = &levels;
    index.exponents = time_vs_dofs_exponent(levels);
    report["error_bars"] = error_bars_json(index.error_bars);
    for (const ChainLevel& l : levels) mesh_rows.push_back({"mesh_scale", l.scale, l.value[0], l.value[1]});
    wall["error_levels"] = clock.seconds();
  }
  clock = Stopwatch();
  progress("k sweep: which protocol reading gives the paper's k");
  index.k_paper_answer =
      k_paper_answer(scene, headline.h_mm, mesh_rows, out_dir + "/kfit", report["k_paper"]).answer;
  wall["k_sweep"] = clock.seconds();

  clock = Stopwatch();
  StageOutput<pipeline::PostDesign> post;
  if (!fast) {
    post = post_design_stage(scene, out_dir + "/green");
    report["post_design"] = post.summary;
    if (post.summary.contains("answer")) {
      index.post = &post.result;
      index.post_answer = post.summary["answer"];
    }
    wall["post_design"] = clock.seconds();
  } else {
    index.left_out = "error bars (the coarser levels)";
    if (scene.contact && scene.contact->sweep)
      index.left_out += ", the hole-signal budget of hypotheses, the defect sweep's VTK frames";
    index.left_out += " and the post design sweep";
    report["fast"] = {{"left_out", index.left_out}};
  }

  clock = Stopwatch();
  progress("figures: the last ones, and the end of the others");
  int stopped_by = 0;
  const int rc_late = run_child({"/usr/bin/python3", script, out_dir, "--only", late_figures}, &stopped_by);
  if (stopped_by != 0) kill(early_figures, stopped_by);
  const int rc_early = wait_background_child(early_figures);
  const int rc = rc_early != 0 ? rc_early : rc_late;
  if (stopped_by != 0) {
    std::fprintf(stderr,
                 "skinfem: report: stopped by signal %d (%s) while drawing the figures; report.json and "
                 "index.html not written\n",
                 stopped_by, strsignal(stopped_by));
    return 128 + stopped_by;
  }
  report["figures_exit_code"] = rc;
  wall["figures"] = clock.seconds();

  report["scene"] = scene_json(scene);
  report["wall_s"] = wall;
  report["wall_total_s"] = index.wall_total_s = total.seconds();
  report["peak_rss_mb"] = index.peak_rss_mb = peak_rss_mb();
  report["units"] = {{"length", "mm"}, {"force", "N"}, {"stress", "kPa in tables and CSV, MPa in the model"}};
  write_json(out_dir + "/report.json", report);
  index.dofs = dofs;
  index.wall = &wall;
  index.x = x ? &*x : nullptr;
  write_index(out_dir, scene, index);
  std::printf("report %s: %d DOFs, one factorization for the chain%s; %.1f s, peak %.0f MB\n",
              scene.name.c_str(), dofs,
              index.error_bars.empty()
                  ? ""
                  : (" and " + std::to_string(error_scales.size()) + " coarser for the error bars").c_str(),
              total.seconds(), peak_rss_mb());
  for (const ErrorBar& e : index.error_bars)
    std::printf("  %s: %s%s%s (%s)\n", e.what.c_str(), with_error(e.value, e.error).c_str(),
                e.unit.empty() ? "" : " ", e.unit.c_str(), e.method.c_str());
  std::printf("  %s\n", index.k_paper_answer.c_str());
  if (index.front) std::printf("  %s\n", index.front->answer.c_str());
  if (rc != 0)
    std::printf("  figures: scripts/figures.py exited with %d; index.html lists the figures written\n", rc);
  if (!index.left_out.empty()) std::printf("  fast: left out the %s\n", index.left_out.c_str());
  // Where the time went, longest first.
  std::vector<std::pair<double, std::string>> stages;
  for (const auto& [stage, t] : wall.items()) stages.push_back({t.get<double>(), stage});
  std::sort(stages.rbegin(), stages.rend());
  std::string line;
  for (const auto& [t, stage] : stages) line += (line.empty() ? "" : ", ") + stage + " " + fmt("%.1f", t);
  std::printf("  seconds per stage: %s\n", line.c_str());
  std::printf("  wrote %s/index.html, report.json\n", out_dir.c_str());
  return 0;
}

}  // namespace skinfem::app
