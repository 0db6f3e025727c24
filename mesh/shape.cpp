#include "skinfem/mesh/shape.hpp"

#include <cmath>
#include <vector>

#include "skinfem/mesh/gauss_legendre.hpp"

namespace skinfem {

SkinShape::SkinShape(const Geometry& geometry)
    : kind_(geometry.kind), cap_(geometry.cap), flat_(geometry.flat), ridges_(geometry.ridges) {}

namespace {
// The ridges' window: 1 up to one period inside the patterned disc, then a half cosine to 0 at its edge.
double ridge_window(double rho, const Ridges& r) {
  const double inner = r.radius - r.period;
  if (rho <= inner) return 1.0;
  return rho < r.radius ? 0.5 * (1 + std::cos(M_PI * (rho - inner) / r.period)) : 0.0;
}
}  // namespace

namespace {
// The profile P(ξ) of scene.hpp's Ridges, in [−1, 1] with a crest at ξ = 0.
double ridge_profile(double xi, const Ridges& r) {
  const double k = 2 * M_PI / r.period;
  if (r.profile == RidgeProfile::sinusoidal) return std::cos(k * xi);
  // Distance from the nearest crest, in [0, period/2]; the walls are centred on period/4.
  const double d = std::abs(xi - r.period * std::round(xi / r.period));
  const double s = (d - 0.25 * r.period) / r.edge_width;  // in [−1/2, 1/2] across the wall
  if (s <= -0.5) return 1.0;
  return s >= 0.5 ? -1.0 : -std::sin(M_PI * s);
}
}  // namespace

double SkinShape::ridge_z(double x, double y) const {
  if (!ridges_.present()) return 0;
  const double dx = x - ridges_.center[0], dy = y - ridges_.center[1];
  const double w = ridge_window(std::hypot(dx, dy), ridges_);
  if (w == 0) return 0;
  const double theta = ridges_.angle_deg * M_PI / 180;
  return 0.5 * ridges_.height * w * ridge_profile(dx * std::cos(theta) + dy * std::sin(theta), ridges_);
}

double SkinShape::mean_top_z(double x, double y) const {
  if (kind_ != GeometryKind::cap) return flat_.h;
  const double dx = x - cap_.apex_x, dy = y - cap_.apex_y;
  if (cap_.spherical()) return cap_.h - cap_.R + std::sqrt(cap_.R * cap_.R - dx * dx - dy * dy);
  const double u = dx / cap_.semi_axis_x(), v = dy / cap_.semi_axis_y(), c = cap_.semi_axis_z();
  return cap_.h - c + c * std::sqrt(1 - u * u - v * v);
}

bool SkinShape::covers(double x, double y) const {
  if (kind_ == GeometryKind::surface) return true;
  if (kind_ == GeometryKind::flat) {
    const double w = flat_.half_width * (1 + 1e-9);
    return std::abs(x) <= w && std::abs(y) <= w;
  }
  return std::hypot(x - cap_.apex_x, y - cap_.apex_y) <= cap_.truncation_radius * (1 + 1e-9);
}

Vec3 SkinShape::on_side(const Vec3& p) const {
  if (kind_ != GeometryKind::cap) return p;
  const double dx = p[0] - cap_.apex_x, dy = p[1] - cap_.apex_y;
  const double scale = cap_.truncation_radius / std::hypot(dx, dy);
  return {cap_.apex_x + scale * dx, cap_.apex_y + scale * dy, p[2]};
}

namespace {
// The profile's cosine series P(ξ) = Σ_n c_n cos(n k ξ), k = 2π/period: P is even and P(ξ + period/2) =
// −P(ξ), so only odd n appear and c_n = (4/period) ∫₀^{period/2} P cos(nkξ) dξ, by Gauss on the plateaus and
// the wall separately (each piece is smooth) and on panels shorter than a quarter of the harmonic's period.
std::vector<double> profile_series(const Ridges& r, int n_max) {
  std::vector<double> c(n_max + 1, 0.0);
  if (r.profile == RidgeProfile::sinusoidal) {
    c[1] = 1;
    return c;
  }
  const double k = 2 * M_PI / r.period, a = 0.25 * r.period - 0.5 * r.edge_width;
  const double b = 0.25 * r.period + 0.5 * r.edge_width;
  const GaussRule1d g = gauss_legendre01(8);
  for (int n = 1; n <= n_max; n += 2) {
    const auto integrate = [&](double lo, double hi) {
      const int panels = 1 + static_cast<int>(4 * n * (hi - lo) / r.period);
      double v = 0;
      for (int p = 0; p < panels; ++p)
        for (size_t i = 0; i < g.x.size(); ++i) {
          const double xi = lo + (hi - lo) * (p + g.x[i]) / panels;
          v += g.w[i] * (hi - lo) / panels * ridge_profile(xi, r) * std::cos(n * k * xi);
        }
      return v;
    };
    c[n] = 4 / r.period * (integrate(0, a) + integrate(a, b) + integrate(b, 0.5 * r.period));
  }
  return c;
}

// ∬ ridge_z dA over the pattern: the angular mean of cos(n k ρ cos φ) is J0(n k ρ), so harmonic n contributes
// c_n (height/2) 2π ∫₀^R w(ρ) J0(nkρ) ρ dρ, by Gauss on panels a quarter of its period long. The rectangular
// profile is C¹, so c_n falls as n⁻³, and the radial integral as n^−3.5 (measured for walls of period/8 to
// period/2): the terms fall as n^−6.5, and the 63rd is 1e-13 of the sum.
double ridges_volume(const Ridges& r) {
  if (!r.present()) return 0;
  constexpr int kHarmonics = 63;
  const std::vector<double> c = profile_series(r, kHarmonics);
  const double k = 2 * M_PI / r.period, R = r.radius;
  const GaussRule1d g = gauss_legendre01(8);
  double v = 0;
  for (int n = 1; n <= kHarmonics; n += 2) {
    if (c[n] == 0) continue;
    const int panels = static_cast<int>(std::ceil(4 * n * R / r.period));
    double vn = 0;
    for (int p = 0; p < panels; ++p)
      for (size_t i = 0; i < g.x.size(); ++i) {
        const double rho = R * (p + g.x[i]) / panels;
        vn += g.w[i] * R / panels * ridge_window(rho, r) * std::cyl_bessel_j(0.0, n * k * rho) * rho;
      }
    v += c[n] * vn;
  }
  return 0.5 * r.height * 2 * M_PI * v;
}
}  // namespace

double SkinShape::volume() const { return smooth_volume() + ridges_volume(ridges_); }

double SkinShape::smooth_volume() const {
  if (kind_ != GeometryKind::cap) return base_area() * flat_.h;
  const double R = cap_.R, rt = cap_.truncation_radius;
  // ∫₀^rt 2πr (h − R + sqrt(R² − r²)) dr
  if (cap_.spherical())
    return M_PI * rt * rt * (cap_.h - R) + 2.0 * M_PI / 3.0 * (R * R * R - std::pow(R * R - rt * rt, 1.5));
  // Ellipsoid: the top is smooth and positive up to rt < rim, so Gauss in r and the (spectrally accurate)
  // periodic trapezoid rule in θ reach round-off.
  const GaussRule1d g = gauss_legendre01(48);
  constexpr int nt = 256;
  double v = 0;
  for (size_t i = 0; i < g.x.size(); ++i)
    for (int j = 0; j < nt; ++j) {
      const double r = rt * g.x[i], th = 2 * M_PI * j / nt;
      v += g.w[i] * rt * r * (2 * M_PI / nt) *
           mean_top_z(cap_.apex_x + r * std::cos(th), cap_.apex_y + r * std::sin(th));
    }
  return v;
}

double SkinShape::base_area() const {
  if (kind_ == GeometryKind::cap) return M_PI * cap_.truncation_radius * cap_.truncation_radius;
  return 4.0 * flat_.half_width * flat_.half_width;
}

}  // namespace skinfem
