// The paper's model against full FE on a run's own set-ups (pipeline/crosscheck.hpp), on a coarse sphere
// pressed into a bonded flat layer with a short hole sweep. References: second paths through the same
// problem — the crosscheck's FE columns must be the contact solver's own solves (readings of the static,
// coupled and uncoupled contacts) and the defect stage's sweeps (ς), and its metrics of FE against itself
// exactly 1 (amplitude), 0 (peak shift) and 0 (shape); the friction ratios as the scene states them; the
// hole positions as the sweep spaces them; the front sensors as validation/crosscheck.hpp defines them
// (ahead of the centre along the sliding direction, the centre's line included), and front_sensor_json
// against the typed answer.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "scenes.hpp"
#include "skinfem/pipeline/crosscheck.hpp"

namespace skinfem::pipeline {
namespace {

// The FE columns and the solver's solves are the same LCPs on the same condensed skin: round-off, amplified
// by the condensed compliance's condition number, below 1e-9 of the largest reading.
constexpr double kRoundOff = 1e-9;
constexpr int kPositions = 5;

int variant(const std::vector<validation::Variant>& v, const std::string& name) {
  for (size_t i = 0; i < v.size(); ++i)
    if (v[i].name == name) return static_cast<int>(i);
  return -1;
}

class Crosscheck : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    scene_ = new Scene(testing::swept_layer("crosscheck_layer", kPositions));
    ContactSkin skin = chain_skin(*scene_);
    adjoints_ = adjoint_setup(*scene_, skin.skin).release();
    contact_ = std::shared_ptr<const ContactSetup>(contact_setup(*scene_, std::move(skin)));
    defect_ = new DefectRun(defect_run(*scene_, contact_, {}, DefectFrames::every));
    x_ = new validation::Crosscheck(crosscheck_run(*scene_, *adjoints_, *contact_, *defect_, 0.3, 1.5));
  }
  static void TearDownTestSuite() {
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
};
Scene* Crosscheck::scene_ = nullptr;
AdjointSetup* Crosscheck::adjoints_ = nullptr;
std::shared_ptr<const ContactSetup> Crosscheck::contact_;
DefectRun* Crosscheck::defect_ = nullptr;
validation::Crosscheck* Crosscheck::x_ = nullptr;

TEST_F(Crosscheck, TheFeReadingsAreTheContactSolversOwn) {
  const validation::Crosscheck& x = *x_;
  const int fe = variant(x.reading_variants, "fe"), un = variant(x.reading_variants, "uncoupled");
  ASSERT_EQ(fe, 0);
  ASSERT_GE(un, 0);
  const contact::ContactSolver& solver = *contact_->solver;
  const Eigen::VectorXd rest = solver.solve(FrictionMode::static_residual).readings;
  const Eigen::VectorXd sliding = solver.solve(FrictionMode::coupled).readings;
  const Eigen::VectorXd uncoupled = solver.solve(FrictionMode::uncoupled).readings;
  const double scale = sliding.cwiseAbs().maxCoeff();
  ASSERT_GT(scale, 0);
  EXPECT_LT((x.readings[fe][validation::Crosscheck::kStatic] - rest).cwiseAbs().maxCoeff(),
            kRoundOff * scale);
  EXPECT_LT((x.readings[fe][validation::Crosscheck::kSliding] - sliding).cwiseAbs().maxCoeff(),
            kRoundOff * scale);
  EXPECT_LT((x.readings[un][validation::Crosscheck::kSliding] - uncoupled).cwiseAbs().maxCoeff(),
            kRoundOff * scale);
  // The ratios as the scene states them (Coulomb: the FE's and the paper's alike).
  EXPECT_NEAR(x.ratio[0], 0.1, 1e-15);
  EXPECT_NEAR(x.ratio[1], 0.5, 1e-15);
  EXPECT_NEAR(x.paper_ratio[0], 0.1, 1e-15);
  EXPECT_NEAR(x.paper_ratio[1], 0.5, 1e-15);
}

TEST_F(Crosscheck, TheFeSignalsAreTheDefectSweepsAndTheirMetricsAgainstThemselvesAreExact) {
  const validation::Crosscheck& x = *x_;
  ASSERT_EQ(variant(x.signal_variants, "fe"), 0);
  for (int c = 0; c < 2; ++c) {
    const Eigen::MatrixXd& fe = x.signals[0][c];
    const Eigen::MatrixXd& sweep = defect_->sweeps[c].varsigma;
    ASSERT_EQ(fe.rows(), sweep.rows());
    ASSERT_EQ(fe.cols(), sweep.cols());
    EXPECT_LT((fe - sweep).cwiseAbs().maxCoeff(), kRoundOff * sweep.cwiseAbs().maxCoeff());
    ASSERT_EQ(x.metrics[0][c].size(), scene_->sensors.positions.size());
    for (const auto& sensor : x.metrics[0][c])
      for (const validation::SignalMetrics& m : sensor) {
        EXPECT_EQ(m.amplitude_ratio, 1);
        EXPECT_EQ(m.peak_shift_mm, 0);
        EXPECT_EQ(m.shape_error, 0);
      }
  }
  // Positions evenly spaced from the sweep's start to its end.
  ASSERT_EQ(x.u.size(), static_cast<size_t>(kPositions));
  for (int i = 0; i < kPositions; ++i) EXPECT_NEAR(x.u[i], -1.5 + 3.0 * i / (kPositions - 1), 1e-12);
  // Every variant against FE: as many metrics as signals.
  EXPECT_EQ(x.metrics.size(), x.signal_variants.size());
  EXPECT_EQ(x.signals.size(), x.signal_variants.size());
}

TEST_F(Crosscheck, TheFrontSensorsAreAheadOfTheCentreAndTheJsonSaysTheAnswer) {
  // Sliding along +x from the origin: sensors at x = 0 (the centre's line) and x = 1 are in front.
  const std::vector<int> front = validation::front_sensors(scene_->sensors, {0, 0}, {1, 0});
  EXPECT_EQ(front, (std::vector<int>{1, 2}));
  EXPECT_EQ(validation::front_sensors(scene_->sensors, {0, 0}, {-1, 0}), (std::vector<int>{0, 1}));
  EXPECT_TRUE(validation::front_sensors(scene_->sensors, {2, 0}, {1, 0}).empty());
  const validation::FrontSensorAnswer a = validation::front_sensor_answer(*x_, front, {1, 0});
  const nlohmann::json j = front_sensor_json(a);
  EXPECT_EQ(j.at("front_sensors"), "#2, #3");
  EXPECT_EQ(j.at("answer"), a.answer);
  EXPECT_EQ(j.at("coupling_amplitude_factor_z"), nlohmann::json::array({a.coupling_lo[0], a.coupling_hi[0]}));
  EXPECT_EQ(j.at("coupling_amplitude_factor_x"), nlohmann::json::array({a.coupling_lo[1], a.coupling_hi[1]}));
  EXPECT_EQ(j.contains("fe_over_paper_model_amplitude_z"), a.model_lo.has_value());
  // No sensor ahead: no amplitude factors, the answer alone.
  const nlohmann::json none = front_sensor_json(validation::front_sensor_answer(*x_, {}, {1, 0}));
  EXPECT_EQ(none.at("front_sensors"), "");
  EXPECT_FALSE(none.contains("coupling_amplitude_factor_z"));
}

}  // namespace
}  // namespace skinfem::pipeline
