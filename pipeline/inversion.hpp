// `skinfem invert`: where the holes are, from a scan's sensor signals (validation/inversion.hpp). The
// dictionary is the scene's own hole swept through the contact (`skinfem defect`'s sweep, the scene's hole
// model) read by virtual sensors at every x_i − δ, δ on the offset grid: the responses of the sensors if
// the contact sat δ from its nominal place. The multi-sensor inversion fits every sensor and the offset; the
// paper's naive one fits each sensor alone at the nominal offset.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "skinfem/pipeline/clock.hpp"
#include "skinfem/scene/scene.hpp"
#include "skinfem/validation/inversion.hpp"

namespace skinfem::pipeline {

struct InversionOptions {
  validation::SensorNoise noise{0.6, 0.4, 14};
  double offset_range = 1.0;                  // mm: δ in [−range, range]
  double offset_step = 0.1;                   // mm
  FrictionMode mode = FrictionMode::coupled;  // the case the signals are of
  double p_fa = 0.01;                         // features below the false-alarm threshold are dropped
};

struct InversionRun {
  validation::Inversion multi;               // every sensor, the offset fitted
  std::vector<validation::Inversion> naive;  // per sensor alone, δ = 0
  validation::HoleResponses responses;
  int dofs = 0;
  Timings wall;
};

// Why the dictionary cannot be built for a scene and the offsets (mm), naming the scene key ("" when it
// can): no contact.sweep (its hole is the dictionary's), sliding other than along +x, sensors off one line
// y = const (the dictionary reads virtual sensors along that line), or posts with an offset other than 0 (a
// post reads the skin only where it is meshed: its dictionary is the posts where they stand).
std::string inversion_unavailable(const Scene& scene, const std::vector<double>& offsets);
// The dictionary for signals sampled every dx (mm) and the offsets. Throws SceneError with
// inversion_unavailable's reason.
validation::HoleResponses hole_responses(const Scene& scene, FrictionMode mode, double dx,
                                         const std::vector<double>& offsets, Timings& wall, int& dofs);
// How many hole positions the dictionary holds for signals sampled every dx (mm): the zone's width and the
// hole's, over dx.
int dictionary_positions(const Scene& scene, double dx);
// The offset grid: −range, −range + step, …, range (0 included).
std::vector<double> offset_grid(double range, double step);
// Why a dictionary built earlier cannot serve signals sampled every dx (mm) with these offsets ("" when it
// can): another step, too few or too many hole positions, or a virtual sensor x_i − δ it lacks.
std::string dictionary_mismatch(const Scene& scene, const validation::HoleResponses& dictionary, double dx,
                                const std::vector<double>& offsets);
// dictionary: one built earlier for this scene and case (its mismatch throws SceneError), or null to build
// it.
InversionRun inversion_run(const Scene& scene, const validation::ScanSignals& signals,
                           const InversionOptions& options,
                           const validation::HoleResponses* dictionary = nullptr);
nlohmann::json inversion_json(const Scene& scene, const InversionRun& run, const InversionOptions& options);

}  // namespace skinfem::pipeline
