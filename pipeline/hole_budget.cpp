#include "skinfem/pipeline/hole_budget.hpp"

#include <algorithm>
#include <optional>

#include "skinfem/pipeline/clock.hpp"
#include "skinfem/pipeline/progress.hpp"
#include "skinfem/scene/laws.hpp"
#include "skinfem/scene/parallel.hpp"
#include "skinfem/validation/text.hpp"

namespace skinfem::pipeline {

namespace {

// Appends a hypothesis's result with its count of facts met and its sliding roughness.
void add_result(HoleBudget& b, validation::HypothesisResult r, int sensors) {
  int met = 0;
  for (const auto& f : r.facts) met += f.met;
  double rough = 0;
  for (int col = 0; col < 2 * sensors; ++col)
    rough = std::max(rough, validation::roughness(r.signals[1].col(col)));
  b.results.push_back(std::move(r));
  b.facts_met.push_back(met);
  b.sliding_roughness.push_back(rough);
}

// The answer, from the verdicts: the hypothesis meeting the most facts (the first listed of equals) and the
// facts none meets.
void say_answer(HoleBudget& b) {
  if (b.results.empty()) {
    b.answer = "Every hypothesis was skipped: " + b.skipped.at(0).why;
    return;
  }
  int best_met = -1;
  std::string best;
  for (size_t i = 0; i < b.results.size(); ++i)
    if (b.facts_met[i] > best_met) best_met = b.facts_met[i], best = b.results[i].hypothesis.name;
  std::string answer = "Of " + std::to_string(b.results.size()) + " hypotheses, " + best +
                       " meets the most of the paper's facts (" + std::to_string(best_met) + " of 5";
  std::vector<std::string> facts;
  for (const auto& f : b.results[0].facts) facts.push_back(f.fact);
  std::sort(facts.begin(), facts.end());  // F1 … F5
  std::string failed;
  for (const std::string& fact : facts) {
    bool any = false;
    for (const auto& r : b.results)
      for (const auto& f : r.facts) any = any || (f.fact == fact && f.met);
    if (!any) failed += (failed.empty() ? "" : ", ") + fact;
  }
  answer += failed.empty() ? "); every fact is met by at least one." : "); none meets " + failed + ".";
  if (!b.skipped.empty()) answer += " Skipped: " + std::to_string(b.skipped.size()) + " (report.json).";
  b.answer = answer;
}

}  // namespace

HoleBudget hole_budget(const Scene& scene, const ContactSetup& setup, const validation::Crosscheck& x,
                       const Eigen::VectorXd& reading_scale) {
  HoleBudget out;
  Stopwatch clock;
  int model = -1;
  for (size_t v = 0; v < x.signal_variants.size(); ++v)
    if (x.signal_variants[v].name == "paper_model") model = static_cast<int>(v);
  if (model < 0) {
    out.unavailable =
        "the paper's model needs a sphere-on-flat equivalent of the contact, and this scene has none "
        "(equivalent_sphere_radius)";
    return out;
  }
  validation::FactsInput& base = out.base;
  base.u = x.u;
  base.model = x.signals[model];
  base.sensors = scene.sensors;
  base.center = contact_center(scene);
  base.direction = scene.contact->direction;
  base.reading_scale = reading_scale;
  const int ns = static_cast<int>(scene.sensors.positions.size());
  // The mean pressure of the hard frictionless contact sets each rough interface's stiffness.
  ContactLoad hard = *scene.contact;
  hard.interface = {};
  const contact::ContactResult r0 =
      contact::ContactSolver(*setup.condensed, hard, setup.mirror.get()).solve(FrictionMode::none);
  double area = 0;
  for (int i : r0.active) area += setup.solver->zone().area[i];
  out.mean_pressure_MPa = r0.force_N / area;
  std::vector<validation::Hypothesis> hypotheses = validation::friction_hypotheses(*scene.contact);
  for (auto& h : validation::interface_hypotheses(*scene.contact, out.mean_pressure_MPa))
    hypotheses.push_back(std::move(h));
  // The interface hypotheses sweep resolved holes over the same positions: one set of cut problems for
  // all of them and both modes, where it fits in kMaxSharedCutsMb (the default scene's 201 take 80 MB).
  constexpr double kMaxSharedCutsMb = 256;
  std::optional<contact::HoleCuts> cuts;
  if (setup.condensed->path) {
    progress("hole budget: the resolved hole's cut problems");
    cuts = contact::hole_cuts(*setup.condensed, *scene.contact->sweep, kMaxSharedCutsMb);
  }
  // The hypotheses share only read-only data (the condensed skin, its cut problems): one per thread, each in
  // its own slot, kept in the listed order.
  std::vector<std::optional<validation::HypothesisResult>> runs(hypotheses.size());
  std::vector<std::string> why(hypotheses.size());
  for_each_index(
      hypotheses.size(),
      [&](std::size_t i) {
        try {
          runs[i] = validation::run_hypothesis(hypotheses[i], *setup.condensed, setup.mirror.get(),
                                               setup.mesh(), *setup.top, *scene.contact->sweep,
                                               scene.material, base, cuts ? &*cuts : nullptr);
        } catch (const std::runtime_error& e) {
          why[i] = e.what();
        }
      },
      true,
      [&](std::size_t done) {
        progress_step("hole budget: hypotheses", static_cast<int>(done), static_cast<int>(hypotheses.size()),
                      clock.seconds());
      });
  for (size_t i = 0; i < hypotheses.size(); ++i) {
    if (!runs[i]) {
      out.skipped.push_back({hypotheses[i], why[i]});
      continue;
    }
    add_result(out, std::move(*runs[i]), ns);
  }
  say_answer(out);
  return out;
}

void add_finite_row(HoleBudget& b, const Scene& scene, const FiniteDefectRun& run) {
  if (!b.unavailable.empty()) return;
  if (run.cases.size() != 2 || run.cases[0].mode != FrictionMode::static_residual ||
      run.cases[1].mode != FrictionMode::coupled)
    throw std::invalid_argument("add_finite_row: the run's cases are static_residual, then coupled");
  const ContactLoad& load = *scene.contact;
  const std::string mu = validation::fmt("%g", load.mu);
  std::string law;
  switch (load.law) {
    case FrictionLaw::coulomb:
      law = "Coulomb friction (mu = " + mu + ")";
      break;
    case FrictionLaw::shear_strength:
      law = "a shear strength tau0 = " + (load.tau0 ? validation::fmt("%g MPa", *load.tau0) : "mu F / A") +
            " (mu = " + mu + ") where the skin touches";
      break;
    case FrictionLaw::mixed:
      law = "Coulomb friction (mu = " + mu + ") with a shear strength";
      break;
  }
  validation::HypothesisResult r;
  r.hypothesis = {std::string(to_string(load.law)) + "_finite",
                  law +
                      " on the neo-Hookean skin in finite strain: the plate meets the deformed surface, the "
                      "hole acts on the material under it, its signal the tangent's answer",
                  load};
  r.tau0_MPa = run.cases[1].state.tau0_MPa;
  for (int c = 0; c < 2; ++c) {
    r.signals[c] = run.cases[c].sweep.varsigma;
    r.seconds += run.cases[c].sweep.seconds + run.cases[c].tangent_seconds + run.cases[c].state.wall.total();
  }
  r.contact_radius_mm = run.cases[1].metrics.contact_radius_mm;
  r.tangential_force_N = run.cases[1].state.tangential_force_N;
  validation::judge_hypothesis(r, b.base);
  add_result(b, std::move(r), static_cast<int>(scene.sensors.positions.size()));
  say_answer(b);
}

nlohmann::json hole_budget_json(const Scene& scene, const HoleBudget& b) {
  if (!b.unavailable.empty()) return {{"skipped", b.unavailable}};
  const validation::FactsInput& base = b.base;
  const int ns = static_cast<int>(scene.sensors.positions.size());
  nlohmann::json out;
  out["noise"] = {{"sigma_z_kPa", 1e3 * base.noise.sigma_z_MPa},
                  {"sigma_x_kPa", 1e3 * base.noise.sigma_x_MPa},
                  {"passages", base.noise.passages},
                  {"k_sigma", base.noise.k},
                  {"threshold_z_kPa", 1e3 * base.noise.threshold(0)},
                  {"threshold_x_kPa", 1e3 * base.noise.threshold(1)}};
  out["rules"] = {{"match_band", {base.rules.match_lo, base.rules.match_hi}},
                  {"front_min_ratio", base.rules.front_min},
                  {"front_over_back_ratio", base.rules.front_over_back},
                  {"antisymmetric_lobe", base.rules.antisym},
                  {"comparable_maximum", base.rules.comparable},
                  {"dip", base.rules.dip}};
  out["mean_pressure_kPa"] = 1e3 * b.mean_pressure_MPa;
  if (base.reading_scale.size()) {
    out["units"] =
        "the paper's: each sensor's FE reading over its calibration scale (kfit.json, paper_calibration)";
    for (int k = 0; k < ns; ++k)
      out["reading_scale"].push_back({base.reading_scale[2 * k], base.reading_scale[2 * k + 1]});
  } else {
    out["units"] = "the sensors' own readings";
  }
  const char* cases[2] = {"static", "sliding"};
  for (size_t i = 0; i < b.results.size(); ++i) {
    const validation::HypothesisResult& r = b.results[i];
    const validation::Hypothesis& h = r.hypothesis;
    nlohmann::json j = {
        {"name", h.name},
        {"what", h.what},
        {"tau0_kPa", 1e3 * r.tau0_MPa},
        {"interface_K_MPa_per_mm", h.load.interface.law == InterfaceLaw::linear ? h.load.interface.K : 0.0},
        {"contact_radius_mm", r.contact_radius_mm},
        {"tangential_force_N", r.tangential_force_N},
        {"seconds", r.seconds}};
    for (const auto& f : r.facts) j["facts"][f.fact] = {{"met", f.met}, {"why", f.why}};
    for (int c = 0; c < 2; ++c)
      for (int k = 0; k < ns; ++k)
        for (int d = 0; d < 2; ++d) {
          j["amplitude_ratio"][cases[c]][d ? "x" : "z"].push_back(r.ratio[c][k][d]);
          j["fe_peak_kPa"][cases[c]][d ? "x" : "z"].push_back(
              1e3 * r.signals[c].col(2 * k + d).cwiseAbs().maxCoeff());
        }
    j["facts_met"] = b.facts_met[i];
    j["sliding_roughness"] = b.sliding_roughness[i];
    out["hypotheses"].push_back(j);
  }
  for (const auto& s : b.skipped)
    out["skipped"].push_back({{"name", s.hypothesis.name}, {"what", s.hypothesis.what}, {"why", s.why}});
  out["answer"] = b.answer;
  return out;
}

}  // namespace skinfem::pipeline
