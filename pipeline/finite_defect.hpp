// `skinfem defect` on the neo-Hookean skin: the hole's signals about the deformed states at rest and sliding.
// A small hole is a small change of the plate's gaps (its bulge, contact/holes/dimple.hpp), so its signal is
// the linearized response about the finite solution (pipeline/finite_contact.hpp): the contact condensed on
// the tangent at that state (contact/finite_contact.hpp's tangent_contact, one factorization), then one
// complementarity solve per hole position, the set free to change. Each case has a finite state of its own:
// static (the plate's residual traction static_ratio·p, mode static_residual) and sliding (μp, coupled). The
// hole at spatial position c acts on the material under it, the reference point X with X + u(X) = c on the
// top. Units: mm, N, MPa.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "skinfem/contact/holes/sweep.hpp"
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
  double tangent_seconds = 0;            // the condensation on the tangent and the bulges' set-up
};

struct FiniteDefectRun {
  std::vector<FiniteDefectCase> cases;
  Timings wall;  // per case: mesh_<case>, newton_<case>, tangent_<case>, sweep_<case>
};

// modes: the cases, static_residual and/or coupled, in order. Throws SceneError as check_finite_contact, when
// the scene has no contact.sweep or its hole model is not the bulge, and SolverError when Newton cannot carry
// the load.
FiniteDefectRun finite_defect_run(const Scene& scene,
                                  const std::vector<FrictionMode>& modes = {FrictionMode::static_residual,
                                                                            FrictionMode::coupled});

// summary.json of `skinfem defect` on the neo-Hookean skin.
nlohmann::json finite_defect_json(const Scene& scene, const FiniteDefectRun& run);

}  // namespace skinfem::pipeline
