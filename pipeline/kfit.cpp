#include "skinfem/pipeline/kfit.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>

#include "skinfem/green/kfit.hpp"
#include "skinfem/pipeline/clock.hpp"
#include "skinfem/pipeline/progress.hpp"
#include "skinfem/scene/parallel.hpp"

namespace skinfem::pipeline {

using green::LayerLoad;

KfitResult kfit(const Scene& scene, const SensorGreens& greens, LayerLoad load,
                const MeridianCheck* axis_check, bool thickness_fits) {
  KfitResult r;
  r.load = load;
  r.punch_diameter_mm = load == LayerLoad::point ? 0.0 : scene.calibration.punch_diameter;
  r.nu = scene.material.nu;
  const double radius = 0.5 * scene.calibration.punch_diameter;
  r.flat = scene.geometry.kind == GeometryKind::flat;
  // On a ridged flat layer the exact layer of equal mean thickness is the smooth skin to compare with, and
  // the difference is the ridges' effect, not an FE error.
  r.ridged = scene.geometry.ridges.present();
  r.post = scene.sensors.model == SensorModel::post;
  r.wall = greens.wall;
  Stopwatch clock;
  const int ns = static_cast<int>(scene.sensors.positions.size());
  // On a cap solved in 3D, the first sensor on its axis is checked against the meridian path.
  const int axis = axis_sensor(scene, greens);
  // Sensors at the same thickness (a cap's mirror pairs) share their gains' meridian solves, made first
  // and in order (MUMPS).
  std::map<double, SensorGains> gains_at;  // by thickness
  for (int s = 0; s < ns; ++s)
    if (!gains_at.count(greens.thickness[s]))
      gains_at[greens.thickness[s]] = sensor_gains(scene.sensors, scene.material.nu, greens.thickness[s]);
  std::vector<KfitSensor> ks(ns);
  std::vector<green::ScanProfile> profs(ns);
  // One sensor's scan and fits: independent of the others' (the 3D maps are read only), so they run on the
  // machine's cores; each sensor's numbers do not depend on the thread that computes them.
  const auto scan = [&](int s) {
    KfitSensor& k = ks[s];
    k.sensor = s + 1;
    k.x_mm = scene.sensors.positions[s][0];
    k.y_mm = scene.sensors.positions[s][1];
    const double h = k.h_mm = greens.thickness[s];
    const auto& prof = profs[s] =
        green::scan_profile(greens.of(s), load, radius, greens.scan_half_width[s], scene.calibration.spacing);
    k.scan_half_width_mm = prof.offset_x.back();
    k.gains = gains_at.at(h);
    k.fe = green::fit_profile(prof.offset_x, prof.point, h, k.gains.gains);
    for (size_t c = 0; c < 4; ++c)
      k.peak_point_per_mm2[c] = green::peak_abs(prof.point, green::kComponents[c]);
    // A fit whose best thickness is its search bound has no answer: the sensor says why, kfit goes on.
    try {
      if (r.post) {
        // A post's scan is not a layer's: calibrate it as the paper did, scale and thickness.
        k.paper_calibration =
            green::paper_calibration(prof.offset_x, prof.point, h, scene.material.nu, load, radius);
      } else if (scene.geometry.kind == GeometryKind::cap && thickness_fits) {
        std::vector<double> zz;
        for (const auto& g : prof.point) zz.push_back(g.zz);
        k.effective_thickness_mm =
            green::effective_thickness(prof.offset_x, zz, h, scene.material.nu, load, radius);
      }
    } catch (const std::domain_error& e) {
      k.thickness_fit_failed = e.what();
    }
    if (r.flat) {
      const green::LayerGreen layer(h, scene.material.nu, load, radius);
      const auto exact = green::exact_profile(layer, prof.offset_x);
      const auto exact_disc = green::exact_profile(layer, prof.offset_x, scene.sensors.disc_diameter);
      k.exact = green::fit_profile(prof.offset_x, exact, h);
      // Sensor readings (disc means) against the exact disc means; point values against point values.
      const auto err = green::max_error_over_peak(prof.disc, exact_disc);
      const auto err_point = green::max_error_over_peak(prof.point, exact);
      for (size_t c = 0; c < 4; ++c) {
        k.point_max_diff_over_peak[c] = err_point[c];
        k.disc_max_diff_over_peak[c] = err[c];
        k.peak_point_exact_per_mm2[c] = green::peak_abs(exact, green::kComponents[c]);
      }
    }
  };
  // The meridian path's maps are evaluated on one thread (its modes keep their own accounts).
  for_each_index(
      ns, [&](std::size_t s) { scan(static_cast<int>(s)); }, greens.path == "3d",
      [&](std::size_t done) {
        progress_step("kfit: calibration scans", static_cast<int>(done), ns, clock.seconds());
      });
  for (int s = 0; s < ns; ++s) {
    KfitSensor& k = ks[s];
    const auto& prof = profs[s];
    const double h = k.h_mm;
    if (greens.coarse_at) {
      // The k fits again at half the resolution (point values on the fit window |x| ≤ 3h): the change bounds
      // the error, the meridian converging at order ≥ 2 (tests/green/test_meridian).
      std::vector<double> xs;
      std::vector<green::GreenSample> coarse;
      for (double x : prof.offset_x)
        if (std::abs(x) <= 3 * h + 1e-12)
          xs.push_back(x), coarse.push_back(greens.coarse_at(s, false, x, 0, load, radius));
      const green::KReport ck = green::fit_profile(xs, coarse, h, k.gains.gains);
      k.k_central_change_from_half_resolution = k.fe.k_central / ck.k_central - 1;
      k.k_lsq_line_change_from_half_resolution = k.fe.k_lsq_line / ck.k_lsq_line - 1;
    }
    if (s == axis)
      r.meridian_check = k.meridian_check =
          axis_check && axis_check->sensor == s + 1 && load == LayerLoad::punch
              ? *axis_check
              : meridian_check(scene, s, prof, load, radius, h);
    r.sensors.push_back(std::move(k));
  }
  r.wall["profiles"] = clock.seconds();
  r.path = greens.path;
  r.path_model = greens.model;
  r.dofs = greens.dofs;
  r.adjoint_solves = greens.adjoint_solves;
  r.max_adjoint_residual = greens.max_adjoint_residual;
  r.peak_rss_mb = peak_rss_mb();

  // The headline numbers are those of the first sensor.
  const KfitSensor& first = r.sensors.at(0);
  r.paper_k = green::kPaperK;
  const double kc = first.fe.k_central, kl = first.fe.k_lsq_line;
  r.paper_k_reproduced = green::reproduces_paper_k(kc) || green::reproduces_paper_k(kl);
  // The finding and its reason: the exact flat layer of sensor #1's thickness, ν and load, the paper's
  // setting without the mesh or the skin's curvature (docs/k_correction.md).
  char components[160];
  std::snprintf(components, sizeof components,
                "one k for all four components: zz %.3f, zx %.3f, xz %.3f, xx %.3f", first.fe.components[0].k,
                first.fe.components[1].k, first.fe.components[2].k, first.fe.components[3].k);
  char reason[320] = ": reproduced within 1%";
  if (!r.paper_k_reproduced) {
    std::snprintf(reason, sizeof reason, ": neither within 1%%");
    if (!r.post) {
      const double exact = green::k_central(
          green::LayerGreen(first.h_mm, scene.material.nu, load, radius).at(0, 0).zz, first.h_mm);
      std::snprintf(
          reason, sizeof reason,
          green::reproduces_paper_k(exact)
              ? "; the exact flat layer of this thickness (%.3f mm), nu and load gives k_central = %.4f "
                "(%+.1f%%), within 1%%: the difference is this skin's shape or mesh"
              : "; the exact flat layer of this thickness (%.3f mm), nu and load gives k_central = %.4f "
                "(%+.1f%%): 1.48 is not this layer's k by the central criterion (docs/k_correction.md)",
          first.h_mm, exact, 100 * (exact / r.paper_k - 1));
    }
  }
  char verdict[900];
  std::snprintf(
      verdict, sizeof verdict,
      "sensor #1 at (%.3g, %.3g) mm: k_central = %.4f (%+.1f%%) and k_lsq_line = %.4f (%+.1f%%) against "
      "the paper's %.2f%s; %s",
      first.x_mm, first.y_mm, kc, 100 * (kc / r.paper_k - 1), kl, 100 * (kl / r.paper_k - 1), r.paper_k,
      reason, components);
  r.verdict = verdict;
  if (r.flat && !r.ridged && !r.post) {
    // Which criterion, load model or resolution could explain 1.48: the exact layer under each model.
    const double h = first.h_mm;
    std::array<double, 3> models{};
    const LayerLoad kinds[3] = {LayerLoad::point, LayerLoad::uniform, LayerLoad::punch};
    for (int m = 0; m < 3; ++m)
      models[m] = green::k_central(green::LayerGreen(h, scene.material.nu, kinds[m], radius).at(0, 0).zz, h);
    r.k_central_exact_by_load_model = models;
    // The FE error widens what the exact values could be; the verdict follows from the numbers.
    const double fe_err = std::abs(first.fe.k_central / first.exact->k_central - 1);
    double closest = first.exact->k_lsq_line;
    // In the order kfit.json lists them (by name: point, punch, uniform).
    for (int m : {0, 2, 1})
      if (std::abs(models[m] - r.paper_k) < std::abs(closest - r.paper_k)) closest = models[m];
    const bool reaches = std::abs(closest - r.paper_k) <= 0.01 + fe_err * closest;
    char why[640];
    std::snprintf(
        why, sizeof why,
        "exact layer k_central: point %.4f, uniform disc %.4f, punch %.4f; k_lsq_line %.4f; FE error "
        "%.2f%%: %s %.2f ± 0.01 (closest %.4f) with this punch size and nu",
        models[0], models[1], models[2], first.exact->k_lsq_line, 100 * fe_err,
        reaches ? "a criterion or load model reaches" : "no criterion, load model or FE error reaches",
        r.paper_k, closest);
    r.explanation = why;
  }
  return r;
}

Eigen::VectorXd paper_reading_scale(const KfitResult& r) {
  for (const KfitSensor& k : r.sensors)
    if (!k.paper_calibration) return {};
  Eigen::VectorXd s(2 * r.sensors.size());
  for (size_t k = 0; k < r.sensors.size(); ++k) {
    s[2 * k] = r.sensors[k].paper_calibration->scale_z;
    s[2 * k + 1] = r.sensors[k].paper_calibration->scale_x;
  }
  return s;
}

namespace {
nlohmann::json components_json(const green::KReport& r) {
  nlohmann::json j;
  for (size_t c = 0; c < 4; ++c)
    j[green::component_name(green::kComponents[c])] = {
        {"k", r.components[c].k}, {"rms_residual_over_peak", r.components[c].rms_residual_over_peak}};
  return j;
}

nlohmann::json per_component(const std::array<double, 4>& v) {
  nlohmann::json j;
  for (size_t c = 0; c < 4; ++c) j[green::component_name(green::kComponents[c])] = v[c];
  return j;
}

nlohmann::json sensor_json(const KfitResult& r, const KfitSensor& k) {
  nlohmann::json js = {{"sensor", k.sensor},
                       {"x_mm", k.x_mm},
                       {"y_mm", k.y_mm},
                       {"h_mm", k.h_mm},
                       {"scan_half_width_mm", k.scan_half_width_mm},
                       {"k_central", k.fe.k_central},
                       {"k_lsq_line", k.fe.k_lsq_line},
                       {"components", components_json(k.fe)}};
  if (r.post && k.gains.gains.fitted) {
    for (size_t c = 0; c < 4; ++c)
      js["gains"]["fitted_" + std::string(green::component_name(green::kComponents[c]))] =
          k.fe.components[c].gain;
  } else if (r.post) {
    js["gains"] = {{"sigma_z", k.gains.gains.z},
                   {"sigma_x", k.gains.gains.x},
                   {"change_from_half_resolution", k.gains.change},
                   {"dofs", k.gains.dofs},
                   {"seconds", k.gains.seconds}};
  }
  if (k.k_central_change_from_half_resolution) {
    js["k_central_change_from_half_resolution"] = *k.k_central_change_from_half_resolution;
    js["k_lsq_line_change_from_half_resolution"] = *k.k_lsq_line_change_from_half_resolution;
  }
  js["peak_point_per_mm2"] = per_component(k.peak_point_per_mm2);
  if (k.meridian_check) js["meridian_check"] = meridian_check_json(*k.meridian_check);
  if (k.effective_thickness_mm) js["effective_thickness_mm"] = *k.effective_thickness_mm;
  if (!k.thickness_fit_failed.empty()) js["thickness_fit_failed"] = k.thickness_fit_failed;
  if (const auto& c = k.paper_calibration)
    js["paper_calibration"] = {{"thickness_mm", c->thickness_mm},
                               {"scale_z", c->scale_z},
                               {"scale_x", c->scale_x},
                               {"rms_z_over_peak", c->rms_z_over_peak},
                               {"rms_x_over_peak", c->rms_x_over_peak}};
  if (k.exact) {
    // Against the smooth layer (ridged), the exact layer's disc (posts) or the exact layer: an FE error.
    const std::string vs = r.ridged ? "_vs_smooth" : r.post ? "_vs_exact_disc" : "_rel_error";
    js["k_central" + vs] = k.fe.k_central / k.exact->k_central - 1;
    js["k_lsq_line" + vs] = k.fe.k_lsq_line / k.exact->k_lsq_line - 1;
    js[r.ridged ? "point_vs_smooth_max_diff_over_peak"
       : r.post ? "point_vs_exact_disc_max_diff_over_peak"
                : "fe_point_vs_exact_max_err_over_peak"] = per_component(k.point_max_diff_over_peak);
    js["peak_point_exact_per_mm2"] = per_component(k.peak_point_exact_per_mm2);
    js["k_central_exact"] = k.exact->k_central;
    js["k_lsq_line_exact"] = k.exact->k_lsq_line;
    js["components_exact"] = components_json(*k.exact);
    js[r.ridged ? "disc_vs_smooth_max_diff_over_peak"
       : r.post ? "post_vs_exact_disc_max_diff_over_peak"
                : "fe_vs_exact_max_err_over_peak"] = per_component(k.disc_max_diff_over_peak);
  }
  return js;
}
}  // namespace

KfitRanges k_ranges(const KfitResult& r) {
  KfitRanges out{{1e300, -1e300}, {1e300, -1e300}};
  for (const KfitSensor& k : r.sensors) {
    out.k_central = {std::min(out.k_central[0], k.fe.k_central), std::max(out.k_central[1], k.fe.k_central)};
    out.k_lsq_line = {std::min(out.k_lsq_line[0], k.fe.k_lsq_line),
                      std::max(out.k_lsq_line[1], k.fe.k_lsq_line)};
  }
  return out;
}

void add_k_ranges(const KfitResult& r, nlohmann::json& j) {
  const KfitRanges k = k_ranges(r);
  j["k_central_range_over_sensors"] = k.k_central;
  j["k_lsq_line_range_over_sensors"] = k.k_lsq_line;
}

nlohmann::json kfit_json(const KfitResult& r) {
  nlohmann::json sensors = nlohmann::json::array();
  for (const KfitSensor& k : r.sensors) sensors.push_back(sensor_json(r, k));
  nlohmann::json summary = sensors.at(0);
  summary.erase("sensor");
  summary["nu"] = r.nu;
  summary["load"] = r.load == LayerLoad::point ? "point" : "punch";
  summary["load_model"] =
      r.load == LayerLoad::point
          ? "unit point force"
          : "rigid-punch half-space profile F/(2πa√(a²−r²)) for both normal and tangential load";
  summary["punch_diameter_mm"] = r.punch_diameter_mm;
  summary["definitions"] = {
      {"k_central", "g_zz at zero offset (point value at the base, no sensor averaging) / (3/(2*pi*h^2))"},
      {"k_lsq_line",
       "least-squares fit of k*g_half(sqrt(k)x, 0) to g_zz along y = 0, |x| <= 3h, uniform weight"}};
  if (r.post) {
    summary["definitions"]["k_central"] = "g_zz at zero offset / (gain of zz * 3/(2*pi*h^2))";
    summary["definitions"]["k_lsq_line"] =
        "least-squares fit of gain*k*g_half(sqrt(k)x, 0) to g_zz along y = 0, |x| <= 3h, uniform weight";
    summary["definitions"]["gains"] =
        "the post's readings under a uniform unit pressure (sigma_z) and shear (sigma_x) on the unbounded "
        "flat layer of its thickness, the post held: the model's integral for zz, xz (sigma_z) and zx, xx "
        "(sigma_x). sigma_z is 1 at nu = 0.5 (the layer is hydrostatic and the post reads the pressure), "
        "else the integral of g_zz on the meridian; sigma_x is the integral of g_xx there. A post on springs "
        "has none computed yet: each component's gain is fitted with its k (fitted_zz, ...)";
    summary["definitions"]["paper_calibration"] =
        "the paper's calibration of the scan: the exact bonded layer's base stress under the same load, "
        "thickness and scale_z fitted to g_zz, scale_x to g_zx at that thickness; a reading / its scale is "
        "in the paper's kPa";
  }
  summary["sensors"] = sensors;
  if (r.meridian_check) summary["meridian_check"] = meridian_check_json(*r.meridian_check);
  summary["path"] = r.path;
  summary["path_model"] = r.path_model;
  summary["dofs"] = r.dofs;
  summary["adjoint_solves"] = r.adjoint_solves;
  if (r.path == "3d") summary["max_adjoint_residual"] = r.max_adjoint_residual;
  summary["wall_s"] = r.wall;
  summary["wall_total_s"] = r.wall.total();
  summary["peak_rss_mb"] = r.peak_rss_mb;
  summary["paper_k"] = r.paper_k;
  summary["paper_k_reproduced_within_1pct"] = r.paper_k_reproduced;
  summary["verdict"] = r.verdict;
  if (r.k_central_exact_by_load_model) {
    const auto& m = *r.k_central_exact_by_load_model;
    summary["k_central_exact_by_load_model"] = {{"point", m[0]}, {"uniform", m[1]}, {"punch", m[2]}};
    summary["explanation"] = r.explanation;
  }
  return summary;
}

validation::KTargetAnswer k_paper_sweep(const Scene& scene, double h) {
  validation::KProtocol base;
  base.h = h;
  base.nu = scene.material.nu;
  base.punch_diameter = scene.calibration.punch_diameter;
  return validation::k_target_answer(base, green::kPaperK);
}

nlohmann::json k_paper_json(const validation::KTargetAnswer& a) {
  nlohmann::json j;
  for (const auto& n : a.near)
    j["within_0.01"].push_back(
        {{"parameter", n.parameter}, {"value", n.value}, {"criterion", n.criterion}, {"k", n.k}});
  for (const auto& c : a.crossings)
    j["crossings"].push_back({{"parameter", c.parameter},
                              {"criterion", c.criterion},
                              {"value", c.value},
                              {"linear_interpolation", c.interpolated}});
  j["answer"] = a.answer;
  return j;
}

}  // namespace skinfem::pipeline
