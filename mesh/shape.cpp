#include "mesh/shape.hpp"

#include <cmath>

namespace skinfem {

SkinShape::SkinShape(const Geometry& geometry)
    : kind_(geometry.kind), cap_(geometry.cap), flat_(geometry.flat) {}

double SkinShape::top_z(double x, double y) const {
  if (kind_ != GeometryKind::cap) return flat_.h;
  const double dx = x - cap_.apex_x, dy = y - cap_.apex_y;
  return cap_.h - cap_.R + std::sqrt(cap_.R * cap_.R - dx * dx - dy * dy);
}

Vec3 SkinShape::on_side(const Vec3& p) const {
  if (kind_ != GeometryKind::cap) return p;
  const double dx = p[0] - cap_.apex_x, dy = p[1] - cap_.apex_y;
  const double scale = cap_.truncation_radius / std::hypot(dx, dy);
  return {cap_.apex_x + scale * dx, cap_.apex_y + scale * dy, p[2]};
}

double SkinShape::volume() const {
  if (kind_ != GeometryKind::cap) return base_area() * flat_.h;
  // ∫₀^rt 2πr (h − R + sqrt(R² − r²)) dr
  const double R = cap_.R, rt = cap_.truncation_radius;
  return M_PI * rt * rt * (cap_.h - R) + 2.0 * M_PI / 3.0 * (R * R * R - std::pow(R * R - rt * rt, 1.5));
}

double SkinShape::base_area() const {
  if (kind_ == GeometryKind::cap) return M_PI * cap_.truncation_radius * cap_.truncation_radius;
  return 4.0 * flat_.half_width * flat_.half_width;
}

}  // namespace skinfem
