// A textured plate scanned over a coarse sphere pressed into a bonded flat layer (pipeline/scan.hpp).
// References: `skinfem defect`'s resolved sweep of the same hole (a second method: hole_sweep's cut per
// position, not texture_scan's sum of cuts); ς's definition (the reading with the holes − without); two
// holes too far apart to touch the contact together, whose scan is the sum of their single-hole scans to
// round-off (the contact is the same linear problem at every position); and two holes that do share the
// contact, whose scan differs from that sum by less than the single-hole signal's own mesh error (its largest
// change from a mesh 1.5× coarser: the holes' interaction, C_zz's cross terms and the contact set's motion,
// must stay below what the mesh resolves for "superposition holds" to mean anything).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "scenes.hpp"
#include "skinfem/mesh/sizing.hpp"
#include "skinfem/pipeline/defect.hpp"
#include "skinfem/pipeline/scan.hpp"

namespace skinfem::pipeline {
namespace {

// As tests/pipeline/test_defect.cpp: equal contacts repeat their readings to below 1e-9 of the peak.
constexpr double kRoundOff = 1e-9;
constexpr double kHole = 0.4;

// The layer with a resolved sweep along y = 0 from −1.8 to 1.8 mm and a texture of `holes` scanned over
// [from, to] by `step`.
Scene scanned_layer(const std::vector<Hole>& holes, double from, double to, double step, int positions) {
  Scene s = testing::swept_layer("scanned_layer", positions, {-1.8, 0}, {1.8, 0}, 2.0, kHole);
  s.contact->sweep->model = HoleModel::resolved;
  Texture t;
  t.listed = holes;
  t.holes = holes;
  s.contact->texture = t;
  s.contact->scan = Scan{from, to, step};
  return s;
}

Hole hole(double x) { return Hole{{x, 0}, kHole, 0, 0.5}; }

TEST(Scan, ATextureOfOneHoleIsTheDefectSweepOfThatHole) {
  // The sweep's 13 positions from −1.8 to 1.8 mm are the scan's of a hole at the plate's origin.
  const Scene scene = scanned_layer({hole(0)}, -1.8, 1.8, 0.3, 13);
  const std::shared_ptr<const ContactSetup> setup(contact_setup(scene));
  const DefectRun defect = defect_run(scene, setup);
  const ScanRun scan = scan_run(scene, setup, false, DefectFrames::every);
  ASSERT_EQ(scan.cases, defect.cases);
  for (size_t c = 0; c < scan.cases.size(); ++c) {
    const Eigen::MatrixXd& a = scan.scans[c].varsigma;
    const Eigen::MatrixXd& b = defect.sweeps[c].varsigma;
    ASSERT_EQ(a.rows(), 13);
    ASSERT_EQ(b.rows(), 13);
    const double peak = b.cwiseAbs().maxCoeff();
    ASSERT_GT(peak, 0);
    EXPECT_LT((a - b).cwiseAbs().maxCoeff(), kRoundOff * peak) << scan.cases[c];
    for (int i = 0; i < 13; ++i) {
      EXPECT_NEAR(scan.scans[c].u[i], defect.sweeps[c].centers[i][0], 1e-12);
      // ς is the reading with the holes less the reading without.
      const Eigen::VectorXd v = scan.frames[c][i].readings - scan.scans[c].baseline.readings;
      EXPECT_LT((a.row(i).transpose() - v).cwiseAbs().maxCoeff(), kRoundOff * peak);
    }
  }
}

TEST(Scan, TwoHolesThatNeverShareTheZoneScanToTheSumOfTheirSingleHoleScans) {
  // 5.6 mm apart: more than the zone's diameter (4.4 mm) and a hole, so at most one cuts at a time.
  const Scene scene = scanned_layer({hole(-2.8), hole(2.8)}, -4.6, 4.6, 0.2, 13);
  const std::shared_ptr<const ContactSetup> setup(contact_setup(scene));
  const ScanRun run = scan_run(scene, setup, true);
  for (size_t c = 0; c < run.cases.size(); ++c) {
    const contact::ScanResult& s = run.scans[c];
    EXPECT_EQ(*std::max_element(s.holes_in.begin(), s.holes_in.end()), 1) << run.cases[c];
    const double peak = s.varsigma.cwiseAbs().maxCoeff();
    ASSERT_GT(peak, 0);
    EXPECT_LT((s.varsigma - run.superposed[c].varsigma).cwiseAbs().maxCoeff(), kRoundOff * peak)
        << run.cases[c];
  }
}

TEST(Scan, TwoHolesSharingTheContactDifferFromTheirSumByLessThanTheMeshError) {
  // 1.6 mm apart on a contact about 2 mm across: both press into it at once over part of the scan.
  const std::vector<Hole> pair{hole(-0.8), hole(0.8)};
  const Scene scene = scanned_layer(pair, -1.6, 1.6, 0.1, 13);
  const ScanRun run = scan_run(scene, std::shared_ptr<const ContactSetup>(contact_setup(scene)), true);
  // The mesh error of a single hole's signal: its largest change, over positions and sensors, from a mesh
  // 1.5× coarser (the hole's mesh capped at its diameter, as the scene rule asks).
  Scene one = scanned_layer({hole(0)}, -1.6, 1.6, 0.1, 13);
  Scene coarse = scaled_scene(one, 1.5, true);
  const ScanRun fine_one = scan_run(one, std::shared_ptr<const ContactSetup>(contact_setup(one)), false);
  const ScanRun coarse_one =
      scan_run(coarse, std::shared_ptr<const ContactSetup>(contact_setup(coarse)), false);
  for (size_t c = 0; c < run.cases.size(); ++c) {
    const contact::ScanResult& s = run.scans[c];
    EXPECT_EQ(*std::max_element(s.holes_in.begin(), s.holes_in.end()), 2) << run.cases[c];
    const double mesh_error =
        (fine_one.scans[c].varsigma - coarse_one.scans[c].varsigma).cwiseAbs().maxCoeff();
    const double interaction = (s.varsigma - run.superposed[c].varsigma).cwiseAbs().maxCoeff();
    EXPECT_GT(interaction, kRoundOff * s.varsigma.cwiseAbs().maxCoeff())
        << "the holes interact: not exactly additive";
    EXPECT_LT(interaction, mesh_error) << run.cases[c];
  }
}

TEST(Scan, AZoneTheContactOutgrowsIsRefusedBeforeTheTracksAreCondensed) {
  Scene scene = scanned_layer({hole(0)}, -1.8, 1.8, 0.3, 13);
  scene.contact->zone_radius = 0.8;  // the hole-free contact is about 2 mm across
  try {
    contact_setup(scene);  // scan_run would check it only after the whole condensation
    ADD_FAILURE() << "a zone the contact outgrows was accepted";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("contact.zone_radius"), std::string::npos) << e.what();
  }
}

TEST(Scan, WithoutATextureTheSweepsHoleIsScannedAlongItsPath) {
  const Scene scene = testing::swept_layer("swept_only", 13, {-1.8, 0}, {1.8, 0}, 2.0, kHole);
  const Scene s = scanned_scene(scene);
  ASSERT_TRUE(s.contact->texture && s.contact->scan);
  ASSERT_EQ(s.contact->texture->holes.size(), 1u);
  EXPECT_EQ(s.contact->texture->holes[0].center[0], -1.8);
  EXPECT_EQ(s.contact->texture->holes[0].diameter, kHole);
  EXPECT_EQ(s.contact->scan->positions(), 13);
  const std::vector<double> u = scan_positions(*s.contact->scan);
  for (int i = 0; i < 13; ++i)
    EXPECT_NEAR(-1.8 + u[i], contact::sweep_center(*scene.contact->sweep, i)[0], 1e-12) << i;
  // A sweep across the sliding direction cannot be a scan.
  Scene across = scene;
  across.contact->sweep->from = {0, -1};
  across.contact->sweep->to = {0, 1};
  EXPECT_THROW(scanned_scene(across), SceneError);
}

TEST(Scan, AStageWithoutATextureIsRefusedNamingIt) {
  Scene scene = testing::swept_layer("no_texture", 3);
  scene.contact->sweep.reset();
  try {
    scanned_scene(scene);
    FAIL() << "no throw";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("contact.texture: missing"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace skinfem::pipeline
