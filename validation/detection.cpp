#include "skinfem/validation/detection.hpp"

#include <cmath>
#include <stdexcept>

#include "skinfem/scene/random.hpp"

namespace skinfem::validation {

Eigen::RowVectorXd filter_weights(int columns, const SensorNoise& noise, const std::vector<int>& sensors) {
  if (!(noise.sigma_z_kPa > 0) || !(noise.sigma_x_kPa > 0) || noise.passages < 1)
    throw std::invalid_argument("SensorNoise: the deviations must be > 0 and the passages >= 1");
  Eigen::RowVectorXd w = Eigen::RowVectorXd::Zero(columns);
  const auto use = [&](int k) {
    if (k < 0 || 2 * k + 1 >= columns)
      throw std::invalid_argument("matched filter: no sensor " + std::to_string(k));
    w[2 * k] = noise.passages / (noise.sigma_z_kPa * noise.sigma_z_kPa);
    w[2 * k + 1] = noise.passages / (noise.sigma_x_kPa * noise.sigma_x_kPa);
  };
  if (sensors.empty())
    for (int k = 0; 2 * k + 1 < columns; ++k) use(k);
  for (int k : sensors) use(k);
  return w;
}

double normal_cdf(double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); }

double normal_quantile(double p) {
  if (!(p > 0 && p < 1)) throw std::invalid_argument("normal_quantile: p must lie in (0, 1)");
  double lo = -40, hi = 40;
  for (int i = 0; i < 200 && hi - lo > 1e-14; ++i) {
    const double mid = 0.5 * (lo + hi);
    (normal_cdf(mid) < p ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

double matched_filter_snr(const Eigen::MatrixXd& s, const SensorNoise& noise,
                          const std::vector<int>& sensors) {
  const Eigen::RowVectorXd w = filter_weights(static_cast<int>(s.cols()), noise, sensors);
  return std::sqrt((s.array().square().rowwise() * w.array()).sum());
}

double detection_threshold(double p_fa) { return normal_quantile(1 - p_fa); }
double detection_probability(double snr, double p_fa) {
  return 1 - normal_cdf(detection_threshold(p_fa) - snr);
}
double required_snr(double p_fa, double p_d) { return detection_threshold(p_fa) + normal_quantile(p_d); }

MonteCarloRates monte_carlo_rates(const Eigen::MatrixXd& s, const SensorNoise& noise,
                                  const std::vector<int>& sensors, double p_fa, int trials,
                                  std::uint64_t seed) {
  const Eigen::RowVectorXd w = filter_weights(static_cast<int>(s.cols()), noise, sensors);
  const double d = matched_filter_snr(s, noise, sensors), tau = detection_threshold(p_fa);
  if (!(d > 0)) throw std::invalid_argument("monte_carlo_rates: the signal is zero on the filter's sensors");
  // The filter's weights s_j/σ_j² / d, and per column the noise's standard deviation.
  const Eigen::MatrixXd filter = (s.array().rowwise() * w.array()).matrix() / d;
  Eigen::RowVectorXd sigma = Eigen::RowVectorXd::Zero(s.cols());
  for (int j = 0; j < s.cols(); ++j)
    if (w[j] > 0) sigma[j] = 1 / std::sqrt(w[j]);
  const double mean = d;  // Σ filter·s = d: the statistic with the hole is the noise's plus d
  SplitMix64 rng{seed};
  long above0 = 0, above1 = 0;
  for (int t = 0; t < trials; ++t) {
    double T = 0;
    for (int j = 0; j < s.cols(); ++j) {
      if (w[j] == 0) continue;
      for (int i = 0; i < s.rows(); ++i) T += filter(i, j) * sigma[j] * rng.normal();
    }
    above0 += T > tau;
    above1 += T + mean > tau;
  }
  MonteCarloRates r;
  r.trials = trials;
  r.false_alarm = double(above0) / trials;
  r.detection = double(above1) / trials;
  r.false_alarm_sigma = std::sqrt(p_fa * (1 - p_fa) / trials);
  const double pd = detection_probability(d, p_fa);
  r.detection_sigma = std::sqrt(pd * (1 - pd) / trials);
  return r;
}

}  // namespace skinfem::validation
