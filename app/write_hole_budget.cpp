// The hole-signal budget of `report` (pipeline/hole_budget.hpp) written out: DIR/hole_budget.csv
// (hypothesis,case,sensor,component,fe_peak_kPa,model_peak_kPa,ratio) and DIR/hole_budget_signals.csv
// (hypothesis,case,u_mm,sensor,varsigma_z_kPa,varsigma_x_kPa) and DIR/hole_budget_facts.csv
// (hypothesis,fact,met: the paper's facts F1-F5, met 1 or 0); nothing when no hypothesis ran.
#include <sstream>

#include "app/common.hpp"
#include "app/stages.hpp"

namespace skinfem::app {

void write_hole_budget(const Scene& scene, const HoleBudget& b, const validation::Crosscheck& x,
                       const std::string& out_dir) {
  if (!b.unavailable.empty() || b.results.empty()) return;
  const int ns = static_cast<int>(scene.sensors.positions.size());
  std::ostringstream csv, signals, facts;
  csv.precision(8);
  signals.precision(8);
  csv << "hypothesis,case,sensor,component,fe_peak_kPa,model_peak_kPa,ratio\n";
  signals << "hypothesis,case,u_mm,sensor,varsigma_z_kPa,varsigma_x_kPa\n";
  facts << "hypothesis,fact,met\n";
  const char* cases[2] = {"static", "sliding"};
  for (const validation::HypothesisResult& r : b.results) {
    const std::string& name = r.hypothesis.name;
    for (const validation::FactVerdict& f : r.facts) facts << name << "," << f.fact << "," << f.met << "\n";
    for (int c = 0; c < 2; ++c)
      for (int k = 0; k < ns; ++k)
        for (int d = 0; d < 2; ++d)
          csv << name << "," << cases[c] << "," << k + 1 << "," << (d ? "x" : "z") << ","
              << 1e3 * r.signals[c].col(2 * k + d).cwiseAbs().maxCoeff() << ","
              << 1e3 * b.base.model[c].col(2 * k + d).cwiseAbs().maxCoeff() << "," << r.ratio[c][k][d]
              << "\n";
    for (int c = 0; c < 2; ++c)
      for (int p = 0; p < r.signals[c].rows(); ++p)
        for (int k = 0; k < ns; ++k)
          signals << name << "," << cases[c] << "," << x.u[p] << "," << k + 1 << ","
                  << 1e3 * r.signals[c](p, 2 * k) << "," << 1e3 * r.signals[c](p, 2 * k + 1) << "\n";
  }
  write_text_atomic(out_dir + "/hole_budget.csv", csv.str());
  write_text_atomic(out_dir + "/hole_budget_signals.csv", signals.str());
  write_text_atomic(out_dir + "/hole_budget_facts.csv", facts.str());
}

}  // namespace skinfem::app
