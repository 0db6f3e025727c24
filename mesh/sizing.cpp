#include "skinfem/mesh/sizing.hpp"

#include <algorithm>
#include <cmath>

#include "skinfem/scene/texture.hpp"

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
  // A post's wall and rim are curved P2 faces, its rim singular: 0.6 of its radius (docs/posts.md).
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
    if (const auto& t = scene.contact->texture; t && t->h > 0) {
      // Each hole's track where it comes within the zone, plus one element (a row's holes share one).
      for (const HoleTrack& k : hole_tracks(t->holes, scene.contact->direction, *scene.contact->scan, c,
                                            contact_zone_radius(scene) + t->h))
        top_.push_back({k.from, k.to, k.radius + t->h, t->h});
    }
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
  // A region is first bounded from below with sqrt (within 1e-15 of hypot; the margin 1e-12 covers it): far
  // regions, most of them in most columns, cannot lower the size and cost no hypot.
  const auto lower_bound = [&](const RegionOfInterest& r) {
    const double ex = r.b[0] - r.a[0], ey = r.b[1] - r.a[1], len2 = ex * ex + ey * ey;
    const double t = std::clamp(len2 > 0 ? ((x - r.a[0]) * ex + (y - r.a[1]) * ey) / len2 : 0.0, 0.0, 1.0);
    const double px = x - r.a[0] - t * ex, py = y - r.a[1] - t * ey;
    return r.h + (growth_ - 1.0) * std::max(0.0, std::sqrt(px * px + py * py) * (1 - 1e-12) - r.radius);
  };
  double through = h_max_;
  // hypot(d, 0) is |d| exactly (C, Annex F), so at() and this give the same through sizes.
  for (const auto& r : through_)
    if (!(lower_bound(r) > through * (1 + 1e-12)))
      through = std::min(
          through, r.h + (growth_ - 1.0) * std::max(0.0, distance_to_segment(x, y, r.a, r.b) - r.radius));
  // A region's size at depth is at least its size at the top, `least` (hypot(d, depth) >= d): regions are
  // taken in the order of `least`, and the rest skipped once it exceeds the size found, which they cannot
  // then lower (the margin covers hypot's rounding). One that loses to the through regions is dropped.
  struct Near {
    double least, h, d;
    bool base;
  };
  std::vector<Near> near;
  const auto add = [&](const std::vector<RegionOfInterest>& list, bool base) {
    for (const auto& r : list) {
      if (lower_bound(r) > through * (1 + 1e-12)) continue;
      const double d = std::max(0.0, distance_to_segment(x, y, r.a, r.b) - r.radius);
      const double least = r.h + (growth_ - 1.0) * d;
      if (least <= through * (1 + 1e-12)) near.push_back({least, r.h, d, base});
    }
  };
  add(top_, false);
  if (!base_.empty()) add(base_, true);
  std::sort(near.begin(), near.end(), [](const Near& p, const Near& q) { return p.least < q.least; });
  for (int k = 0; k < n; ++k) {
    const double depth = shape_ ? std::max(0.0, top - z[k]) : 0.0;
    const double height = std::max(0.0, top - depth - post_height_);
    double size = through;
    for (const Near& r : near) {
      if (r.least > size * (1 + 1e-12)) break;
      size = std::min(size, r.h + (growth_ - 1.0) * std::hypot(r.d, r.base ? height : depth));
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
    if (scene.contact->texture) scene.contact->texture->h *= s;
  }
  if (scene.contact && cap_holes) {
    // The scene rule: the mesh over a hole at most its diameter.
    const auto cap = [&scene](double& h, double diameter) {
      if (hole_mesh_h(scene, h) > diameter) h = diameter;
    };
    for (auto& hole : scene.contact->holes) cap(hole.h, hole.diameter);
    if (scene.contact->sweep) cap(scene.contact->sweep->h, scene.contact->sweep->hole_diameter);
    if (auto& t = scene.contact->texture)
      for (const Hole& hole : t->holes) cap(t->h, hole.diameter);
  }
  return scene;
}

}  // namespace skinfem
