// How small a hole the sensor array perceives under the paper's noise (validation/detection.hpp): the
// scene's hole sweep (`skinfem defect`'s, static and sliding) at the scene's diameter and on a ladder of
// smaller ones on the same factorization, the matched filter's signal-to-noise ratio per sensor and across
// the array, and from it the smallest diameter detected with probability p_d at false-alarm rate p_fa,
// interpolated on the ladder (log d against log D: the bulge's signal grows as D³ under Coulomb friction, a
// shear strength's hole as D²), where the filter knows the hole's place and where it does not (the filter
// slid along a scan, validation/scan_detection.hpp). `skinfem perceive` writes perception_json's object
// as perception.json and the ROC curves as roc.csv.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "skinfem/pipeline/clock.hpp"
#include "skinfem/pipeline/contact_setup.hpp"
#include "skinfem/validation/detection.hpp"

namespace skinfem::pipeline {

struct PerceptionOptions {
  validation::SensorNoise noise;  // the paper's: 0.6 and 0.4 kPa, N = 14 passages
  double sample_mm = 0;           // spacing of independent noise samples along u; 0: the sweep's step
  double p_fa = 0.01, p_d = 0.9;
  int trials = 20000;  // Monte Carlo draws checking the false-alarm and detection rates
  std::uint64_t seed = 1;
  // A hole at an unknown place (validation/scan_detection.hpp): the filter slid along a scan this long, its
  // threshold from Rice's formula, checked on scan_trials noise-only scans (0: no check).
  double scan_mm = 10;
  int scan_trials = 2000;
  PerceptionOptions() { noise.passages = 14; }
};

struct PerceptionCase {
  std::string name;                  // "static", "sliding"
  Eigen::MatrixXd signal;            // the scene's hole, sampled: samples × 2·sensors, kPa
  std::vector<double> sensor_snr;    // per sensor, at the scene's hole
  double array_snr = 0;              // every sensor together
  std::vector<double> ladder_array;  // per ladder diameter, the array's SNR
  std::vector<double> ladder_best;   // per ladder diameter, the best single sensor's
  // The smallest detected diameter (mm) across the array and by the best single sensor; none when even the
  // ladder's smallest is detected (then below it) or the scene's is not (then above it).
  std::optional<double> array_min_mm, sensor_min_mm;
  // The array's filter on the scene's signal scaled to the required SNR (the threshold hole's): its
  // detection rate is p_d there.
  validation::MonteCarloRates rates;
  // At an unknown place along options.scan_mm: the filter's decorrelation √λ₂ (1/mm) and Rice's threshold,
  // for the array and for the best sensor at the scene's hole (the bulge's ladder only scales the signal, so
  // the best sensor and these numbers hold on every rung), the SNR that detects with p_d there (threshold +
  // Φ⁻¹(p_d)), the smallest hole detected with p_d, and the array's slid filter on noise-only scans and with
  // the threshold hole.
  double scan_decorrelation_array = 0, scan_threshold_array = 0, scan_required_array = 0;
  double scan_decorrelation_best = 0, scan_threshold_best = 0, scan_required_best = 0;
  int best_sensor = 0;  // 0-based, the largest sensor_snr
  std::optional<double> array_min_unknown_mm, sensor_min_unknown_mm;
  validation::MonteCarloRates scan_rates;
};

struct PerceptionRun {
  PerceptionOptions options;
  double sample_mm = 0;           // the spacing used
  std::vector<double> diameters;  // the ladder, mm, the scene's first
  std::vector<PerceptionCase> cases;
  int dofs = 0;
  Timings wall;
};

// The smallest diameter of the ladder D (decreasing) whose SNR reaches `need`, log-linear between the rungs
// that bracket it; none when even the smallest rung reaches it, the largest does not, or the SNR is not
// monotone there.
std::optional<double> smallest_detected(const std::vector<double>& D, const std::vector<double>& snr,
                                        double need);

// Throws SceneError without a contact.sweep or with a resolved one (its ladder goes below the mesh): what a
// command checks before it sets up the contact.
void require_perceivable(const Scene& scene);
// Throws as require_perceivable, and std::invalid_argument for options out of range.
PerceptionRun perception_run(const Scene& scene, std::shared_ptr<const ContactSetup> setup,
                             const PerceptionOptions& options);
nlohmann::json perception_json(const Scene& scene, const PerceptionRun& run);

}  // namespace skinfem::pipeline
