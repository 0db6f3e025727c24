// The hole-signal budget of `report`: every friction and interface hypothesis (validation/hole_budget.hpp)
// swept on the report's condensed skin, its FE / paper-model amplitude ratios, and the paper's facts F1–F5
// judged from them; `answer` says which hypothesis meets the most facts and which facts none meets.
// Units: mm, N, MPa.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "skinfem/pipeline/contact_setup.hpp"
#include "skinfem/pipeline/finite_defect.hpp"
#include "skinfem/validation/crosscheck.hpp"
#include "skinfem/validation/hole_budget.hpp"

namespace skinfem::pipeline {

struct HoleBudget {
  // Non-empty when nothing was run: the crosscheck has no paper_model signals (why).
  std::string unavailable;
  validation::FactsInput base;   // positions, the paper's model signals, noise model and judgement rules
  double mean_pressure_MPa = 0;  // of the hard frictionless contact: sets each rough interface's K
  std::vector<validation::HypothesisResult> results;  // in the order run
  std::vector<int> facts_met;                         // per result
  std::vector<double> sliding_roughness;              // per result: validation::roughness, worst curve
  struct Skipped {
    validation::Hypothesis hypothesis;
    std::string why;
  };
  std::vector<Skipped> skipped;  // hypotheses whose contact outgrew the zone
  std::string answer;
};

// reading_scale: validation::FactsInput's (post sensors: from pipeline::paper_reading_scale).
HoleBudget hole_budget(const Scene& scene, const ContactSetup& setup, const validation::Crosscheck& x,
                       const Eigen::VectorXd& reading_scale = {});
// Adds a finite-kinematics row, named <law>_finite: the scene's friction law on the neo-Hookean skin in
// finite strain, its static and sliding cases (run.cases, in that order) judged against b.base as the linear
// rows are, and says b.answer again over every row.
void add_finite_row(HoleBudget& b, const Scene& scene, const FiniteDefectRun& run);
// report.json's hole_budget entry: noise, rules, units, each hypothesis's facts and peaks, the answer; or
// {"skipped": why}.
nlohmann::json hole_budget_json(const Scene& scene, const HoleBudget& b);

}  // namespace skinfem::pipeline
