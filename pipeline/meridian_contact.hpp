// `skinfem contact` on the meridian (contact/meridian_contact.hpp): a scene whose skin is a body of
// revolution about the indenter's axis (a flat layer, read as the unbounded layer of its thickness as the
// meridian Green path does, or a spherical cap with the indenter at its apex), solved in 2D. The frictionless
// and uncoupled modes are exact restrictions of the 3D problem; the static and coupled modes are too only
// when their ratio is 0 (then they are the frictionless one). Where a mode is not exact it is left out, and
// said.
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "skinfem/contact/meridian_contact.hpp"
#include "skinfem/pipeline/clock.hpp"
#include "skinfem/pipeline/sensor_greens.hpp"

namespace skinfem::pipeline {

// Why the meridian contact path cannot serve the scene with `chosen` written in full (a sentence naming what
// breaks the symmetry or exactness), empty when it can. every_mode: also every mode `contact` reports (the
// automatic choice: then the path does not change what is written).
std::string meridian_contact_unavailable(const Scene& scene, FrictionMode chosen, bool every_mode);

// Whether `contact` with `path` takes the meridian: asked, or automatic and every reported mode exact there.
// not_meridian (when automatic and not taken): why.
bool contact_on_meridian(const Scene& scene, FrictionMode chosen, GreenPath path, std::string* not_meridian);

struct MeridianContactRun {
  std::string model;  // what was solved, one sentence
  FrictionMode chosen = FrictionMode::none;
  contact::MeridianContactResult solved;  // the frictionless contact and the readings per unit ratio
  struct Mode {
    double ratio = 0;          // the Coulomb traction's p_t / p (0: frictionless)
    Eigen::VectorXd readings;  // 2·sensors, MPa
  };
  std::map<FrictionMode, Mode> modes;  // the exact ones
  std::vector<FrictionMode> left_out;  // static, coupled with a ratio > 0
  double zone_radius = 0;              // mm
  Vec2 axis{0, 0};                     // the meridian's axis on the base, mm
  Timings wall;                        // seconds per stage
};

// Throws SceneError with meridian_contact_unavailable's reason, or naming contact.zone_radius when the
// contact reaches the zone's edge.
MeridianContactRun meridian_contact_run(const Scene& scene, FrictionMode chosen);
nlohmann::json meridian_contact_json(const Scene& scene, const MeridianContactRun& run);

}  // namespace skinfem::pipeline
