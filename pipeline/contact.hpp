// The scene's indenter in contact with the skin, in all four friction modes on one condensed skin
// (pipeline/contact_setup.hpp), with the chosen mode's volume solution and two checks of it: the pointwise
// penetration at every node of the zone's faces, and the condensed sensor readings against the reactions
// of the full solve (a second method). `skinfem contact` writes contact_json's object as summary.json.
#pragma once

#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "skinfem/contact/meridian_contact.hpp"
#include "skinfem/contact/metrics.hpp"
#include "skinfem/fem/mixed_solver.hpp"
#include "skinfem/pipeline/clock.hpp"
#include "skinfem/pipeline/contact_setup.hpp"
#include "skinfem/pipeline/meridian_contact.hpp"

namespace skinfem::pipeline {

struct ContactRun {
  std::shared_ptr<const ContactSetup> setup;  // what the results refer to (zone, mesh, solver)
  FrictionMode chosen = FrictionMode::none;
  std::map<FrictionMode, contact::ContactResult> results;   // every mode
  std::map<FrictionMode, contact::ContactMetrics> metrics;  // every mode
  MixedSolution solution;         // the chosen mode on the solved skin (the half under mirror symmetry)
  Eigen::VectorXd reactions;      // its base reactions, N
  double max_penetration_mm = 0;  // pointwise, outside the holes
  double readings_condensed_vs_reactions_rel = 0;
  // What coupling changes (coupled − uncoupled at the same μ; the paper's assumption is "nothing"): the
  // pressure and contact-zone centroid shifts, along the sliding direction t (positive: ahead) and as
  // vectors.
  struct CouplingShift {
    double pressure_mm = 0, zone_mm = 0;
    Vec2 pressure_xy_mm{0, 0}, zone_xy_mm{0, 0};
  } coupling_shift;
  Timings wall;  // seconds per stage (the set-up's, contact_solves, full_solve)
  // Why the 3D path ran where the path was automatic (pipeline/meridian_contact.hpp); empty otherwise.
  std::string not_meridian;
  // A second method where the scene is a body of revolution about the indenter
  // (pipeline/meridian_contact.hpp): the frictionless and uncoupled modes on the meridian, exact restrictions
  // of this problem, against the 3D ones. readings_rel: the largest |3D − meridian| over every sensor, σ_z
  // and σ_x and both modes, over the largest |reading|; the frictionless contact radius, p0 and indentation
  // as 3D / meridian − 1.
  struct MeridianCheck {
    double readings_rel = 0, a_rel = 0, p0_rel = 0, indentation_rel = 0;
    int dofs = 0;
    double seconds = 0;
    contact::MeridianContactResult frictionless;  // its pressure, edge resolved (the report's profile)
  };
  std::optional<MeridianCheck> meridian_check;

  const contact::ContactResult& result() const { return results.at(chosen); }
  const contact::ContactMetrics& metric() const { return metrics.at(chosen); }
};

// Throws SceneError, naming the command's need, when the scene has no contact section.
void require_contact(const Scene& scene);
// Throws SceneError when the scene has no contact. frictionless: the meridian's frictionless run that checks
// the 3D one (meridian_contact_run(scene, FrictionMode::none)), made beforehand (the report makes it before
// the 3D factorization, whose memory it would otherwise add to); null: made here where the scene has one.
ContactRun contact_run(const Scene& scene, std::shared_ptr<const ContactSetup> setup, FrictionMode chosen,
                       const MeridianContactRun* frictionless = nullptr);
// How the contact was solved: on the half (mirror symmetry) or whole, and why whole.
std::string symmetry_used(const Scene& scene, const ContactSetup& setup);
// The same for a skin solved on its half (half_solved) or whole.
std::string symmetry_said(const Scene& scene, bool half_solved);
// summary.json of `skinfem contact`.
nlohmann::json contact_json(const Scene& scene, const ContactRun& run);
// The friction mode named as the command line names it (none, static, uncoupled, coupled), or the
// scene's when "scene" or empty; anything else is a SceneError naming the argument.
FrictionMode friction_mode_named(const Scene& scene, const std::string& name);

}  // namespace skinfem::pipeline
