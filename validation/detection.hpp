// Whether a sensor array perceives a hole under the paper's noise (shared by `skinfem perceive`).
//
// Noise: on every sample of a passage, independent Gaussian noise of standard deviation sigma_z on each ς_z
// and sigma_x on each ς_x (the paper's §IV: "typically 0.6 kPa for ς_z and 0.4 kPa for ς_x"); the mean of
// N passages divides both by √N. Samples are `sample_mm` apart along the scan: the paper gives no sampling
// rate, so the spacing is the caller's (the signal's samples are taken every sample_mm).
//
// The matched filter of a known signal s at a known place (Kay, Fundamentals of Statistical Signal
// Processing, vol. II, §4.3): T = Σ_j s_j y_j / σ_j² / d with d = √(Σ_j s_j² / σ_j²), the filter's
// signal-to-noise ratio. Without the hole T ~ N(0, 1), with it T ~ N(d, 1): the threshold
// τ = Φ⁻¹(1 − P_FA) sets the false-alarm rate and the detection probability is P_D = 1 − Φ(τ − d).
#pragma once

#include <Eigen/Dense>
#include <cstdint>
#include <vector>

namespace skinfem::validation {

struct SensorNoise {
  double sigma_z_kPa = 0.6, sigma_x_kPa = 0.4;  // per sample and passage
  int passages = 1;                             // N: the mean of N passages
};

double normal_cdf(double x);
// Φ⁻¹(p) for p in (0, 1), to 1e-14 (bisection on normal_cdf).
double normal_quantile(double p);

// signal: samples × 2·sensors, kPa (σ_z of sensor k in column 2k, σ_x in 2k + 1); sensors: the 0-based
// sensors the filter uses (empty: all).
// Per column of such a signal, 1/σ² of the mean of N passages, 0 for a sensor the filter leaves out (the
// weights every filter here shares). Throws on a non-positive deviation, N < 1 or a sensor not in `columns`.
Eigen::RowVectorXd filter_weights(int columns, const SensorNoise& noise, const std::vector<int>& sensors);
double matched_filter_snr(const Eigen::MatrixXd& signal, const SensorNoise& noise,
                          const std::vector<int>& sensors = {});
double detection_threshold(double p_fa);                // τ = Φ⁻¹(1 − p_fa)
double detection_probability(double snr, double p_fa);  // 1 − Φ(τ − d)
double required_snr(double p_fa, double p_d);           // Φ⁻¹(1 − p_fa) + Φ⁻¹(p_d)

// The filter run on `trials` noise draws (splitmix64 from `seed`) without and with the signal: the
// fractions above the threshold, each with its binomial standard error √(p (1 − p) / trials).
struct MonteCarloRates {
  double false_alarm = 0, false_alarm_sigma = 0, detection = 0, detection_sigma = 0;
  int trials = 0;
};
MonteCarloRates monte_carlo_rates(const Eigen::MatrixXd& signal, const SensorNoise& noise,
                                  const std::vector<int>& sensors, double p_fa, int trials,
                                  std::uint64_t seed);

}  // namespace skinfem::validation
