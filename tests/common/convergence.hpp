// Observed convergence order over several refinement levels (MFEM ConvergenceStudy style): the
// least-squares slope of log(error) against log(h).
#pragma once

#include <array>
#include <cmath>
#include <vector>

namespace skinfem::testing {

inline double observed_order(const std::vector<double>& h, const std::vector<double>& err) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double n = h.size();
  for (size_t i = 0; i < h.size(); ++i) {
    const double x = std::log(h[i]), y = std::log(err[i]);
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

// The order of a sequence q0, q1, q2 converging to an unknown limit with the step shrinking by `ratio` per
// level: |q0 − q1| / |q1 − q2| = ratio^order (Richardson; no exact value needed).
inline double order_from_differences(const std::array<double, 3>& q, double ratio) {
  return std::log(std::abs(q[0] - q[1]) / std::abs(q[1] - q[2])) / std::log(ratio);
}

}  // namespace skinfem::testing
