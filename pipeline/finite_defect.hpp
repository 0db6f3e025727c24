// `skinfem defect` on the neo-Hookean skin: the hole's signals about the deformed states at rest and sliding.
// A small hole is a small change of the plate's gaps (its bulge, contact/holes/dimple.hpp), so its signal is
// the linearized response about the finite solution (pipeline/finite_contact.hpp): the contact condensed on
// the tangent at that state (contact/finite_contact.hpp's tangent_contact, one factorization), then one
// complementarity solve per hole position, the set free to change. Each case has a finite state of its own:
// static (the plate's residual traction static_ratio·p, mode static_residual) and sliding (μp, coupled). The
// hole at spatial position c acts on the material under it, the reference point X with X + u(X) = c on the
// top. Units: mm, N, MPa.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "skinfem/contact/holes/sweep.hpp"
#include "skinfem/contact/metrics.hpp"
#include "skinfem/pipeline/chain_level.hpp"
#include "skinfem/pipeline/finite_contact.hpp"

namespace skinfem::pipeline {

// One case: a finite state and the sweep about it.
struct FiniteDefectCase {
  std::string name;  // "static" or "sliding"
  FrictionMode mode = FrictionMode::coupled;
  FiniteContactRun state;              // the deformed state (static_residual or coupled)
  contact::SweepResult sweep;          // ς about it, per position (spatial hole centres)
  std::vector<Vec2> material_centres;  // the reference point under each hole centre
  // The tangent problem's own hole-free solution against the finite one: max |Δλ| / max λ (it should be
  // round-off: the tangent's gaps are set to have the finite λ as their solution).
  double baseline_rel = 0;
  double max_roughness = 0;  // the jaggedest curve's validation::roughness
  int max_roughness_column = 0;
  double largest_material_shift_mm = 0;  // max |hole centre − the material point under it|
  contact::ContactMetrics metrics;       // the state's contact in the reference frame, as the linear one's
  double tangent_seconds = 0;            // the condensation on the tangent and the bulges' set-up
};

// A converged state on a case's load path: its friction coefficient (the mode's μ or static_ratio, which
// scales a shear strength from the force too), tangential force (N), approach (mm) and contact zone in the
// material and spatial frames.
struct FinitePathPoint {
  double ratio = 0, tangential_force_N = 0, depth_mm = 0;
  contact::ContactZoneFrame material, spatial;
};

struct FiniteDefectRun {
  std::vector<FiniteDefectCase> cases;
  // The frictionless contact at the full force that the cases' paths start from, when they share it (several
  // cases or stations, or given): another law's run on the same scene can start from it too.
  std::shared_ptr<const FiniteContactRun> frictionless;
  // The states the cases' paths went through at the full force, by ratio: the shared frictionless one (with
  // several cases or stations), the sliding stations, each case's own.
  std::vector<FinitePathPoint> path;
  Timings wall;  // per case: mesh_<case>, newton_<case>, tangent_<case>, sweep_<case>
  // The sliding case's headline quantities (finite_sliding_level) on coarser levels and this one, last;
  // empty without error bars.
  std::vector<ChainLevel> levels;
};

// Throws SceneError as check_finite_contact for each mode, when the scene has no contact.sweep or its hole
// model is not the bulge; std::invalid_argument for a mode other than static_residual and coupled.
void check_finite_defect(const Scene& scene, const std::vector<FrictionMode>& modes);

// modes: the cases, static_residual and/or coupled, in order. Throws as check_finite_defect, and SolverError
// when Newton cannot carry the load. coarse: finite_sliding_levels' result, kept in the run with this
// level's appended (the modes must then include coupled). sliding_stations K: the sliding case's ratio path
// stops at k/K of μ (k < K) on its way, each stop a converged state in `path` (K − 1 more finite solves).
// frictionless: null, or the frictionless run of a scene differing from this one in its friction alone
// (another run's `frictionless`): the paths start from it instead of solving it again.
FiniteDefectRun finite_defect_run(const Scene& scene,
                                  const std::vector<FrictionMode>& modes = {FrictionMode::static_residual,
                                                                            FrictionMode::coupled},
                                  std::vector<ChainLevel> coarse = {}, int sliding_stations = 1,
                                  std::shared_ptr<const FiniteContactRun> frictionless = nullptr);

// The sliding case's contact radius (mm), p0 (MPa), indentation (mm) and largest |ς_z| (MPa), under
// chain_level's names (contact_radius, contact_p0, indentation, hole_signal), so that chain_errors and
// error_bars take them; throws std::invalid_argument when the run has no sliding case.
ChainLevel finite_sliding_level(const FiniteDefectRun& run, double scale = 1);
// The same on the scene scaled by each of `scales` (every mesh size × s > 1, mesh/sizing.hpp's
// scaled_scene; the candidate zone grown by its coarser outer ring), each level solved, swept and freed in
// turn (the sliding case alone): run before the scene's own level, the peak memory stays that level's.
std::vector<ChainLevel> finite_sliding_levels(const Scene& scene, const std::vector<double>& scales);

// summary.json of `skinfem defect` on the neo-Hookean skin; with levels, error_bars and chain_study's levels.
nlohmann::json finite_defect_json(const Scene& scene, const FiniteDefectRun& run);

}  // namespace skinfem::pipeline
