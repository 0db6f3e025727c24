// The hole-signal budget of `report` (pipeline/hole_budget.hpp) written out: DIR/hole_budget.csv
// (hypothesis,case,sensor,component,fe_peak_kPa,model_peak_kPa,ratio) and DIR/hole_budget_signals.csv
// (hypothesis,case,u_mm,sensor,varsigma_z_kPa,varsigma_x_kPa); returns the report.json entry `hole_budget`.
#include <sstream>

#include "app/common.hpp"
#include "app/stages.hpp"

namespace skinfem::app {

StageOutput<HoleBudget> hole_budget_stage(const Scene& scene, const ContactSetup& setup,
                                          const validation::Crosscheck& x, const std::string& out_dir,
                                          const Eigen::VectorXd& reading_scale) {
  HoleBudget b = hole_budget(scene, setup, x, reading_scale);
  if (!b.unavailable.empty()) {
    nlohmann::json skipped = {{"skipped", b.unavailable}};
    return {std::move(b), std::move(skipped)};
  }
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
  std::ostringstream csv, signals;
  csv.precision(8);
  signals.precision(8);
  csv << "hypothesis,case,sensor,component,fe_peak_kPa,model_peak_kPa,ratio\n";
  signals << "hypothesis,case,u_mm,sensor,varsigma_z_kPa,varsigma_x_kPa\n";
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
          const double fe = r.signals[c].col(2 * k + d).cwiseAbs().maxCoeff(),
                       m = base.model[c].col(2 * k + d).cwiseAbs().maxCoeff();
          j["amplitude_ratio"][cases[c]][d ? "x" : "z"].push_back(r.ratio[c][k][d]);
          j["fe_peak_kPa"][cases[c]][d ? "x" : "z"].push_back(1e3 * fe);
          csv << h.name << "," << cases[c] << "," << k + 1 << "," << (d ? "x" : "z") << "," << 1e3 * fe << ","
              << 1e3 * m << "," << r.ratio[c][k][d] << "\n";
        }
    for (int c = 0; c < 2; ++c)
      for (int p = 0; p < r.signals[c].rows(); ++p)
        for (int k = 0; k < ns; ++k)
          signals << h.name << "," << cases[c] << "," << x.u[p] << "," << k + 1 << ","
                  << 1e3 * r.signals[c](p, 2 * k) << "," << 1e3 * r.signals[c](p, 2 * k + 1) << "\n";
    j["facts_met"] = b.facts_met[i];
    j["sliding_roughness"] = b.sliding_roughness[i];
    out["hypotheses"].push_back(j);
  }
  for (const auto& s : b.skipped)
    out["skipped"].push_back({{"name", s.hypothesis.name}, {"what", s.hypothesis.what}, {"why", s.why}});
  out["answer"] = b.answer;
  if (!b.results.empty()) {
    write_text_atomic(out_dir + "/hole_budget.csv", csv.str());
    write_text_atomic(out_dir + "/hole_budget_signals.csv", signals.str());
  }
  return {std::move(b), std::move(out)};
}

}  // namespace skinfem::app
