// The k correction of the paper (§III (iii)) for every sensor of a scene, from its Green tensors
// (pipeline/sensor_greens.hpp: the 3D or the meridian path):
//   k_central  = g_zz at zero offset (point value at the base, no sensor averaging) / (3/(2πh²));
//   k_lsq_line = least-squares fit of g_k(x, 0) = k·g_half(√k x, 0) to g_zz along y = 0 over |x| ≤ 3h,
//                uniform weight in x, with g_half the Boussinesq value at depth h.
// On flat scenes each sensor is also compared with the exact layer (Hankel transforms; on a ridged layer,
// the smooth layer of equal mean thickness). `skinfem kfit` writes kfit_json's object as kfit.json.
#pragma once

#include <array>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "skinfem/green/calibration.hpp"
#include "skinfem/pipeline/clock.hpp"
#include "skinfem/pipeline/sensor_greens.hpp"
#include "skinfem/validation/k_sweep.hpp"

namespace skinfem::pipeline {

// Arrays over components are in green::kComponents order (zz, zx, xz, xx).
struct KfitSensor {
  int sensor = 0;             // 1-based
  double x_mm = 0, y_mm = 0;  // its centre on the base
  double h_mm = 0;            // skin thickness above it
  double scan_half_width_mm = 0;
  green::KReport fe;  // from the computed Green tensor
  SensorGains gains;  // the model's (posts: computed on the meridian; discs: 1)
  std::array<double, 4> peak_point_per_mm2{};
  // Meridian path only: relative change of k from the same fit at half the resolution (bounds its error).
  std::optional<double> k_central_change_from_half_resolution, k_lsq_line_change_from_half_resolution;
  std::optional<MeridianCheck> meridian_check;   // the axis sensor of a cap solved in 3D
  std::optional<double> effective_thickness_mm;  // caps, discs: the flat layer whose scan fits best
  // Posts: the paper's calibration of the scan, scale and thickness both fitted (green::paper_calibration).
  std::optional<green::PaperCalibration> paper_calibration;
  std::string thickness_fit_failed;  // why neither of the two above is set where it would be
  // Flat scenes: the exact (smooth) layer's k and the largest difference of the readings over the peak.
  std::optional<green::KReport> exact;
  std::array<double, 4> peak_point_exact_per_mm2{}, point_max_diff_over_peak{}, disc_max_diff_over_peak{};
};

struct KfitResult {
  green::LayerLoad load = green::LayerLoad::punch;
  double punch_diameter_mm = 0;  // 0 for a point load
  double nu = 0;
  bool flat = false, ridged = false;
  bool post = false;  // post sensors: the exact layer's readings are a disc's, what the post differs from
  std::vector<KfitSensor> sensors;
  std::optional<MeridianCheck> meridian_check;  // as in its sensor
  std::string path, path_model;                 // of the Green tensors
  int dofs = 0, adjoint_solves = 0;
  double max_adjoint_residual = 0;  // 3D path
  Timings wall;                     // seconds per stage
  double peak_rss_mb = 0;
  double paper_k = 0;
  bool paper_k_reproduced = false;  // by sensor #1's k_central or k_lsq_line within 1 %
  std::string verdict;              // sensor #1 against the paper's k, from the numbers
  // Smooth flat layers: k_central of the exact layer under each load model (point, uniform, punch), and
  // whether any criterion, load model or the FE error reaches the paper's k.
  std::optional<std::array<double, 3>> k_central_exact_by_load_model;
  std::string explanation;
};

// load: point or punch (the calibration punch of the scene). axis_check: the axis sensor's meridian check of
// the same scan, already made (pipeline/green.hpp GreenRun's, under the punch), reused instead of solved
// again; null or of another sensor or load: kfit makes its own. thickness_fits false: no cap's
// effective-thickness fit (three quarters of kfit's time; a fast report leaves it out).
KfitResult kfit(const Scene& scene, const SensorGreens& greens, green::LayerLoad load,
                const MeridianCheck* axis_check = nullptr, bool thickness_fits = true);
// 2·sensors: each reading's scale in the paper's calibration (σ_z of sensor k at 2k, σ_x at 2k + 1), for
// the hole budget's units; empty unless every sensor was calibrated (posts).
Eigen::VectorXd paper_reading_scale(const KfitResult& r);
// The result as kfit.json holds it.
nlohmann::json kfit_json(const KfitResult& r);
// The range of each k over the sensors; report.json's kfit entry is kfit_json plus these two
// (add_k_ranges: k_central_range_over_sensors and k_lsq_line_range_over_sensors).
struct KfitRanges {
  std::array<double, 2> k_central, k_lsq_line;  // lowest, highest
};
KfitRanges k_ranges(const KfitResult& r);
void add_k_ranges(const KfitResult& r, nlohmann::json& kfit_entry);

// The exact layer's k as each reading of the calibration protocol changes about the scene's (thickness h at
// the headline sensor): which single change gives the paper's k (validation/k_sweep.hpp); and report.json's
// k_paper entry of the answer.
validation::KTargetAnswer k_paper_sweep(const Scene& scene, double h);
nlohmann::json k_paper_json(const validation::KTargetAnswer& a);

}  // namespace skinfem::pipeline
