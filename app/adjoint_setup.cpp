#include "app/adjoint_setup.hpp"

#include <algorithm>
#include <cmath>

#include "app/common.hpp"
#include "mesh/shape.hpp"

namespace skinfem::app {

std::unique_ptr<AdjointSetup> adjoint_setup(const Scene& scene, std::shared_ptr<Skin> skin) {
  auto s = std::make_unique<AdjointSetup>(skin ? std::move(skin) : skin_setup(scene));
  s->wall = s->skin->wall;
  Stopwatch clock;
  s->fe = std::make_unique<green::FeGreen>(*s->model, scene.sensors, progress);
  s->wall["adjoint_solves"] = clock.seconds();
  return s;
}

double thickness_at(const Scene& scene, const Vec2& sensor) {
  const SkinShape shape(scene.geometry);
  return shape.exact() ? shape.top_z(sensor[0], sensor[1]) : nominal_thickness(scene);
}

double scan_half_width(const Scene& scene, double h, const Vec2& sensor) {
  const double wanted = scene.calibration.scan_half_width > 0 ? scene.calibration.scan_half_width : 4 * h;
  // The loaded disc must stay on the top: along x through the sensor, both ways, to the footprint's edge
  // (half a step inside it, so the grid's last offset is strictly on the skin).
  const double a = 0.5 * scene.calibration.punch_diameter;
  const Geometry& g = scene.geometry;
  double room = wanted;
  if (g.kind == GeometryKind::flat) {
    room = g.flat.half_width - a - std::abs(sensor[0]);
  } else if (g.kind == GeometryKind::cap) {
    const double reach = g.cap.truncation_radius - a, dy = sensor[1] - g.cap.apex_y;
    room = std::sqrt(std::max(0.0, reach * reach - dy * dy)) - std::abs(sensor[0] - g.cap.apex_x);
  }
  const double w = room >= wanted ? wanted : room - 0.5 * scene.calibration.spacing;
  if (!(w > 0))
    throw SceneError(scene.source_path + ": calibration: the calibration load (punch_diameter " +
                     std::to_string(scene.calibration.punch_diameter) +
                     " mm) cannot be scanned through sensor (" + std::to_string(sensor[0]) + ", " +
                     std::to_string(sensor[1]) + "): it leaves the skin's footprint at once");
  return w;
}

}  // namespace skinfem::app
