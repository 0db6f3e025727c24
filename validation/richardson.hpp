// Richardson extrapolation of a quantity computed on three meshes whose sizes are scaled by s₁ > s₂ > s₃:
// Q = Q∞ + C sᵖ through the three values, the observed order p solving (s₁ᵖ − s₂ᵖ)/(s₂ᵖ − s₃ᵖ) =
// (Q₁ − Q₂)/(Q₂ − Q₃) (for equal ratios r: p = ln|(Q₁ − Q₂)/(Q₂ − Q₃)| / ln r), then Q∞ = Q₃ − C s₃ᵖ.
// Only meaningful in the asymptotic regime: the two differences have the same sign and shrink, and p lies in
// [1e-3, 30]; otherwise `asymptotic` is false and the limit is the finest value.
#pragma once

#include <array>
#include <vector>

namespace skinfem::validation {

struct Richardson {
  bool asymptotic = false;
  double order = 0;  // p (0 when not asymptotic)
  double limit = 0;  // Q∞, or Q₃
};

Richardson richardson(const std::array<double, 3>& q, const std::array<double, 3>& scales);

// Least-squares slope of log y against log x (y ≈ C xᵉ: the exponent e), over ≥ 2 points with x, y > 0;
// NaN otherwise. Used for the time-vs-DOFs exponent of each stage.
double loglog_slope(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace skinfem::validation
