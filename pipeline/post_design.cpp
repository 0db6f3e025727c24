#include "skinfem/pipeline/post_design.hpp"

#include <algorithm>
#include <cmath>
#include <ctime>

#include "skinfem/fem/blas_threads.hpp"
#include "skinfem/pipeline/sensor_greens.hpp"
#include "skinfem/scene/parallel.hpp"
#include "skinfem/validation/text.hpp"

namespace skinfem::pipeline {

using validation::fmt;

namespace {
// The scene with one sensor on its skin's axis.
Scene on_axis(const Scene& scene) {
  Scene one = scene;
  const Geometry& g = scene.geometry;
  one.sensors.positions = {g.kind == GeometryKind::cap ? Vec2{g.cap.apex_x, g.cap.apex_y} : Vec2{0, 0}};
  return one;
}

// The calling thread's CPU time: a design's own cost, however long a low-priority process waited for a core.
double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
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
// A design as the doubles a worker process hands back (scene/parallel.hpp), its DOFs and seconds last.
constexpr std::size_t kDesignValues = 15;
std::vector<double> to_values(const SensorDesign& d, int dofs, double seconds) {
  return {d.diameter,
          d.height,
          d.zz.peak,
          d.zz.peak_at,
          d.zz.half_width,
          d.zz.integral,
          d.xx.peak,
          d.xx.peak_at,
          d.xx.half_width,
          d.xx.integral,
          d.peak_change,
          d.half_width_change,
          d.integral_change,
          static_cast<double>(dofs),
          seconds};
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

struct PostDesignRun::Jobs {
  struct Job {
    double diameter, height, scale;
  };
  std::vector<Job> list;
  MeridianSkin skin;
  double nu = 0;
  std::vector<double> run(std::size_t i) const {
    // One BLAS thread per design, set where it runs (a child process, or here with no other work beside):
    // the 2D fronts are too small for more, and the numbers then do not depend on how many processes ran.
    const BlasThreads one(1);
    const double start = thread_cpu_seconds();
    int dofs = 0;
    const SensorDesign d = design(skin, nu, list[i].diameter, list[i].height, list[i].scale, &dofs);
    return to_values(d, dofs, thread_cpu_seconds() - start);
  }
};

PostDesignRun::PostDesignRun(const Scene& scene, const std::vector<double>& diameters,
                             const std::vector<double>& heights, double sweep_scale, int processes) {
  const Scene axis = on_axis(scene);
  if (const std::string why = meridian_unavailable(axis); !why.empty())
    throw SceneError(scene.source_path + ": no meridian to compare a post with a disc on: " + why);
  auto jobs = std::make_shared<Jobs>(Jobs{{}, meridian_skin(axis), scene.material.nu});
  // Every design is independent: the disc, the post, then the sweep.
  const double d = scene.sensors.post.diameter;
  jobs->list = {{d, 0, 1}, {d, scene.sensors.post.height, 1}};
  for (double diameter : diameters)
    for (double height : heights) jobs->list.push_back({diameter, height, sweep_scale});
  jobs_ = jobs;
  skin_ = jobs->skin.model;
  sweep_scale_ = sweep_scale;
  if (processes > 0)
    designs_ = std::make_unique<ProcessMap>(
        jobs->list.size(), kDesignValues, [jobs](std::size_t i) { return jobs->run(i); }, processes, 19);
}

PostDesignRun::PostDesignRun(PostDesignRun&&) noexcept = default;
PostDesignRun::~PostDesignRun() = default;

PostDesign PostDesignRun::finish() {
  const auto designs = designs_ ? designs_->get()
                                : map_in_processes(jobs_->list.size(), kDesignValues,
                                                   [this](std::size_t i) { return jobs_->run(i); });
  PostDesign p;
  p.skin = skin_;
  p.sweep_scale = sweep_scale_;
  p.disc = from_values(designs[0]);
  p.post = from_values(designs[1], &p.dofs);
  for (size_t i = 2; i < designs.size(); ++i) p.sweep.push_back(from_values(designs[i]));
  for (const std::vector<double>& v : designs) p.seconds += v[kDesignValues - 1];
  return p;
}

PostDesign post_design(const Scene& scene, const std::vector<double>& diameters,
                       const std::vector<double>& heights, double sweep_scale) {
  return PostDesignRun(scene, diameters, heights, sweep_scale, 0).finish();
}

namespace {

nlohmann::json design_json(const pipeline::SensorDesign& d) {
  const auto shape = [](const MeridianGreen::Shape& s) {
    return nlohmann::json{{"peak_per_mm2", s.peak},
                          {"peak_at_mm", s.peak_at},
                          {"half_width_mm", s.half_width},
                          {"integral", s.integral}};
  };
  return {{"diameter_mm", d.diameter},
          {"height_mm", d.height},
          {"g_zz", shape(d.zz)},
          {"g_xx", shape(d.xx)},
          {"peak_change", d.peak_change},
          {"half_width_change", d.half_width_change},
          {"integral_change", d.integral_change}};
}

// The heights of the sweep a skin of thickness h takes (a post stays below 0.9 h, the scene rule).
std::vector<double> sweep_heights(double h) {
  std::vector<double> out;
  for (double t : {0.0, 0.2, 0.4, 0.6, 0.8, 1.0})
    if (t < 0.9 * h) out.push_back(t);
  return out;
}
}  // namespace
PostDesignRun report_post_design(const Scene& scene, int processes) {
  const double h = scene.geometry.kind == GeometryKind::flat ? scene.geometry.flat.h : scene.geometry.cap.h;
  return PostDesignRun(scene, {0.1, 0.2, 0.3, 0.4}, sweep_heights(h), 1.41, processes);
}

nlohmann::json post_design_json(const PostDesign& p) {
  // The sentence, from the numbers: the scene's post against its disc, then the sweep's ranges.
  const pipeline::SensorDesign &post = p.post, &disc = p.disc;
  double gain_lo = 1e300, gain_hi = -1e300, width_lo = 1e300, width_hi = -1e300, change = 0;
  double t_lo = 1e300, t_hi = 0, d_lo = 1e300, d_hi = 0;
  for (const auto& d : p.sweep) {
    t_lo = std::min(t_lo, d.height), t_hi = std::max(t_hi, d.height);
    d_lo = std::min(d_lo, d.diameter), d_hi = std::max(d_hi, d.diameter);
    gain_lo = std::min(gain_lo, d.zz.integral), gain_hi = std::max(gain_hi, d.zz.integral);
    width_lo = std::min(width_lo, d.zz.half_width), width_hi = std::max(width_hi, d.zz.half_width);
    change = std::max({change, d.peak_change, d.half_width_change, d.integral_change});
  }
  const std::string answer =
      "At the skin's axis (" + p.skin + "), an isolated post " + fmt("%.3g", post.diameter) +
      " mm wide and " + fmt("%.3g", post.height) +
      " mm high against the disc of its diameter: g_zz peaks at " + fmt("%.4g", post.zz.peak) + " against " +
      fmt("%.4g", disc.zz.peak) + " /mm² (" + fmt("%.2f", post.zz.peak / disc.zz.peak) + "×), half width " +
      fmt("%.3g", post.zz.half_width) + " against " + fmt("%.3g", disc.zz.half_width) + " mm, ∫ g_zz dA " +
      fmt("%.3g", post.zz.integral) + " against " + fmt("%.3g", disc.zz.integral) + "; g_xx peaks at " +
      fmt("%.4g", post.xx.peak) + " against " + fmt("%.4g", disc.xx.peak) + " /mm² (" +
      fmt("%.2f", post.xx.peak / disc.xx.peak) + "×), half width " + fmt("%.3g", post.xx.half_width) +
      " against " + fmt("%.3g", disc.xx.half_width) + " mm, ∫ g_xx dA " + fmt("%.3g", post.xx.integral) +
      " against " + fmt("%.3g", disc.xx.integral) + " (largest change from the mesh twice as coarse: " +
      fmt("%.2g", 100 * std::max({post.peak_change, post.half_width_change, post.integral_change})) +
      " %). Over the sweep (heights " + fmt("%g", t_lo) + "–" + fmt("%g", t_hi) + " mm, diameters " +
      fmt("%g", d_lo) + "–" + fmt("%g", d_hi) + " mm) ∫ g_zz dA runs " + fmt("%.3g", gain_lo) + "–" +
      fmt("%.3g", gain_hi) + " and its half width " + fmt("%.3g", width_lo) + "–" + fmt("%.3g", width_hi) +
      " mm (mesh change up to " + fmt("%.2g", 100 * change) +
      " %). The integrals are the readings under a uniform vertical load (or shear) per unit base area over "
      "the "
      "whole top, on a curved top not a pressure; under a uniform pressure a post reads it exactly "
      "(hydrostatic).";
  nlohmann::json j = {{"skin", p.skin},
                      {"post", design_json(post)},
                      {"disc", design_json(disc)},
                      {"sweep_mesh_scale", p.sweep_scale},
                      {"dofs", p.dofs},
                      {"seconds", p.seconds},
                      {"answer", answer}};
  for (const auto& d : p.sweep) j["sweep"].push_back(design_json(d));
  return j;
}

}  // namespace skinfem::pipeline
