// skinfem study --ridges — how ridges change the Green tensor and k, with the discretization error
// cancelled: at each ridge resolution (period/L on the pattern) the ridged skin is meshed and solved, then
// the same mesh with its ridges scaled down to 2 % of their height (mesh/scale_ridges.hpp) is solved: the
// difference of the two is the ridges' effect on identical elements.
//
//   $ skinfem study scenes/ridged_layer.json --ridges 4,5,6,8 --out out/ridge_study
//   L 8 (ridge h 0.0275 mm): 348358 DOFs, 0 straightened, 155.3 s (mesh 1.2, factor 74.6 + 69.1), peak 5757
//   MB
//     k_central ridged 1.55432 control 1.54565: +0.561 %; k_lsq_line 1.60983 / 1.60368: +0.383 %
//     ...
//   k_central_change: +0.561 % ± 0.015 % (last change: the levels are not asymptotic; + 0.011 % for ...)
//
// Per level, sensor #1's calibration scan (the scene's punch, green/calibration.hpp) on both meshes:
// k_central, k_lsq_line, the peaks of the four components, their max |ridged − control| / peak over the scan
// (disc readings), DOFs, seconds per stage and peak memory; on a flat layer also the control mesh's k against
// the exact smooth layer (its own discretization error). The observed order and Richardson limit of each
// difference over the three finest levels (validation/richardson.hpp). Writes DIR/ridge_study.json and
// DIR/ridge_study.csv.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "app/commands.hpp"
#include "app/common.hpp"
#include "green/calibration.hpp"
#include "green/layer_exact.hpp"
#include "mesh/build.hpp"
#include "mesh/scale_ridges.hpp"
#include "mesh/surface.hpp"
#include "pipeline/adjoint_setup.hpp"
#include "pipeline/resources.hpp"
#include "validation/richardson.hpp"

