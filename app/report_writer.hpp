// What `skinfem report` does with pipeline::report_run's stages as each becomes final: writes its folder
// under DIR and prints its lines (app/stages.hpp), starts the figures that read them
// (app/report_figures.hpp), and at the end writes report.json and index.html (app/report_page.hpp) and the
// summary on stdout.
#pragma once

#include <string>

#include "app/report_figures.hpp"
#include "skinfem/pipeline/report.hpp"

namespace skinfem::app {

class ReportWriter : public pipeline::ReportSink {
 public:
  ReportWriter(const Scene& scene, std::string out_dir, const pipeline::ReportOptions& options);

  void mesh(const TetMesh& mesh, const pipeline::MeshSummary& s, const nlohmann::json& summary) override;
  void green(const SensorGreens& greens, const pipeline::GreenRun& run,
             const nlohmann::json& summary) override;
  void kfit(const pipeline::KfitResult& r, const nlohmann::json& file) override;
  void contact(const pipeline::ContactRun& run, nlohmann::json& summary) override;
  void defect(const pipeline::DefectRun& run, nlohmann::json& summary) override;
  void crosscheck(const validation::Crosscheck& x) override;
  void finite_deformation(const nlohmann::json& entry) override;
  void hole_budget(const pipeline::HoleBudget& b, const validation::Crosscheck& x) override;
  void perception(const pipeline::ReportPerception& p, const nlohmann::json& entry) override;
  void chain_done() override;
  void chain_study(const std::vector<pipeline::ChainLevel>& levels, const nlohmann::json& study) override;
  void k_sweep(const validation::KTargetAnswer& a) override;
  void post_design(const pipeline::PostDesign& p, const nlohmann::json& entry) override;

  // Waits for every figure, then writes report.json and index.html and prints the summary; run's times
  // become the command's (the figures' included). 0, or 128 + the signal that stopped the drawing (nothing
  // more is written then).
  int finish(pipeline::ReportResult& run);

 private:
  const Scene& scene_;
  const std::string out_;
  const bool fast_;
  const size_t coarse_levels_;
  // k_sweep.png is drawn with the contact's figures, or at the end when the mesh levels join the sweep.
  const bool k_figure_with_contact_;
  pipeline::Stopwatch total_;
  ReportFigures figures_;
  std::string mesh_lines_;  // written beside the green stage, printed before its lines
};

}  // namespace skinfem::app
