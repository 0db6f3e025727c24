#include "skinfem/pipeline/post_design.hpp"

#include <algorithm>
#include <cmath>

#include "skinfem/fem/blas_threads.hpp"
#include "skinfem/pipeline/clock.hpp"
#include "skinfem/pipeline/sensor_greens.hpp"
#include "skinfem/scene/parallel.hpp"

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
  // A post of no height is the base under its outline: the disc.
  const ReadingSite site = height > 0 ? post_site({0, 0}, diameter, height) : disc_site({0, 0}, diameter);
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
// A design as the doubles a worker process hands back (scene/parallel.hpp), its DOFs last.
constexpr std::size_t kDesignValues = 14;
std::vector<double> to_values(const SensorDesign& d, int dofs) {
  return {d.diameter,        d.height,
          d.zz.peak,         d.zz.peak_at,
          d.zz.half_width,   d.zz.integral,
          d.xx.peak,         d.xx.peak_at,
          d.xx.half_width,   d.xx.integral,
          d.peak_change,     d.half_width_change,
          d.integral_change, static_cast<double>(dofs)};
}
SensorDesign from_values(const std::vector<double>& v, int* dofs = nullptr) {
  SensorDesign d;
  d.diameter = v[0], d.height = v[1];
  d.zz = {v[2], v[3], v[4], v[5]}, d.xx = {v[6], v[7], v[8], v[9]};
  d.peak_change = v[10], d.half_width_change = v[11], d.integral_change = v[12];
  if (dofs) *dofs = static_cast<int>(v[13]);
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
  // Every design is independent: the disc, the post, then the sweep, on the machine's cores in separate
  // processes (MUMPS instances are not shared between threads), each with one BLAS thread (the 2D fronts
  // are too small for more; and the numbers then do not depend on how many processes ran).
  struct Job {
    double diameter, height, scale;
  };
  std::vector<Job> jobs = {{d, 0, 1}, {d, scene.sensors.post.height, 1}};
  for (double diameter : diameters)
    for (double height : heights) jobs.push_back({diameter, height, sweep_scale});
  const BlasThreads one(1);
  const auto designs = map_in_processes(jobs.size(), kDesignValues, [&](std::size_t i) {
    int dofs = 0;
    const SensorDesign design_i = design(skin, nu, jobs[i].diameter, jobs[i].height, jobs[i].scale, &dofs);
    return to_values(design_i, dofs);
  });
  p.disc = from_values(designs[0]);
  p.post = from_values(designs[1], &p.dofs);
  for (size_t i = 2; i < jobs.size(); ++i) p.sweep.push_back(from_values(designs[i]));
  p.seconds = clock.seconds();
  return p;
}

}  // namespace skinfem::pipeline
