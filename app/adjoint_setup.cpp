#include "app/adjoint_setup.hpp"

#include <algorithm>

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

double scan_half_width(const Scene& scene, double h) {
  return std::max(4 * h, scene.calibration.scan_half_width);
}

}  // namespace skinfem::app
