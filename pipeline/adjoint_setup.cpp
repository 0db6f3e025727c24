#include "skinfem/pipeline/adjoint_setup.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "skinfem/fem/face_index.hpp"
#include "skinfem/mesh/shape.hpp"
#include "skinfem/pipeline/clock.hpp"
#include "skinfem/pipeline/progress.hpp"
#include "skinfem/pipeline/symmetry.hpp"

namespace skinfem::pipeline {

std::unique_ptr<AdjointSetup> adjoint_setup(const Scene& scene, std::shared_ptr<Skin> skin) {
  auto s = std::make_unique<AdjointSetup>(skin ? std::move(skin) : skin_setup(scene, green_mesh_part(scene)));
  s->wall = s->skin->wall;
  Stopwatch clock;
  s->fe = std::make_unique<green::FeGreen>(*s->model, scene.sensors, progress);
  s->wall["adjoint_solves"] = clock.seconds();
  return s;
}

double thickness_at(const Scene& scene, const TetMesh& mesh, const Vec2& p) {
  try {
    return skin_thickness(scene.geometry, mesh, p[0], p[1]);
  } catch (const std::out_of_range& e) {
    throw SceneError(scene.source_path + ": sensors: " + e.what() + "; every sensor must lie under the skin");
  }
}

void check_sensors_on_skin(const Scene& scene, const TetMesh& mesh) {
  const PlanarFaceIndex base(mesh, kBase);
  // A disc on the base; a post stands in a hole of the base, which surrounds it.
  const bool post = scene.sensors.model == SensorModel::post;
  const double r = scene.sensors.footprint_radius() * (post ? 1.05 : 1.0);
  for (size_t i = 0; i < scene.sensors.positions.size(); ++i) {
    const Vec2& p = scene.sensors.positions[i];
    double s, t;
    for (auto [dx, dy] : {std::pair{0.0, 0.0}, {r, 0.0}, {-r, 0.0}, {0.0, r}, {0.0, -r}})
      if (!(post && dx == 0 && dy == 0) && base.find(p[0] + dx, p[1] + dy, s, t) < 0)
        throw SceneError(scene.source_path + ": sensors: sensor " + std::to_string(i + 1) + " at (" +
                         std::to_string(p[0]) + ", " + std::to_string(p[1]) + "): its " +
                         (post ? "post" : "disc") + " (diameter " +
                         std::to_string(2 * scene.sensors.footprint_radius()) +
                         ") is not entirely on the skin's base; sensors must lie under the skin");
  }
}

double scan_half_width(const Scene& scene, const TetMesh* mesh, double h, const Vec2& sensor) {
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
  } else {
    // An imported skin: walk out along x from the sensor, both ways, while the disc's rim stays above the
    // meshed top (its footprint is known only from the mesh).
    if (!mesh) throw std::logic_error("scan_half_width: an imported skin needs its mesh");
    const PlanarFaceIndex top(*mesh, kTop);
    double ps, pt;
    const auto on_top = [&](double x, double y) { return top.find(x, y, ps, pt) >= 0; };
    room = 0;
    for (double w = 0; w <= wanted + 1e-12; w += scene.calibration.spacing) {
      bool ok = true;
      for (int side : {-1, 1})
        for (double dy : {-a, 0.0, a})
          ok = ok && on_top(sensor[0] + side * (w + (dy == 0 ? a : 0)), sensor[1] + dy);
      if (!ok) break;
      room = w + 0.5 * scene.calibration.spacing;  // the last offset fits; half a step, as below
    }
  }
  const double w = room >= wanted ? wanted : room - 0.5 * scene.calibration.spacing;
  if (!(w > 0))
    throw SceneError(scene.source_path + ": calibration: the calibration load (punch_diameter " +
                     std::to_string(scene.calibration.punch_diameter) +
                     " mm) cannot be scanned through sensor (" + std::to_string(sensor[0]) + ", " +
                     std::to_string(sensor[1]) + "): it leaves the skin's footprint at once");
  return w;
}

}  // namespace skinfem::pipeline
