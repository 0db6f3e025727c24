// The report's "Perception" section: the paper's two open questions (its conclusion) answered on the
// report's own skin, with its hole and its friction law.
//   - A row: the scene's hole repeated at a period of 3 diameters along the sweep's track, scanned until
//     every hole has crossed the whole track, sliding (the dynamic exploration), beside the linear
//     prediction Σ_k ς_k(u) from the holes one at a time (contact/holes/scan.hpp): the paper's fig. 3 for a
//     texture.
//   - Pairs: two holes at spacings of 1.2 to 6 diameters, where superposition holds (largest |ς − Σ ς_k|
//     over the largest |ς|, static and sliding; every second step of the sweep, the pair solved where both
//     holes come within 1.5 diameters of the contact).
//   The period and the spacings are rounded to whole steps of the sweep, so that each superposition is a
//   sum of one table of single-hole signals on the step's grid.
//   - Detection: `skinfem perceive`'s ladder (pipeline/perception.hpp) at the paper's noise, and the smallest
//     hole detected against the passages N (the matched filter's SNR grows as √N).
//   - Inversion: the row's sliding FE signals with the paper's noise (N = 14, seeded), inverted by
//     `skinfem invert`'s multi-sensor fit and by the paper's naive one, against the row's true holes.
// Every scan runs on the report's contact set-up (its path watches the sweep's line); the inversion's
// dictionary is built on its own mesh, after the chain's set-up is released. Units: mm, kPa.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "skinfem/contact/holes/scan.hpp"
#include "skinfem/pipeline/clock.hpp"
#include "skinfem/pipeline/contact_setup.hpp"
#include "skinfem/pipeline/inversion.hpp"
#include "skinfem/pipeline/perception.hpp"

namespace skinfem::pipeline {

// Two holes `spacing_mm` apart scanned across the contact: the superposition's largest difference over the
// scan's largest signal, per component.
struct PairPoint {
  std::string case_name;  // "static", "sliding"
  double spacing_mm = 0;
  double rel_diff_z = 0, rel_diff_x = 0;
  int positions = 0;  // solved with both holes
};

// The smallest hole detected (mm) at N passages, across the array and by the best single sensor; none when
// it falls outside the ladder, then `*_outside` says "above" (not even the scene's hole is detected) or
// "below" (the ladder's smallest, an eighth of it, is).
struct DetectionPoint {
  std::string case_name;
  int passages = 0;
  std::optional<double> array_mm, sensor_mm;
  std::string array_outside, sensor_outside;
};

struct ReportPerception {
  double period_mm = 0;  // the row's
  // The single hole's sliding signal's largest second difference along u over its largest |ς_z|: the
  // resolved rim's wiggle on the track's mesh.
  double wiggle_rel = 0;
  std::vector<double> row_holes_mm;  // the row's holes on the plate at u = 0 (x; y = the track's)
  contact::ScanResult row;           // sliding
  Eigen::MatrixXd row_superposed;    // the row's superposition: positions × 2·sensors (ς_z, ς_x), MPa
  std::vector<PairPoint> pairs;
  PerceptionRun detection;
  std::vector<DetectionPoint> detection_map;
  // The inversion example (empty until report_perception_inversion).
  validation::ScanSignals noisy;
  std::optional<InversionRun> inversion;
  validation::InversionScore multi_score;
  std::vector<validation::InversionScore> naive_scores;  // per sensor
  Timings wall;
};

// Why a scene gets no perception section (empty: it gets one), naming the scene key: what the inversion
// needs (inversion_unavailable), a sweep along the sliding direction +x and a hard interface.
std::string perception_unavailable(const Scene& scene);

// The row, the pairs and the detection on the report's set-up: its path (HolePath::always) watches the
// sweep's line across the whole zone, so that a hole is cut wherever it meets the contact (beyond the
// sweep's ends on the zone's mesh, not the sweep's). Throws SceneError when perception_unavailable says why
// not.
ReportPerception report_perception_scans(const Scene& scene, std::shared_ptr<const ContactSetup> setup);
// The inversion example: its own factorization (the dictionary's virtual sensors); call it with the
// chain's set-up released.
void report_perception_inversion(const Scene& scene, ReportPerception& p);

// report.json's "perception".
nlohmann::json report_perception_json(const Scene& scene, const ReportPerception& p);

}  // namespace skinfem::pipeline