namespace skinfem::app {

namespace {

// The control's ridges, relative to the scene's. The ridges' effect vanishes with them, at least linearly, so
// the control still carries at most kControl of it: added to each difference's error bar.
constexpr double kControl = 0.02;

struct Solved {
  int dofs = 0;
  green::KReport k;
  green::ScanProfile profile;
  nlohmann::json wall;
};

Solved solve_scan(const Scene& scene, std::shared_ptr<Skin> skin, double h, const Vec2& sensor) {
  const auto setup = adjoint_setup(scene, std::move(skin));
  Solved s;
  s.dofs = setup->model->solver().free_dofs();
  const double radius = 0.5 * scene.calibration.punch_diameter;
  s.profile = green::scan_profile(*setup->fe, 0, green::LayerLoad::punch, radius,
                                  scan_half_width(scene, &setup->mesh, h, sensor), scene.calibration.spacing);
  s.k = green::fit_profile(s.profile.offset_x, s.profile.point, h);
  s.wall = setup->wall;
  return s;
}

}  // namespace

int run_ridge_study(const Scene& scene, const std::string& out_dir, std::vector<double> per_period) {
  const Ridges& ridges = scene.geometry.ridges;
  if (!ridges.present())
    throw SceneError(scene.source_path + ": geometry.ridges: --ridges needs a scene with ridges");
  std::sort(per_period.begin(), per_period.end());
  if (per_period.size() < 3)
    throw SceneError("--ridges: a ridge study needs at least 3 levels for an observed order, got " +
                     std::to_string(per_period.size()));
  check_output_dir(out_dir);
  for (double L : per_period) {
    Scene level = scene;
    level.geometry.ridges.h = ridges.period / L;
    check_resources(level, g_max_dofs);
  }
  const bool flat = scene.geometry.kind == GeometryKind::flat;
  const Vec2 sensor = scene.sensors.positions[0];

  nlohmann::json levels = nlohmann::json::array();
  std::ostringstream csv;
  csv << "per_period,ridge_h_mm,dofs,straightened,mesh_s,assemble_s,factor_s,adjoint_s,peak_rss_mb,"
         "k_central_ridged,k_central_control,k_lsq_line_ridged,k_lsq_line_control,diff_zz,diff_zx,"
         "diff_xz,diff_xx\n";
  std::vector<double> d_central, d_lsq, scale;
  std::array<std::vector<double>, 4> d_peak;
  for (double L : per_period) {
    Scene level = scene;
    level.geometry.ridges.h = ridges.period / L;
    char buf[200];
    std::snprintf(buf, sizeof buf, "%g elements per period (h %.4g mm on the pattern)", L,
                  level.geometry.ridges.h);
    progress(std::string("ridge study: ") + buf);
    Stopwatch clock;
    TetMesh mesh = build_mesh(level);
    check_meshed_dofs(level, mesh, g_max_dofs);
    check_sensors_on_skin(level, mesh);
    const double mesh_s = clock.seconds();
    TetMesh control;
    try {
      control = scale_ridges(mesh, level.geometry, kControl);
    } catch (const MeshError& e) {
      throw MeshError(std::string("ridge study at ") + buf +
                      ", lowering the ridges for the same-mesh control: " + e.what());
    }
    const int straightened = mesh.straightened;
    const double h = thickness_at(level, mesh, sensor);  // the mean top's: the same for both
    const Solved r = solve_scan(level, factored_skin(level, std::move(mesh), mesh_s), h, sensor);
    progress("ridge study: the same mesh, ridges " + std::to_string(kControl).substr(0, 4) + " x as high");
    const Solved f = solve_scan(level, factored_skin(level, std::move(control), 0.0), h, sensor);

    const auto diff = green::max_error_over_peak(r.profile.disc, f.profile.disc);
    nlohmann::json jl = {{"per_period", L},
                         {"ridge_h_mm", level.geometry.ridges.h},
                         {"dofs", r.dofs},
                         {"straightened_elements", straightened},
                         {"wall_s", {{"ridged", r.wall}, {"control", f.wall}}},
                         {"peak_rss_mb", peak_rss_mb()},
                         {"k_central", {{"ridged", r.k.k_central}, {"control", f.k.k_central}}},
                         {"k_lsq_line", {{"ridged", r.k.k_lsq_line}, {"control", f.k.k_lsq_line}}}};
    scale.push_back(1 / L);
    d_central.push_back(r.k.k_central / f.k.k_central - 1);
    d_lsq.push_back(r.k.k_lsq_line / f.k.k_lsq_line - 1);
    for (size_t c = 0; c < 4; ++c) {
      const auto comp = green::kComponents[c];
      const char* name = green::component_name(comp);
      const double pr = green::peak_abs(r.profile.point, comp), pf = green::peak_abs(f.profile.point, comp);
      jl["peak_point_per_mm2"][name] = {{"ridged", pr}, {"control", pf}};
      jl["disc_max_diff_over_peak"][name] = diff[c];
      d_peak[c].push_back(pr / pf - 1);
    }
    jl["k_central_change"] = d_central.back();
    jl["k_lsq_line_change"] = d_lsq.back();
    if (flat) {  // the control mesh's own error against the exact smooth layer
      const green::LayerGreen layer(h, scene.material.nu, green::LayerLoad::punch,
                                    0.5 * scene.calibration.punch_diameter);
      const auto ex =
          green::fit_profile(f.profile.offset_x, green::exact_profile(layer, f.profile.offset_x), h);
      jl["control_vs_exact"] = {{"k_central", f.k.k_central / ex.k_central - 1},
                                {"k_lsq_line", f.k.k_lsq_line / ex.k_lsq_line - 1}};
      jl["k_exact_smooth"] = {{"k_central", ex.k_central}, {"k_lsq_line", ex.k_lsq_line}};
    }
    levels.push_back(jl);
    csv << L << "," << level.geometry.ridges.h << "," << r.dofs << "," << straightened << ","
        << r.wall["mesh"].get<double>() << "," << r.wall["assemble"].get<double>() << ","
        << r.wall["factor"].get<double>() << "," << r.wall["adjoint_solves"].get<double>() << ","
        << peak_rss_mb() << "," << r.k.k_central << "," << f.k.k_central << "," << r.k.k_lsq_line << ","
        << f.k.k_lsq_line << "," << diff[0] << "," << diff[1] << "," << diff[2] << "," << diff[3] << "\n";
    std::printf(
        "L %g (ridge h %.4f mm): %d DOFs, %d straightened, %.1f s (mesh %.1f, factor %.1f + %.1f), peak %.0f "
        "MB\n  k_central ridged %.5f control %.5f: %+.3f %%; k_lsq_line %.5f / %.5f: %+.3f %%\n"
        "  peaks zz %+.2f %%, zx %+.2f %%, xz %+.2f %%, xx %+.2f %%; max |ridged - control| / peak "
        "zz %.2f %%, zx %.2f %%, xz %.2f %%, xx %.2f %%\n",
        L, level.geometry.ridges.h, r.dofs, straightened, total_seconds(r.wall) + total_seconds(f.wall),
        mesh_s, r.wall["factor"].get<double>(), f.wall["factor"].get<double>(), peak_rss_mb(), r.k.k_central,
        f.k.k_central, 100 * d_central.back(), r.k.k_lsq_line, f.k.k_lsq_line, 100 * d_lsq.back(),
        100 * d_peak[0].back(), 100 * d_peak[1].back(), 100 * d_peak[2].back(), 100 * d_peak[3].back(),
        100 * diff[0], 100 * diff[1], 100 * diff[2], 100 * diff[3]);
    std::fflush(stdout);
  }

  // The ridges' effect and its discretization error: Richardson over the three finest levels.
  nlohmann::json limits;
  const size_t n = scale.size();
  const std::array<double, 3> s3{scale[n - 3], scale[n - 2], scale[n - 1]};
  const auto extrapolate = [&](const std::string& name, const std::vector<double>& q) {
    const auto R = validation::richardson({q[n - 3], q[n - 2], q[n - 1]}, s3);
    const double mesh_err = R.asymptotic ? std::abs(q[n - 1] - R.limit) : std::abs(q[n - 1] - q[n - 2]);
    const double control_err = kControl * std::abs(q[n - 1]);
    limits[name] = {{"finest", q[n - 1]},
                    {"asymptotic", R.asymptotic},
                    {"order", R.order},
                    {"limit", R.limit},
                    {R.asymptotic ? "mesh_error_richardson" : "mesh_error_last_change", mesh_err},
                    {"control_ridges_bound", control_err},
                    {"error", mesh_err + control_err}};
    std::printf("%s: %+.3f %% ± %.3f %% (%s; + %.3f %% for the control's own ridges)\n", name.c_str(),
                100 * q[n - 1], 100 * (mesh_err + control_err),
                R.asymptotic ? ("Richardson, observed order " + std::to_string(R.order).substr(0, 4)).c_str()
                             : "last change: the levels are not asymptotic",
                100 * control_err);
  };
  extrapolate("k_central_change", d_central);
  extrapolate("k_lsq_line_change", d_lsq);
  for (size_t c = 0; c < 4; ++c)
    extrapolate(std::string("peak_") + green::component_name(green::kComponents[c]) + "_change", d_peak[c]);

  prepare_output_dir(out_dir);
  write_json(out_dir + "/ridge_study.json",
             {{"scene", scene_json(scene)},
              {"sensor", 1},
              {"definitions",
               {{"change", "ridged / control - 1 on the same mesh, the control's ridges " +
                               std::to_string(kControl) + " x as high (mesh/scale_ridges.hpp)"},
                {"disc_max_diff_over_peak", "max over the scan of |ridged - control| / max |control|"}}},
              {"levels", levels},
              {"ridge_effect", limits}});
  write_text_atomic(out_dir + "/ridge_study.csv", csv.str());
  std::printf("wrote %s/ridge_study.json, ridge_study.csv\n", out_dir.c_str());
  return 0;
}

}  // namespace skinfem::app
