// Fitting the k-rescaled (docs/theory.md §Conventions) half-space Green tensor to a layer's Green tensor.
#pragma once

#include <cmath>
#include <optional>
#include <vector>

#include "skinfem/green/halfspace.hpp"

namespace skinfem::green {

// The paper's k (§III (iii), fig. 4), given to 3 digits: a k reproduces it when within 1 % (its last digit
// plus the FE's own error, 0.1 %).
inline constexpr double kPaperK = 1.48;
inline constexpr double kPaperKRelTolerance = 0.01;
inline bool reproduces_paper_k(double k) { return k > 0 && std::abs(k / kPaperK - 1) < kPaperKRelTolerance; }

struct KFit {
  double k = 0;                       ///< best rescaling factor in [kMinK, kMaxK]
  double gain = 1;                    ///< the model's: as given, or fitted
  double rms_residual_over_peak = 0;  ///< √(mean (model − g)²) / max|g|
};

/// The range searched for k. A post concentrates the stress over its top, so its k (a narrower, taller map of
/// the same integral) reaches 7 for the paper's post; a disc's stays within [1, 2].
inline constexpr double kMinK = 0.25, kMaxK = 16;

/// Least-squares fit, uniform weights, of gain·rescaled_green(x_i, 0, h, k).<component> to the samples g_i
/// taken on the line y = 0 at offsets x_i (force − sensor, mm); the gain (the sensor's reading under a
/// uniform unit load, green/calibration.hpp's ChannelGains) holds the model's integral. Minimises over k ∈
/// [kMinK, kMaxK] by a coarse logarithmic scan followed by golden section search in the bracket around the
/// best scan point (relative bracket width 1e-12 at exit). Throws std::invalid_argument on empty or
/// mismatched inputs, h ≤ 0 or gain ≤ 0, and std::domain_error when the minimum lies at a bound of the range
/// (no fit: the bound is not an answer). Without a gain (std::nullopt) the gain is fitted too: at each k,
/// the linear least-squares amplitude of the model.
KFit fit_k_line(const std::vector<double>& x, const std::vector<double>& g, double h,
                GreenComponent component, std::optional<double> gain = 1.0);

/// Amplitude ratio g_zz(0) / (3/(2πh²)): the k for which the rescaled model matches the layer at zero offset
/// (the rescaled model gives k·3/(2πh²) there).
double k_central(double g_zz_at_zero, double h);

}  // namespace skinfem::green
