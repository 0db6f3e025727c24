// The matched filter under the paper's noise (validation/detection.hpp). References: the standard normal's
// tabulated quantiles (Abramowitz & Stegun, table 26.5: Φ⁻¹(0.99) = 2.326347874, Φ⁻¹(0.9) = 1.281551566);
// the filter's SNR of a one-sample signal, s/σ·√N, by hand; and a Monte Carlo of the filter on noise drawn
// independently of the closed forms: its false-alarm and detection rates within 4 binomial standard errors
// of the nominal ones (a false failure once in 16,000 runs per rate; the draws are seeded, so the run is
// deterministic).
#include <gtest/gtest.h>

#include <cmath>

#include "skinfem/validation/detection.hpp"

namespace skinfem::validation {
namespace {

TEST(Detection, TheNormalQuantilesAreTheTablesAndInvertTheDistribution) {
  EXPECT_NEAR(normal_quantile(0.99), 2.326347874, 1e-9);
  EXPECT_NEAR(normal_quantile(0.9), 1.281551566, 1e-9);
  EXPECT_NEAR(normal_quantile(0.5), 0.0, 1e-13);
  // Above 5 the distribution is within 3e-7 of 1 and its rounding, not the bisection, limits the inverse.
  for (double x = -5; x <= 5; x += 0.25) EXPECT_NEAR(normal_quantile(normal_cdf(x)), x, 1e-8) << x;
  EXPECT_NEAR(required_snr(0.01, 0.9), 2.326347874 + 1.281551566, 1e-8);
  EXPECT_NEAR(detection_probability(required_snr(0.01, 0.9), 0.01), 0.9, 1e-12);
}

TEST(Detection, TheFiltersSnrIsTheSignalOverTheNoiseOfTheMean) {
  Eigen::MatrixXd s = Eigen::MatrixXd::Zero(3, 4);  // 3 samples, 2 sensors
  s(1, 0) = 1.2;                                    // sensor 1, varsigma_z
  s(2, 3) = 0.8;                                    // sensor 2, varsigma_x
  SensorNoise n{0.6, 0.4, 14};
  EXPECT_NEAR(matched_filter_snr(s, n, {0}), 1.2 / 0.6 * std::sqrt(14.0), 1e-12);
  EXPECT_NEAR(matched_filter_snr(s, n, {1}), 0.8 / 0.4 * std::sqrt(14.0), 1e-12);
  EXPECT_NEAR(matched_filter_snr(s, n), std::sqrt(14.0 * (4.0 + 4.0)), 1e-12);
  EXPECT_THROW(matched_filter_snr(s, n, {2}), std::invalid_argument);
}

TEST(Detection, MonteCarloRatesMatchTheNominalOnes) {
  // A smooth two-sensor signal of 40 samples whose array SNR is about 3 at N = 4.
  Eigen::MatrixXd s(40, 4);
  for (int i = 0; i < 40; ++i) {
    const double u = (i - 20) / 6.0;
    s(i, 0) = 0.2 * std::exp(-u * u);
    s(i, 1) = 0.1 * u * std::exp(-u * u);
    s(i, 2) = -0.15 * std::exp(-u * u);
    s(i, 3) = 0.05 * std::exp(-u * u);
  }
  const SensorNoise n{0.6, 0.4, 4};
  const double d = matched_filter_snr(s, n);
  ASSERT_GT(d, 1);
  ASSERT_LT(d, 5);
  for (double p_fa : {0.01, 0.1}) {
    const MonteCarloRates r = monte_carlo_rates(s, n, {}, p_fa, 40000, 7);
    EXPECT_NEAR(r.false_alarm, p_fa, 4 * r.false_alarm_sigma) << p_fa;
    EXPECT_NEAR(r.detection, detection_probability(d, p_fa), 4 * r.detection_sigma) << p_fa;
  }
}

}  // namespace
}  // namespace skinfem::validation
