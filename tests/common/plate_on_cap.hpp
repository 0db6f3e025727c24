// A plate on a small, strongly curved cap (R = 20 mm, h = 3 mm, apex at the origin, E = 3 MPa, ν = 0.5) at a
// coarse mesh (h 0.5 to 1.5 mm), a sensor at the apex, 0.3 N, μ = 1: the contact reaches about 1 mm, so the
// strain a/R is 5 % and finite kinematics shows. The finite-strain contact's suites share it.
#pragma once

#include "skinfem/scene/scene.hpp"

namespace skinfem::testing {

inline Scene plate_on_cap(double truncation_radius, double zone_radius) {
  Scene s;
  s.name = "plate_on_cap";
  s.source_path = "plate_on_cap.json";
  s.geometry.kind = GeometryKind::cap;
  s.geometry.cap = {20.0, 3.0, 0.0, 0.0, truncation_radius};
  s.material = {3.0, 0.5};
  s.sensors.positions = {{0.0, 0.0}};
  s.sensors.disc_diameter = 0.2;
  s.mesh.h_min = 0.5, s.mesh.growth = 1.8, s.mesh.h_max = 1.5;
  s.mesh.refine_sensors = false;
  ContactLoad c;
  c.indenter = IndenterKind::plane;
  c.force = 0.3;
  c.zone_radius = zone_radius;
  c.h = 0.5;
  c.mu = 1.0;
  s.contact = c;
  return s;
}

}  // namespace skinfem::testing
