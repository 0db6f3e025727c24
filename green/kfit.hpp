// Fitting the k-rescaled (docs/theory.md §Conventions) half-space Green tensor to a layer's Green tensor.
#pragma once

#include <cmath>
#include <vector>

#include "green/halfspace.hpp"

namespace skinfem::green {

// The paper's k (§III (iii), fig. 4), given to 3 digits: a k reproduces it when within 1 % (its last digit
// plus the FE's own error, 0.1 %).
inline constexpr double kPaperK = 1.48;
inline constexpr double kPaperKRelTolerance = 0.01;
inline bool reproduces_paper_k(double k) { return k > 0 && std::abs(k / kPaperK - 1) < kPaperKRelTolerance; }

struct KFit {
  double k = 0;                       ///< best rescaling factor in [0.5, 4]
  double gain = 1;                    ///< c of the model c·k·g_half(√k x): 1 unless fitted
  double rms_residual_over_peak = 0;  ///< √(mean (model − g)²) / max|g|
};

/// Whether the fit holds the model's integral ∬g dA at the half space's (gain 1) or fits it too. A reading
/// of base traction has gain 1 by equilibrium (a uniform pressure on a flat layer is read exactly); a post
/// standing in the skin concentrates the stress and has no such law, so its gain is a second parameter.
enum class Gain { fixed, fitted };

/// Least-squares fit, uniform weights, of rescaled_green(x_i, 0, h, k).<component> to the samples g_i taken
/// on the line y = 0 at offsets x_i (force − sensor, mm). Minimises over k ∈ [0.5, 4] by a coarse logarithmic
/// scan followed by golden section search in the bracket around the best scan point (relative bracket width
/// 1e-12 at exit). Throws std::invalid_argument on empty or mismatched inputs or h ≤ 0, and
/// std::domain_error when the minimum lies at a bound of [0.5, 4] (no fit: the bound is not an answer).
/// With Gain::fitted the gain c is, at each k, the linear least-squares amplitude of the model.
KFit fit_k_line(const std::vector<double>& x, const std::vector<double>& g, double h,
                GreenComponent component, Gain gain = Gain::fixed);

/// Amplitude ratio g_zz(0) / (3/(2πh²)): the k for which the rescaled model matches the layer at zero offset
/// (the rescaled model gives k·3/(2πh²) there).
double k_central(double g_zz_at_zero, double h);

}  // namespace skinfem::green
