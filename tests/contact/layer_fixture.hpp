// Shared fixture for the contact suites: the paper's layer (h = 3.04 mm, half width 12 mm, E = 3 MPa,
// ν = 0.5, bonded to a rigid base) under a rigid sphere R = 129.7 mm centred at the origin, meshed, factored
// and condensed onto the multipliers of a zone about the origin.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "skinfem/contact/condensed.hpp"
#include "skinfem/mesh/build.hpp"

namespace skinfem::testing {

inline constexpr double kLayerH = 3.04, kLayerE = 3.0, kLayerNu = 0.5, kSphereR = 129.7;

// The scene: mesh size h in the zone (mesh.h_min and contact.h), sensor discs of 0.2 mm at `sensors`, the
// sphere with `load`'s force or depth, holes, friction and interface (its indenter, R, centre, zone radius
// and h are set here).
inline Scene layer_scene(const std::string& name, double h, std::vector<Vec2> sensors, ContactLoad load,
                         double zone_radius) {
  Scene s;
  s.name = name;
  s.geometry.kind = GeometryKind::flat;
  s.geometry.flat = {kLayerH, 12.0};
  s.material = {kLayerE, kLayerNu};
  s.sensors.positions = std::move(sensors);
  s.sensors.disc_diameter = 0.2;
  s.mesh.h_min = h;
  s.mesh.h_max = 3.0;
  s.mesh.growth = 1.7;
  s.mesh.refine_sensors = false;
  load.indenter = IndenterKind::sphere;
  load.sphere_R = kSphereR;
  load.center = {0, 0};
  load.zone_radius = zone_radius;
  load.h = h;
  s.contact = load;
  return s;
}

struct CondensedLayer {
  Scene scene;
  TetMesh mesh;
  std::unique_ptr<ElasticModel> model;
  std::unique_ptr<contact::Indenter> indenter;
  std::unique_ptr<contact::CondensedContact> condensed;
};

// Meshes, factors and condenses `scene` (from layer_scene) onto its zone, sliding along +x, into x in place:
// the model and the indenter refer to x.mesh, so x must not move afterwards.
inline void condense_layer(CondensedLayer& x, Scene scene) {
  x.scene = std::move(scene);
  const Scene& s = x.scene;
  x.mesh = build_mesh(s);
  x.model = std::make_unique<ElasticModel>(x.mesh, s.material, s.geometry.side, std::vector<Punch>{});
  x.indenter = std::make_unique<contact::Indenter>(s, x.mesh);
  const auto zone = contact::mortar_zone(x.mesh, {0, 0}, s.contact->zone_radius);
  // With a sweep, the nodes its hole can reach are condensed too (contact/holes/cut.hpp).
  std::vector<int> faces;
  if (s.contact->sweep)
    faces = contact::watch_path(x.mesh, zone, s.contact->sweep->from, s.contact->sweep->to,
                                0.5 * s.contact->sweep->hole_diameter);
  x.condensed = std::make_unique<contact::CondensedContact>(contact::condense(
      *x.model, zone, *x.indenter, SensorReadings(x.mesh, reading_sites(s.sensors)), {1, 0}, {}, faces));
}

}  // namespace skinfem::testing
