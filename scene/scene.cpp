#include "scene/scene.hpp"

#include <cmath>

namespace skinfem {

double nominal_thickness(const Scene& scene) {
  switch (scene.geometry.kind) {
    case GeometryKind::cap:
      return scene.geometry.cap.h;
    case GeometryKind::flat:
      return scene.geometry.flat.h;
    case GeometryKind::surface:
      return 0.0;  // unknown until the surface file is read (see scene.hpp)
  }
  return 0.0;
}

Vec2 contact_center(const Scene& scene) {
  const ContactLoad& c = *scene.contact;
  if (c.indenter == IndenterKind::plane && scene.geometry.kind == GeometryKind::cap)
    return {scene.geometry.cap.apex_x, scene.geometry.cap.apex_y};
  return c.center;
}

double contact_zone_radius(const Scene& scene) {
  const ContactLoad& c = *scene.contact;
  if (c.zone_radius > 0) return c.zone_radius;
  const bool cap = scene.geometry.kind == GeometryKind::cap;
  double R = c.indenter == IndenterKind::plane ? scene.geometry.cap.R : c.sphere_R;
  if (c.indenter == IndenterKind::sphere && cap) R = 1.0 / (1.0 / c.sphere_R + 1.0 / scene.geometry.cap.R);
  const double E_star = scene.material.E / (1 - scene.material.nu * scene.material.nu);
  // Johnson (1985) §4.2: a³ = 3FR/(4E*) under a force, a² = Rδ at a depth.
  const double a =
      c.force ? std::cbrt(3 * *c.force * R / (4 * E_star)) : std::sqrt(R * c.depth.value_or(0.0));
  return 1.25 * a;
}

double contact_zone_h(const Scene& scene) {
  return scene.contact && scene.contact->h > 0 ? scene.contact->h : scene.mesh.h_min;
}

}  // namespace skinfem
