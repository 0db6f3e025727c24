#include "skinfem/green/kfit.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace skinfem::green {
KFit fit_k_line(const std::vector<double>& x, const std::vector<double>& g, double h,
                GreenComponent component, std::optional<double> gain) {
  if (x.empty() || x.size() != g.size())
    throw std::invalid_argument("fit_k_line: need equally many x and g samples");
  if (!(h > 0.0)) throw std::invalid_argument("fit_k_line: h must be > 0");
  if (gain && !(*gain > 0.0)) throw std::invalid_argument("fit_k_line: the gain must be > 0");
  double peak = 0.0;
  for (double v : g) peak = std::max(peak, std::fabs(v));
  if (!(peak > 0.0)) throw std::invalid_argument("fit_k_line: samples are all zero");

  // The model at k and its gain: as given, or the amplitude c minimising Σ(c m_i − g_i)², c = Σ m g / Σ m².
  std::vector<double> m(x.size());
  const auto gain_at = [&](double k) {
    double mg = 0.0, mm = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      m[i] = green::component(rescaled_green(x[i], 0.0, h, k), component);
      mg += m[i] * g[i];
      mm += m[i] * m[i];
    }
    if (gain) return *gain;
    return mm > 0 ? mg / mm : 0.0;
  };
  const auto cost = [&](double k) {
    const double c = gain_at(k);  // fills m
    double sum = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) sum += (c * m[i] - g[i]) * (c * m[i] - g[i]);
    return sum;
  };

  // Coarse scan: 281 points, logarithmic in k (spacing 1.5 %); the cost is smooth in k, so the global minimum
  // of the scan brackets the minimiser between its neighbours unless the cost has a second minimum within 1.5
  // % — not the case for these one-parameter families.
  constexpr int n_scan = 281;
  std::vector<double> ks(n_scan), cs(n_scan);
  for (int i = 0; i < n_scan; ++i) {
    ks[i] = kMinK * std::pow(kMaxK / kMinK, static_cast<double>(i) / (n_scan - 1));
    cs[i] = cost(ks[i]);
  }
  const int best = static_cast<int>(std::min_element(cs.begin(), cs.end()) - cs.begin());
  // A minimum at the scan's edge is the bound, not a fit: the rescaled half-space does not fit these samples.
  if (best == 0 || best == n_scan - 1)
    throw std::domain_error("k fit: the least-squares minimum lies at the search bound k = " +
                            std::to_string(ks[best]).substr(0, 4) + " of [" +
                            std::to_string(kMinK).substr(0, 4) + ", " + std::to_string(kMaxK).substr(0, 2) +
                            "]; the k-rescaled half-space does not fit this skin (h = " + std::to_string(h) +
                            " mm)");
  double lo = ks[std::max(best - 1, 0)], hi = ks[std::min(best + 1, n_scan - 1)];

  // Golden section on [lo, hi].
  const double invphi = (std::sqrt(5.0) - 1.0) / 2.0;
  double c = hi - invphi * (hi - lo), d = lo + invphi * (hi - lo);
  double fc = cost(c), fd = cost(d);
  while (hi - lo > 1e-12 * hi) {
    if (fc < fd) {
      hi = d;
      d = c;
      fd = fc;
      c = hi - invphi * (hi - lo);
      fc = cost(c);
    } else {
      lo = c;
      c = d;
      fc = fd;
      d = lo + invphi * (hi - lo);
      fd = cost(d);
    }
  }
  KFit fit;
  fit.k = 0.5 * (lo + hi);
  fit.gain = gain_at(fit.k);
  fit.rms_residual_over_peak = std::sqrt(cost(fit.k) / static_cast<double>(x.size())) / peak;
  return fit;
}

double k_central(double g_zz_at_zero, double h) {
  if (!(h > 0.0)) throw std::invalid_argument("k_central: h must be > 0");
  return g_zz_at_zero / (3.0 / (2.0 * M_PI * h * h));
}

}  // namespace skinfem::green
