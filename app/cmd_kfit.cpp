// skinfem kfit — the k correction of the paper (§III (iii)), computed rather than quoted.
//
//   $ skinfem kfit scenes/flat_layer.json --out out/kfit
//   kfit flat_layer, headline sensor #1 of 1: h 3.040 mm, nu 0.5, punch load; meridian path (the unbounded
//   layer h = 3.04 mm (meridian radius 60.8 mm = 20 h, traction-free there)): 47027 DOFs, 1.08 s (...)
//     k_central 1.54995, k_lsq_line 1.60863 (exact layer: 1.54996, 1.60856); FE vs exact, ...
//
// Definitions (also in the README and kfit.json):
//   k_central  = g_zz at zero offset (point value at the base, no sensor averaging) / (3/(2πh²));
//   k_lsq_line = least-squares fit of g_k(x, 0) = k·g_half(√k x, 0) to g_zz along y = 0 over |x| ≤ 3h,
//                uniform weight in x, with g_half the Boussinesq value at depth h.
// The Green tensor comes from adjoint solves (reciprocity): on the meridian where the skin is a body of
// revolution with every sensor on its axis (pipeline/sensor_greens.hpp; --path auto, the default), else on
// the 3D mesh; flat scenes are also compared with the exact layer solution (Hankel transforms). Writes
// DIR/kfit.json.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "app/commands.hpp"
#include "app/common.hpp"
#include "app/stages.hpp"
#include "green/calibration.hpp"
#include "pipeline/adjoint_setup.hpp"
#include "pipeline/sensor_greens.hpp"

