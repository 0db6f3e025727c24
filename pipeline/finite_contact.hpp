// `skinfem contact` on the neo-Hookean skin (material.model "neo_hookean"): the scene's plate pressed with
// its force, frictionless, at rest with its residual traction (the static mode, coupled) or in steady
// sliding (the coupled mode) under the scene's friction law (Coulomb, a shear strength or both), against the
// deformed surface
// x = X + u (contact/finite_contact.hpp: Josephy–Newton, the condensed complementarity problem on each
// iterate's tangent). A mirror-symmetric scene (pipeline/symmetry.hpp) is solved on its half y ≥ 0 at half
// the force; everything here is reported for the whole skin. The sensors read the base's reaction over their
// reference discs (the base does not move). Units: mm, N, MPa.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "skinfem/contact/contact_solver.hpp"
#include "skinfem/contact/finite_contact.hpp"
#include "skinfem/contact/mortar.hpp"
#include "skinfem/fem/sensor_reading.hpp"
#include "skinfem/fem/supports.hpp"
#include "skinfem/pipeline/clock.hpp"
#include "skinfem/scene/scene.hpp"

namespace skinfem::pipeline {

struct FiniteContactRun {
  FrictionMode mode = FrictionMode::none;  // none, static_residual or coupled
  double force_N = 0, tangential_force_N = 0;
  // A shear strength's: the τ this mode solved with, and the sliding τ0 (contact.friction.tau0, or μF/A on
  // this path's frictionless contact), MPa; 0 without one.
  double tau_MPa = 0, tau0_MPa = 0;
  // What was solved: the skin (its half under mirror symmetry), its supports, its zone, the indenter and the
  // load, and the solution there (the half's force where mirrored).
  std::shared_ptr<const TetMesh> solved;
  Supports held;
  contact::MortarZone solved_zone;
  std::unique_ptr<contact::Indenter> indenter;
  contact::FiniteContactLoad load;
  contact::FiniteContactResult solved_result;
  // The whole skin: the solved one, or the half's mirror image with each node's half node (source) and the
  // whole zone's view of the half's multipliers.
  std::shared_ptr<const TetMesh> mesh;
  std::vector<int> source;  // empty unless mirrored
  bool mirrored = false;
  std::optional<contact::MirrorView> mirror;
  contact::MortarZone zone;  // the whole skin's candidate multipliers
  // On the whole skin: u, p, λ, gaps, the active set; steps and counts as solved (forces of the half where
  // mirrored: half the force).
  contact::FiniteContactResult result;
  contact::ContactZoneFrame reference, current;  // the zone in the material (X) and the spatial (X + u) frame
  double p0_MPa = 0;              // λ at the multiplier nearest the first-touch point (reference)
  double p_max_MPa = 0;           // largest λ
  double max_penetration_mm = 0;  // pointwise: every zone face node's current height against the plate
  double max_tangential_mm = 0;   // largest |u_t| (along the sliding direction) over the zone's vertices
  // Σ the base's reactions: the force the base holds the skin with, the plate's reversed at equilibrium.
  Eigen::Vector3d base_force_N = Eigen::Vector3d::Zero();
  double balance_rel = 0;               // |base force + the plate's force| / |the plate's force|
  std::vector<SensorReading> readings;  // per sensor, MPa
  // The sensors' reading weights on the solved skin (a reference to *solved): the hole sweep's condensation
  // reads through them too.
  std::shared_ptr<const SensorReadings> sensor_sites;
  int dofs = 0;  // free displacements + pressures of the solved skin
  double zone_radius = 0, zone_h = 0;
  Timings wall;  // mesh, newton
  // The solved skin's part of the scene's force: ½ on a mirrored half.
  double share() const { return mirrored ? 0.5 : 1.0; }
};

// Throws SceneError (one line naming the field or option, its value and what is allowed) for what the
// finite-strain contact does not model: a depth instead of a force, holes, a compliant interface, posts on
// springs, and the uncoupled mode.
void check_finite_contact(const Scene& scene, FrictionMode mode);

// Throws SceneError as check_finite_contact, beyond the resource guard (before meshing), when the contact
// reaches the zone's outer element ring, and SolverError when Newton cannot carry the load. from: null, or
// the solved_result of an earlier run of this scene at a smaller friction ratio (its frictionless state),
// whose path this run's goes on from; its steps and factorizations count as this run's.
FiniteContactRun finite_contact_run(const Scene& scene, FrictionMode mode,
                                    const contact::FiniteContactResult* from = nullptr);

// summary.json of `skinfem contact` on the neo-Hookean skin.
nlohmann::json finite_contact_json(const Scene& scene, const FiniteContactRun& run);

}  // namespace skinfem::pipeline
