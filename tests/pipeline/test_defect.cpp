// The hole sweep of the paper's §IV as a stage (pipeline/defect.hpp) on a coarse sphere pressed into a
// bonded flat layer. References: the header's frame rule (at most kDefectFrames per case, both ends, evenly
// spaced; every position when there are no more), checked over every sweep length up to 3000; ς's
// definition, recomputed here as a kept frame's readings minus the hole-free contact's; the physics of a
// hole where the skin does not touch (the contact is unchanged: ς = 0 to round-off); the error bar through
// coarser levels against chain_errors on the same levels (pipeline/chain_level.hpp), given synthetic
// coarse levels; defect_json against the typed run (kPa = 1e3 MPa; the bulge model's next term (ε/h)² from
// the layer's thickness h); and the refusal of a scene without a sweep.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "scenes.hpp"
#include "skinfem/pipeline/defect.hpp"

namespace skinfem::pipeline {
namespace {

// The LCP is solved by pivoting and the condensation by direct solves: equal contacts repeat their readings
// to round-off amplified by the condensed compliance's condition number, below 1e-9 of the peak reading.
constexpr double kRoundOff = 1e-9;
constexpr double kH = 2.0, kHole = 0.4;
constexpr int kPositions = 7;

// Both ends of the sweep outside the contact (its radius is about 1 mm here).
Scene defect_layer() {
  return testing::swept_layer("defect_layer", kPositions, {-1.8, 0}, {1.8, 0}, kH, kHole);
}

class Defect : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    scene_ = new Scene(defect_layer());
    setup_ = std::shared_ptr<const ContactSetup>(contact_setup(*scene_));
    // Two synthetic coarser levels for the error bar: it needs only their values (chain_errors).
    std::vector<ChainLevel> coarse(2);
    coarse[0].scale = 2, coarse[1].scale = 1.5;
    for (ChainLevel& l : coarse) {
      l.names = {"largest_sliding_varsigma_z"};
      l.seconds = {0.25};
    }
    coarse[0].value = {0.05};
    coarse[1].value = {0.04};
    run_ = new DefectRun(defect_run(*scene_, setup_, coarse, DefectFrames::every));
  }
  static void TearDownTestSuite() {
    delete run_;
    setup_.reset();
    delete scene_;
  }
  static Scene* scene_;
  static std::shared_ptr<const ContactSetup> setup_;
  static DefectRun* run_;
};
Scene* Defect::scene_ = nullptr;
std::shared_ptr<const ContactSetup> Defect::setup_;
DefectRun* Defect::run_ = nullptr;

TEST_F(Defect, AtMost201FramesBothEndsEvenlySpaced) {
  for (int n = 1; n <= 3000; ++n) {
    std::vector<int> kept;
    for (int i = 0; i < n; ++i)
      if (written_frame(i, n)) kept.push_back(i);
    ASSERT_LE(static_cast<int>(kept.size()), kDefectFrames) << n;
    ASSERT_EQ(kept.front(), 0) << n;
    ASSERT_EQ(kept.back(), n - 1) << n;
    if (n <= kDefectFrames) {
      ASSERT_EQ(static_cast<int>(kept.size()), n) << n;
    }
    // Evenly spaced but for the last gap, which is no wider than the others.
    const int stride = kept.size() > 1 ? kept[1] - kept[0] : 1;
    for (size_t k = 1; k + 1 < kept.size(); ++k) ASSERT_EQ(kept[k] - kept[k - 1], stride) << n;
    ASSERT_LE(kept.back() - kept[kept.size() > 1 ? kept.size() - 2 : 0], stride) << n;
    // Not needlessly sparse: the next smaller stride (multiples of it, and the last position) would exceed
    // the limit.
    if (n > kDefectFrames && stride > 1) {
      const int s = stride - 1, denser = (n - 1) / s + 1 + ((n - 1) % s != 0);
      ASSERT_GT(denser, kDefectFrames) << n;
    }
  }
}

