// The hole-signal budget of `report` (pipeline/hole_budget.hpp) on a coarse sphere pressed into a bonded flat
// layer with a short sweep. References: a second path to the mean pressure of the hard frictionless contact
// (its force over the contact's area, from contact/metrics.hpp's equivalent radius: F/(π a_eq²), no holes);
// the hypotheses the budget must run (validation/hole_budget.hpp's friction and interface lists, named from
// the scene's load and that pressure); each result's facts met and sliding roughness recounted here from its
// own verdicts and signals; the answer naming the first hypothesis that meets the most facts; the JSON
// against the typed budget (kPa = 1e3 MPa); and a scene whose contact has no sphere-on-flat equivalent
// (a plane on a flat layer) skipped with the reason.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "scenes.hpp"
#include "skinfem/contact/metrics.hpp"
#include "skinfem/pipeline/crosscheck.hpp"
#include "skinfem/pipeline/hole_budget.hpp"
#include "skinfem/validation/hole_budget.hpp"

namespace skinfem::pipeline {
namespace {

constexpr double kRoundOff = 1e-12;  // relative: the same sums in another order
constexpr int kPositions = 5;

bool has(const std::string& text, const std::string& what) { return text.find(what) != std::string::npos; }

class HoleBudgetStage : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    scene_ = new Scene(testing::swept_layer("budget_layer", kPositions));
    ContactSkin skin = chain_skin(*scene_, HolePath::always);  // the report's: interface hypotheses cut holes
    adjoints_ = adjoint_setup(*scene_, skin.skin).release();
    contact_ = std::shared_ptr<const ContactSetup>(contact_setup(*scene_, std::move(skin)));
    defect_ = new DefectRun(defect_run(*scene_, contact_, {}, DefectFrames::every));
    x_ = new validation::Crosscheck(crosscheck_run(*scene_, *adjoints_, *contact_, *defect_, 0.3, 1.5));
    budget_ = new HoleBudget(hole_budget(*scene_, *contact_, *x_));
  }
  static void TearDownTestSuite() {
    delete budget_;
    delete x_;
    delete defect_;
    contact_.reset();
    delete adjoints_;
    delete scene_;
  }
  static Scene* scene_;
  static AdjointSetup* adjoints_;
  static std::shared_ptr<const ContactSetup> contact_;
  static DefectRun* defect_;
  static validation::Crosscheck* x_;
  static HoleBudget* budget_;
};
Scene* HoleBudgetStage::scene_ = nullptr;
AdjointSetup* HoleBudgetStage::adjoints_ = nullptr;
std::shared_ptr<const ContactSetup> HoleBudgetStage::contact_;
DefectRun* HoleBudgetStage::defect_ = nullptr;
validation::Crosscheck* HoleBudgetStage::x_ = nullptr;
HoleBudget* HoleBudgetStage::budget_ = nullptr;

TEST_F(HoleBudgetStage, TheMeanPressureIsTheForceOverTheContactsArea) {
  const HoleBudget& b = *budget_;
  ASSERT_EQ(b.unavailable, "");
  const contact::ContactResult r = contact_->solver->solve(FrictionMode::none);
  const contact::ContactMetrics m = contact::contact_metrics(*contact_->solver, contact_->mesh(),
                                                             *contact_->top, r, contact_center(*scene_));
  const double a = m.equivalent_radius_mm;
  EXPECT_NEAR(b.mean_pressure_MPa, r.force_N / (M_PI * a * a), 1e-9 * b.mean_pressure_MPa);
  EXPECT_NEAR(r.force_N, 0.3, 1e-9);
}

