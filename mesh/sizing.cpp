#include "mesh/sizing.hpp"

#include <algorithm>
#include <cmath>

namespace skinfem {

namespace {
double distance_to_segment(double x, double y, const Vec2& a, const Vec2& b) {
  const double ex = b[0] - a[0], ey = b[1] - a[1];
  const double len2 = ex * ex + ey * ey;
  double t = len2 > 0 ? ((x - a[0]) * ex + (y - a[1]) * ey) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(x - a[0] - t * ex, y - a[1] - t * ey);
}
}  // namespace

double sensor_mesh_size(const Scene& scene) {
  if (scene.mesh.sensor_h > 0) return scene.mesh.sensor_h;
  // A post's wall and rim are curved P2 faces, its rim singular: 0.6 of its radius (README, "Post sensors").
  const double disc_radius = scene.sensors.footprint_radius();
  const double size = scene.sensors.model == SensorModel::post ? 0.6 * disc_radius : disc_radius;
  return size > 0 ? std::min(scene.mesh.h_min, size) : scene.mesh.h_min;
}

SizingField::SizingField(const Scene& scene, MeshPart part)
    : through_(scene.mesh.regions), growth_(scene.mesh.growth), h_max_(scene.mesh.h_max) {
  const double h_min = scene.mesh.h_min;
  for (auto& r : through_)
    if (r.h <= 0) r.h = h_min;
  // Imported surfaces have no exact height above the base: their discs keep an h_min column.
  const bool generated = scene.geometry.kind != GeometryKind::surface;
  if (scene.sensors.model == SensorModel::post) post_height_ = scene.sensors.post.height;
  if (scene.mesh.refine_sensors)
    for (const auto& s : scene.sensors.positions) {
      const RegionOfInterest disc{s, s, scene.sensors.footprint_radius(), sensor_mesh_size(scene)};
      if (generated)
        base_.push_back(disc);
      else
        through_.push_back({s, s, disc.radius, h_min});
    }
  for (const auto& p : scene.loads.punches) through_.push_back({p.center, p.center, 0.5 * p.diameter, h_min});
  for (const auto& p : scene.loads.patches) through_.push_back({p.center, p.center, 0.5 * p.diameter, h_min});
  if (scene.contact) {
    const Vec2 c = contact_center(scene);
    top_.push_back({c, c, contact_zone_radius(scene), contact_zone_h(scene)});
    for (const auto& hole : scene.contact->holes)
      top_.push_back(
          {hole.center, hole.center, 0.5 * hole.diameter, hole.h > 0 ? hole.h : contact_zone_h(scene)});
    if (const auto& s = scene.contact->sweep; s && s->h > 0)
      top_.push_back({s->from, s->to, 0.5 * s->hole_diameter + s->h, s->h});
    // The readings see the contact through the layer: its resolution is carried down to every sensor.
    for (const auto& p : scene.sensors.positions)
      through_.push_back({p, p, scene.sensors.footprint_radius(), contact_zone_h(scene)});
  }
  // Ridges are resolved on the top only: their field decays within about a period below it.
  if (const Ridges& r = scene.geometry.ridges; r.present())
    top_.push_back({r.center, r.center, r.radius, r.mesh_size()});
  if (scene.geometry.kind != GeometryKind::surface) shape_.emplace(scene.geometry);
  if (part == MeshPart::half_y)
    for (auto* list : {&through_, &top_, &base_}) {
      const size_t n = list->size();
      for (size_t i = 0; i < n; ++i) {
        RegionOfInterest m = (*list)[i];
        if (m.a[1] == 0 && m.b[1] == 0) continue;  // its own mirror image
        m.a[1] = -m.a[1], m.b[1] = -m.b[1];
        list->push_back(m);
      }
    }
}

double SizingField::at(double x, double y, double depth) const {
  double size = h_max_;
  const auto grow = [&](const RegionOfInterest& r, double depth_counted) {
    const double d = std::max(0.0, distance_to_segment(x, y, r.a, r.b) - r.radius);
    size = std::min(size, r.h + (growth_ - 1.0) * std::hypot(d, depth_counted));
  };
  for (const auto& r : through_) grow(r, 0.0);
  for (const auto& r : top_) grow(r, depth);
  if (!base_.empty()) {
    const double height = std::max(0.0, shape_->top_z(x, y) - depth - post_height_);
    for (const auto& r : base_) grow(r, height);
  }
  return size;
}

double SizingField::on_base(double x, double y) const { return at(x, y, shape_ ? shape_->top_z(x, y) : 0.0); }

double SizingField::in_volume(double x, double y, double z) const {
  return at(x, y, shape_ ? std::max(0.0, shape_->top_z(x, y) - z) : 0.0);
}

void SizingField::in_column(double x, double y, const double* z, int n, double* out) const {
  const double top = shape_ ? shape_->top_z(x, y) : 0.0;
  double through = h_max_;
  for (const auto& r : through_)
    through = std::min(
        through, r.h + (growth_ - 1.0) *
                           std::hypot(std::max(0.0, distance_to_segment(x, y, r.a, r.b) - r.radius), 0.0));
  // A region's size at depth is at least its size at the top (hypot(d, depth) >= d): one that already loses
  // to the through regions there loses at every depth and is skipped (the margin covers hypot's rounding).
  struct Near {
    double h, d;
  };
  std::vector<Near> near_top, near_base;
  const auto near = [&](const std::vector<RegionOfInterest>& list, std::vector<Near>& out) {
    for (const auto& r : list) {
      const double d = std::max(0.0, distance_to_segment(x, y, r.a, r.b) - r.radius);
      if (r.h + (growth_ - 1.0) * d <= through * (1 + 1e-12)) out.push_back({r.h, d});
    }
  };
  near(top_, near_top);
  if (!base_.empty()) near(base_, near_base);
  for (int k = 0; k < n; ++k) {
    const double depth = shape_ ? std::max(0.0, top - z[k]) : 0.0;
    double size = through;
    for (const Near& r : near_top) size = std::min(size, r.h + (growth_ - 1.0) * std::hypot(r.d, depth));
    if (!base_.empty()) {
      const double height = std::max(0.0, top - depth - post_height_);
      for (const Near& r : near_base) size = std::min(size, r.h + (growth_ - 1.0) * std::hypot(r.d, height));
    }
    out[k] = size;
  }
}

Scene scaled_scene(const Scene& base, double s, bool cap_holes) {
  Scene scene = base;
  scene.mesh.sensor_h = sensor_mesh_size(base) * s;
  scene.mesh.h_min *= s;
  scene.mesh.h_max *= s;
  scene.mesh.growth = 1 + s * (scene.mesh.growth - 1);
  for (auto& r : scene.mesh.regions) r.h *= s;
  if (scene.contact) {
    scene.contact->h = contact_zone_h(base) * s;
    for (auto& hole : scene.contact->holes) hole.h *= s;
    if (scene.contact->sweep) scene.contact->sweep->h *= s;
  }
  if (scene.contact && cap_holes) {
    // The scene rule: the mesh over a hole at most its diameter.
    const auto cap = [&scene](double& h, double diameter) {
      if (hole_mesh_h(scene, h) > diameter) h = diameter;
    };
    for (auto& hole : scene.contact->holes) cap(hole.h, hole.diameter);
    if (scene.contact->sweep) cap(scene.contact->sweep->h, scene.contact->sweep->hole_diameter);
  }
  return scene;
}

}  // namespace skinfem
