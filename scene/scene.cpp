#include "skinfem/scene/scene.hpp"

#include <algorithm>
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

// The automatic zone: 1.25 × an upper bound a of the contact radius, from the half-space Hertz solution of
// the two bodies' relative curvature (Johnson 1985, §4.2): E* = E/(1 − ν²) (the indenter is rigid),
// 1/R_eff = 1/R_sphere + 1/R_cap (a plane: 1/R_sphere = 0; a flat layer or imported surface: 1/R_cap = 0).
//  - Force control: a = (3 F R_eff / (4 E*))^(1/3), Hertz's radius. A thin layer bonded to a rigid base is
//    stiffer than the half-space (for ν = 1/2 its compliance at wavelengths beyond h falls as (h/a)³), and
//    a stiffer body carries the same force on a smaller disc: the bonded-layer contact is smaller than
//    Hertz's (thin-layer limit: a ∝ (F R h³/E)^(1/6), far below it).
//  - Depth control: a = 2 sqrt(R_eff δ), twice Hertz's sqrt(R_eff δ). Here the bound goes the other way: at
//    a given approach the incompressible layer, unable to spread sideways over the base, bulges up around
//    the indenter and the contact is LARGER than Hertz's, already by more than the 25 % margin at h ≈ a.
//    Its limit is the thin-layer (lubrication) one: w = 0 outside the contact, so the volume pushed down
//    inside must come back up inside, ∫(δ − r²/2R) dA = 0 over r < a, a² = 4 R δ. Thicker layers lie between
//    that and Hertz (a² = R δ); a compressible thin layer (Winkler-like) tends to the intersection, 2 R δ.
// Why the 25 % margin: the multipliers must cover the whole contact and a ring of free vertices around it
// (the command checks that the solved contact stays one element inside its edge, pipeline/contact_setup.cpp);
// sliding friction shifts the pressure forwards and enlarges the contact on the leading side.
std::optional<double> equivalent_sphere_radius(const Scene& scene) {
  const ContactLoad& c = *scene.contact;
  double curvature = 0;  // 1/R_eff, 1/mm
  if (c.indenter == IndenterKind::sphere) curvature += 1 / c.sphere_R;
  // An ellipsoidal cap: the equivalent sphere of an elliptic Hertz contact, R_e = sqrt(R R_y) (Johnson §4.2).
  if (scene.geometry.kind == GeometryKind::cap) curvature += 1 / scene.geometry.cap.semi_axis_z();
  if (!(curvature > 0)) return std::nullopt;
  return 1 / curvature;
}

double contact_zone_radius(const Scene& scene) {
  const ContactLoad& c = *scene.contact;
  if (c.zone_radius > 0) return c.zone_radius;
  const std::optional<double> R = equivalent_sphere_radius(scene);
  if (!R)
    throw SceneError(
        scene.source_path +
        ": contact.indenter: a plane on a flat layer or an imported surface has no Hertz radius; "
        "use a sphere or give contact.zone_radius");
  if (!c.force && !c.depth)
    throw SceneError(scene.source_path +
                     ": contact: needs \"force\" or \"depth\" for an automatic zone_radius");
  // An ellipsoidal cap makes the contact an ellipse, longest along the flatter relative curvature. Half-space
  // Hertz (Johnson 1985, §4.2): its semi-axes are about sqrt(a_e² · (κ_max/κ_min)^{±2/3}) with a_e the
  // radius for R_eff = sqrt(R_x R_y), so the long one is a_e (κ_max/κ_min)^{1/3}; at a depth the thin-layer
  // bound scales each axis with its own radius, 2 sqrt(R_flat δ).
  double kx = c.indenter == IndenterKind::sphere ? 1 / c.sphere_R : 0, ky = kx;
  if (scene.geometry.kind == GeometryKind::cap) {
    kx += 1 / scene.geometry.cap.R;
    ky += 1 / scene.geometry.cap.radius_y();
  }
  const double k_max = std::max(kx, ky), k_min = std::min(kx, ky);
  const double E_star = scene.material.E / (1 - scene.material.nu * scene.material.nu);
  const double a = c.force ? std::cbrt(3 * *c.force * *R / (4 * E_star)) * std::cbrt(k_max / k_min)
                           : 2 * std::sqrt(*c.depth / k_min);
  return 1.25 * a;
}

double contact_zone_h(const Scene& scene) {
  return scene.contact && scene.contact->h > 0 ? scene.contact->h : scene.mesh.h_min;
}

double hole_mesh_h(const Scene& scene, double hole_h) {
  return hole_h > 0 ? std::min(hole_h, contact_zone_h(scene)) : contact_zone_h(scene);
}

}  // namespace skinfem
