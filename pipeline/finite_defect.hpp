// `skinfem defect` on the neo-Hookean skin: the hole's signals about the deformed sliding state. A small hole
// is a small change of the plate's gaps (its bulge, contact/holes/dimple.hpp), so its signal is the
// linearized response about the finite sliding solution (pipeline/finite_contact.hpp): the contact condensed
// on the tangent at that state (contact/finite_contact.hpp's tangent_contact, one factorization), then one
// complementarity solve per hole position, the set free to change. The hole at spatial position c acts on the
// material under it, the reference point X with X + u(X) = c on the top. Only the sliding case (coupled, the
// scene's μ): the static case's state at rest would need a finite solve of its own. Units: mm, N, MPa.
#pragma once

#include <nlohmann/json.hpp>
#include <vector>

#include "skinfem/contact/holes/sweep.hpp"
#include "skinfem/pipeline/finite_contact.hpp"

namespace skinfem::pipeline {

struct FiniteDefectRun {
  FiniteContactRun state;              // the deformed sliding state (coupled)
  contact::SweepResult sliding;        // ς about it, per position (spatial hole centres)
  std::vector<Vec2> material_centres;  // the reference point under each hole centre
  // The tangent problem's own hole-free solution against the finite one: max |Δλ| / max λ (it should be
  // round-off: the tangent's gaps are set to have the finite λ as their solution).
  double baseline_rel = 0;
  double max_roughness = 0;  // the jaggedest curve's validation::roughness
  int max_roughness_column = 0;
  Timings wall;  // mesh, newton, tangent, sweep
};

// Throws SceneError as check_finite_contact (the sliding case, coupled), when the scene has no contact.sweep
// or its hole model is not the bulge, and SolverError when Newton cannot carry the load.
FiniteDefectRun finite_defect_run(const Scene& scene);

// summary.json of `skinfem defect` on the neo-Hookean skin.
nlohmann::json finite_defect_json(const Scene& scene, const FiniteDefectRun& run);

}  // namespace skinfem::pipeline
