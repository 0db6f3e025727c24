// The hole-signal budget of `report` (validation/hole_budget.hpp): every friction hypothesis swept on the
// report's condensed skin, its FE/model amplitude ratios and the paper's facts F1–F5 judged from them.
// Writes DIR/hole_budget.csv (hypothesis,case,sensor,component,fe_peak_kPa,model_peak_kPa,ratio) and
// DIR/hole_budget_signals.csv (hypothesis,case,u_mm,sensor,varsigma_z_kPa,varsigma_x_kPa); returns the
// report.json entry `hole_budget`.
#include <sstream>

#include "app/common.hpp"
#include "app/stages.hpp"
#include "validation/hole_budget.hpp"

namespace skinfem::app {

nlohmann::json hole_budget_stage(const Scene& scene, const ContactSetup& setup,
                                 const validation::Crosscheck& x, const std::string& out_dir) {
  int model = -1;
  for (size_t v = 0; v < x.signal_variants.size(); ++v)
    if (x.signal_variants[v].name == "paper_model") model = static_cast<int>(v);
  if (model < 0)
    return {{"skipped",
             "the paper's model needs a sphere-on-flat equivalent of the contact, and this scene "
             "has none (equivalent_sphere_radius)"}};
  validation::FactsInput base;
  base.u = x.u;
  base.model = x.signals[model];
  base.sensors = scene.sensors;
  base.center = contact_center(scene);
  base.direction = scene.contact->direction;
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
                  {"antisymmetric_lobe", base.rules.antisym},
                  {"comparable_maximum", base.rules.comparable},
                  {"dip", base.rules.dip}};
  std::ostringstream csv, signals;
  csv.precision(8);
  signals.precision(8);
  csv << "hypothesis,case,sensor,component,fe_peak_kPa,model_peak_kPa,ratio\n";
  signals << "hypothesis,case,u_mm,sensor,varsigma_z_kPa,varsigma_x_kPa\n";
  const char* cases[2] = {"static", "sliding"};
  std::string best;
  int best_met = -1;
  // The mean pressure of the hard frictionless contact sets each rough interface's stiffness.
  ContactLoad hard = *scene.contact;
  hard.interface = {};
  const contact::ContactResult r0 =
      contact::ContactSolver(*setup.condensed, hard, setup.mirror.get()).solve(FrictionMode::none);
  double area = 0;
  for (int i : r0.active) area += setup.solver->zone().area[i];
  const double p_mean = r0.force_N / area;
  out["mean_pressure_kPa"] = 1e3 * p_mean;
  std::vector<validation::Hypothesis> hypotheses = validation::friction_hypotheses(*scene.contact);
  for (auto& h : validation::interface_hypotheses(*scene.contact, p_mean)) hypotheses.push_back(std::move(h));
  for (const validation::Hypothesis& h : hypotheses) {
    progress("hole budget: " + h.name);
    validation::HypothesisResult r;
    try {
      r = validation::run_hypothesis(h, *setup.condensed, setup.mirror.get(), setup.mesh(), *setup.top,
                                     *scene.contact->sweep, base);
    } catch (const std::runtime_error& e) {
      out["skipped"].push_back({{"name", h.name}, {"what", h.what}, {"why", e.what()}});
      continue;
    }
    nlohmann::json j = {
        {"name", h.name},
        {"what", h.what},
        {"tau0_kPa", 1e3 * r.tau0_MPa},
        {"interface_K_MPa_per_mm", h.load.interface.law == InterfaceLaw::linear ? h.load.interface.K : 0.0},
        {"contact_radius_mm", r.contact_radius_mm},
        {"tangential_force_N", r.tangential_force_N},
        {"seconds", r.seconds}};
    int met = 0;
    for (const auto& f : r.facts) {
      j["facts"][f.fact] = {{"met", f.met}, {"why", f.why}};
      met += f.met;
    }
    for (int c = 0; c < 2; ++c)
      for (int k = 0; k < ns; ++k)
        for (int b = 0; b < 2; ++b) {
          const double fe = r.signals[c].col(2 * k + b).cwiseAbs().maxCoeff(),
                       m = base.model[c].col(2 * k + b).cwiseAbs().maxCoeff();
          j["amplitude_ratio"][cases[c]][b ? "x" : "z"].push_back(r.ratio[c][k][b]);
          j["fe_peak_kPa"][cases[c]][b ? "x" : "z"].push_back(1e3 * fe);
          csv << h.name << "," << cases[c] << "," << k + 1 << "," << (b ? "x" : "z") << "," << 1e3 * fe << ","
              << 1e3 * m << "," << r.ratio[c][k][b] << "\n";
        }
    for (int c = 0; c < 2; ++c)
      for (int i = 0; i < r.signals[c].rows(); ++i)
        for (int k = 0; k < ns; ++k)
          signals << h.name << "," << cases[c] << "," << x.u[i] << "," << k + 1 << ","
                  << 1e3 * r.signals[c](i, 2 * k) << "," << 1e3 * r.signals[c](i, 2 * k + 1) << "\n";
    j["facts_met"] = met;
    double rough = 0;
    for (int col = 0; col < 2 * ns; ++col)
      rough = std::max(rough, validation::roughness(r.signals[1].col(col)));
    j["sliding_roughness"] = rough;
    out["hypotheses"].push_back(j);
    if (met > best_met) best_met = met, best = h.name;
  }
  // The answer, from the verdicts.
  if (!out.contains("hypotheses")) {
    out["answer"] = "Every hypothesis was skipped: " + out["skipped"][0]["why"].get<std::string>();
    return out;
  }
  std::string answer = "Of " + std::to_string(out["hypotheses"].size()) + " hypotheses, " + best +
                       " meets the most of the paper's facts (" + std::to_string(best_met) + " of 5";
  std::string failed;
  for (const auto& [fact, v] : out["hypotheses"][0]["facts"].items()) {
    bool any = false;
    for (const auto& h : out["hypotheses"]) any = any || h["facts"][fact]["met"].get<bool>();
    if (!any) failed += (failed.empty() ? "" : ", ") + fact;
  }
  answer += failed.empty() ? "); every fact is met by at least one." : "); none meets " + failed + ".";
  if (out.contains("skipped"))
    answer += " Skipped: " + std::to_string(out["skipped"].size()) + " (report.json).";
  out["answer"] = answer;
  write_text_atomic(out_dir + "/hole_budget.csv", csv.str());
  write_text_atomic(out_dir + "/hole_budget_signals.csv", signals.str());
  return out;
}

}  // namespace skinfem::app
