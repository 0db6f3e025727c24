// The report's run on one skin: its stages in order on the main thread, the work that feeds no later stage
// on threads beside them (kfit's scans and fits, the k sweep, the mesh's files; in a fast report the
// meridian checks), the figures drawn as their inputs become final (app/report_figures.hpp), and at the end
// report.json, index.html and the summary on stdout. app/cmd_report.cpp calls the steps in order.
#pragma once

#include <future>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "app/report_figures.hpp"
#include "app/report_page.hpp"
#include "app/stages.hpp"
#include "skinfem/pipeline/clock.hpp"
#include "skinfem/validation/k_sweep.hpp"

namespace skinfem::app {

class ReportRun {
 public:
  // error_scales: the coarser levels' mesh scales for the error bars (empty: none). fast: no error bars,
  // budget, post design, k sweep or effective-thickness fits, said on the page.
  ReportRun(const Scene& scene, std::string out_dir, std::vector<double> error_scales, bool fast);
  ReportRun(const ReportRun&) = delete;  // index_ points into its own members
  ReportRun& operator=(const ReportRun&) = delete;
  void factor_chain();   // the meridian checks, the one factorization and the sensors' adjoints
  void green();          // the green stage, the mesh's files beside it; starts kfit and the k sweep
  void contact_chain();  // contact, defect sweep, crosscheck, hole budget (a scene with a contact)
  void error_levels();   // kfit's and the k sweep's ends, then the coarser levels of the error bars
  void post_design();    // or, in a fast report, what it left out
  // Waits for every figure. 0, or 128 + the signal that stopped the drawing (nothing more is written then).
  int figures();
  void write_and_print();  // report.json, index.html, the summary lines

 private:
  void finish_kfit();
  void finish_k_sweep(const std::vector<validation::KSweepPoint>& mesh_rows);

  const Scene& scene_;
  const std::string out_;
  const std::vector<double> error_scales_;
  const bool fast_;
  // k_sweep.png is drawn with the contact's figures, or at the end when the mesh levels join the sweep.
  const bool k_figure_with_contact_;
  Stopwatch total_;
  nlohmann::json report_;
  Timings wall_, beside_;  // beside_: the stages run on another thread
  IndexInput index_;
  ReportFigures figures_;
  int figures_rc_ = 0;

  std::optional<pipeline::MeridianContactRun> meridian_check_;  // the 3D frictionless contact's check
  std::optional<pipeline::MeridianScan> axis_scan_;
  pipeline::ContactSkin factored_;
  std::shared_ptr<Skin> skin_;
  std::unique_ptr<AdjointSetup> adjoints_;
  std::optional<SensorGreens> greens_;
  std::optional<MeridianCheck> axis_check_;  // the green stage's, which kfit would otherwise solve again
  std::shared_ptr<ContactSetup> contact_;
  std::optional<DefectRun> defect_;
  std::optional<validation::Crosscheck> x_;
  std::optional<StageOutput<pipeline::KfitResult>> kfit_;
  std::vector<ChainLevel> levels_;
  StageOutput<pipeline::PostDesign> post_;
  int dofs_ = 0;

  // Declared after what they read, so that they are waited for before it goes.
  struct MeridianChecks {
    std::optional<pipeline::MeridianContactRun> contact;
    std::optional<pipeline::MeridianScan> axis;
  };
  std::future<MeridianChecks> meridian_run_;
  double meridian_seconds_ = 0, k_sweep_seconds_ = 0, kfit_seconds_ = 0;
  std::future<validation::KTargetAnswer> k_sweep_;
  std::future<pipeline::KfitResult> kfit_run_;
};

}  // namespace skinfem::app