TEST_F(HoleBudgetStage, EveryHypothesisIsRunOrSkippedWithItsReason) {
  const HoleBudget& b = *budget_;
  std::vector<validation::Hypothesis> expected = validation::friction_hypotheses(*scene_->contact);
  for (auto& h : validation::interface_hypotheses(*scene_->contact, b.mean_pressure_MPa))
    expected.push_back(h);
  ASSERT_EQ(b.results.size() + b.skipped.size(), expected.size());
  size_t r = 0, s = 0;
  for (const validation::Hypothesis& h : expected) {  // in the listed order, each either run or skipped
    if (r < b.results.size() && b.results[r].hypothesis.name == h.name) {
      ++r;
    } else {
      ASSERT_LT(s, b.skipped.size()) << h.name;
      EXPECT_EQ(b.skipped[s].hypothesis.name, h.name);
      EXPECT_FALSE(b.skipped[s].why.empty());
      ++s;
    }
  }
  EXPECT_GT(b.results.size(), 0u);
  ASSERT_EQ(b.facts_met.size(), b.results.size());
  ASSERT_EQ(b.sliding_roughness.size(), b.results.size());
  int best = -1;
  std::string best_name;
  for (size_t i = 0; i < b.results.size(); ++i) {
    const validation::HypothesisResult& h = b.results[i];
    int met = 0;
    for (const auto& f : h.facts) met += f.met;
    EXPECT_EQ(b.facts_met[i], met) << h.hypothesis.name;
    double rough = 0;
    for (int col = 0; col < h.signals[1].cols(); ++col)
      rough = std::max(rough, validation::roughness(h.signals[1].col(col)));
    EXPECT_EQ(b.sliding_roughness[i], rough) << h.hypothesis.name;
    ASSERT_EQ(h.signals[1].rows(), kPositions);
    if (met > best) best = met, best_name = h.hypothesis.name;
  }
  EXPECT_TRUE(has(b.answer, "Of " + std::to_string(b.results.size()) + " hypotheses, " + best_name +
                                " meets the most of the paper's facts (" + std::to_string(best) + " of 5"))
      << b.answer;
}

TEST_F(HoleBudgetStage, TheJsonSaysTheTypedBudget) {
  const HoleBudget& b = *budget_;
  const nlohmann::json j = hole_budget_json(*scene_, b);
  EXPECT_NEAR(j.at("mean_pressure_kPa").get<double>(), 1e3 * b.mean_pressure_MPa,
              kRoundOff * 1e3 * b.mean_pressure_MPa);
  EXPECT_EQ(j.at("units"), "the sensors' own readings");  // discs: no calibration scale
  EXPECT_EQ(j.at("answer"), b.answer);
  ASSERT_EQ(j.at("hypotheses").size(), b.results.size());
  for (size_t i = 0; i < b.results.size(); ++i) {
    const nlohmann::json& h = j.at("hypotheses")[i];
    const validation::HypothesisResult& r = b.results[i];
    EXPECT_EQ(h.at("name"), r.hypothesis.name);
    EXPECT_EQ(h.at("facts_met").get<int>(), b.facts_met[i]);
    EXPECT_EQ(h.at("sliding_roughness").get<double>(), b.sliding_roughness[i]);
    for (const auto& f : r.facts) EXPECT_EQ(h.at("facts").at(f.fact).at("met").get<bool>(), f.met);
    // Per case, component and sensor: the FE peak in kPa.
    for (int k = 0; k < 3; ++k) {
      const double peak = r.signals[1].col(2 * k).cwiseAbs().maxCoeff();
      EXPECT_NEAR(h.at("fe_peak_kPa").at("sliding").at("z")[k].get<double>(), 1e3 * peak,
                  kRoundOff * 1e3 * peak);
      EXPECT_EQ(h.at("amplitude_ratio").at("static").at("x")[k].get<double>(), r.ratio[0][k][1]);
    }
  }
  EXPECT_EQ(j.contains("skipped"), !b.skipped.empty());
}

