// Exact shape of a cap or flat layer: top height, projections onto the curved faces, closed-form measures.
// Imported surfaces have no exact shape beyond their triangles (SkinShape::exact() is false).
#pragma once

#include "scene/scene.hpp"

namespace skinfem {

class SkinShape {
 public:
  explicit SkinShape(const Geometry& geometry);

  bool exact() const { return kind_ != GeometryKind::surface; }
  GeometryKind kind() const { return kind_; }
  // Top surface height s(x, y), mm. Cap: the sphere or ellipsoid of scene.hpp's CapGeometry; flat: h.
  double top_z(double x, double y) const;
  // Point on the exact top surface above (x, y).
  Vec3 on_top(double x, double y) const { return {x, y, top_z(x, y)}; }
  // Point on the exact lateral face nearest to p, keeping p's z (cap: radial projection onto the
  // truncation cylinder; flat: p itself, the sides are planes).
  Vec3 on_side(const Vec3& p) const;
  // Closed-form volume (mm³) and base area (mm²) of the truncated layer.
  double volume() const;
  double base_area() const;

 private:
  GeometryKind kind_;
  CapGeometry cap_;
  FlatGeometry flat_;
};

}  // namespace skinfem
