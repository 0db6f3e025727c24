// How close two holes may be and still come out of the inversion as two (the paper's conclusion asks for
// an inversion; its resolution decides what texture it can read), every sensor together against each
// sensor alone, against the number of passages N.
//
// The signals are the dictionary model's (validation::simulated_signals): two of the scene's holes `s`
// apart crossing the contact, superposed, plus the paper's noise of N passages (seeded draws). So the limit
// found is the noise's and the estimator's, not the model's: the full contact departs from the
// superposition by at most 4 % of the peak down to 1.2 diameters on the default scene (docs/perception.md).
// Each draw is inverted as `skinfem invert` does (every sensor, the contact's offset fitted on its grid) and
// by each sensor alone at the nominal offset (the paper's naive inversion). Two holes are resolved when each
// has its own feature within half the spacing (validation::score_inversion): one feature between them, the
// two merged, goes to one hole only. Features elsewhere (the detector's false alarms, 1 % per feature) are
// the detection's question, not the resolution's.
// The limit is the smallest spacing from which on every spacing tried is resolved in at least `required` of
// the draws. Units: mm.
#pragma once

#include <optional>
#include <vector>

#include "skinfem/pipeline/clock.hpp"
#include "skinfem/pipeline/inversion.hpp"

namespace skinfem::pipeline {

struct ResolutionOptions {
  std::vector<double> spacings_mm{0.6, 0.7, 0.8, 1.0, 1.2, 1.5, 2.0, 3.0};  // rounded to the step
  std::vector<int> passages{1, 4, 14, 50};
  int draws = 20;
  validation::SensorNoise noise{0.6, 0.4, 14};   // its passages replaced by each of `passages`
  double offset_range = 0.3, offset_step = 0.1;  // the multi-sensor fit's offset grid
  double required = 0.9;                         // the fraction of draws resolved
  double p_fa = 0.01;
  FrictionMode mode = FrictionMode::coupled;
  std::uint64_t seed = 1;
};

struct ResolutionPoint {
  int passages = 0;
  double spacing_mm = 0;
  double multi = 0;       // the fraction of draws resolved by every sensor together
  double naive_best = 0;  // by the best single sensor at this spacing
  int naive_sensor = 0;   // that sensor, 1-based
};

struct ResolutionLimit {
  int passages = 0;
  std::optional<double> multi_mm, naive_mm;  // none: not resolved at the largest spacing
  bool multi_below = false,
       naive_below = false;  // resolved at the smallest spacing tried: the limit is below it
};

struct ResolutionRun {
  double step_mm = 0;  // the dictionary's and the signals'
  std::vector<ResolutionPoint> points;
  std::vector<ResolutionLimit> limits;  // per passages
  int dofs = 0;                         // the dictionary's
  Timings wall;
};

// The dictionary is hole_responses's for the scene's sweep step. Throws SceneError as hole_responses does,
// std::invalid_argument for options out of range.
ResolutionRun resolution_run(const Scene& scene, const ResolutionOptions& options);

}  // namespace skinfem::pipeline
