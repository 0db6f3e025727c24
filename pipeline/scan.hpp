// A textured plate scanned over the skin (contact.texture, contact.scan): at every position the full
// contact with every hole over the zone (contact/holes/scan.hpp), in two cases like `skinfem defect`:
// static (residual traction, static_ratio/μ of the sliding one) and sliding (coupled, the scene's friction
// law), and beside each the paper's linear prediction Σ_k ς_k(u) from the holes one at a time.
// `skinfem scan` writes scan_json's object as summary.json, the signals as scan.csv and the frames as a
// ParaView animation.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "skinfem/contact/holes/scan.hpp"
#include "skinfem/pipeline/clock.hpp"
#include "skinfem/pipeline/contact_setup.hpp"
#include "skinfem/pipeline/defect.hpp"

namespace skinfem::pipeline {

struct ScanRun {
  std::shared_ptr<const ContactSetup> setup;
  std::vector<std::string> cases;                           // "static", "sliding"
  std::vector<contact::ScanResult> scans;                   // per case
  std::vector<contact::Superposition> superposed;           // per case; empty when not asked
  std::vector<std::vector<contact::ContactResult>> frames;  // [case][kept frame]
  std::vector<std::vector<int>> frame_positions;            // [case][kept frame]: its position
  std::vector<std::vector<std::vector<Hole>>> frame_holes;  // [case][kept frame]: the holes there, in space
  Timings wall;                                             // seconds per stage
};

// The scene `skinfem scan` runs: the scene itself when it has a contact.texture, else (with a contact.sweep
// along the sliding direction) the sweep's hole as a texture of one hole, resolved, scanned along the
// sweep's path at its step: the paper's single-hole experiment. Throws SceneError, naming the command's
// need, when it has neither, or a sweep across the sliding direction.
Scene scanned_scene(const Scene& scene);
// Throws SceneError, naming the command's need, when the scene has no contact.texture.
void require_texture(const Scene& scene);
// Throws SceneError when the skin reaches the bottom of one of `holes` (those cutting the contact r at scan
// position u, mm): the contact is solved for holes whose bottom it does not touch.
void check_texture_clearance(const ContactSetup& setup, const contact::ContactResult& r,
                             const std::vector<Hole>& holes, double u);
// The scan's positions u (mm).
std::vector<double> scan_positions(const Scan& scan);
// Throws SceneError when the skin reaches a hole's bottom at some position. superpose: also the linear
// prediction (one single-hole scan per distinct hole in space).
ScanRun scan_run(const Scene& scene, std::shared_ptr<const ContactSetup> setup, bool superpose = true,
                 DefectFrames keep = DefectFrames::written);
// summary.json of `skinfem scan`: per case the peaks per sensor, the holes in the zone, complementarity and
// pivots, and the superposition's error: max_u |ς − Σ_k ς_k| over max_u |ς|, per sensor and component.
nlohmann::json scan_json(const Scene& scene, const ScanRun& run);

}  // namespace skinfem::pipeline