// The finite row is judged as the linear rows are: fed the linear skin's own static and sliding sweeps (the
// scene's Coulomb law, as the "coulomb" row sweeps them), it is that row again, and the answer counts it; a
// run under the shear strength is named after its law.
TEST_F(HoleBudgetStage, AFiniteRowOfTheLinearSweepsIsTheCoulombRow) {
  HoleBudget b = *budget_;
  const auto coulomb = std::find_if(b.results.begin(), b.results.end(),
                                    [](const auto& r) { return r.hypothesis.name == "coulomb"; });
  ASSERT_NE(coulomb, b.results.end());
  const size_t coulomb_row = coulomb - b.results.begin();
  const validation::HypothesisResult linear = *coulomb;
  FiniteDefectRun run;
  for (int c = 0; c < 2; ++c) {
    FiniteDefectCase fc;
    fc.mode = defect_->sweeps[c].mode;
    fc.sweep = defect_->sweeps[c];
    fc.metrics = contact::contact_metrics(*contact_->solver, contact_->mesh(), *contact_->top,
                                          fc.sweep.baseline, contact_center(*scene_));
    fc.state.tangential_force_N = linear.tangential_force_N;
    run.cases.push_back(std::move(fc));
  }
  add_finite_row(b, *scene_, run);
  ASSERT_EQ(b.results.size(), budget_->results.size() + 1);
  const validation::HypothesisResult& finite = b.results.back();
  EXPECT_EQ(finite.hypothesis.name, "coulomb_finite");
  for (int c = 0; c < 2; ++c) {
    EXPECT_EQ(finite.signals[c], linear.signals[c]);
    EXPECT_EQ(finite.ratio[c], linear.ratio[c]);
  }
  EXPECT_EQ(finite.contact_radius_mm, linear.contact_radius_mm);
  ASSERT_EQ(finite.facts.size(), linear.facts.size());
  for (size_t i = 0; i < linear.facts.size(); ++i) {
    EXPECT_EQ(finite.facts[i].met, linear.facts[i].met) << linear.facts[i].fact;
    EXPECT_EQ(finite.facts[i].why, linear.facts[i].why);
  }
  EXPECT_EQ(b.facts_met.back(), b.facts_met[coulomb_row]);
  EXPECT_TRUE(has(b.answer, "Of " + std::to_string(b.results.size()) + " hypotheses")) << b.answer;
  // Its cases must be static, then sliding.
  std::swap(run.cases[0], run.cases[1]);
  EXPECT_THROW(add_finite_row(b, *scene_, run), std::invalid_argument);
  // A run under another law is that law's finite row, with the sliding state's τ0.
  std::swap(run.cases[0], run.cases[1]);
  Scene shear = *scene_;
  shear.contact->law = FrictionLaw::shear_strength;
  run.cases[1].state.tau0_MPa = 0.125;
  add_finite_row(b, shear, run);
  EXPECT_EQ(b.results.back().hypothesis.name, "shear_strength_finite");
  EXPECT_EQ(b.results.back().tau0_MPa, 0.125);
}

TEST_F(HoleBudgetStage, WithoutThePapersModelTheBudgetIsSkippedWithTheReason) {
  validation::Crosscheck without = *x_;  // as a plane on a flat layer leaves it: no paper_model variant
  for (size_t v = 0; v < without.signal_variants.size(); ++v)
    if (without.signal_variants[v].name == "paper_model") without.signal_variants[v].name = "other";
  const HoleBudget b = hole_budget(*scene_, *contact_, without);
  EXPECT_TRUE(has(b.unavailable, "equivalent_sphere_radius")) << b.unavailable;
  EXPECT_TRUE(b.results.empty());
  EXPECT_EQ(hole_budget_json(*scene_, b), (nlohmann::json{{"skipped", b.unavailable}}));
  // And the crosscheck of this scene does have it: the sphere on a flat layer has an equivalent radius.
  EXPECT_TRUE(equivalent_sphere_radius(*scene_).has_value());
  Scene plane = *scene_;
  plane.contact->indenter = IndenterKind::plane;
  EXPECT_FALSE(equivalent_sphere_radius(plane).has_value());
}

}  // namespace
}  // namespace skinfem::pipeline
