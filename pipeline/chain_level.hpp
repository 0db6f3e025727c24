// The chain's headline quantities at one mesh level, shared by `study --chain` (every level) and `report`
// (error bars: the scene's own level plus coarser ones): k of sensor #1 (central and line criteria), the
// coupled contact (radius mm, central pressure MPa, indentation mm) and the sliding hole sweep's largest
// |ς_z| over sensors and positions (MPa).
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "skinfem/pipeline/adjoint_setup.hpp"
#include "skinfem/pipeline/clock.hpp"
#include "skinfem/pipeline/contact_setup.hpp"

namespace skinfem::pipeline {

struct ChainLevel {
  double scale = 1;
  int dofs = 0;
  std::vector<std::string> names;
  std::vector<double> value;    // per name, units above
  std::vector<double> seconds;  // per name: every stage the quantity needs (mesh, factor, adjoints, ...)
  Timings wall;                 // seconds per stage
  double peak_rss_mb = 0;  // this level's own peak (chain_level: sampled); the process's up to here otherwise
  // Set when the uniformly scaled level left a hole unresolved and was redone with cap_holes: this level
  // is then not a uniform scaling of the scene, which Richardson assumes.
  std::string note;
};

// On an already set-up skin (contact null when the scene has none).
ChainLevel chain_values(const Scene& scene, const AdjointSetup& adjoints, const ContactSetup* contact);
// Meshes and factors the scene scaled by `scale`, then chain_values; once more with cap_holes (and a note)
// if the scaled mesh cannot see the scene's hole.
ChainLevel chain_level(const Scene& base, double scale);

// Per quantity, over the three finest levels (validation/richardson.hpp): the finest value, its error
// estimate (|Q − Q∞| in the asymptotic regime; else the last change |Q₃ − Q₂|, only an order of magnitude)
// and how it was obtained. An observed order above kMaxPlausibleOrder is not taken as asymptotic: P2–P1
// converges at order 3 in displacement and 2 in traction, and the levels are unrelated TetGen meshes, so a
// steeper fall is a coincidence of their placement. Measured on candelier2011's whole skin: k_central of
// sensor #1 at order 7.8 gave ± 7e-5, while the axis sensor's k_central on the same mesh was 3.5e-3 off the
// meridian (pipeline/sensor_greens.hpp's meridian_check).
constexpr double kMaxPlausibleOrder = 4;
struct ChainError {
  std::string name;
  double value = 0, error = 0, reference = 0;
  double order = 0;  // observed (0 when the differences change sign or grow)
  bool asymptotic = false;
  std::string why_not;  // when not asymptotic, why (computed from the levels)
};
std::vector<ChainError> chain_errors(const std::vector<ChainLevel>& levels);
// Error-bar levels (--error-scales): none, or at least two coarser ones (each s > 1) for Richardson. Throws
// SceneError (one line) otherwise.
void check_error_scales(const std::vector<double>& error_scales);

// Seconds ∝ DOFs^e per stage, fitted over the levels that timed it (validation::loglog_slope); stages
// whose fit is undefined are left out.
std::map<std::string, double> time_vs_dofs_exponent(const std::vector<ChainLevel>& levels);

// chain_study.json (`study --chain`, the report's DIR/study/): the levels, each quantity's extrapolation
// (observed order or why none, its reference) and the stages' time-vs-DOFs exponents.
nlohmann::json chain_study_json(const Scene& scene, const std::vector<ChainLevel>& levels);

// The chain's errors as the page and report.json show them: in display units (kPa, µm as "um"), what each
// quantity is and how its error was estimated; coarse_scales: the coarser levels' mesh scales, coarse to
// fine.
// How a chain quantity is shown (the page, the terminal): its description, its unit and the factor from the
// chain's own units (mm, MPa) to it; null for a name the chain does not have.
struct QuantityDisplay {
  const char* name;
  const char* what;
  const char* unit;
  double factor;
};
const QuantityDisplay* quantity_display(const std::string& name);

struct ErrorBar {
  std::string quantity, what, unit, method;
  double value = 0, error = 0, relative_error = 0;
};
std::vector<ErrorBar> error_bars(const std::vector<ChainError>& errors,
                                 const std::vector<double>& coarse_scales);
nlohmann::json error_bars_json(const std::vector<ErrorBar>& bars);

}  // namespace skinfem::pipeline
