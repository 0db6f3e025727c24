// The matched filter slid along a scan, for a hole at an unknown place (validation/scan_detection.hpp).
// References: a Gaussian template's decorrelation in closed form (for s = exp(−x²/2a²), ∫s'² / ∫s² =
// 1/(2a²)); the threshold between the known place's Φ⁻¹(1 − p_fa) and Bonferroni's union bound over the
// scan's shifts; and a Monte Carlo of the slid filter on noise drawn independently of Rice's formula: its
// false-alarm rate within 4 binomial standard errors of the nominal one (seeded, so deterministic), and its
// detection rate at least the known place's p_d less 4 standard errors.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "skinfem/scene/parallel.hpp"
#include "skinfem/validation/scan_detection.hpp"

namespace skinfem::validation {
namespace {

// Two sensors (four columns) seeing a Gaussian bump of width a (mm) sampled every dx, the second sensor's
// shifted by `lag` and with a varsigma_x lobe.
Eigen::MatrixXd bump(double a, double dx, double lag = 0) {
  const int n = static_cast<int>(std::lround(12 * a / dx)) + 1;
  Eigen::MatrixXd s(n, 4);
  for (int i = 0; i < n; ++i) {
    const double x = (i - (n - 1) / 2) * dx;
    s(i, 0) = std::exp(-x * x / (2 * a * a));
    s(i, 1) = 0;
    s(i, 2) = 0.5 * std::exp(-(x - lag) * (x - lag) / (2 * a * a));
    s(i, 3) = -0.3 * (x - lag) / a * std::exp(-(x - lag) * (x - lag) / (2 * a * a));
  }
  return s;
}

TEST(ScanDetection, TheDecorrelationOfAGaussianIsOneOverASqrtTwo) {
  const double a = 0.3;
  Eigen::MatrixXd s = bump(a, a / 50);
  s.rightCols(2).setZero();
  const SensorNoise n{0.6, 0.4, 14};
  // The first difference's error is O((dx / a)²) = 4e-4.
  EXPECT_NEAR(scan_decorrelation(s, n, {0}, a / 50) * a * std::sqrt(2.0), 1.0, 1e-3);
  // It does not depend on the noise or on the signal's scale.
  EXPECT_NEAR(scan_decorrelation(3 * s, SensorNoise{1.0, 2.0, 1}, {0}, a / 50),
              scan_decorrelation(s, n, {0}, a / 50), 1e-12);
  EXPECT_THROW(scan_decorrelation(s, n, {1}, a / 50), std::invalid_argument);  // zero on sensor 2
}

TEST(ScanDetection, TheThresholdLiesBetweenTheKnownPlacesAndBonferronis) {
  const double rate = 1 / (0.3 * std::sqrt(2.0)), dx = 0.03;
  for (double L : {1.0, 10.0, 100.0}) {
    const double tau = scan_threshold(rate, L, 0.01);
    const double shifts = L / dx + 1;
    EXPECT_GT(tau, normal_quantile(0.99)) << L;
    EXPECT_LT(tau, normal_quantile(1 - 0.01 / shifts)) << L;
  }
  EXPECT_NEAR(scan_threshold(rate, 0.0, 0.01), normal_quantile(0.99), 1e-9);
  EXPECT_LT(scan_threshold(rate, 10.0, 0.01), scan_threshold(rate, 20.0, 0.01));
}

TEST(ScanDetection, MonteCarloRatesMatchRicesThreshold) {
  // 0.3 mm bumps sampled every 0.03 mm on a 10 mm scan: 334 shifts, the filter decorrelating over ~0.4 mm.
  const double a = 0.3, dx = 0.03, L = 10;
  const SensorNoise n{0.6, 0.4, 4};
  const Eigen::MatrixXd s0 = bump(a, dx, 0.4);
  const double rate = scan_decorrelation(s0, n, {}, dx), tau = scan_threshold(rate, L, 0.01);
  // The threshold hole: its SNR is tau + Φ⁻¹(0.9), where the known place's filter detects with 0.9.
  const double need = tau + normal_quantile(0.9);
  const MonteCarloRates r =
      monte_carlo_scan(s0 * (need / matched_filter_snr(s0, n)), n, {}, dx, L, tau, 0.01, 8000, 7);
  std::printf("slid filter, tau %.3f: false alarms %.4f +- %.4f, detections %.4f\n", tau, r.false_alarm,
              r.false_alarm_sigma, r.detection);
  EXPECT_NEAR(r.false_alarm, 0.01, 4 * r.false_alarm_sigma);
  EXPECT_GE(r.detection, 0.9 - 4 * std::sqrt(0.9 * 0.1 / r.trials));
  // The known place's threshold on the slid filter: far more false alarms than 1 %.
  const MonteCarloRates loose = monte_carlo_scan(s0, n, {}, dx, L, normal_quantile(0.99), 0.01, 2000, 8);
  EXPECT_GT(loose.false_alarm, 0.05);
}

TEST(ScanDetection, TheCountsDoNotDependOnTheThreads) {
  const Eigen::MatrixXd s = bump(0.3, 0.05);
  const SensorNoise n{0.6, 0.4, 1};
  const MonteCarloRates a = monte_carlo_scan(s, n, {}, 0.05, 3, 3.0, 0.01, 300, 11);
  MonteCarloRates b;
  {
    const ThreadCap one(1);
    b = monte_carlo_scan(s, n, {}, 0.05, 3, 3.0, 0.01, 300, 11);
  }
  EXPECT_EQ(a.false_alarm, b.false_alarm);
  EXPECT_EQ(a.detection, b.detection);
}

}  // namespace
}  // namespace skinfem::validation
