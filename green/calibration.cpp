#include "skinfem/green/calibration.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

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

KReport fit_profile(const std::vector<double>& x, const std::vector<GreenSample>& g, double h,
                    ChannelGains gains) {
  KReport r;
  r.gains = gains;
  size_t zero = x.size();
  for (size_t i = 0; i < x.size(); ++i)
    if (std::abs(x[i]) < 1e-12) zero = i;
  if (zero == x.size()) throw std::invalid_argument("fit_profile: offset 0 missing");
  std::vector<double> xs;
  for (size_t i = 0; i < x.size(); ++i)
    if (std::abs(x[i]) <= 3 * h + 1e-12) xs.push_back(x[i]);
  for (size_t c = 0; c < 4; ++c) {
    std::vector<double> v;
    for (size_t i = 0; i < x.size(); ++i)
      if (std::abs(x[i]) <= 3 * h + 1e-12) v.push_back(component(g[i], kComponents[c]));
    r.components[c] = fit_k_line(xs, v, h, kComponents[c], gains.of(kComponents[c]));
  }
  r.k_lsq_line = r.components[0].k;
  r.k_central = k_central(g[zero].zz, h) / r.components[0].gain;
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

namespace {
// Golden section for the minimum of a thickness misfit on [lo, hi] (to 1e-6 of h0); a minimum at a bound
// is no fit. misfit(h, stop) may return early, with any value above `stop`, once its sum exceeds it: a
// sum of squares only grows term by term, so the comparison that needs it has its answer, and the
// search keeps only the smaller of the two values it compares. The search's steps, and its result, are
// those of the full sums.
template <class Misfit>
double best_thickness(const Misfit& misfit, double lo, double hi, double h0, const char* what) {
  constexpr double kNone = std::numeric_limits<double>::infinity();
  double a = lo, b = hi;
  const double phi = 0.5 * (std::sqrt(5.0) - 1);
  double c = b - phi * (b - a), d = a + phi * (b - a), fc = misfit(c, kNone), fd = misfit(d, fc);
  while (b - a > 1e-6 * h0) {
    if (fc < fd) {
      b = d, d = c, fd = fc;
      // fc is kept only if fc < fd: a sum past the largest value below fd has answered.
      c = b - phi * (b - a), fc = misfit(c, std::nextafter(fd, 0.0));
    } else {
      a = c, c = d, fc = fd;
      d = a + phi * (b - a), fd = misfit(d, fc);  // fd is kept only if fd <= fc
    }
  }
  const double h = 0.5 * (a + b);
  if (h - lo < 1e-5 * h0 || hi - h < 1e-5 * h0)
    throw std::domain_error(std::string(what) + ": the best thickness lies at the bound " +
                            std::to_string(h).substr(0, 5) + " mm of [" + std::to_string(lo).substr(0, 5) +
                            ", " + std::to_string(hi).substr(0, 5) + "] mm; no layer fits this scan");
  return h;
}

// The exact layer of thickness h along the offsets (y = 0).
std::vector<GreenSample> layer_line(double h, double nu, LayerLoad load, double radius,
                                    const std::vector<double>& x) {
  const LayerGreen layer(h, nu, load, radius);
  std::vector<GreenSample> out;
  for (double xi : x) out.push_back(layer.at(xi, 0.0));
  return out;
}

// Σ m g / Σ m²: the scale s minimising Σ (s m − g)².
double linear_scale(const std::vector<double>& m, const std::vector<double>& g) {
  double mg = 0, mm = 0;
  for (size_t i = 0; i < m.size(); ++i) mg += m[i] * g[i], mm += m[i] * m[i];
  return mm > 0 ? mg / mm : 0.0;
}

double rms_over_peak(const std::vector<double>& m, double s, const std::vector<double>& g) {
  double r = 0, peak = 0;
  for (size_t i = 0; i < m.size(); ++i)
    r += std::pow(s * m[i] - g[i], 2), peak = std::max(peak, std::abs(g[i]));
  return peak > 0 ? std::sqrt(r / m.size()) / peak : 0.0;
}
}  // namespace

double effective_thickness(const std::vector<double>& x, const std::vector<double>& g_zz, double h0,
                           double nu, LayerLoad load, double radius) {
  auto misfit = [&](double h, double stop) {
    const LayerGreen layer(h, nu, load, radius);
    double s = 0;
    for (size_t i = 0; i < x.size() && !(s > stop); ++i) s += std::pow(layer.zz_at(x[i], 0.0) - g_zz[i], 2);
    return s;
  };
  return best_thickness(misfit, 0.5 * h0, 1.5 * h0, h0, "effective thickness");
}

PaperCalibration paper_calibration(const std::vector<double>& x, const std::vector<GreenSample>& g, double h0,
                                   double nu, LayerLoad load, double radius) {
  std::vector<double> zz, zx;
  for (const GreenSample& s : g) zz.push_back(s.zz), zx.push_back(s.zx);
  const auto layer_at = [&](double h, std::vector<double>& mz, std::vector<double>& mx) {
    mz.clear(), mx.clear();
    for (const GreenSample& s : layer_line(h, nu, load, radius, x)) mz.push_back(s.zz), mx.push_back(s.zx);
  };
  std::vector<double> mz, mx;
  const auto misfit = [&](double h, double /*stop: the scale needs every term*/) {
    layer_at(h, mz, mx);
    const double s = linear_scale(mz, zz);
    double r = 0;
    for (size_t i = 0; i < x.size(); ++i) r += std::pow(s * mz[i] - zz[i], 2);
    return r;
  };
  PaperCalibration c;
  c.thickness_mm = best_thickness(misfit, 0.25 * h0, 2.0 * h0, h0, "paper calibration");
  layer_at(c.thickness_mm, mz, mx);
  c.scale_z = linear_scale(mz, zz);
  c.scale_x = linear_scale(mx, zx);
  c.rms_z_over_peak = rms_over_peak(mz, c.scale_z, zz);
  c.rms_x_over_peak = rms_over_peak(mx, c.scale_x, zx);
  return c;
}

}  // namespace skinfem::green
