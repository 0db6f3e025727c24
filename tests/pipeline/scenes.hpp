// A coarse scene the pipeline's contact suites share: a flat layer (2 mm thick unless given, 10 mm wide)
// bonded to its base, three sensors on the x axis, pressed by a sphere (R = 20 mm, 0.3 N, coupled friction
// μ = 0.5, static ratio 0.1) while a hole (0.4 mm unless given) crosses it along x.
#pragma once

#include <string>

#include "skinfem/scene/scene.hpp"

namespace skinfem::pipeline::testing {

inline Scene swept_layer(const std::string& name, int positions, Vec2 from = {-1.5, 0}, Vec2 to = {1.5, 0},
                         double thickness = 2.0, double hole = 0.4) {
  Scene s;
  s.name = name;
  s.source_path = name + ".json";
  s.geometry.kind = GeometryKind::flat;
  s.geometry.flat = {thickness, 5.0};
  s.sensors.positions = {{-1, 0}, {0, 0}, {1, 0}};
  s.mesh.h_min = 0.5;
  s.mesh.growth = 1.7;
  s.mesh.h_max = 1.5;
  s.mesh.sensor_h = 0.5;
  ContactLoad c;
  c.indenter = IndenterKind::sphere;
  c.sphere_R = 20;
  c.force = 0.3;
  c.zone_radius = 2.2;
  c.h = 0.35;
  c.mu = 0.5;
  c.static_ratio = 0.1;
  c.friction = FrictionMode::coupled;
  c.sweep = HoleSweep{from, to, positions, hole};
  s.contact = c;
  return s;
}

}  // namespace skinfem::pipeline::testing
