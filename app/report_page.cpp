// index.html: the report's page, from what its stages returned (app/report_page.hpp).
#include "app/report_page.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <map>
#include <ostream>
#include <sstream>
#include <utility>

#include "app/common.hpp"
#include "skinfem/validation/text.hpp"

namespace skinfem::app {

using validation::fmt;

namespace {
// A value and its error, the value rounded to the error's second significant digit (no error: 6 digits).
std::array<std::string, 2> rounded_to_error(double value, double error) {
  if (!(error > 0)) return {fmt("%.6g", value), ""};
  const int decimals = std::max(0, 1 - static_cast<int>(std::floor(std::log10(error))));
  const std::string f = "%." + std::to_string(decimals) + "f";
  return {fmt(f.c_str(), value), fmt(f.c_str(), error)};
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
       "and FE with coupled friction (its tangential traction q dotted). Near the contact's edges the FE "
       "tractions wiggle over a few cells of the mesh along y = 0 (most visibly p and q with coupled "
       "friction "
       "at the front edge): the discrete contact resolves an edge to a cell, no finer." +
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
      {"pareto", "Cost against accuracy of each stage over the error-bar levels (labels: DOFs)." + on},
      {"perception_scan",
       "Laid out like the paper's fig. 3: a row of the scene's holes scanned across the contact, sliding, "
       "each sensor's ςz (top) and ςx (bottom) against the plate's displacement u; the full contact with "
       "every hole in the zone (left) against the sum of the holes' single-hole signals (right). The "
       "wiggles are the resolved holes' rims on the track's mesh (see the Perception section), in both." +
           on},
      {"perception_superposition",
       "Where superposition holds: the largest difference between two holes' full scan and the sum of their "
       "single-hole scans, over the scan's largest signal, against the holes' spacing (static and sliding, "
       "ςz and ςx); stars: the row." +
           on},
      {"perception_detection",
       "The matched filter's SNR against the hole's diameter at the paper's noise (the array and its best "
       "sensor, static and sliding) and the smallest hole detected at p_fa 1 %, p_d 90 % against the "
       "number of passages N." +
           on},
      {"perception_inversion",
       "The row's sliding signals with the paper's noise (N = 14; ςz shown) inverted: the features found by "
       "every sensor together with the contact's offset fitted, and by each sensor alone (the paper's naive "
       "inversion), against the true holes." +
           on},
      {"finite_path",
       "The contact zone against the tangential load from 0 to μF at the full normal force: its edges (the "
       "outermost touching vertices, in steps of the mesh) and force centroid along the sliding direction, "
       "and its radius and anisotropy from the pressure's second moments; the linear skin (lines) beside the "
       "neo-Hookean one (markers: the converged states of its load path) in the material and the spatial "
       "frame." +
           on}};
  if (budget)
    for (const validation::HypothesisResult& y : budget->results)
      f.push_back({"budget_" + y.hypothesis.name,
                   "The hole-signal budget under '" + y.hypothesis.name + "' (" + y.hypothesis.what +
                       "): sliding ςz (top) and ςx (bottom) of full FE against the paper's model per sensor, "
                       "titled with their amplitude ratio." +
                       on});
  return f;
}

// The pictures of the mesh and of the contact's fields (scripts/figures.py draws them from the VTK files),
// then the hole budget's summary, last.
std::vector<std::pair<std::string, std::string>> field_captions(const Scene& scene, const ReportResult& in) {
  const std::string on = " Scene " + scene.name + ".";
  std::vector<std::pair<std::string, std::string>> f;
  if (in.json.contains("mesh")) {
    const nlohmann::json& m = in.json.at("mesh");
    f.push_back({"skin_mesh",
                 "The mesh: the skin's top seen from above (its triangles; red: the outline of the nodes "
                 "in contact under the sliding plate; dots: the sensors' centres on the base), and "
                 "the section y = 0 (the cut tetrahedra, z stretched 2×; ▲: the sensors). " +
                     std::to_string(m.at("elements").get<int>()) + " quadratic tetrahedra, " +
                     std::to_string(m.at("nodes").get<int>()) + " nodes, edges from " +
                     fmt("%.2g", m.at("min_edge_mm").get<double>()) + " to " +
                     fmt("%.2g", m.at("max_edge_mm").get<double>()) +
                     " mm: fine along the sensors' line, at their discs and under the contact. The "
                     "outline steps at the mesh's scale." +
                     on});
  }
  if (in.json.contains("contact")) {
    const nlohmann::json& c = in.json.at("contact");
    const std::string mode = c.at("friction").get<std::string>();
    f.push_back(
        {"contact_pressure_map",
         "The contact pressure p on the skin's top (" + mode +
             " friction), seen from above with the outline of the nodes in contact, and along y = 0. "
             "Largest p " +
             fmt("%.1f", c.at("p_max_kPa").get<double>()) + " kPa; contact radius " +
             fmt("%.3f", c.at("contact_radius_mm").get<double>()) +
             " mm. Near the edges p wiggles over the last cells before it falls to zero, and the "
             "colour reaches about a cell past the outline (nodes beside the contact carry a small p in "
             "contact/pressure.vtp): the discrete contact resolves an edge to a cell, no finer." +
             on});
    f.push_back(
        {"skin_stress",
         "σzz on the section y = 0 through the skin under the plate (" + mode +
             " friction), kPa (negative: compression; z stretched 2×; ▲: the sensors, whose σz is −σzz "
             "averaged over their disc on the base). With friction, compression gathers under the "
             "front of the contact and tension behind it. The thin streaks at the contact's edges near "
             "the top are a cell wide." +
             on});
  }
  f.push_back(
      {"budget_summary",
       "The hole-signal budget in one figure: the sliding amplitude of full FE over the paper's model per "
       "sensor, ςz (left) and ςx (right), one line per hypothesis labelled with the paper's facts it "
       "meets (the budget's table gives each verdict's reason). Bands: F2 asks the back sensors to match "
       "the model (0.5–2×), F3 the front ones to reach 2–4×. Each hypothesis's signals: the folded "
       "figures at the end." +
           on});
  return f;
}

// The page up to its first table: scene, units, size, time and memory, and what a fast report left out.
void page_head(std::ostream& h, const Scene& scene, const ReportResult& in) {
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
    << fmt("%.1f", in.seconds) << " s, peak memory " << fmt("%.0f", in.peak_rss_mb) << " MB.</p>\n";
  if (!in.left_out.empty())
    h << "<p><b>A fast report</b> (<code>--fast</code>): it leaves out the " << html_escape(in.left_out)
      << ". Run <code>skinfem report</code> without it for them.</p>\n";
}

void headline_numbers(std::ostream& h, const ReportResult& in) {
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
}

void error_levels(std::ostream& h, const ReportResult& in) {
  if (!in.levels.empty()) {
    const std::vector<ChainLevel>& levels = in.levels;
    std::vector<std::string> stages;
    for (const auto& [stage, t] : levels.back().wall) stages.push_back(stage);
    // The quantities in name order, as chain_study.json lists them.
    std::vector<size_t> order(levels.back().names.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(),
              [&](size_t a, size_t b) { return levels.back().names[a] < levels.back().names[b]; });
    // Transposed (a row per stage or quantity, a column per level): as wide as the levels are many.
    h << "<h2>Speed against error: the levels behind the error bars</h2><table><tr><th "
         "style=\"text-align:left\">"
         "</th><th>unit</th>";
    for (const ChainLevel& l : levels) h << "<th>mesh scale " << fmt("%g", l.scale) << "</th>";
    h << "<th>time &prop; DOFs<sup>e</sup>: e</th></tr>\n";
    const auto row = [&](const std::string& what, const std::string& unit, const auto& cell,
                         const std::string& last) {
      h << "<tr><td style=\"text-align:left\">" << what << "</td><td>" << unit << "</td>";
      for (const ChainLevel& l : levels) h << "<td>" << cell(l) << "</td>";
      h << "<td>" << last << "</td></tr>\n";
    };
    row(
        "DOFs", "", [](const ChainLevel& l) { return std::to_string(l.dofs); }, "");
    row(
        "peak memory", "MB", [](const ChainLevel& l) { return fmt("%.0f", l.peak_rss_mb); }, "");
    for (const auto& st : stages) {
      const auto e = in.exponents.find(st);
      row(
          "time: " + st, "s",
          [&](const ChainLevel& l) {
            return l.wall.contains(st) ? fmt("%.2f", l.wall.at(st)) : std::string();
          },
          e != in.exponents.end() ? fmt("%.2f", e->second) : "");
    }
    for (size_t i : order) {
      const std::string& name = levels.back().names[i];
      const pipeline::QuantityDisplay* d = pipeline::quantity_display(name);
      row(
          d ? html_escape(d->what) : name, d ? html_escape(d->unit) : "",
          [&](const ChainLevel& l) { return fmt("%.6g", (d ? d->factor : 1) * l.value[i]); }, "");
    }
    h << "</table><p>Peak memory per level: each coarser level's own; the scene's level (scale 1) is the "
         "report's up to its error bars. Errors per level: <a href=\"study/chain_study.csv\">"
         "study/chain_study.csv</a>, Pareto plot below.</p>\n";
  }
}

void stage_times_and_k(std::ostream& h, const ReportResult& in) {
  h << "<h2>Time per stage</h2><table><tr><th>stage</th><th>seconds</th></tr>\n";
  for (const auto& [stage, sec] : in.wall)
    h << "<tr><td style=\"text-align:left\">" << stage << "</td><td>" << fmt("%.2f", sec) << "</td></tr>\n";
  for (const auto& [stage, sec] : in.beside)
    h << "<tr><td style=\"text-align:left\">" << stage << " (beside the others: a thread or process)</td><td>"
      << fmt("%.2f", sec) << "</td></tr>\n";
  h << "</table>\n";
  h << "<h2>k</h2><p>" << html_escape(in.kfit_verdict) << "</p>\n";
  if (!in.k_paper_answer.empty())
    h << "<p>" << html_escape(in.k_paper_answer)
      << " (<a href=\"kfit/k_sweep.csv\">kfit/k_sweep.csv</a>)</p>\n";
}

void post_design(std::ostream& h, const ReportResult& in) {
  if (const pipeline::PostDesign* p = in.post ? &*in.post : nullptr) {
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
}

void front_sensors(std::ostream& h, const ReportResult& in) {
  if (in.front)
    h << "<h2>Does friction-pressure coupling explain the front sensors?</h2><p>"
      << html_escape(in.front->answer) << "</p>\n";
}

void hole_budget(std::ostream& h, const Scene& scene, const ReportResult& in) {
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
}

// report.json's finite_deformation entry as a paragraph and two tables (the sliding case).
void finite_deformation(std::ostream& h, const ReportResult& in) {
  if (!in.json.contains("finite_deformation")) return;
  const nlohmann::json& f = in.json.at("finite_deformation");
  const nlohmann::json& c = f.at("cases").at("sliding");
  h << "<h2>Does finite deformation matter at the paper's load?</h2><p>"
    << html_escape(f.at("answer").get<std::string>())
    << " Linear: the small-strain skin the rest of this page solves; finite: the incompressible neo-Hookean "
       "skin, the plate meeting its deformed surface (docs/theory.md). "
    << f.at("dofs").get<int>() << " DOFs, " << fmt("%.1f", f.at("seconds").get<double>()) << " s for "
    << (f.contains("shear_strength") ? "each law's" : "both") << " states and their sweeps."
    << (f.contains("shear_strength")
            ? " Under the shear strength (τ0 = " +
                  fmt("%.4g", f.at("shear_strength").at("tau0_kPa").get<double>()) +
                  " kPa where the skin touches), the finite skin slides with " +
                  fmt("%.3f", f.at("shear_strength").at("tangential_force_N").get<double>()) + " N."
            : std::string())
    << "</p>\n<table><tr><th>sliding contact (material frame)</th>"
       "<th>linear</th><th>finite</th><th>change</th></tr>\n";
  for (const char* key : {"contact_radius_mm", "p0_kPa", "indentation_um", "front_edge_mm", "back_edge_mm",
                          "zone_centroid_x_mm", "pressure_centroid_x_mm"}) {
    const nlohmann::json& v = c.at("contact").at(key);
    const double lin = v.at("linear"), fin = v.at("finite");
    // A position's change in mm, a size's in per cent.
    const std::string name = key;
    const bool position =
        name.find("edge") != std::string::npos || name.find("centroid") != std::string::npos;
    h << "<tr><td style=\"text-align:left\">" << key << "</td><td>" << fmt("%.4g", lin) << "</td><td>"
      << fmt("%.4g", fin) << "</td><td>"
      << (position ? fmt("%+.3f mm", fin - lin) : fmt("%+.2f %%", 100 * v.at("change_rel").get<double>()))
      << "</td></tr>\n";
  }
  const nlohmann::json* shear = f.contains("shear_strength") ? &f.at("shear_strength") : nullptr;
  h << "</table>\n<table><tr><th>sensor</th><th>σz kPa linear / finite</th><th>σx kPa linear / "
       "finite</th><th>sliding |ςz| finite/linear</th><th>|ςx| finite/linear</th>"
    << (shear ? "<th>shear strength |ςz| finite/linear</th><th>|ςx| finite/linear</th>" : "") << "</tr>\n";
  for (size_t k = 0; k < c.at("readings").size(); ++k) {
    const nlohmann::json &r = c.at("readings")[k], &a = c.at("hole_amplitudes")[k];
    h << "<tr><td>" << r.at("sensor").get<int>() << (a.at("front").get<bool>() ? " (front)" : "") << "</td>";
    for (const char* d : {"sigma_z_kPa", "sigma_x_kPa"})
      h << "<td>" << fmt("%.3f", r.at(d).at("linear").get<double>()) << " / "
        << fmt("%.3f", r.at(d).at("finite").get<double>()) << "</td>";
    for (const char* d : {"z", "x"}) h << "<td>" << fmt("%.3f", a.at(d).at("ratio").get<double>()) << "</td>";
    if (shear)
      for (const char* d : {"z", "x"}) {
        const nlohmann::json& s = shear->at("hole_amplitudes").at(k).at(d);
        h << "<td>" << (s.contains("ratio") ? fmt("%.3f", s.at("ratio").get<double>()) : std::string("–"))
          << "</td>";
      }
    h << "</tr>\n";
  }
  h << "</table>\n";
  if (!f.contains("error_bars") || !in.json.contains("error_bars")) return;
  // Each headline value with its mesh error on both skins: a change is resolved when it exceeds both.
  const auto pm = [](double v, double e) {
    const auto [value, error] = rounded_to_error(v, e);
    return error.empty() ? value : value + " ± " + error;
  };
  h << "<table><tr><th>sliding, mesh error from the coarser levels</th><th>linear</th><th>finite</th>"
       "<th>change / larger error</th></tr>\n";
  for (const nlohmann::json& b : f.at("error_bars"))
    for (const nlohmann::json& l : in.json.at("error_bars"))
      if (l.at("quantity") == b.at("quantity")) {
        const double lv = l.at("value"), le = l.at("error"), fv = b.at("value"), fe = b.at("error");
        const double larger = std::max(le, fe);
        h << "<tr><td style=\"text-align:left\">" << html_escape(b.at("what").get<std::string>()) << ", "
          << html_escape(b.at("unit").get<std::string>() == "um" ? "µm" : b.at("unit").get<std::string>())
          << "</td><td>" << pm(lv, le) << "</td><td>" << pm(fv, fe) << "</td><td>"
          << (larger > 0 ? fmt("%.1f", std::abs(fv - lv) / larger) : std::string("–")) << "</td></tr>\n";
      }
  h << "</table>\n";
}

void crosscheck(std::ostream& h, const Scene& scene, const ReportResult& in) {
  if (const validation::Crosscheck* x = in.crosscheck ? &*in.crosscheck : nullptr) {
    const int ns = static_cast<int>(scene.sensors.positions.size());
    h << "<h2>Mean sensor stresses (kPa), each variant swaps one assumption into full FE</h2>\n";
    for (int c = 0; c < 2; ++c) {
      h << "<h3>" << (c ? "sliding" : "static") << " (p_x = "
        << (x->shear[c] != 0 ? fmt("%.3g kPa", 1e3 * x->shear[c]) + (x->ratio[c] != 0 ? " + " : "") : "")
        << (x->ratio[c] != 0 || x->shear[c] == 0 ? fmt("%.3g p_z", x->ratio[c]) : "") << ")</h3>\n";
      // A row per sensor, a column per variant; σz and σx side by side as two tables.
      for (int b = 0; b < 2; ++b) {
        h << "<table style=\"display:inline-block;vertical-align:top;margin-right:1em\"><tr><th>"
          << (b ? "σx" : "σz") << " kPa</th>";
        for (size_t v = 0; v < x->readings.size(); ++v)
          h << "<th title=\"" << html_escape(x->reading_variants[v].what) << "\">"
            << x->reading_variants[v].name << "</th>";
        h << "</tr>\n";
        for (int k = 0; k < ns; ++k) {
          h << "<tr><td>#" << k + 1 << "</td>";
          for (size_t v = 0; v < x->readings.size(); ++v)
            h << "<td>" << fmt("%.2f", 1e3 * x->readings[v][c][2 * k + b]) << "</td>";
          h << "</tr>\n";
        }
        h << "</table>\n";
      }
    }
    h << "<h2>Hole signals: amplitude of each variant over full FE (sliding), attribution</h2>\n";
    for (int b = 0; b < 2; ++b) {
      h << "<table "
           "style=\"display:inline-block;vertical-align:top;margin-right:1em\"><tr><th>sensor</th><th>FE "
           "max|"
        << (b ? "ςx" : "ςz") << "| kPa</th>";
      for (size_t v = 1; v < x->signals.size(); ++v) h << "<th>" << x->signal_variants[v].name << "</th>";
      h << "</tr>\n";
      for (int k = 0; k < ns; ++k) {
        h << "<tr><td>#" << k + 1 << "</td><td>"
          << fmt("%.4f", 1e3 * x->signals[0][1].col(2 * k + b).cwiseAbs().maxCoeff()) << "</td>";
        for (size_t v = 1; v < x->signals.size(); ++v)
          h << "<td>" << fmt("%.3g", x->metrics[v][1][k][b].amplitude_ratio) << "</td>";
        h << "</tr>\n";
      }
      h << "</table>\n";
    }
    h << "<p>Variants:</p><ul>\n";
    for (const auto& v : x->signal_variants)
      h << "<li><b>" << v.name << "</b>: " << html_escape(v.what) << "</li>\n";
    h << "</ul><p>Peak shifts and shape errors of every variant, case and sensor: <a "
         "href=\"crosscheck/attribution.csv\">"
         "crosscheck/attribution.csv</a>.</p>\n";
  }
}

void figures(std::ostream& h, const std::string& dir, const Scene& scene, const ReportResult& in) {
  h << "<h2>Figures</h2>\n";
  std::vector<std::string> drawn;  // PNG stems, sorted: the directory's own order is the file system's
  if (std::filesystem::is_directory(dir + "/figures"))
    for (const auto& e : std::filesystem::directory_iterator(dir + "/figures"))
      if (e.path().extension() == ".png") drawn.push_back(e.path().stem().string());
  std::sort(drawn.begin(), drawn.end());
  auto captions = figure_captions(scene.name, in.budget);
  // The pictures of the skin's fields come after the pressure profiles, the budget's summary before its
  // grids.
  const auto after = [&](const std::string& stem) {
    auto it = std::find_if(captions.begin(), captions.end(), [&](const auto& c) { return c.first == stem; });
    return it == captions.end() ? captions.end() : it + 1;
  };
  auto fields = field_captions(scene, in);
  captions.insert(after("pressure_profiles"), fields.begin(), fields.end() - 1);
  const auto grid = std::find_if(captions.begin(), captions.end(),
                                 [](const auto& c) { return c.first.rfind("budget_", 0) == 0; });
  captions.insert(grid, fields.back());
  for (const std::string& stem : drawn)
    if (std::none_of(captions.begin(), captions.end(), [&](const auto& c) { return c.first == stem; }))
      captions.push_back({stem, stem});
  // The per-hypothesis budget grids come last, folded: the budget's summary figure stands for them.
  const auto is_grid = [](const std::string& stem) {
    return stem.rfind("budget_", 0) == 0 && stem != "budget_summary";
  };
  int number = 0, grids = 0;
  std::ostringstream folded;
  for (const bool grid : {false, true})
    for (const auto& [stem, caption] : captions)
      if (is_grid(stem) == grid && std::binary_search(drawn.begin(), drawn.end(), stem)) {
        const std::string file = "figures/" + stem + ".png";
        std::ostream& out = grid ? static_cast<std::ostream&>(folded) : h;
        out << "<figure id=\"" << stem << "\"><a href=\"" << file << "\"><img src=\"" << file << "\" alt=\""
            << html_escape(stem) << "\"></a><figcaption>Figure " << ++number << " (" << stem
            << ".png, click for full size). " << html_escape(caption) << "</figcaption></figure>\n";
        grids += grid;
      }
  if (grids > 0)
    h << "<details><summary>The hole budget hypothesis by hypothesis: " << grids
      << " figures of full FE against the paper's model per sensor (open)</summary>\n"
      << folded.str() << "</details>\n";
}

// A contents list of the page's sections: every <h2> gets an id, and the list goes before the first.
std::string with_contents(const std::string& page) {
  std::string out, nav = "<nav><b>Contents</b><ol>\n";
  std::size_t pos = 0, first = std::string::npos;
  for (int n = 1;; ++n) {
    const std::size_t a = page.find("<h2>", pos);
    const std::size_t b = a == std::string::npos ? a : page.find("</h2>", a);
    if (b == std::string::npos) break;
    const std::string title = page.substr(a + 4, b - a - 4), id = "section-" + std::to_string(n);
    out += page.substr(pos, a - pos);
    if (first == std::string::npos) first = out.size();
    out += "<h2 id=\"" + id + "\">" + title + "</h2>";
    nav += "<li><a href=\"#" + id + "\">" + title + "</a></li>\n";
    pos = b + 5;
  }
  out += page.substr(pos);
  if (first != std::string::npos) out.insert(first, nav + "</ol></nav>\n");
  return out;
}

// report.json's perception entry as paragraphs and a table: the row, the pairs, the detection map and the
// inversion example (pipeline/report_perception.hpp).
void perception(std::ostream& h, const ReportResult& in) {
  if (!in.json.contains("perception")) return;
  const nlohmann::json& p = in.json.at("perception");
  h << "<h2>Perception: a textured plate, superposition, detection, inversion</h2>\n";
  if (p.contains("skipped")) {
    h << "<p>Not computed for this scene: " << html_escape(p.at("skipped").get<std::string>()) << ".</p>\n";
    return;
  }
  const auto pct = [](double v) { return fmt("%.2g %%", 100 * v); };
  const auto mm = [](const nlohmann::json& b) {
    if (b.is_null()) return std::string("no single value (the ladder's SNR is not monotone)");
    if (b.contains("mm")) return fmt("%.3g mm", b.at("mm").get<double>());
    if (b.contains("above_mm")) return "above " + fmt("%.3g mm", b.at("above_mm").get<double>());
    return "below " + fmt("%.3g mm", b.at("below_mm").get<double>());
  };
  const nlohmann::json& row = p.at("row");
  const double D = p.at("hole_diameter_mm").get<double>();
  h << "<p>A row of " << row.at("holes_mm").size() << " holes of " << fmt("%.3g", D) << " mm at a "
    << fmt("%.4g", row.at("period_mm").get<double>()) << " mm period, scanned sliding over "
    << row.at("positions").get<int>() << " positions until each has crossed the contact: the full contact "
    << "differs from the sum of the holes' single-hole signals (the paper's linear prediction) by at most "
    << pct(row.at("superposition_rel_diff_z").get<double>()) << " (ςz) and "
    << pct(row.at("superposition_rel_diff_x").get<double>()) << " (ςx) of the largest signal. Its curves "
    << "wiggle: the holes are resolved, and the rim's pressure concentration falls between the track's nodes "
    << "(mesh " << fmt("%.3g", row.at("track_mesh_h_mm").get<double>()) << " mm; a single hole's ςz changes "
    << "its slope by up to " << pct(row.at("single_hole_second_difference_rel").get<double>())
    << " of its peak from one step to the next); both sides of the comparison carry the wiggles.";
  // The smallest spacing from which every larger one holds within 5 % (the larger of ςz and ςx), per case.
  for (const char* c : {"static", "sliding"}) {
    std::vector<std::pair<double, double>> worst;  // spacing, larger of the two components
    for (const nlohmann::json& q : p.at("pairs"))
      if (q.at("case") == c)
        worst.push_back({q.at("spacing_mm").get<double>(),
                         std::max(q.at("rel_diff_z").get<double>(), q.at("rel_diff_x").get<double>())});
    if (worst.empty()) continue;
    std::sort(worst.begin(), worst.end());
    size_t from = worst.size();
    while (from > 0 && worst[from - 1].second <= 0.05) --from;
    const auto at = [&](size_t i) {
      return pct(worst[i].second) + " at " + fmt("%.4g", worst[i].first) + " mm (" +
             fmt("%.2g", worst[i].first / D) + " diameters)";
    };
    h << " Two holes, " << c << ": ";
    if (from == worst.size())
      h << "superposition misses 5 % at every spacing computed, " << at(0) << " to " << at(worst.size() - 1)
        << ".";
    else if (from == 0)
      h << "within 5 % at every spacing computed, " << at(0) << " to " << at(worst.size() - 1) << ".";
    else
      h << "within 5 % from " << fmt("%.4g", worst[from].first) << " mm on, " << at(0) << ".";
  }
  h << "</p>\n";
  const nlohmann::json& det = p.at("detection");
  const nlohmann::json& noise = det.at("noise");
  h << "<p>Detection of a hole at a known place (the matched filter) under the paper's noise, "
    << fmt("%g", noise.at("sigma_z_kPa").get<double>()) << " kPa on ςz and "
    << fmt("%g", noise.at("sigma_x_kPa").get<double>()) << " kPa on ςx per sample and passage, samples "
    << fmt("%.3g", noise.at("sample_mm").get<double>()) << " mm apart, at a false-alarm rate of "
    << pct(det.at("p_fa").get<double>()) << " and a detection rate of " << pct(det.at("p_d").get<double>())
    << " (required SNR " << fmt("%.3f", det.at("required_snr").get<double>())
    << "): the smallest hole detected, the bulge's ladder from " << fmt("%.3g", D) << " mm down to an eighth "
    << "of it.</p>\n<table><tr><th>case</th><th>passages N</th><th>every sensor</th><th>the best sensor "
       "alone</th></tr>\n";
  for (const nlohmann::json& d : p.at("detection_map"))
    h << "<tr><td>" << d.at("case").get<std::string>() << "</td><td>" << d.at("passages").get<int>()
      << "</td><td>" << mm(d.at("smallest_detected_array")) << "</td><td>"
      << mm(d.at("smallest_detected_best_sensor")) << "</td></tr>\n";
  h << "</table>\n";
  for (const char* c : {"static", "sliding"})
    if (det.at("cases").contains(c)) {
      const nlohmann::json& m = det.at("cases").at(c).at("monte_carlo");
      h << "<p>Monte Carlo check, " << c << " (" << m.at("trials").get<int>()
        << " draws at the threshold hole): "
        << "false alarms " << fmt("%.4f", m.at("false_alarm").get<double>()) << " ± "
        << fmt("%.4f", m.at("false_alarm_sigma").get<double>()) << ", detections "
        << fmt("%.3f", m.at("detection").get<double>()) << " ± "
        << fmt("%.3f", m.at("detection_sigma").get<double>()) << ".</p>\n";
    }
  if (p.contains("inversion")) {
    const nlohmann::json& inv = p.at("inversion");
    const nlohmann::json& ms = inv.at("multi_sensor");
    int false_lo = 1 << 30, false_hi = 0, missed_lo = 1 << 30, missed_hi = 0;
    for (const nlohmann::json& n : inv.at("naive_single_sensor")) {
      false_lo = std::min(false_lo, n.at("false_features").get<int>());
      false_hi = std::max(false_hi, n.at("false_features").get<int>());
      missed_lo = std::min(missed_lo, n.at("missed").get<int>());
      missed_hi = std::max(missed_hi, n.at("missed").get<int>());
    }
    const auto range = [](int a, int b) {
      return a == b ? std::to_string(a) : std::to_string(a) + "–" + std::to_string(b);
    };
    h << "<p>Inversion: the row's sliding signals with that noise (N = 14, one seeded draw) against a "
         "dictionary "
      << "of the hole's responses on its own mesh (" << inv.at("dictionary").at("virtual_sensors").get<int>()
      << " virtual sensors, " << inv.at("dictionary").at("dofs").get<int>()
      << " DOFs). Every sensor together, "
      << "the contact's offset fitted (" << fmt("%.2g", inv.at("contact_offset_mm").get<double>())
      << " mm): " << ms.at("found").get<int>() << " of " << row.at("holes_mm").size() << " holes found, rms "
      << "position error " << fmt("%.2g", ms.at("rms_error_mm").get<double>()) << " mm (largest "
      << fmt("%.2g", ms.at("largest_error_mm").get<double>()) << " mm), "
      << ms.at("false_features").get<int>()
      << " false features. Each sensor alone (the paper's naive inversion): " << range(missed_lo, missed_hi)
      << " missed and " << range(false_lo, false_hi)
      << " false features per sensor. A feature counts for the "
      << "nearest hole within half the period; a second one for the same hole, or one near none, is "
         "false.</p>\n";
  }
  const nlohmann::json& w = p.at("wall_s");
  double scans = 0;
  for (const char* k : {"perception_row", "perception_pairs", "perception_detection"})
    if (w.contains(k)) scans += w.at(k).get<double>();
  h << "<p>Cost: " << fmt("%.1f", scans) << " s for the scans and the ladder on the chain's factorization";
  if (w.contains("perception_inversion"))
    h << ", " << fmt("%.1f", w.at("perception_inversion").get<double>())
      << " s for the inversion with its dictionary";
  h << ". Files: <a href=\"perception/summary.json\">perception/summary.json</a> and its CSVs.</p>\n";
}

// Every file a report writes but its figures and the defect frames, in the page's order.
constexpr const char* kReportFiles[] = {"mesh/mesh.vtu",
                                        "mesh/boundary.vtu",
                                        "mesh/summary.json",
                                        "green/green_maps.vtp",
                                        "green/green.csv",
                                        "green/summary.json",
                                        "kfit/kfit.json",
                                        "kfit/k_sweep.csv",
                                        "contact/pressure.vtp",
                                        "contact/fields.vtu",
                                        "contact/modes.csv",
                                        "contact/sensors.csv",
                                        "contact/summary.json",
                                        "contact/finite_path.csv",
                                        "defect/defect.pvd",
                                        "green/post_design.csv",
                                        "defect/defect.csv",
                                        "defect/summary.json",
                                        "crosscheck/readings.csv",
                                        "crosscheck/defect.csv",
                                        "crosscheck/pressure.csv",
                                        "crosscheck/attribution.csv",
                                        "crosscheck/hole_budget.csv",
                                        "crosscheck/hole_budget_signals.csv",
                                        "crosscheck/hole_budget_facts.csv",
                                        "perception/row.csv",
                                        "perception/pairs.csv",
                                        "perception/detection.csv",
                                        "perception/detection_map.csv",
                                        "perception/features.csv",
                                        "perception/summary.json",
                                        "study/chain_study.csv",
                                        "study/chain_study.json",
                                        "report.json"};

void files(std::ostream& h, const std::string& dir) {
  h << "<h2>Files</h2><ul>\n";
  for (const char* f : kReportFiles)
    if (std::filesystem::exists(dir + "/" + f)) h << "<li><a href=\"" << f << "\">" << f << "</a></li>\n";
  h << "</ul></body></html>\n";
}

}  // namespace

void remove_earlier_report(const std::string& dir) {
  namespace fs = std::filesystem;
  for (const char* f : kReportFiles) fs::remove(dir + "/" + f);
  fs::remove(dir + "/index.html");
  fs::remove_all(dir + "/defect/frames");
  std::vector<fs::path> figures;
  if (fs::is_directory(dir + "/figures"))
    for (const auto& e : fs::directory_iterator(dir + "/figures"))
      if (e.path().extension() == ".png") figures.push_back(e.path());
  for (const fs::path& f : figures) fs::remove(f);
  std::error_code not_empty;  // a folder holding anything else stays
  for (const char* sub :
       {"mesh", "green", "kfit", "contact", "defect", "crosscheck", "perception", "study", "figures"})
    fs::remove(dir + "/" + sub, not_empty);
}

// "value +- error" (the terminal's ASCII).
std::string with_error(double value, double error) {
  const auto [v, e] = rounded_to_error(value, error);
  return e.empty() ? v : v + " +- " + e;
}

void write_index(const std::string& dir, const Scene& scene, const ReportResult& in) {
  std::ostringstream h;
  page_head(h, scene, in);
  headline_numbers(h, in);
  error_levels(h, in);
  stage_times_and_k(h, in);
  post_design(h, in);
  front_sensors(h, in);
  hole_budget(h, scene, in);
  finite_deformation(h, in);
  crosscheck(h, scene, in);
  perception(h, in);
  figures(h, dir, scene, in);
  files(h, dir);
  write_text_atomic(dir + "/index.html", with_contents(h.str()));
}

}  // namespace skinfem::app
