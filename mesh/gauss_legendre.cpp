#include "skinfem/mesh/gauss_legendre.hpp"

#include <cmath>

namespace skinfem {

GaussRule1d gauss_legendre01(int n) {
  GaussRule1d rule;
  rule.x.resize(n);
  rule.w.resize(n);
  for (int i = 0; i < n; ++i) {
    double z = std::cos(M_PI * (i + 0.75) / (n + 0.5)), dp = 1.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1, p1 = z;
      for (int k = 2; k <= n; ++k) {
        const double pk = ((2.0 * k - 1) * z * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = pk;
      }
      dp = n * (z * p1 - p0) / (z * z - 1);
      const double dz = p1 / dp;
      z -= dz;
      if (std::abs(dz) < 1e-16) break;
    }
    rule.x[i] = 0.5 * (1 - z);
    rule.w[i] = 1.0 / ((1 - z * z) * dp * dp);  // half the weight on [−1, 1]
  }
  return rule;
}

std::vector<std::array<double, 3>> uniform_disc_rule(double radius, int nr, int nt) {
  const GaussRule1d g = gauss_legendre01(nr);
  std::vector<std::array<double, 3>> pts;
  pts.reserve(static_cast<size_t>(nr) * nt);
  for (int i = 0; i < nr; ++i)
    for (int j = 0; j < nt; ++j) {
      const double th = 2 * M_PI * (j + 0.5) / nt, r = radius * g.x[i];
      pts.push_back({r * std::cos(th), r * std::sin(th), 2 * g.w[i] * g.x[i] / nt});
    }
  return pts;
}

}  // namespace skinfem
