#include "skinfem/pipeline/perception.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "skinfem/contact/holes/sweep.hpp"
#include "skinfem/pipeline/defect.hpp"
#include "skinfem/pipeline/progress.hpp"
#include "skinfem/pipeline/resources.hpp"
#include "skinfem/pipeline/scene_json.hpp"
#include "skinfem/validation/scan_detection.hpp"

namespace skinfem::pipeline {

namespace {
// The ladder: the scene's diameter, then 2^(−k/4) of it down to an eighth.
constexpr int kRungs = 13;
}  // namespace

std::optional<double> smallest_detected(const std::vector<double>& D, const std::vector<double>& snr,
                                        double need) {
  if (snr[0] < need || snr.back() >= need) return std::nullopt;
  for (size_t k = 0; k + 1 < D.size(); ++k)
    if (snr[k] >= need && snr[k + 1] < need) {
      if (!(snr[k + 1] > 0)) return D[k];
      const double t = std::log(need / snr[k + 1]) / std::log(snr[k] / snr[k + 1]);
      return D[k + 1] * std::pow(D[k] / D[k + 1], t);
    }
  return std::nullopt;  // not monotone: no single answer
}

void require_perceivable(const Scene& scene) {
  require_sweep(scene);
  // A resolved hole below the mesh is not resolved: the ladder of smaller holes is the bulge's, the small
  // hole's own model.
  if (scene.contact->sweep->model != HoleModel::bulge)
    throw SceneError(
        scene.source_path +
        ": contact.sweep.hole_model = \"resolved\": skinfem perceive sweeps holes down to an eighth "
        "of the scene's, below the mesh: it needs the small hole's model, \"bulge\" (under a hard "
        "interface)");
}

PerceptionRun perception_run(const Scene& scene, std::shared_ptr<const ContactSetup> setup,
                             const PerceptionOptions& o) {
  require_perceivable(scene);
  if (!(o.p_fa > 0 && o.p_fa < 1) || !(o.p_d > 0 && o.p_d < 1) || o.trials < 1 || o.sample_mm < 0 ||
      !(o.scan_mm >= 0) || o.scan_trials < 0)
    throw std::invalid_argument(
        "perception_run: p_fa and p_d in (0, 1), trials >= 1, sample_mm >= 0, scan_mm >= 0, scan_trials >= "
        "0");
  PerceptionRun run;
  run.options = o;
  run.wall = setup->wall;
  run.dofs = setup->model->solver().free_dofs();
  const HoleSweep& sweep = *scene.contact->sweep;
  const double step =
      std::hypot(sweep.to[0] - sweep.from[0], sweep.to[1] - sweep.from[1]) / std::max(1, sweep.positions - 1);
  const int every = o.sample_mm > 0 ? std::max(1, static_cast<int>(std::lround(o.sample_mm / step))) : 1;
  run.sample_mm = every * step;
  for (int k = 0; k < kRungs; ++k) run.diameters.push_back(sweep.hole_diameter * std::pow(2.0, -k / 4.0));
  const contact::HoleDimples dimples(*setup->solver, setup->mesh(), *setup->top, scene.material.E,
                                     scene.material.nu);
  const std::vector<std::pair<std::string, FrictionMode>> modes{{"static", FrictionMode::static_residual},
                                                                {"sliding", FrictionMode::coupled}};
  const double need = validation::required_snr(o.p_fa, o.p_d);
  const int sensors = static_cast<int>(scene.sensors.positions.size());
  for (const auto& [name, mode] : modes) {
    PerceptionCase c;
    c.name = name;
    Stopwatch clock;
    for (size_t r = 0; r < run.diameters.size(); ++r) {
      HoleSweep s = sweep;
      s.hole_diameter = run.diameters[r];
      const contact::SweepResult res = contact::hole_sweep(*setup->solver, setup->mesh(), s, mode, &dimples);
      Eigen::MatrixXd sampled((res.varsigma.rows() + every - 1) / every, res.varsigma.cols());
      for (int s = 0; s < sampled.rows(); ++s) sampled.row(s) = 1e3 * res.varsigma.row(s * every);
      double best = 0;
      std::vector<double> per_sensor;
      for (int k = 0; k < sensors; ++k) {
        per_sensor.push_back(validation::matched_filter_snr(sampled, o.noise, {k}));
        best = std::max(best, per_sensor.back());
      }
      c.ladder_array.push_back(validation::matched_filter_snr(sampled, o.noise));
      c.ladder_best.push_back(best);
      if (r == 0) {
        c.signal = sampled;
        c.sensor_snr = per_sensor;
        c.array_snr = c.ladder_array.back();
      }
    }
    c.array_min_mm = smallest_detected(run.diameters, c.ladder_array, need);
    c.sensor_min_mm = smallest_detected(run.diameters, c.ladder_best, need);
    run.wall["ladder_" + name] = clock.seconds();
    progress("perceive " + name + ": Monte Carlo of the filter (" + std::to_string(o.trials) + " draws)");
    Stopwatch mc;
    // At the threshold hole's SNR, where the detection rate is p_d rather than 1: the statistic depends on
    // the signal only through its SNR (T ~ N(d, 1)), so the scene's signal scaled stands for the threshold
    // hole's.
    if (c.array_snr > 0)
      c.rates = validation::monte_carlo_rates(c.signal * (need / c.array_snr), o.noise, {}, o.p_fa, o.trials,
                                              o.seed);
    run.wall["monte_carlo_" + name] = mc.seconds();
    for (size_t k = 0; k < c.sensor_snr.size(); ++k)
      if (c.sensor_snr[k] > c.sensor_snr[c.best_sensor]) c.best_sensor = static_cast<int>(k);
    if (c.array_snr > 0) {
      Stopwatch scan;
      const double z_pd = validation::normal_quantile(o.p_d);
      c.scan_decorrelation_array = validation::scan_decorrelation(c.signal, o.noise, {}, run.sample_mm);
      c.scan_threshold_array = validation::scan_threshold(c.scan_decorrelation_array, o.scan_mm, o.p_fa);
      c.scan_decorrelation_best =
          validation::scan_decorrelation(c.signal, o.noise, {c.best_sensor}, run.sample_mm);
      c.scan_threshold_best = validation::scan_threshold(c.scan_decorrelation_best, o.scan_mm, o.p_fa);
      c.scan_required_array = c.scan_threshold_array + z_pd;
      c.scan_required_best = c.scan_threshold_best + z_pd;
      c.array_min_unknown_mm = smallest_detected(run.diameters, c.ladder_array, c.scan_required_array);
      c.sensor_min_unknown_mm = smallest_detected(run.diameters, c.ladder_best, c.scan_required_best);
      if (o.scan_trials > 0) {
        char line[160];
        std::snprintf(line, sizeof line, "perceive %s: Monte Carlo of the filter slid along %g mm (%d scans)",
                      name.c_str(), o.scan_mm, o.scan_trials);
        progress(line);
        c.scan_rates = validation::monte_carlo_scan(c.signal * (c.scan_required_array / c.array_snr), o.noise,
                                                    {}, run.sample_mm, o.scan_mm, c.scan_threshold_array,
                                                    o.p_fa, o.scan_trials, o.seed);
      }
      run.wall["unknown_place_" + name] = scan.seconds();
    }
    run.cases.push_back(std::move(c));
  }
  return run;
}

nlohmann::json perception_json(const Scene& scene, const PerceptionRun& run) {
  const PerceptionOptions& o = run.options;
  const double need = validation::required_snr(o.p_fa, o.p_d);
  nlohmann::json j;
  j["scene"] = scene_json(scene);
  j["noise"] = {{"sigma_z_kPa", o.noise.sigma_z_kPa},
                {"sigma_x_kPa", o.noise.sigma_x_kPa},
                {"passages", o.noise.passages},
                {"sample_mm", run.sample_mm}};
  j["p_fa"] = o.p_fa;
  j["p_d"] = o.p_d;
  j["threshold"] = validation::detection_threshold(o.p_fa);
  j["required_snr"] = need;
  j["hole_diameter_mm"] = scene.contact->sweep->hole_diameter;
  j["hole_model"] = scene.contact->sweep->model == HoleModel::bulge ? "bulge" : "resolved";
  j["ladder_mm"] = run.diameters;
  for (const PerceptionCase& c : run.cases) {
    nlohmann::json k;
    k["array_snr"] = c.array_snr;
    k["array_p_d"] = validation::detection_probability(c.array_snr, o.p_fa);
    k["sensor_snr"] = c.sensor_snr;
    k["ladder_array_snr"] = c.ladder_array;
    k["ladder_best_sensor_snr"] = c.ladder_best;
    const auto bound_at = [&](const std::optional<double>& v, const std::vector<double>& snr,
                              double required) -> nlohmann::json {
      if (v) return {{"mm", *v}};
      if (snr.back() >= required) return {{"below_mm", run.diameters.back()}};
      return {{"above_mm", run.diameters.front()}};
    };
    const auto bound = [&](const std::optional<double>& v, const std::vector<double>& snr) {
      return bound_at(v, snr, need);
    };
    k["smallest_detected_array"] = bound(c.array_min_mm, c.ladder_array);
    k["smallest_detected_best_sensor"] = bound(c.sensor_min_mm, c.ladder_best);
    nlohmann::json u{{"scan_mm", o.scan_mm},
                     {"samples", static_cast<int>(std::lround(o.scan_mm / run.sample_mm)) + 1},
                     {"array_decorrelation_per_mm", c.scan_decorrelation_array},
                     {"array_threshold", c.scan_threshold_array},
                     {"array_required_snr", c.scan_required_array},
                     {"best_sensor", c.best_sensor + 1},
                     {"best_sensor_decorrelation_per_mm", c.scan_decorrelation_best},
                     {"best_sensor_threshold", c.scan_threshold_best},
                     {"best_sensor_required_snr", c.scan_required_best}};
    u["smallest_detected_array"] = bound_at(c.array_min_unknown_mm, c.ladder_array, c.scan_required_array);
    u["smallest_detected_best_sensor"] =
        bound_at(c.sensor_min_unknown_mm, c.ladder_best, c.scan_required_best);
    if (c.scan_rates.trials > 0)
      u["monte_carlo"] = {{"trials", c.scan_rates.trials},
                          {"false_alarm", c.scan_rates.false_alarm},
                          {"false_alarm_sigma", c.scan_rates.false_alarm_sigma},
                          {"detection", c.scan_rates.detection},
                          {"detection_sigma", c.scan_rates.detection_sigma}};
    k["unknown_place"] = u;
    k["monte_carlo"] = {{"trials", c.rates.trials},
                        {"false_alarm", c.rates.false_alarm},
                        {"false_alarm_sigma", c.rates.false_alarm_sigma},
                        {"detection", c.rates.detection},
                        {"detection_sigma", c.rates.detection_sigma}};
    j["cases"][c.name] = k;
  }
  j["dofs"] = run.dofs;
  j["wall_s"] = run.wall;
  j["wall_total_s"] = run.wall.total();
  j["peak_rss_mb"] = peak_rss_mb();
  return j;
}

}  // namespace skinfem::pipeline
