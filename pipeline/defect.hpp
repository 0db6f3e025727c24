// The paper's §IV on a scene: a hole in the indenter swept along contact.sweep through the contact, a full
// contact solve at every position, in two cases: static (residual traction, static_ratio/μ of the sliding
// one) and sliding (coupled, with the scene's friction law). ς = sensor reading with the hole − without.
// `skinfem defect` writes defect_json's object as summary.json, the signals as defect.csv and the frames
// as a ParaView animation.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "skinfem/contact/holes/sweep.hpp"
#include "skinfem/pipeline/chain_level.hpp"
#include "skinfem/pipeline/clock.hpp"
#include "skinfem/pipeline/contact_setup.hpp"

namespace skinfem::pipeline {

// The frames a run keeps: the ones `skinfem defect` writes (at most kDefectFrames per case, evenly spaced
// with both ends: a frame is ~100 kB on disk, and 100,000 positions wrote 1.8 GB), or every position's (the
// report's crosscheck convolves each position's tractions).
enum class DefectFrames { written, every };
constexpr int kDefectFrames = 201;
// Whether `skinfem defect` writes position i of n.
bool written_frame(int i, int n);

struct DefectRun {
  std::shared_ptr<const ContactSetup> setup;  // what the results refer to
  std::vector<std::string> cases;             // "static", "sliding"
  std::vector<contact::SweepResult> sweeps;   // per case: centres, ς (positions × 2·sensors, MPa), costs
  std::vector<std::vector<contact::ContactResult>> frames;  // [case][kept frame]: the contact with the hole
  std::vector<std::vector<int>> frame_positions;            // [case][kept frame]: its position
  // Per case, the jaggedest curve: validation::roughness and its column of ς (σ_z of sensor k at 2k).
  std::vector<double> max_roughness;
  std::vector<int> max_roughness_column;
  Timings wall;  // seconds per stage
  // The largest sliding |ς_z| over sensors and positions on coarser levels (largest_sliding_levels) and this
  // one, last; empty without error bars.
  std::vector<ChainLevel> levels;
};

// The largest sliding |ς_z| (MPa, over sensors and positions) of the scene scaled by each of `scales`
// (every mesh size × s > 1, mesh/sizing.hpp's scaled_scene; a level whose mesh cannot see a resolved hole
// is redone with the mesh over the hole capped, as chain_level does), each level set up, swept and freed
// in turn: run before the scene's own level, the peak memory stays that level's.
std::vector<ChainLevel> largest_sliding_levels(const Scene& scene, const std::vector<double>& scales);
// That quantity's error bar through the coarser levels and this run's (pipeline/chain_level.hpp's
// chain_errors: Richardson when asymptotic, else the last change). Throws std::invalid_argument with fewer
// than two coarser levels.
ChainError largest_sliding_error(const DefectRun& run);

// Throws SceneError, naming the command's need, when the scene has no contact.sweep: before contact_setup,
// whose condensation is the expensive part.
void require_sweep(const Scene& scene);
// Throws SceneError when the scene has no contact.sweep, or when a position's hole reaches past what the
// mesh resolves (contact::check_hole_clearance, every position, kept or not). coarse:
// largest_sliding_levels' result, kept in the run (with this level's value appended) for
// largest_sliding_error.
DefectRun defect_run(const Scene& scene, std::shared_ptr<const ContactSetup> setup,
                     std::vector<ChainLevel> coarse = {}, DefectFrames keep = DefectFrames::written);
// summary.json of `skinfem defect`: per case the peaks per sensor, complementarity, pivots, and
// max_roughness (the largest second difference along u over its curve's peak, validation::roughness); with
// levels, largest_sliding: the value, its error bar and how it was obtained, and the levels.
nlohmann::json defect_json(const Scene& scene, const DefectRun& run);
// Per sensor, a sweep's peak |ς_z| and |ς_x| (kPa) and the hole's x there (mm).
nlohmann::json sweep_peaks_json(const contact::SweepResult& sweep);

}  // namespace skinfem::pipeline
