// Richardson extrapolation of a quantity computed on three meshes whose sizes are scaled by s₁ > s₂ > s₃:
// Q = Q∞ + C sᵖ through the three values, the observed order p solving (s₁ᵖ − s₂ᵖ)/(s₂ᵖ − s₃ᵖ) =
// (Q₁ − Q₂)/(Q₂ − Q₃) (for equal ratios r: p = ln|(Q₁ − Q₂)/(Q₂ − Q₃)| / ln r), then Q∞ = Q₃ − C s₃ᵖ.
// Only meaningful in the asymptotic regime: the two differences have the same sign and shrink, and p lies in
// [1e-3, max_order] (max_order ≤ 30: the highest order the discretization can give, with some room for
// superconvergence); otherwise `asymptotic` is false and the limit is the finest value. A p found above
// max_order is still returned, with above_max_order set: a steeper fall across unrelated meshes is a
// coincidence, not convergence.
#pragma once

#include <array>
#include <vector>

namespace skinfem::validation {

struct Richardson {
  bool asymptotic = false;
  bool above_max_order = false;
  double order = 0;  // p (0 when the differences change sign, grow or need p outside [1e-3, 30])
  double limit = 0;  // Q∞, or Q₃
};

Richardson richardson(const std::array<double, 3>& q, const std::array<double, 3>& scales,
                      double max_order = 30);

// Least-squares slope of log y against log x (y ≈ C xᵉ: the exponent e), over ≥ 2 points with x, y > 0;
// NaN otherwise. Used for the time-vs-DOFs exponent of each stage.
double loglog_slope(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace skinfem::validation