TEST_F(Defect, VarsigmaIsTheReadingWithTheHoleLessTheReadingWithout) {
  ASSERT_EQ(run_->cases, (std::vector<std::string>{"static", "sliding"}));
  const FrictionMode modes[] = {FrictionMode::static_residual, FrictionMode::coupled};
  for (size_t c = 0; c < 2; ++c) {
    const contact::SweepResult& sw = run_->sweeps[c];
    ASSERT_EQ(sw.varsigma.rows(), kPositions);
    ASSERT_EQ(sw.varsigma.cols(), 2 * 3);
    // DefectFrames::every keeps every position.
    ASSERT_EQ(run_->frames[c].size(), static_cast<size_t>(kPositions));
    const contact::ContactResult without = setup_->solver->solve(modes[c]);
    const double scale = without.readings.cwiseAbs().maxCoeff();
    for (int i = 0; i < kPositions; ++i) {
      EXPECT_EQ(run_->frame_positions[c][i], i);
      const Eigen::VectorXd v = run_->frames[c][i].readings - without.readings;
      EXPECT_LT((sw.varsigma.row(i).transpose() - v).cwiseAbs().maxCoeff(), kRoundOff * scale)
          << run_->cases[c] << ", position " << i;
      // The hole's centre moves evenly from `from` to `to`.
      EXPECT_NEAR(sw.centers[i][0], -1.8 + 3.6 * i / (kPositions - 1), 1e-12);
      EXPECT_EQ(sw.centers[i][1], 0);
    }
  }
}

TEST_F(Defect, AHoleWhereTheSkinDoesNotTouchChangesNothing) {
  for (size_t c = 0; c < 2; ++c) {
    const contact::SweepResult& sw = run_->sweeps[c];
    // The hole-free contact's reach along x, from its active multipliers.
    double reach = 0;
    const auto& zone = setup_->solver->zone();
    for (int a : sw.baseline.active)
      reach = std::max(reach, std::abs(setup_->mesh().nodes(zone.vertices[a], 0)));
    ASSERT_LT(reach + 0.5 * kHole + setup_->zone_h, 1.8) << "the ends must lie beyond the contact";
    const double scale = sw.baseline.readings.cwiseAbs().maxCoeff();
    for (int i : {0, kPositions - 1})
      EXPECT_LT(sw.varsigma.row(i).cwiseAbs().maxCoeff(), kRoundOff * scale) << run_->cases[c] << ", " << i;
    // Mid-sweep, through the contact, the hole is seen.
    EXPECT_GT(sw.varsigma.row(kPositions / 2).cwiseAbs().maxCoeff(), 1e-3 * scale) << run_->cases[c];
  }
}

TEST_F(Defect, TheErrorBarIsChainErrorsOverTheCoarserLevelsAndThisOne) {
  ASSERT_EQ(run_->levels.size(), 3u);
  const double own = contact::largest_varsigma_z(run_->sweeps.back().varsigma);
  EXPECT_EQ(run_->levels.back().value.at(0), own);
  double largest = 0;  // recomputed: max |ς_z| over sensors and positions of the sliding case
  for (int k = 0; k < 3; ++k)
    largest = std::max(largest, run_->sweeps[1].varsigma.col(2 * k).cwiseAbs().maxCoeff());
  EXPECT_EQ(own, largest);
  const ChainError e = largest_sliding_error(*run_);
  const ChainError reference = chain_errors(run_->levels).at(0);
  EXPECT_EQ(e.value, reference.value);
  EXPECT_EQ(e.error, reference.error);
  EXPECT_EQ(e.asymptotic, reference.asymptotic);
  EXPECT_EQ(run_->wall.at("error_bar_levels"), 0.5);  // the two coarse levels' seconds

  const nlohmann::json j = defect_json(*scene_, *run_);
  const nlohmann::json& b = j.at("largest_sliding");
  EXPECT_NEAR(b.at("value_kPa").get<double>(), 1e3 * own, 1e-12 * 1e3 * own);
  EXPECT_NEAR(b.at("error_kPa").get<double>(), 1e3 * e.error, 1e-12 * 1e3 * std::abs(e.error));
  EXPECT_EQ(b.at("asymptotic").get<bool>(), e.asymptotic);
  ASSERT_EQ(b.at("levels").size(), 3u);
  EXPECT_EQ(b.at("levels")[0].at("mesh_scale").get<double>(), 2);
  EXPECT_NEAR(b.at("levels")[1].at("value_kPa").get<double>(), 40, 1e-12);

  DefectRun without = *run_;
  without.levels.resize(2);
  EXPECT_THROW(largest_sliding_error(without), std::invalid_argument);
  EXPECT_FALSE(defect_json(*scene_, without).contains("largest_sliding"));
}

