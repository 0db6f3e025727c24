// How ridges change the Green tensor and k, with the discretization error cancelled (`skinfem study
// --ridges`): at each ridge resolution (elements per period on the pattern) the ridged skin is meshed and
// solved, then the same mesh with its ridges scaled down to kRidgeControl of their height
// (mesh/scale_ridges.hpp): the difference of the two is the ridges' effect on identical elements. Sensor
// #1's calibration scan (the scene's punch, green/calibration.hpp) on both; on a flat layer also the
// control's k against the exact smooth layer (its own discretization error). Each difference's limit and
// error over the three finest levels (validation/richardson.hpp).
#pragma once

#include <array>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "skinfem/green/calibration.hpp"
#include "skinfem/pipeline/clock.hpp"
#include "skinfem/scene/scene.hpp"
#include "skinfem/validation/richardson.hpp"

namespace skinfem::pipeline {

// The control's ridges, relative to the scene's. The ridges' effect vanishes with them, at least linearly, so
// the control still carries at most this share of it: added to each difference's error bar.
inline constexpr double kRidgeControl = 0.02;

struct RidgeLevel {
  double per_period = 0, ridge_h_mm = 0;
  int dofs = 0, straightened = 0;
  double mesh_s = 0, peak_rss_mb = 0;
  Timings wall_ridged, wall_control;  // seconds per stage of each solve
  green::KReport ridged, control;
  // zz, zx, xz, xx: peaks of the point readings over the scan (1/mm²), and max |ridged − control| / peak
  // of the disc readings.
  std::array<double, 4> peak_ridged{}, peak_control{}, disc_max_diff_over_peak{};
  double k_central_change = 0, k_lsq_line_change = 0;  // ridged / control − 1
  std::array<double, 4> peak_change{};
  std::optional<green::KReport> exact_smooth;  // flat layers
};

struct RidgeLimit {
  std::string name;  // k_central_change, k_lsq_line_change, peak_<ab>_change
  double finest = 0;
  validation::Richardson richardson;
  double mesh_error = 0;     // |finest − limit| when asymptotic, else the last change
  double control_error = 0;  // kRidgeControl · |finest|
  double error() const { return mesh_error + control_error; }
};

struct RidgeStudy {
  std::vector<RidgeLevel> levels;  // by increasing resolution
  std::vector<RidgeLimit> limits;
};

// per_period: at least 3 levels. Throws SceneError for a scene without ridges, too few levels, or a level
// beyond the resource guard (before any meshing). on_level: called as each level completes.
RidgeStudy ridge_study(const Scene& scene, std::vector<double> per_period,
                       const std::function<void(const RidgeLevel&)>& on_level = {});

}  // namespace skinfem::pipeline
