// A hole at an unknown place: the matched filter (validation/detection.hpp) slid along a scan of length L,
// the hole declared where its maximum exceeds a threshold.
//
// Without a hole, T(q) = Σ_ij w_j s_ij y_{q+i,j} / d at every shift q is a stationary Gaussian process of
// unit variance (w_j = 1/σ_j², d the filter's SNR) whose correlation is the template's own,
// ρ(q) = Σ_ij w_j s_ij s_{i+q,j} / d². The chance that its maximum over the scan exceeds τ follows from
// Rice's formula for the expected number of upcrossings (Rice, Bell Syst. Tech. J. 24, 1945, §3.3; Adler &
// Taylor, Random Fields and Geometry, 2007, §11.7):
//   P(max T > τ) ≈ 1 − Φ(τ) + L √λ₂ / (2π) · exp(−τ²/2),  λ₂ = −ρ''(0) = Σ_ij w_j (s_{i+1,j} − s_ij)² / (d
//   Δ)²,
// Δ the sample spacing. It bounds the continuous scan's false-alarm rate from above and is tight when the
// rate is small; on the sampled scan the maximum is a little lower, so the threshold errs on the safe side.
// It lies between the known place's Φ⁻¹(1 − p_fa) and Bonferroni's Φ⁻¹(1 − p_fa / M) over M shifts.
#pragma once

#include <Eigen/Dense>
#include <cstdint>
#include <vector>

#include "skinfem/validation/detection.hpp"

namespace skinfem::validation {

// √λ₂ (1/mm): how fast the filter's output decorrelates along the scan. signal: samples × 2·sensors, kPa,
// sample_mm apart; sensors: the filter's (empty: all).
double scan_decorrelation(const Eigen::MatrixXd& signal, const SensorNoise& noise,
                          const std::vector<int>& sensors, double sample_mm);

// τ with Rice's P(max T > τ) = p_fa over a scan of length_mm, by bisection.
double scan_threshold(double decorrelation_per_mm, double length_mm, double p_fa);

// The slid filter on `trials` noise-only scans of length_mm (splitmix64 from `seed`, the draws split over the
// machine's cores in a fixed way): the fraction whose maximum exceeds tau, with its binomial standard error
// at p_fa; and with the signal placed at the scan's middle, the fraction whose maximum exceeds tau (at least
// 1 − Φ(tau − d), the known place's, since the maximum is at least T there).
MonteCarloRates monte_carlo_scan(const Eigen::MatrixXd& signal, const SensorNoise& noise,
                                 const std::vector<int>& sensors, double sample_mm, double length_mm,
                                 double tau, double p_fa, int trials, std::uint64_t seed);

}  // namespace skinfem::validation
