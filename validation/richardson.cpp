#include "skinfem/validation/richardson.hpp"

#include <cmath>

namespace skinfem::validation {

Richardson richardson(const std::array<double, 3>& q, const std::array<double, 3>& s, double max_order) {
  Richardson r;
  r.limit = q[2];
  const double d1 = q[0] - q[1], d2 = q[1] - q[2];
  if (!(d1 * d2 > 0 && std::abs(d2) < std::abs(d1))) return r;
  // (s₁ᵖ − s₂ᵖ)/(s₂ᵖ − s₃ᵖ) = d1/d2 grows with p (from ln(s₁/s₂)/ln(s₂/s₃) at p → 0): bisection on [1e-3,
  // 30].
  const auto ratio = [&](double p) {
    return (std::pow(s[0], p) - std::pow(s[1], p)) / (std::pow(s[1], p) - std::pow(s[2], p));
  };
  const double target = d1 / d2;
  double lo = 1e-3, hi = 30;
  if (!(ratio(lo) < target && target < ratio(hi))) return r;
  for (int it = 0; it < 200 && hi - lo > 1e-14 * hi; ++it) {
    const double mid = 0.5 * (lo + hi);
    (ratio(mid) < target ? lo : hi) = mid;
  }
  r.order = 0.5 * (lo + hi);
  if (r.order > max_order) {
    r.above_max_order = true;
    return r;
  }
  r.asymptotic = true;
  const double C = d2 / (std::pow(s[1], r.order) - std::pow(s[2], r.order));
  r.limit = q[2] - C * std::pow(s[2], r.order);
  return r;
}

double loglog_slope(const std::vector<double>& x, const std::vector<double>& y) {
  const size_t n = x.size();
  if (n < 2 || y.size() != n) return std::nan("");
  double mx = 0, my = 0;
  for (size_t i = 0; i < n; ++i) {
    if (!(x[i] > 0 && y[i] > 0)) return std::nan("");
    mx += std::log(x[i]) / n;
    my += std::log(y[i]) / n;
  }
  double sxy = 0, sxx = 0;
  for (size_t i = 0; i < n; ++i) {
    sxy += (std::log(x[i]) - mx) * (std::log(y[i]) - my);
    sxx += (std::log(x[i]) - mx) * (std::log(x[i]) - mx);
  }
  return sxx > 0 ? sxy / sxx : std::nan("");
}

}  // namespace skinfem::validation
