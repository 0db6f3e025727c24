// The main job as one call: the whole chain on one mesh and one factorization (the mesh's quality, the
// sensors' Green tensors, k, the contact, the hole sweep, the paper's model checked against it, the
// hole-signal budget), error bars from coarser meshes, and what a post changes. `skinfem report` and
// skinfem.report() in Python both run it; what each does with a stage's results (files, lines, figures) is a
// ReportSink's.
//
// The stages run in order on the calling thread. Beside them, on threads: kfit's scans and fits, the exact
// layer's k sweep and the mesh's summary (no MUMPS), and in a fast report the meridian checks (their MUMPS
// calls take turns with the 3D ones). Memory: the factorization is released once the contact is solved, and
// every set-up before the error bars' coarser levels (pipeline/clock.hpp release_freed_memory), so that the
// scene's own level sets the peak. Units: mm, N, MPa (kPa in the summaries, as their keys say).
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "skinfem/pipeline/chain_level.hpp"
#include "skinfem/pipeline/clock.hpp"
#include "skinfem/pipeline/contact.hpp"
#include "skinfem/pipeline/defect.hpp"
#include "skinfem/pipeline/green.hpp"
#include "skinfem/pipeline/hole_budget.hpp"
#include "skinfem/pipeline/kfit.hpp"
#include "skinfem/pipeline/mesh_summary.hpp"
#include "skinfem/pipeline/post_design.hpp"
#include "skinfem/pipeline/report_perception.hpp"
#include "skinfem/pipeline/sensor_greens.hpp"
#include "skinfem/validation/crosscheck.hpp"
#include "skinfem/validation/k_sweep.hpp"

namespace skinfem::pipeline {

struct ReportOptions {
  // The coarser levels' mesh scales for the error bars (empty: none; else check_error_scales's rules).
  std::vector<double> error_scales;
  // No error bars, hole budget, post design, k sweep or effective-thickness fits (left_out says so).
  bool fast = false;
};

// What a front end does with each stage's results as they become final. The calls come in the order
// declared, each once at most (a scene without a contact has no contact, defect, crosscheck or budget),
// except kfit(), whose fits run on a thread beside the contact and the hole sweep: it comes after green()
// and before crosscheck() and chain_done(). They come on the thread that called report_run, except mesh(),
// which comes from a thread of its own beside the Green stage's computation and has returned before green()
// is called. The defaults do nothing.
class ReportSink {
 public:
  virtual ~ReportSink() = default;
  // The whole skin's mesh (mirrored from the half solved, if so) and its summary (report.json's "mesh").
  virtual void mesh(const TetMesh&, const MeshSummary&, const nlohmann::json& /*summary*/) {}
  virtual void green(const SensorGreens&, const GreenRun&, const nlohmann::json& /*summary*/) {}
  virtual void kfit(const KfitResult&, const nlohmann::json& /*file*/) {}  // file: kfit_json's
  // summary: contact_json's and defect_json's; a sink may add to it (its writing's seconds), and
  // report.json keeps the contact's as the sink leaves it.
  virtual void contact(const ContactRun&, nlohmann::json& /*summary*/) {}
  virtual void defect(const DefectRun&, nlohmann::json& /*summary*/) {}
  virtual void crosscheck(const validation::Crosscheck&) {}
  // A neo-Hookean scene's finite deformation (report.json's finite_deformation), before hole_budget().
  virtual void finite_deformation(const nlohmann::json& /*entry*/) {}
  virtual void hole_budget(const HoleBudget&, const validation::Crosscheck&) {}
  // The perception section (pipeline/report_perception.hpp; entry: report.json's "perception"), before
  // chain_done(); not in a fast report, nor where perception_unavailable says why not.
  virtual void perception(const ReportPerception&, const nlohmann::json& /*entry*/) {}
  // Every output of the chain so far is final; the error bars' levels come next.
  virtual void chain_done() {}
  virtual void chain_study(const std::vector<ChainLevel>&, const nlohmann::json& /*study*/) {}
  // The exact layer's k sweep, with the FE's mesh levels when the error bars brought them.
  virtual void k_sweep(const validation::KTargetAnswer&) {}
  virtual void post_design(const PostDesign&, const nlohmann::json& /*entry*/) {}
};

struct ReportResult {
  // report.json's content: the stages' summaries, the headline answers, scene, dofs, units, wall_s (seconds
  // per stage on the calling thread), wall_beside_s (on threads beside them).
  nlohmann::json json;
  int dofs = 0;
  Timings wall, beside;
  std::string kfit_verdict;
  std::string k_paper_answer;  // which single reading of the protocol gives the paper's k (not fast)
  std::optional<validation::FrontSensorAnswer> front;  // with a hole sweep
  std::optional<validation::Crosscheck> crosscheck;    // with a hole sweep
  std::optional<HoleBudget> budget;                    // with a hole sweep, not fast
  std::vector<ErrorBar> error_bars;                    // empty without error bars
  std::vector<ChainLevel> levels;                      // the error bars' levels, coarse to fine
  std::map<std::string, double> exponents;             // time ∝ DOFs^e per stage
  std::optional<PostDesign> post;                      // what a post changes, when the skin has an axis
  std::string post_answer;
  std::string left_out;    // what a fast report left out, one phrase; empty otherwise
  double seconds = 0;      // the run's wall time
  double peak_rss_mb = 0;  // the process's peak resident memory at its end
};

// Throws SceneError on bad options (check_error_scales; error scales with fast), or on a neo-Hookean scene
// whose finite deformation the report cannot solve (pipeline/finite_defect.hpp check_finite_defect; a fast
// report leaves it out): what report_run checks before any stage, for a front end to call before it writes.
void check_report(const Scene& scene, const ReportOptions& options);

// A scene with material.model neo_hookean is reported on its linear skin (Green tensors, k, contact, hole
// sweep, budget: the small-signal model), then its finite deformation beside it (report.json
// finite_deformation, the budget's coulomb_finite row; pipeline/finite_deformation.hpp). Throws as
// check_report before any stage, SceneError on a scene the chain cannot take and SolverError when a solve
// fails. The sink's calls made by then stand.
ReportResult report_run(const Scene& scene, const ReportOptions& options, ReportSink& sink);

}  // namespace skinfem::pipeline
