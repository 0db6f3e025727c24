// The inversion as a stage (pipeline/inversion.hpp) on the coarse sphere-on-layer scene. Reference: the
// scene's own hole sweep (`defect`, sliding), whose hole sits at the plate's origin when its centre is at
// u: inverted against the dictionary, which is built on another mesh (its virtual sensors refine it), the
// hole comes back at 0 within one scan step, with its diameter within 5 % (the two meshes' difference: the
// amplitude, D³, within 15 %), the contact within one offset step of its nominal place, and as the
// strongest feature. Read by posts, the same at the known offset. Its dictionary given back, the same fit.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "scenes.hpp"
#include "skinfem/pipeline/contact_setup.hpp"
#include "skinfem/pipeline/defect.hpp"
#include "skinfem/pipeline/inversion.hpp"

namespace skinfem::pipeline {
namespace {

// The scene's sliding sweep as signals.
validation::ScanSignals swept_signals(const Scene& scene) {
  const DefectRun defect = defect_run(scene, std::shared_ptr<const ContactSetup>(contact_setup(scene)));
  validation::ScanSignals sig;
  const contact::SweepResult& sliding = defect.sweeps.at(1);
  for (const Vec2& c : sliding.centers) sig.u.push_back(c[0]);
  for (const Vec2& p : scene.sensors.positions) sig.sensors.push_back(p[0]);
  sig.y = 1e3 * sliding.varsigma;
  return sig;
}

InversionOptions searched(double range) {
  InversionOptions o;
  o.offset_range = range;
  return o;
}

// The hole comes back at 0 within one scan step (0.1 mm), the strongest feature, its diameter within 5 %.
void expect_the_hole(const InversionRun& run, size_t sensors) {
  ASSERT_FALSE(run.multi.features.empty());
  const validation::Feature* strongest = &run.multi.features[0];
  for (const validation::Feature& f : run.multi.features)
    if (f.snr > strongest->snr) strongest = &f;
  EXPECT_NEAR(strongest->position_mm, 0, 0.1);
  EXPECT_NEAR(strongest->diameter_mm, 0.4, 0.05 * 0.4);
  ASSERT_EQ(run.naive.size(), sensors);
}

TEST(InversionRun, TheDefectSweepsHoleComesBackAtItsPlaceAndSize) {
  const Scene scene = testing::swept_layer("inverted_layer", 41, {-2.0, 0}, {2.0, 0}, 2.0, 0.4);
  const validation::ScanSignals sig = swept_signals(scene);
  const InversionRun run = inversion_run(scene, sig, searched(0.3));
  // The two meshes' difference leaves a residual far below the noise's (4.5 for 246 samples): its minimum
  // over the offset falls between grid points, within one step of the nominal place.
  EXPECT_LE(std::abs(run.multi.offset_mm), 0.1 + 1e-9);
  expect_the_hole(run, 3);
  // Its dictionary given back (`invert --dictionary`): the same fit, bit for bit; refused for a wider
  // offset range (a virtual sensor missing) and another step.
  const InversionRun again = inversion_run(scene, sig, searched(0.3), &run.responses);
  ASSERT_EQ(again.multi.features.size(), run.multi.features.size());
  for (size_t k = 0; k < run.multi.features.size(); ++k)
    EXPECT_EQ(again.multi.features[k].position_mm, run.multi.features[k].position_mm);
  EXPECT_EQ(again.multi.residuals, run.multi.residuals);
  const double dx = sig.u[1] - sig.u[0];
  EXPECT_NE(dictionary_mismatch(scene, run.responses, dx, offset_grid(0.5, 0.1)).find("no virtual sensor"),
            std::string::npos);
  EXPECT_NE(dictionary_mismatch(scene, run.responses, 2 * dx, offset_grid(0.3, 0.1)).find("step"),
            std::string::npos);
  EXPECT_THROW(inversion_run(scene, sig, searched(0.5), &run.responses), SceneError);
}

// Posts read the skin only where they are meshed: the dictionary is the posts where they stand, the offset
// known (an offset range refused, naming --offset-range).
TEST(InversionRun, PostsReadTheHoleAtItsPlaceAndSizeAtTheKnownOffset) {
  Scene scene = testing::swept_layer("inverted_posts", 41, {-2.0, 0}, {2.0, 0}, 2.0, 0.4);
  scene.sensors.model = SensorModel::post;
  scene.sensors.post = {0.2, 0.4};
  EXPECT_NE(inversion_unavailable(scene, {-0.1, 0, 0.1}).find("--offset-range 0"), std::string::npos);
  EXPECT_EQ(inversion_unavailable(scene, {0}), "");
  const InversionRun run = inversion_run(scene, swept_signals(scene), searched(0));
  EXPECT_EQ(run.multi.offset_mm, 0);
  expect_the_hole(run, 3);
}

}  // namespace
}  // namespace skinfem::pipeline
