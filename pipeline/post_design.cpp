#include "pipeline/post_design.hpp"

#include <algorithm>
#include <cmath>

#include "pipeline/clock.hpp"
#include "pipeline/sensor_greens.hpp"

namespace skinfem::pipeline {

namespace {
// The scene with one sensor on its skin's axis.
Scene on_axis(const Scene& scene) {
  Scene one = scene;
  const Geometry& g = scene.geometry;
  one.sensors.positions = {g.kind == GeometryKind::cap ? Vec2{g.cap.apex_x, g.cap.apex_y} : Vec2{0, 0}};
  return one;
}

double relative_change(double fine, double coarse) {
  return fine != 0 ? std::abs(fine - coarse) / std::abs(fine) : std::abs(coarse);
}

SensorDesign design(const MeridianSkin& skin, double nu, double diameter, double height, double scale,
                    int* dofs = nullptr) {
  const ReadingSite site{{0, 0}, diameter, height};
  const MeridianGreen fine(skin.mesh(site, scale), nu, skin.side, site),
      coarse(skin.mesh(site, 2 * scale), nu, skin.side, site);
  if (dofs) *dofs = fine.dofs();
  SensorDesign d;
  d.diameter = diameter, d.height = height;
  d.zz = fine.shape_zz(), d.xx = fine.shape_xx();
  const MeridianGreen::Shape czz = coarse.shape_zz(), cxx = coarse.shape_xx();
  d.peak_change = std::max(relative_change(d.zz.peak, czz.peak), relative_change(d.xx.peak, cxx.peak));
  d.half_width_change = std::max(relative_change(d.zz.half_width, czz.half_width),
                                 relative_change(d.xx.half_width, cxx.half_width));
  d.integral_change =
      std::max(relative_change(d.zz.integral, czz.integral), relative_change(d.xx.integral, cxx.integral));
  return d;
}
}  // namespace

std::string post_design_unavailable(const Scene& scene) { return meridian_unavailable(on_axis(scene)); }

PostDesign post_design(const Scene& scene, const std::vector<double>& diameters,
                       const std::vector<double>& heights, double sweep_scale) {
  const Scene axis = on_axis(scene);
  if (const std::string why = meridian_unavailable(axis); !why.empty())
    throw SceneError(scene.source_path + ": no meridian to compare a post with a disc on: " + why);
  Stopwatch clock;
  const MeridianSkin skin = meridian_skin(axis);
  const double nu = scene.material.nu, d = scene.sensors.post.diameter;
  PostDesign p;
  p.skin = skin.model;
  p.sweep_scale = sweep_scale;
  p.disc = design(skin, nu, d, 0, 1);
  p.post = design(skin, nu, d, scene.sensors.post.height, 1, &p.dofs);
  for (double diameter : diameters)
    for (double height : heights) p.sweep.push_back(design(skin, nu, diameter, height, sweep_scale));
  p.seconds = clock.seconds();
  return p;
}

}  // namespace skinfem::pipeline
