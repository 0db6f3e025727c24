// The report's perception section (pipeline/report_perception.hpp) on the coarse sphere-on-layer scene.
// References: superposed_scan's own single-hole solves per position (a second method for the section's
// table of single-hole signals on the step's grid); perception_run run again at another number of passages
// (the map's √N scaling of the matched filter's SNR against a second computation); the report's path run on
// along the sweep's line, which leaves the sweep's own signals as they were (round-off) and cuts a hole
// past the sweep's end as a sweep reaching there does.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "scenes.hpp"
#include "skinfem/pipeline/defect.hpp"
#include "skinfem/pipeline/report_perception.hpp"

namespace skinfem::pipeline {
namespace {

constexpr double kRoundOff = 1e-9;  // of the peak, as tests/pipeline/test_scan.cpp

TEST(ReportPerception, TheTablesSumsAreTheSuperpositionAndTheMapScalesAsRootN) {
  const Scene scene = testing::swept_layer("perception_layer", 13, {-1.8, 0}, {1.8, 0}, 2.0, 0.4);
  ASSERT_EQ(perception_unavailable(scene), "");
  const std::shared_ptr<const ContactSetup> setup(contact_setup(scene, nullptr, HolePath::always));
  const ReportPerception p = report_perception_scans(scene, setup);

  // The row: holes a whole number of steps apart (0.3 mm: 1.2 mm, 3 diameters), scanned until the last has
  // crossed the track.
  EXPECT_NEAR(p.period_mm, 1.2, 1e-12);
  ASSERT_EQ(p.row_holes_mm.size(), 4u);
  std::vector<Hole> row;
  for (double x : p.row_holes_mm) row.push_back(Hole{{x, 0}, 0.4, 0, 0.5});
  const contact::Superposition direct =
      contact::superposed_scan(*setup->solver, row, {1, 0}, p.row.u, FrictionMode::coupled);
  const double peak = direct.varsigma.cwiseAbs().maxCoeff();
  ASSERT_GT(peak, 0);
  EXPECT_LT((p.row_superposed - direct.varsigma).cwiseAbs().maxCoeff(), kRoundOff * peak);
  // The full scan differs from it, but by less than the signal.
  const double diff = (p.row.varsigma - direct.varsigma).cwiseAbs().maxCoeff();
  EXPECT_GT(diff, 0);
  EXPECT_LT(diff, 0.2 * peak);

  // Pairs: the spacings 1.2 … 6 diameters rounded to whole steps (0.48 → 0.6, 0.6, 0.8 → 0.9, …), once each.
  ASSERT_FALSE(p.pairs.empty());
  for (const PairPoint& q : p.pairs) {
    EXPECT_NEAR(std::remainder(q.spacing_mm, 0.3), 0, 1e-12) << q.spacing_mm;
    EXPECT_GE(q.rel_diff_z, 0);
    EXPECT_GE(q.rel_diff_x, 0);
  }

  // The map at N = 14 is the ladder's own answer; at N = 4 perception_run's at 4 passages.
  PerceptionOptions o;
  o.noise.passages = 4;
  o.trials = 100;
  Scene bulge = scene;
  bulge.contact->sweep->model = HoleModel::bulge;
  const PerceptionRun four = perception_run(bulge, setup, o);
  int checked = 0;
  for (const DetectionPoint& d : p.detection_map)
    for (size_t c = 0; c < 2; ++c) {
      const PerceptionCase& at14 = p.detection.cases[c];
      const PerceptionCase& at4 = four.cases[c];
      if (d.case_name != at14.name) continue;
      const auto same = [&](const std::optional<double>& a, const std::optional<double>& b) {
        ASSERT_EQ(a.has_value(), b.has_value()) << d.case_name << " N = " << d.passages;
        if (a) {
          EXPECT_NEAR(*a, *b, 1e-9 * *b) << d.case_name << " N = " << d.passages;
        }
        ++checked;
      };
      if (d.passages == 14) same(d.array_mm, at14.array_min_mm), same(d.sensor_mm, at14.sensor_min_mm);
      if (d.passages == 4) same(d.array_mm, at4.array_min_mm), same(d.sensor_mm, at4.sensor_min_mm);
    }
  EXPECT_EQ(checked, 8);
}

TEST(ReportPerception, ThePathRunOnToTheZonesEdgeChangesNoSweepAndCutsAHolePastItsEnd) {
  // The sweep stops at 0.6 mm inside the contact (radius about 1 mm); the report's path runs on.
  Scene scene = testing::swept_layer("short_sweep", 5, {-0.6, 0}, {0.6, 0}, 2.0, 0.4);
  scene.contact->sweep->model = HoleModel::resolved;
  const std::shared_ptr<const ContactSetup> report(contact_setup(scene, nullptr, HolePath::always));
  const std::shared_ptr<const ContactSetup> plain(contact_setup(scene));
  ASSERT_GT(report->condensed->path->nodes.size(), plain->condensed->path->nodes.size());
  const DefectRun a = defect_run(scene, report), b = defect_run(scene, plain);
  for (size_t c = 0; c < a.sweeps.size(); ++c) {
    const double peak = b.sweeps[c].varsigma.cwiseAbs().maxCoeff();
    ASSERT_GT(peak, 0);
    EXPECT_LT((a.sweeps[c].varsigma - b.sweeps[c].varsigma).cwiseAbs().maxCoeff(), kRoundOff * peak);
  }
  // A hole at 0.9 mm, past the sweep's end: as the last position of a sweep that reaches there.
  Scene longer = scene;
  longer.contact->sweep->to = {0.9, 0};
  longer.contact->sweep->positions = 6;
  const DefectRun reaching = defect_run(longer, std::shared_ptr<const ContactSetup>(contact_setup(longer)));
  const contact::ScanResult past = contact::texture_scan(*report->solver, {Hole{{0.9, 0}, 0.4, 0, 0.5}},
                                                         {1, 0}, {0.0}, FrictionMode::coupled);
  const Eigen::RowVectorXd expected = reaching.sweeps.at(1).varsigma.row(5);
  ASSERT_GT(expected.cwiseAbs().maxCoeff(), 0);
  EXPECT_LT((past.varsigma.row(0) - expected).cwiseAbs().maxCoeff(), 1e-6 * expected.cwiseAbs().maxCoeff());
}

}  // namespace
}  // namespace skinfem::pipeline
