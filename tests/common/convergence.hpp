// Observed convergence order over several refinement levels (MFEM ConvergenceStudy style): the
// least-squares slope of log(error) against log(h).
#pragma once

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

}  // namespace skinfem::testing
