// The stages of a run, each on an already set-up skin: compute (pipeline/), write DIR, print its summary
// lines and return its summary.json, with the typed result where a later stage reads its numbers. The
// single-purpose subcommands (green, kfit, contact, defect) set up a skin and run one stage; `report` sets up
// one skin and runs them all on it.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "skinfem/contact/holes/sweep.hpp"
#include "skinfem/pipeline/adjoint_setup.hpp"
#include "skinfem/pipeline/contact.hpp"
#include "skinfem/pipeline/contact_setup.hpp"
#include "skinfem/pipeline/defect.hpp"
#include "skinfem/pipeline/green.hpp"
#include "skinfem/pipeline/hole_budget.hpp"
#include "skinfem/pipeline/kfit.hpp"
#include "skinfem/pipeline/post_design.hpp"
#include "skinfem/pipeline/sensor_greens.hpp"
#include "skinfem/validation/crosscheck.hpp"

namespace skinfem::app {

// lines: where its lines go instead of stdout (common.hpp say: the report's mesh stage runs on a thread
// beside its green stage, and prints both in order).
nlohmann::json mesh_stage(const Scene& scene, const TetMesh& mesh, double mesh_seconds,
                          const std::string& out_dir, std::string* lines = nullptr);
// grid_dx > 0: also the kernel on that grid over the top (kernel.h5, kernel.vti; green/kernel_grid.hpp).
// setup: the 3D path's adjoints (reciprocity check, maps on the mesh), or null for the meridian path.
template <class Result>
struct StageOutput {
  Result result;
  nlohmann::json summary;  // as written
};
StageOutput<pipeline::GreenRun> green_stage(const Scene& scene, const SensorGreens& greens,
                                            const AdjointSetup* setup, const std::string& out_dir,
                                            double grid_dx = 0,
                                            const pipeline::MeridianScan* axis_scan = nullptr,
                                            std::string* lines = nullptr);
// axis_check: pipeline::kfit's (green_stage's, reused).
StageOutput<pipeline::KfitResult> kfit_stage(const Scene& scene, const SensorGreens& greens,
                                             const std::string& out_dir, const std::string& load_name,
                                             const MeridianCheck* axis_check = nullptr);
// Its second half, for a run made elsewhere (the report's, on a thread): writes kfit.json, prints the lines.
StageOutput<pipeline::KfitResult> kfit_stage(const Scene& scene, pipeline::KfitResult r,
                                             const std::string& out_dir);
// not_meridian: why the automatic path did not take the meridian (said and kept in summary.json).
// frictionless: pipeline::contact_run's.
StageOutput<pipeline::ContactRun> contact_stage(const Scene& scene, std::shared_ptr<const ContactSetup> setup,
                                                const std::string& out_dir, FrictionMode chosen,
                                                const std::string& not_meridian = "",
                                                const pipeline::MeridianContactRun* frictionless = nullptr);

// Both sweeps of `defect` (static, then coupled sliding), keeping the contact solutions `keep` says (the
// written frames, or every position's); coarse: pipeline::largest_sliding_levels' levels for the largest
// sliding signal's error bar (empty: none). write_frames false: no frames/ and no defect.pvd (report --fast).
pipeline::DefectRun defect_stage(const Scene& scene, std::shared_ptr<const ContactSetup> setup,
                                 const std::string& out_dir, std::vector<pipeline::ChainLevel> coarse,
                                 pipeline::DefectFrames keep, bool write_frames = true);

// The hole-signal budget (app/hole_budget_stage.cpp): friction hypotheses against the paper's facts, judged
// against the crosscheck's paper_model signals; writes its tables into out_dir (the crosscheck's).
// reading_scale: pipeline::hole_budget's.
StageOutput<pipeline::HoleBudget> hole_budget_stage(const Scene& scene, const ContactSetup& setup,
                                                    const validation::Crosscheck& x,
                                                    const std::string& out_dir,
                                                    const Eigen::VectorXd& reading_scale = {});

// What a post changes (app/post_design_stage.cpp): a post against a disc at the skin's axis and a sweep of
// post height and diameter, on the meridian; writes out_dir/post_design.csv. A skin without an axis returns
// {"skipped": why}.
StageOutput<pipeline::PostDesign> post_design_stage(const Scene& scene, const std::string& out_dir);

}  // namespace skinfem::app
