// skinfem perceive — how small a hole the sensor array perceives under the paper's noise (standard deviations
// 0.6 kPa on ς_z and 0.4 kPa on ς_x per sample and passage, the mean of N = 14 passages; all options): the
// scene's hole sweep (its bulge, static and sliding) at the scene's diameter and on a ladder down to an
// eighth of it, the matched filter's signal-to-noise ratio per sensor and across the array, the smallest
// diameter detected with probability 0.9 at a 1 % false-alarm rate, and a Monte Carlo of the filter checking
// both rates (validation/detection.hpp; docs/perception.md); the same where the hole's place is unknown along
// a scan (--scan-mm, 10 mm: the filter slid along it, its threshold from Rice's formula,
// validation/scan_detection.hpp).
//
//   $ skinfem perceive scenes/candelier2011.json --out out/perceive
//   perceive candelier2011: noise 0.6 kPa (varsigma_z), 0.4 kPa (varsigma_x) per sample every 0.033 mm, ...
//     sliding: the 0.5 mm hole at SNR 17.61 across the array (p_d 1.000), ...; smallest hole detected: ...
//
// Writes DIR/perception.json (pipeline/perception.hpp's perception_json) and DIR/roc.csv
// (case,filter,p_fa,p_d: the ROC curves at the scene's hole of the array's filter and the best single
// sensor's).
#include <cmath>
#include <cstdio>
#include <sstream>

#include "app/commands.hpp"
#include "app/common.hpp"
#include "app/stages.hpp"
#include "skinfem/pipeline/perception.hpp"

namespace skinfem::app {

int run_perceive(const Scene& scene, const std::string& out_dir, const pipeline::PerceptionOptions& options) {
  pipeline::require_perceivable(scene);
  check_output_dir(out_dir);
  const pipeline::PerceptionRun run = pipeline::perception_run(scene, contact_setup(scene), options);
  nlohmann::json j = pipeline::perception_json(scene, run);
  Stopwatch clock;
  prepare_output_dir(out_dir);
  std::ostringstream roc;
  roc.precision(8);
  roc << "case,filter,p_fa,p_d\n";
  for (const pipeline::PerceptionCase& c : run.cases) {
    const double best = c.sensor_snr.empty() ? 0 : c.sensor_snr[c.best_sensor];
    for (int i = 0; i <= 60; ++i) {
      const double p_fa = std::pow(10.0, -6 + 6.0 * i / 60) * (i == 60 ? 0.999 : 1.0);
      roc << c.name << ",array," << p_fa << "," << validation::detection_probability(c.array_snr, p_fa)
          << "\n";
      roc << c.name << ",best_sensor," << p_fa << "," << validation::detection_probability(best, p_fa)
          << "\n";
    }
  }
  write_text_atomic(out_dir + "/roc.csv", roc.str());
  add_write_seconds(j, clock.seconds());
  write_json(out_dir + "/perception.json", j);

  const validation::SensorNoise& n = options.noise;
  std::printf(
      "perceive %s: noise %.3g kPa (varsigma_z), %.3g kPa (varsigma_x) per sample every %.4g mm, mean of %d "
      "passages; detect at p_fa %.3g with p_d %.3g: SNR >= %.3f\n",
      scene.name.c_str(), n.sigma_z_kPa, n.sigma_x_kPa, run.sample_mm, n.passages, options.p_fa, options.p_d,
      j["required_snr"].get<double>());
  const auto smallest = [](const nlohmann::json& b) {
    char buf[64];
    if (b.contains("mm"))
      std::snprintf(buf, sizeof buf, "%.3f mm", b["mm"].get<double>());
    else if (b.contains("below_mm"))
      std::snprintf(buf, sizeof buf, "below %.3f mm", b["below_mm"].get<double>());
    else
      std::snprintf(buf, sizeof buf, "above %.3f mm", b["above_mm"].get<double>());
    return std::string(buf);
  };
  for (const pipeline::PerceptionCase& c : run.cases) {
    const nlohmann::json& k = j["cases"][c.name];
    const int best = c.best_sensor;
    std::printf(
        "  %s: the %.3g mm hole at SNR %.2f across the array (p_d %.3f), %.2f at sensor #%d alone; smallest "
        "hole detected: %s across the array, %s by one sensor\n",
        c.name.c_str(), j["hole_diameter_mm"].get<double>(), c.array_snr, k["array_p_d"].get<double>(),
        c.sensor_snr[best], best + 1, smallest(k["smallest_detected_array"]).c_str(),
        smallest(k["smallest_detected_best_sensor"]).c_str());
    if (c.rates.trials > 0)
      std::printf(
          "  %s: Monte Carlo of the array's filter at the threshold SNR (%d draws): false alarms %.4f "
          "(nominal "
          "%.4f +- %.4f), detections %.4f (nominal %.4f +- %.4f)\n",
          c.name.c_str(), c.rates.trials, c.rates.false_alarm, options.p_fa, c.rates.false_alarm_sigma,
          c.rates.detection, options.p_d, c.rates.detection_sigma);
    const nlohmann::json& u = k["unknown_place"];
    std::printf(
        "  %s, the place unknown along %.3g mm: threshold %.3f across the array, %.3f at sensor #%d (Rice); "
        "smallest hole detected: %s across the array, %s by one sensor\n",
        c.name.c_str(), options.scan_mm, c.scan_threshold_array, c.scan_threshold_best, c.best_sensor + 1,
        smallest(u["smallest_detected_array"]).c_str(), smallest(u["smallest_detected_best_sensor"]).c_str());
    if (c.scan_rates.trials > 0)
      std::printf(
          "  %s: Monte Carlo of the slid filter (%d scans): false alarms %.4f (Rice: at most %.4f, +- %.4f "
          "sampling), detections %.4f (at least %.4f)\n",
          c.name.c_str(), c.scan_rates.trials, c.scan_rates.false_alarm, options.p_fa,
          c.scan_rates.false_alarm_sigma, c.scan_rates.detection, options.p_d);
  }
  std::printf("  %d DOFs; total %.1f s, peak %.0f MB; wrote %s/perception.json, roc.csv\n", run.dofs,
              j["wall_total_s"].get<double>(), peak_rss_mb(), out_dir.c_str());
  return 0;
}

}  // namespace skinfem::app