namespace skinfem::app {

using green::LayerLoad;

namespace {
nlohmann::json components_json(const green::KReport& r) {
  nlohmann::json j;
  for (size_t c = 0; c < 4; ++c)
    j[green::component_name(green::kComponents[c])] = {
        {"k", r.components[c].k}, {"rms_residual_over_peak", r.components[c].rms_residual_over_peak}};
  return j;
}
}  // namespace

nlohmann::json kfit_stage(const Scene& scene, const SensorGreens& greens, const std::string& out_dir,
                          const std::string& load_name) {
  const LayerLoad load = load_name == "point" ? LayerLoad::point : LayerLoad::punch;
  const double radius = 0.5 * scene.calibration.punch_diameter;
  const double paper_k = green::kPaperK;
  Stopwatch clock;
  nlohmann::json wall = greens.wall;

  clock = Stopwatch();
  const bool flat = scene.geometry.kind == GeometryKind::flat;
  // On a ridged flat layer the exact layer of equal mean thickness is the smooth skin to compare with, and
  // the difference is the ridges' effect, not an FE error.
  const bool ridged = scene.geometry.ridges.present();
  const std::string vs = ridged ? "_vs_smooth" : "_rel_error";
  nlohmann::json sensors = nlohmann::json::array();
  nlohmann::json summary;
  const int ns = static_cast<int>(scene.sensors.positions.size());
  // On a cap solved in 3D, the first sensor on its axis is checked against the meridian path.
  const int axis = axis_sensor(scene, greens);
  nlohmann::json check;
  for (int s = 0; s < ns; ++s) {
    progress_step("kfit: calibration scans", s, ns, clock.seconds());
    const auto& pos = scene.sensors.positions[s];
    const double h = greens.thickness[s];
    const auto prof =
        green::scan_profile(greens.of(s), load, radius, greens.scan_half_width[s], scene.calibration.spacing);
    const green::KReport fe_k = green::fit_profile(prof.offset_x, prof.point, h);
    nlohmann::json js = {{"sensor", s + 1},
                         {"x_mm", pos[0]},
                         {"y_mm", pos[1]},
                         {"h_mm", h},
                         {"scan_half_width_mm", prof.offset_x.back()},
                         {"k_central", fe_k.k_central},
                         {"k_lsq_line", fe_k.k_lsq_line},
                         {"components", components_json(fe_k)}};
    if (greens.coarse_at) {
      // The k fits again at half the resolution (point values on the fit window |x| ≤ 3h): the change bounds
      // the error, the meridian converging at order ≥ 2 (tests/green/test_meridian).
      std::vector<double> xs;
      std::vector<green::GreenSample> coarse;
      for (double x : prof.offset_x)
        if (std::abs(x) <= 3 * h + 1e-12)
          xs.push_back(x), coarse.push_back(greens.coarse_at(s, false, x, 0, load, radius));
      const green::KReport ck = green::fit_profile(xs, coarse, h);
      js["k_central_change_from_half_resolution"] = fe_k.k_central / ck.k_central - 1;
      js["k_lsq_line_change_from_half_resolution"] = fe_k.k_lsq_line / ck.k_lsq_line - 1;
    }
    for (auto c : green::kComponents)
      js["peak_point_per_mm2"][green::component_name(c)] = green::peak_abs(prof.point, c);
    if (s == axis) {
      check = meridian_check(scene, s, prof, load, radius, h);
      js["meridian_check"] = check;
    }
    if (scene.geometry.kind == GeometryKind::cap) {
      std::vector<double> zz;
      for (const auto& g : prof.point) zz.push_back(g.zz);
      js["effective_thickness_mm"] =
          green::effective_thickness(prof.offset_x, zz, h, scene.material.nu, load, radius);
    }
    if (flat) {
      const green::LayerGreen layer(h, scene.material.nu, load, radius);
      const auto exact = green::exact_profile(layer, prof.offset_x);
      const auto exact_disc = green::exact_profile(layer, prof.offset_x, scene.sensors.disc_diameter);
      const green::KReport ex_k = green::fit_profile(prof.offset_x, exact, h);
      // Sensor readings (disc means) against the exact disc means; point values against point values.
      const auto err = green::max_error_over_peak(prof.disc, exact_disc);
      const auto err_point = green::max_error_over_peak(prof.point, exact);
      js["k_central" + vs] = fe_k.k_central / ex_k.k_central - 1;
      js["k_lsq_line" + vs] = fe_k.k_lsq_line / ex_k.k_lsq_line - 1;
      for (size_t c = 0; c < 4; ++c) {
        const char* name = green::component_name(green::kComponents[c]);
        js[ridged ? "point_vs_smooth_max_diff_over_peak" : "fe_point_vs_exact_max_err_over_peak"][name] =
            err_point[c];
        js["peak_point_exact_per_mm2"][name] = green::peak_abs(exact, green::kComponents[c]);
      }
      js["k_central_exact"] = ex_k.k_central;
      js["k_lsq_line_exact"] = ex_k.k_lsq_line;
      js["components_exact"] = components_json(ex_k);
      for (size_t c = 0; c < 4; ++c)
        js[ridged ? "disc_vs_smooth_max_diff_over_peak" : "fe_vs_exact_max_err_over_peak"]
          [green::component_name(green::kComponents[c])] = err[c];
    }
    sensors.push_back(js);
  }
  wall["profiles"] = clock.seconds();

  // The headline numbers are those of the first sensor.
  const auto& first = sensors[0];
  summary = first;
  summary.erase("sensor");
  summary["nu"] = scene.material.nu;
  summary["load"] = load == LayerLoad::point ? "point" : "punch";
  summary["load_model"] =
      load == LayerLoad::point
          ? "unit point force"
          : "rigid-punch half-space profile F/(2πa√(a²−r²)) for both normal and tangential load";
  summary["punch_diameter_mm"] = load == LayerLoad::point ? 0.0 : scene.calibration.punch_diameter;
  summary["definitions"] = {
      {"k_central", "g_zz at zero offset (point value at the base, no sensor averaging) / (3/(2*pi*h^2))"},
      {"k_lsq_line",
       "least-squares fit of k*g_half(sqrt(k)x, 0) to g_zz along y = 0, |x| <= 3h, uniform weight"}};
  summary["sensors"] = sensors;
  if (!check.is_null()) summary["meridian_check"] = check;
  summary["path"] = greens.path;
  summary["path_model"] = greens.model;
  summary["dofs"] = greens.dofs;
  summary["adjoint_solves"] = greens.adjoint_solves;
  if (greens.path == "3d") summary["max_adjoint_residual"] = greens.max_adjoint_residual;
  summary["wall_s"] = wall;
  summary["wall_total_s"] = total_seconds(wall);
  summary["peak_rss_mb"] = peak_rss_mb();
  summary["paper_k"] = paper_k;
  const double kc = first["k_central"], kl = first["k_lsq_line"];
  const bool reproduced = green::reproduces_paper_k(kc) || green::reproduces_paper_k(kl);
  summary["paper_k_reproduced_within_1pct"] = reproduced;
  char verdict[640];
  std::snprintf(verdict, sizeof verdict,
                "sensor #1 at (%.3g, %.3g) mm: paper k = %.2f %s: k_central = %.4f (%+.1f%%), k_lsq_line = "
                "%.4f (%+.1f%%); "
                "one k for all four components: zz %.3f, zx %.3f, xz %.3f, xx %.3f",
                first["x_mm"].get<double>(), first["y_mm"].get<double>(), paper_k,
                reproduced ? "reproduced" : "NOT reproduced", kc, 100 * (kc / paper_k - 1), kl,
                100 * (kl / paper_k - 1), first["components"]["zz"]["k"].get<double>(),
                first["components"]["zx"]["k"].get<double>(), first["components"]["xz"]["k"].get<double>(),
                first["components"]["xx"]["k"].get<double>());
  summary["verdict"] = verdict;
  if (flat && !ridged) {
    // Which criterion, load model or resolution could explain 1.48: the exact layer under each model.
    const double h = first["h_mm"];
    nlohmann::json models;
    for (auto [name, model] : {std::pair{"point", LayerLoad::point}, std::pair{"uniform", LayerLoad::uniform},
                               std::pair{"punch", LayerLoad::punch}})
      models[name] = green::k_central(green::LayerGreen(h, scene.material.nu, model, radius).at(0, 0).zz, h);
    summary["k_central_exact_by_load_model"] = models;
    // The FE error widens what the exact values could be; the verdict follows from the numbers.
    const double fe_err = std::abs(first["k_central_rel_error"].get<double>());
    double closest = first["k_lsq_line_exact"].get<double>();
    for (const auto& [name, k] : models.items())
      if (std::abs(k.get<double>() - paper_k) < std::abs(closest - paper_k)) closest = k.get<double>();
    const bool reaches = std::abs(closest - paper_k) <= 0.01 + fe_err * closest;
    char why[640];
    std::snprintf(
        why, sizeof why,
        "exact layer k_central: point %.4f, uniform disc %.4f, punch %.4f; k_lsq_line %.4f; FE error "
        "%.2f%%: %s %.2f ± 0.01 (closest %.4f) with this punch size and nu",
        models["point"].get<double>(), models["uniform"].get<double>(), models["punch"].get<double>(),
        first["k_lsq_line_exact"].get<double>(), 100 * fe_err,
        reaches ? "a criterion or load model reaches" : "no criterion, load model or FE error reaches",
        paper_k, closest);
    summary["explanation"] = why;
  }

  prepare_output_dir(out_dir);
  write_json(out_dir + "/kfit.json", summary);
  double kc_lo = 1e300, kc_hi = -1e300, kl_lo = 1e300, kl_hi = -1e300;
  for (const auto& js : sensors) {
    kc_lo = std::min(kc_lo, js["k_central"].get<double>());
    kc_hi = std::max(kc_hi, js["k_central"].get<double>());
    kl_lo = std::min(kl_lo, js["k_lsq_line"].get<double>());
    kl_hi = std::max(kl_hi, js["k_lsq_line"].get<double>());
  }
  summary["k_central_range_over_sensors"] = {kc_lo, kc_hi};
  summary["k_lsq_line_range_over_sensors"] = {kl_lo, kl_hi};
  std::printf(
      "kfit %s, headline sensor #1 of %zu: h %.3f mm, nu %.3g, %s load; %s path (%s): %d DOFs, %.2f s (mesh "
      "%.2f, "
      "assemble %.2f, factor %.2f, adjoint %.2f)\n",
      scene.name.c_str(), sensors.size(), first["h_mm"].get<double>(), scene.material.nu,
      summary["load"].get<std::string>().c_str(), greens.path.c_str(), greens.model.c_str(), greens.dofs,
      total_seconds(wall), wall["mesh"].get<double>(), wall["assemble"].get<double>(),
      wall["factor"].get<double>(), wall["adjoint_solves"].get<double>());
  std::printf("  k_central %.5f, k_lsq_line %.5f", kc, kl);
  if (flat) {
    const nlohmann::json& d =
        first[ridged ? "disc_vs_smooth_max_diff_over_peak" : "fe_vs_exact_max_err_over_peak"];
    std::printf(" (%s: %.5f, %.5f); %s max |difference| / peak: zz %.1e zx %.1e xz %.1e xx %.1e",
                ridged ? "the smooth exact layer of equal mean thickness" : "exact layer",
                first["k_central_exact"].get<double>(), first["k_lsq_line_exact"].get<double>(),
                ridged ? "ridged vs smooth readings," : "FE vs exact,", d["zz"].get<double>(),
                d["zx"].get<double>(), d["xz"].get<double>(), d["xx"].get<double>());
  }
  std::printf("\n  %s\n", verdict);
  if (sensors.size() > 1)
    std::printf("  over all %zu sensors: k_central %.4f–%.4f, k_lsq_line %.4f–%.4f\n", sensors.size(), kc_lo,
                kc_hi, kl_lo, kl_hi);
  if (!check.is_null()) std::printf("  %s\n", meridian_check_line(check).c_str());
  if (summary.contains("explanation"))
    std::printf("  %s\n", summary["explanation"].get<std::string>().c_str());
  std::printf("  wrote %s/kfit.json\n", out_dir.c_str());
  return summary;
}

int run_kfit(const Scene& scene, const std::string& out_dir, const std::string& load_name, GreenPath path) {
  check_output_dir(out_dir);
  if (path == GreenPath::meridian || (path == GreenPath::automatic && meridian_unavailable(scene).empty())) {
    kfit_stage(scene, meridian_sensor_greens(scene), out_dir, load_name);
  } else {
    const auto setup = adjoint_setup(scene);
    kfit_stage(scene, with_path_reason(sensor_greens(scene, *setup), scene, path), out_dir, load_name);
  }
  return 0;
}

}  // namespace skinfem::app
