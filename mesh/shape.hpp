// Exact shape of a cap or flat layer: top height, projections onto the curved faces, closed-form measures.
// Imported surfaces have no exact shape beyond their triangles (SkinShape::exact() is false).
#pragma once

#include "skinfem/scene/scene.hpp"

namespace skinfem {

class SkinShape {
 public:
  explicit SkinShape(const Geometry& geometry);

  bool exact() const { return kind_ != GeometryKind::surface; }
  GeometryKind kind() const { return kind_; }
  // Top surface height s(x, y), mm. Cap: the sphere or ellipsoid of scene.hpp's CapGeometry; flat: h; plus
  // the ridges, if any (scene.hpp's Ridges).
  double top_z(double x, double y) const { return mean_top_z(x, y) + ridge_z(x, y); }
  // The top without its ridges: the skin's mean thickness, which ridged and smooth skins are compared at.
  double mean_top_z(double x, double y) const;
  // Whether the skin stands above the base point (x, y): the flat layer's square, the cap's truncation disc
  // (edges included, to 1e-9 of the size). An imported surface's footprint is its mesh's: always true here.
  bool covers(double x, double y) const;
  // The ridges' height above the mean top, mm (0 off the pattern or without ridges).
  double ridge_z(double x, double y) const;
  // Point on the exact top surface above (x, y).
  Vec3 on_top(double x, double y) const { return {x, y, top_z(x, y)}; }
  // Point on the exact lateral face nearest to p, keeping p's z (cap: radial projection onto the
  // truncation cylinder; flat: p itself, the sides are planes).
  Vec3 on_side(const Vec3& p) const;
  // Volume (mm³; closed form, the ellipsoid and the ridges by quadrature) and base area (mm²).
  double volume() const;
  double base_area() const;

 private:
  double smooth_volume() const;  // without the ridges

  GeometryKind kind_;
  CapGeometry cap_;
  FlatGeometry flat_;
  Ridges ridges_;
};

}  // namespace skinfem
