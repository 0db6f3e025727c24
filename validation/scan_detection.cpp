#include "skinfem/validation/scan_detection.hpp"

#include <cmath>
#include <stdexcept>

#include "skinfem/scene/parallel.hpp"
#include "skinfem/scene/random.hpp"

namespace skinfem::validation {

namespace {
// Per column, 1/σ² (filter_weights) and σ (0 for a sensor left out).
struct Columns {
  Eigen::RowVectorXd w, sigma;
};
Columns columns(int cols, const SensorNoise& noise, const std::vector<int>& sensors) {
  Columns c{filter_weights(cols, noise, sensors), Eigen::RowVectorXd::Zero(cols)};
  for (int j = 0; j < cols; ++j)
    if (c.w[j] > 0) c.sigma[j] = 1 / std::sqrt(c.w[j]);
  return c;
}

int shifts_of(double sample_mm, double length_mm) {
  if (!(sample_mm > 0) || !(length_mm >= 0))
    throw std::invalid_argument("scanned filter: sample_mm > 0 and length_mm >= 0");
  return static_cast<int>(std::lround(length_mm / sample_mm)) + 1;
}
}  // namespace

double scan_decorrelation(const Eigen::MatrixXd& s, const SensorNoise& noise, const std::vector<int>& sensors,
                          double sample_mm) {
  const Columns c = columns(static_cast<int>(s.cols()), noise, sensors);
  if (!(sample_mm > 0) || s.rows() < 2)
    throw std::invalid_argument("scan_decorrelation: two samples, sample_mm > 0");
  const double d2 = (s.array().square().rowwise() * c.w.array()).sum();
  if (!(d2 > 0))
    throw std::invalid_argument("scan_decorrelation: the signal is zero on the filter's sensors");
  // The template is zero beyond its ends: the first and last differences are its own values.
  Eigen::MatrixXd ds = Eigen::MatrixXd::Zero(s.rows() + 1, s.cols());
  ds.topRows(s.rows()) += s;
  ds.bottomRows(s.rows()) -= s;
  const double e2 = (ds.array().square().rowwise() * c.w.array()).sum();
  return std::sqrt(e2 / d2) / sample_mm;
}

double scan_threshold(double rate, double length_mm, double p_fa) {
  if (!(p_fa > 0 && p_fa < 1) || !(rate >= 0) || !(length_mm >= 0))
    throw std::invalid_argument("scan_threshold: p_fa in (0, 1), rate and length >= 0");
  const auto p = [&](double tau) {
    return 1 - normal_cdf(tau) + length_mm * rate / (2 * M_PI) * std::exp(-0.5 * tau * tau);
  };
  double lo = normal_quantile(1 - p_fa), hi = lo + 40;  // p decreases in τ from p(lo) ≥ p_fa
  for (int i = 0; i < 200 && hi - lo > 1e-12; ++i) {
    const double mid = 0.5 * (lo + hi);
    (p(mid) > p_fa ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

MonteCarloRates monte_carlo_scan(const Eigen::MatrixXd& s, const SensorNoise& noise,
                                 const std::vector<int>& sensors, double sample_mm, double length_mm,
                                 double tau, double p_fa, int trials, std::uint64_t seed) {
  const Columns c = columns(static_cast<int>(s.cols()), noise, sensors);
  const int M = shifts_of(sample_mm, length_mm), rows = static_cast<int>(s.rows());
  if (trials < 1) throw std::invalid_argument("monte_carlo_scan: trials >= 1");
  const double d = std::sqrt((s.array().square().rowwise() * c.w.array()).sum());
  if (!(d > 0)) throw std::invalid_argument("monte_carlo_scan: the signal is zero on the filter's sensors");
  const Eigen::MatrixXd filter = (s.array().rowwise() * c.w.array()).matrix() / d;
  // The hole placed at the middle shift: what it adds to the statistic at every shift, ρ(q − mid) d.
  const int mid = (M - 1) / 2;
  Eigen::VectorXd added = Eigen::VectorXd::Zero(M);
  for (int q = std::max(0, mid - rows + 1); q < std::min(M, mid + rows); ++q) {
    const int k = std::abs(q - mid), n = rows - k;
    added[q] = q >= mid ? (filter.topRows(n).array() * s.bottomRows(n).array()).sum()
                        : (filter.bottomRows(n).array() * s.topRows(n).array()).sum();
  }
  // Blocks of draws, each its own stream: the same counts on any number of threads.
  constexpr int kBlock = 64;
  const int blocks = (trials + kBlock - 1) / kBlock;
  std::vector<long> above0(blocks, 0), above1(blocks, 0);
  for_each_index(blocks, [&](std::size_t b) {
    // The block's stream starts at a hashed state: seed + k·γ would restart the previous block's stream
    // one draw later (splitmix64 steps its state by γ).
    SplitMix64 rng{SplitMix64{seed ^ (0xbf58476d1ce4e5b9ULL * (b + 1))}.next()};
    Eigen::MatrixXd y(M + rows - 1, s.cols());
    for (int t = static_cast<int>(b) * kBlock; t < std::min(trials, static_cast<int>(b + 1) * kBlock); ++t) {
      for (Eigen::Index j = 0; j < y.cols(); ++j)
        for (Eigen::Index i = 0; i < y.rows(); ++i)
          y(i, j) = c.sigma[j] > 0 ? c.sigma[j] * rng.normal() : 0.0;
      double max0 = -1e300, max1 = -1e300;
      for (int q = 0; q < M; ++q) {
        const double T = (filter.array() * y.middleRows(q, rows).array()).sum();
        max0 = std::max(max0, T);
        max1 = std::max(max1, T + added[q]);
      }
      above0[b] += max0 > tau;
      above1[b] += max1 > tau;
    }
  });
  long a0 = 0, a1 = 0;
  for (int b = 0; b < blocks; ++b) a0 += above0[b], a1 += above1[b];
  MonteCarloRates r;
  r.trials = trials;
  r.false_alarm = double(a0) / trials;
  r.false_alarm_sigma = std::sqrt(p_fa * (1 - p_fa) / trials);
  r.detection = double(a1) / trials;
  r.detection_sigma = std::sqrt(std::max(r.detection * (1 - r.detection), 1.0 / trials) / trials);
  return r;
}

}  // namespace skinfem::validation
