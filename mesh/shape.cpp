#include "mesh/shape.hpp"

#include <cmath>

#include "mesh/gauss_legendre.hpp"

namespace skinfem {

SkinShape::SkinShape(const Geometry& geometry)
    : kind_(geometry.kind), cap_(geometry.cap), flat_(geometry.flat) {}

double SkinShape::top_z(double x, double y) const {
  if (kind_ != GeometryKind::cap) return flat_.h;
  const double dx = x - cap_.apex_x, dy = y - cap_.apex_y;
  if (cap_.spherical()) return cap_.h - cap_.R + std::sqrt(cap_.R * cap_.R - dx * dx - dy * dy);
  const double u = dx / cap_.semi_axis_x(), v = dy / cap_.semi_axis_y(), c = cap_.semi_axis_z();
  return cap_.h - c + c * std::sqrt(1 - u * u - v * v);
}

Vec3 SkinShape::on_side(const Vec3& p) const {
  if (kind_ != GeometryKind::cap) return p;
  const double dx = p[0] - cap_.apex_x, dy = p[1] - cap_.apex_y;
  const double scale = cap_.truncation_radius / std::hypot(dx, dy);
  return {cap_.apex_x + scale * dx, cap_.apex_y + scale * dy, p[2]};
}

double SkinShape::volume() const {
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
           top_z(cap_.apex_x + r * std::cos(th), cap_.apex_y + r * std::sin(th));
    }
  return v;
}

double SkinShape::base_area() const {
  if (kind_ == GeometryKind::cap) return M_PI * cap_.truncation_radius * cap_.truncation_radius;
  return 4.0 * flat_.half_width * flat_.half_width;
}

}  // namespace skinfem
