#include "skinfem/pipeline/ridge_study.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "skinfem/green/calibration.hpp"
#include "skinfem/green/layer_exact.hpp"
#include "skinfem/mesh/build.hpp"
#include "skinfem/mesh/scale_ridges.hpp"
#include "skinfem/mesh/surface.hpp"
#include "skinfem/pipeline/adjoint_setup.hpp"
#include "skinfem/pipeline/clock.hpp"
#include "skinfem/pipeline/kfit.hpp"
#include "skinfem/pipeline/progress.hpp"
#include "skinfem/pipeline/resources.hpp"

namespace skinfem::pipeline {

namespace {

struct Solved {
  int dofs = 0;
  green::KReport k;
  green::ScanProfile profile;
  Timings wall;
};

Solved solve_scan(const Scene& scene, std::shared_ptr<Skin> skin, double h, const Vec2& sensor) {
  const auto setup = adjoint_setup(scene, std::move(skin));
  Solved s;
  s.dofs = setup->model->solver().free_dofs();
  const double radius = 0.5 * scene.calibration.punch_diameter;
  s.profile = green::scan_profile(*setup->fe, 0, green::LayerLoad::punch, radius,
                                  scan_half_width(scene, &setup->mesh, h, sensor), scene.calibration.spacing);
  s.k = green::fit_profile(s.profile.offset_x, s.profile.point, h,
                           sensor_gains(scene.sensors, scene.material.nu, h).gains);
  s.wall = setup->wall;
  return s;
}

}  // namespace

RidgeStudy ridge_study(const Scene& scene, std::vector<double> per_period,
                       const std::function<void(const RidgeLevel&)>& on_level) {
  const Ridges& ridges = scene.geometry.ridges;
  if (!ridges.present())
    throw SceneError(scene.source_path + ": geometry.ridges: --ridges needs a scene with ridges");
  std::sort(per_period.begin(), per_period.end());
  if (per_period.size() < 3)
    throw SceneError("--ridges: a ridge study needs at least 3 levels for an observed order, got " +
                     std::to_string(per_period.size()));
  for (double L : per_period) {
    Scene level = scene;
    level.geometry.ridges.h = ridges.period / L;
    check_resources(level);
  }
  const bool flat = scene.geometry.kind == GeometryKind::flat;
  const Vec2 sensor = scene.sensors.positions[0];
  RidgeStudy study;
  for (double L : per_period) {
    Scene level = scene;
    level.geometry.ridges.h = ridges.period / L;
    char buf[200];
    std::snprintf(buf, sizeof buf, "%g elements per period (h %.4g mm on the pattern)", L,
                  level.geometry.ridges.h);
    progress(std::string("ridge study: ") + buf);
    Stopwatch clock;
    TetMesh mesh = build_mesh(level);
    check_meshed_dofs(level, mesh);
    check_sensors_on_skin(level, mesh);
    RidgeLevel out;
    out.per_period = L;
    out.ridge_h_mm = level.geometry.ridges.h;
    out.mesh_s = clock.seconds();
    TetMesh control;
    try {
      control = scale_ridges(mesh, level.geometry, kRidgeControl);
    } catch (const MeshError& e) {
      throw MeshError(std::string("ridge study at ") + buf +
                      ", lowering the ridges for the same-mesh control: " + e.what());
    }
    out.straightened = mesh.straightened;
    const double h = thickness_at(level, mesh, sensor);  // the mean top's: the same for both
    const Solved r = solve_scan(level, factored_skin(level, std::move(mesh), out.mesh_s), h, sensor);
    progress("ridge study: the same mesh, ridges " + std::to_string(kRidgeControl).substr(0, 4) +
             " x as high");
    const Solved f = solve_scan(level, factored_skin(level, std::move(control), 0.0), h, sensor);
    out.dofs = r.dofs;
    out.wall_ridged = r.wall;
    out.wall_control = f.wall;
    out.peak_rss_mb = peak_rss_mb();
    out.ridged = r.k;
    out.control = f.k;
    out.disc_max_diff_over_peak = green::max_error_over_peak(r.profile.disc, f.profile.disc);
    out.k_central_change = r.k.k_central / f.k.k_central - 1;
    out.k_lsq_line_change = r.k.k_lsq_line / f.k.k_lsq_line - 1;
    for (size_t c = 0; c < 4; ++c) {
      out.peak_ridged[c] = green::peak_abs(r.profile.point, green::kComponents[c]);
      out.peak_control[c] = green::peak_abs(f.profile.point, green::kComponents[c]);
      out.peak_change[c] = out.peak_ridged[c] / out.peak_control[c] - 1;
    }
    if (flat) {  // the control mesh's own error against the exact smooth layer
      const green::LayerGreen layer(h, scene.material.nu, green::LayerLoad::punch,
                                    0.5 * scene.calibration.punch_diameter);
      out.exact_smooth =
          green::fit_profile(f.profile.offset_x, green::exact_profile(layer, f.profile.offset_x), h);
    }
    study.levels.push_back(out);
    if (on_level) on_level(study.levels.back());
  }

  // The ridges' effect and its discretization error: Richardson over the three finest levels.
  const size_t n = study.levels.size();
  std::array<double, 3> s3;
  for (size_t i = 0; i < 3; ++i) s3[i] = 1 / study.levels[n - 3 + i].per_period;
  const auto extrapolate = [&](const std::string& name, const std::function<double(const RidgeLevel&)>& q) {
    RidgeLimit lim;
    lim.name = name;
    const std::array<double, 3> v{q(study.levels[n - 3]), q(study.levels[n - 2]), q(study.levels[n - 1])};
    lim.finest = v[2];
    lim.richardson = validation::richardson(v, s3);
    lim.mesh_error =
        lim.richardson.asymptotic ? std::abs(v[2] - lim.richardson.limit) : std::abs(v[2] - v[1]);
    lim.control_error = kRidgeControl * std::abs(v[2]);
    study.limits.push_back(lim);
  };
  extrapolate("k_central_change", [](const RidgeLevel& l) { return l.k_central_change; });
  extrapolate("k_lsq_line_change", [](const RidgeLevel& l) { return l.k_lsq_line_change; });
  for (size_t c = 0; c < 4; ++c)
    extrapolate(std::string("peak_") + green::component_name(green::kComponents[c]) + "_change",
                [c](const RidgeLevel& l) { return l.peak_change[c]; });
  return study;
}

}  // namespace skinfem::pipeline