TEST_F(Defect, TheSummarySaysTheTypedRun) {
  const nlohmann::json j = defect_json(*scene_, *run_);
  EXPECT_EQ(j.at("positions").get<int>(), kPositions);
  EXPECT_EQ(j.at("hole_diameter_mm").get<double>(), kHole);
  EXPECT_EQ(j.at("hole_model"), "bulge");
  // (ε/d)² with ε the hole's radius and d the layer's thickness.
  EXPECT_NEAR(j.at("bulge_next_term").get<double>(), std::pow(0.5 * kHole / kH, 2), 1e-12);
  EXPECT_EQ(j.at("from_mm"), nlohmann::json::array({-1.8, 0.0}));
  EXPECT_EQ(j.at("dofs").get<int>(), setup_->model->solver().free_dofs());
  const nlohmann::json& st = j.at("cases").at("static");
  const nlohmann::json& sl = j.at("cases").at("sliding");
  EXPECT_EQ(st.at("friction"), "static");
  EXPECT_NEAR(st.at("ratio").get<double>(), 0.1, 1e-15);
  EXPECT_EQ(sl.at("friction"), "coupled");
  EXPECT_NEAR(sl.at("ratio").get<double>(), 0.5, 1e-15);
  for (size_t c = 0; c < 2; ++c) {
    const contact::SweepResult& sw = run_->sweeps[c];
    const nlohmann::json& jc = j.at("cases").at(run_->cases[c]);
    EXPECT_EQ(jc.at("max_roughness").get<double>(), run_->max_roughness[c]);
    double pivots = 0;
    for (int p : sw.pivots) pivots += p;
    EXPECT_NEAR(jc.at("mean_pivots").get<double>(), pivots / kPositions, 1e-12);
    ASSERT_EQ(jc.at("sensors").size(), 3u);
    for (int k = 0; k < 3; ++k) {
      const nlohmann::json& js = jc.at("sensors")[k];
      EXPECT_EQ(js.at("sensor").get<int>(), k + 1);
      // The peak and where it is, recomputed from the positions.
      int at = 0;
      for (int i = 1; i < kPositions; ++i)
        if (std::abs(sw.varsigma(i, 2 * k)) > std::abs(sw.varsigma(at, 2 * k))) at = i;
      EXPECT_NEAR(js.at("peak_abs_varsigma_z_kPa").get<double>(), 1e3 * std::abs(sw.varsigma(at, 2 * k)),
                  1e-12);
      EXPECT_EQ(js.at("u_at_peak_z_mm").get<double>(), sw.centers[at][0]);
    }
  }
}

TEST_F(Defect, AStageWithoutASweepIsRefusedNamingIt) {
  Scene s = defect_layer();
  s.contact->sweep.reset();
  for (const Scene& bad : {s, [] {
                             Scene t = defect_layer();
                             t.contact.reset();
                             return t;
                           }()}) {
    try {
      require_sweep(bad);
      ADD_FAILURE() << "a scene without a sweep was accepted";
    } catch (const SceneError& e) {
      EXPECT_NE(std::string(e.what()).find("contact.sweep"), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(defect_run(s, setup_), SceneError);
}

}  // namespace
}  // namespace skinfem::pipeline
