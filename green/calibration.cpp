#include "green/calibration.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

namespace skinfem::green {

const char* component_name(GreenComponent c) {
  switch (c) {
    case GreenComponent::zz:
      return "zz";
    case GreenComponent::zx:
      return "zx";
    case GreenComponent::xz:
      return "xz";
    default:
      return "xx";
  }
}

ScanProfile scan_profile(const SensorGreen& g, LayerLoad load, double radius, double half_width,
                         double spacing) {
  ScanProfile p;
  const int n = static_cast<int>(std::floor(half_width / spacing + 1e-9));
  for (int i = -n; i <= n; ++i) {
    const double x = i * spacing;
    p.offset_x.push_back(x);
    p.point.push_back(g(false, x, 0.0, load, radius));
    p.disc.push_back(g(true, x, 0.0, load, radius));
  }
  return p;
}

KReport fit_profile(const std::vector<double>& x, const std::vector<GreenSample>& g, double h) {
  KReport r;
  size_t zero = x.size();
  for (size_t i = 0; i < x.size(); ++i)
    if (std::abs(x[i]) < 1e-12) zero = i;
  if (zero == x.size()) throw std::invalid_argument("fit_profile: offset 0 missing");
  r.k_central = k_central(g[zero].zz, h);
  std::vector<double> xs, zz;
  for (size_t i = 0; i < x.size(); ++i)
    if (std::abs(x[i]) <= 3 * h + 1e-12) xs.push_back(x[i]), zz.push_back(g[i].zz);
  r.k_lsq_line = fit_k_line(xs, zz, h, GreenComponent::zz).k;
  for (size_t c = 0; c < 4; ++c) {
    std::vector<double> v;
    for (size_t i = 0; i < x.size(); ++i)
      if (std::abs(x[i]) <= 3 * h + 1e-12) v.push_back(component(g[i], kComponents[c]));
    r.components[c] = fit_k_line(xs, v, h, kComponents[c]);
  }
  return r;
}

std::vector<GreenSample> exact_profile(const LayerGreen& layer, const std::vector<double>& x,
                                       double disc_diameter) {
  std::optional<LayerGreen> disc;
  if (disc_diameter > 0)
    disc.emplace(layer.thickness(), layer.poisson_ratio(), layer.load(), layer.load_radius(),
                 LayerQuadrature{}, 0.5 * disc_diameter);
  const LayerGreen& g = disc ? *disc : layer;
  std::vector<GreenSample> out;
  for (double xi : x) out.push_back(g.at(xi, 0));
  return out;
}

double peak_abs(const std::vector<GreenSample>& profile, GreenComponent c) {
  double p = 0;
  for (const auto& g : profile) p = std::max(p, std::abs(component(g, c)));
  return p;
}

std::array<double, 4> max_error_over_peak(const std::vector<GreenSample>& fe,
                                          const std::vector<GreenSample>& exact) {
  std::array<double, 4> out{};
  for (size_t c = 0; c < 4; ++c) {
    double peak = 0, err = 0;
    for (size_t i = 0; i < exact.size(); ++i) {
      peak = std::max(peak, std::abs(component(exact[i], kComponents[c])));
      err = std::max(err, std::abs(component(fe[i], kComponents[c]) - component(exact[i], kComponents[c])));
    }
    out[c] = err / peak;
  }
  return out;
}

double effective_thickness(const std::vector<double>& x, const std::vector<double>& g_zz, double h0,
                           double nu, LayerLoad load, double radius) {
  auto misfit = [&](double h) {
    const LayerGreen layer(h, nu, load, radius);
    double s = 0;
    for (size_t i = 0; i < x.size(); ++i) s += std::pow(layer.at(x[i], 0.0).zz - g_zz[i], 2);
    return s;
  };
  double a = 0.5 * h0, b = 1.5 * h0;
  const double phi = 0.5 * (std::sqrt(5.0) - 1);
  double c = b - phi * (b - a), d = a + phi * (b - a), fc = misfit(c), fd = misfit(d);
  while (b - a > 1e-6 * h0) {
    if (fc < fd) {
      b = d, d = c, fd = fc;
      c = b - phi * (b - a), fc = misfit(c);
    } else {
      a = c, c = d, fc = fd;
      d = a + phi * (b - a), fd = misfit(d);
    }
  }
  return 0.5 * (a + b);
}

}  // namespace skinfem::green
