#include "skinfem/pipeline/hole_budget.hpp"

#include <algorithm>
#include <optional>

#include "skinfem/pipeline/clock.hpp"
#include "skinfem/pipeline/progress.hpp"
#include "skinfem/scene/parallel.hpp"

namespace skinfem::pipeline {

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
  int best_met = -1;
  std::string best;
  for (size_t i = 0; i < hypotheses.size(); ++i) {
    if (!runs[i]) {
      out.skipped.push_back({hypotheses[i], why[i]});
      continue;
    }
    out.results.push_back(std::move(*runs[i]));
    const validation::HypothesisResult& r = out.results.back();
    int met = 0;
    for (const auto& f : r.facts) met += f.met;
    double rough = 0;
    for (int col = 0; col < 2 * ns; ++col)
      rough = std::max(rough, validation::roughness(r.signals[1].col(col)));
    out.facts_met.push_back(met);
    out.sliding_roughness.push_back(rough);
    if (met > best_met) best_met = met, best = hypotheses[i].name;
  }
  // The answer, from the verdicts.
  if (out.results.empty()) {
    out.answer = "Every hypothesis was skipped: " + out.skipped.at(0).why;
    return out;
  }
  std::string answer = "Of " + std::to_string(out.results.size()) + " hypotheses, " + best +
                       " meets the most of the paper's facts (" + std::to_string(best_met) + " of 5";
  std::vector<std::string> facts;
  for (const auto& f : out.results[0].facts) facts.push_back(f.fact);
  std::sort(facts.begin(), facts.end());  // F1 … F5
  std::string failed;
  for (const std::string& fact : facts) {
    bool any = false;
    for (const auto& r : out.results)
      for (const auto& f : r.facts) any = any || (f.fact == fact && f.met);
    if (!any) failed += (failed.empty() ? "" : ", ") + fact;
  }
  answer += failed.empty() ? "); every fact is met by at least one." : "); none meets " + failed + ".";
  if (!out.skipped.empty()) answer += " Skipped: " + std::to_string(out.skipped.size()) + " (report.json).";
  out.answer = answer;
  return out;
}

}  // namespace skinfem::pipeline
