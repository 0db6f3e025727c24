// How small a hole the array perceives (pipeline/perception.hpp), on the coarse sphere-on-layer scene.
// References: the bulge's signal grows as the hole's volume, D³ (contact/holes/dimple.hpp: the opening is
// ∫_H p ω, ω ∝ ε), so the matched filter's SNR falls by 2^(3/4) per rung of the ladder to the bulge's next
// term, (ε/a)² with a the contact's radius (here (0.2/1)² = 4 %: 5 % asserted); the smallest detected hole,
// whose SNR by that law is the required one; a Monte Carlo of the filter within 4 binomial standard errors
// of the nominal rates; at an unknown place, the threshold between the known place's and Bonferroni's and
// the slid filter's Monte Carlo within Rice's bound; and the refusal of a resolved hole.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "scenes.hpp"
#include "skinfem/pipeline/perception.hpp"

namespace skinfem::pipeline {
namespace {

TEST(Perception, TheSnrFallsAsTheHolesVolumeAndTheThresholdHoleMeetsTheRequiredSnr) {
  const Scene scene = testing::swept_layer("perceived_layer", 41, {-1.8, 0}, {1.8, 0}, 2.0, 0.4);
  PerceptionOptions o;
  o.trials = 20000;
  const PerceptionRun run =
      perception_run(scene, std::shared_ptr<const ContactSetup>(contact_setup(scene)), o);
  ASSERT_EQ(run.cases.size(), 2u);
  ASSERT_EQ(run.diameters.size(), 13u);
  const double need = validation::required_snr(o.p_fa, o.p_d);
  for (const PerceptionCase& c : run.cases) {
    for (size_t k = 0; k + 1 < run.diameters.size(); ++k)
      EXPECT_NEAR(c.ladder_array[k] / c.ladder_array[k + 1], std::pow(2.0, 0.75), 0.05 * std::pow(2.0, 0.75))
          << c.name << ", rung " << k;
    ASSERT_TRUE(c.array_min_mm) << c.name;
    EXPECT_NEAR(c.array_snr * std::pow(*c.array_min_mm / run.diameters[0], 3), need, 0.05 * need) << c.name;
    // One sensor alone sees less than the array.
    if (c.sensor_min_mm) {
      EXPECT_GT(*c.sensor_min_mm, *c.array_min_mm) << c.name;
    }
    EXPECT_NEAR(c.rates.false_alarm, o.p_fa, 4 * c.rates.false_alarm_sigma) << c.name;
    EXPECT_NEAR(c.rates.detection, o.p_d, 4 * c.rates.detection_sigma) << c.name;
    // At an unknown place: the threshold between the known place's and Bonferroni's over the scan's
    // samples; a larger hole needed, again by the D³ law; the slid filter's false alarms at most Rice's
    // bound and its detections at least p_d, each within 4 sampling errors.
    const double samples = o.scan_mm / run.sample_mm + 1;
    EXPECT_GT(c.scan_threshold_array, validation::detection_threshold(o.p_fa)) << c.name;
    EXPECT_LT(c.scan_threshold_array, validation::detection_threshold(o.p_fa / samples)) << c.name;
    ASSERT_TRUE(c.array_min_unknown_mm) << c.name;
    EXPECT_GT(*c.array_min_unknown_mm, *c.array_min_mm) << c.name;
    const double need_unknown = c.scan_threshold_array + validation::normal_quantile(o.p_d);
    EXPECT_NEAR(c.array_snr * std::pow(*c.array_min_unknown_mm / run.diameters[0], 3), need_unknown,
                0.05 * need_unknown)
        << c.name;
    EXPECT_LE(c.scan_rates.false_alarm, o.p_fa + 4 * c.scan_rates.false_alarm_sigma) << c.name;
    EXPECT_GE(c.scan_rates.detection, o.p_d - 4 * std::sqrt(o.p_d * (1 - o.p_d) / c.scan_rates.trials))
        << c.name;
  }
}

TEST(Perception, AResolvedHoleIsRefusedNamingTheModel) {
  Scene scene = testing::swept_layer("resolved_layer", 5);
  scene.contact->sweep->model = HoleModel::resolved;
  try {
    perception_run(scene, nullptr, PerceptionOptions());
    FAIL() << "no throw";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("contact.sweep.hole_model"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace skinfem::pipeline
