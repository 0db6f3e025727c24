#include "app/report_writer.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <sstream>

#include "app/chain_study.hpp"
#include "app/common.hpp"
#include "app/report_outputs.hpp"
#include "app/report_page.hpp"
#include "app/stages.hpp"
#include "skinfem/validation/text.hpp"

namespace skinfem::app {

using validation::fmt;

ReportWriter::ReportWriter(const Scene& scene, std::string out_dir, const pipeline::ReportOptions& options)
    : scene_(scene),
      out_(std::move(out_dir)),
      fast_(options.fast),
      coarse_levels_(options.error_scales.size()),
      k_figure_with_contact_(!options.fast && options.error_scales.empty() && scene.contact),
      figures_(out_) {}

void ReportWriter::mesh(const TetMesh& mesh, const pipeline::MeshSummary& s, const nlohmann::json& summary) {
  write_mesh(scene_, mesh, s, summary, out_ + "/mesh", &mesh_lines_);
}

void ReportWriter::green(const SensorGreens& greens, const pipeline::GreenRun& run,
                         const nlohmann::json& summary) {
  std::string lines;
  write_green(scene_, greens, run, summary, out_ + "/green", &lines);
  std::fputs((mesh_lines_ + lines).c_str(), stdout);
}

// kfit's end: its outputs, and the calibration's figures drawn beside the stages still to come. The
// contact's are drawn after the crosscheck (and the budget), by an interpreter started now that waits for
// the word; the rest at the end.
void ReportWriter::kfit(const pipeline::KfitResult& r, const nlohmann::json& file) {
  write_kfit(scene_, r, file, out_ + "/kfit");
  const std::vector<std::string> calibration{"fig1_calibration.png", "green_vs_halfspace.png"};
  figures_.draw_now(calibration);
  if (scene_.contact) {
    std::vector<std::string> later = calibration;
    later.insert(later.end(), {"pareto.png", "post_design.png"});
    if (!k_figure_with_contact_) later.push_back("k_sweep.png");
    figures_.draw_on_go(later);
  }
}

void ReportWriter::contact(const pipeline::ContactRun& run, nlohmann::json& summary) {
  write_contact(scene_, run, summary, out_ + "/contact");
}

void ReportWriter::defect(const pipeline::DefectRun& run, nlohmann::json& summary) {
  write_defect(scene_, run, summary, out_ + "/defect", !fast_);
}

void ReportWriter::crosscheck(const validation::Crosscheck& x) {
  write_crosscheck(x, scene_.sensors, out_ + "/crosscheck");
}

// contact/finite_path.csv (model,frame,ratio,tangential_force_N,indentation_um,area_mm2,equivalent_radius_mm,
// front_edge_mm,back_edge_mm,zone_centroid_x_mm,force_centroid_x_mm,anisotropy,moment_radius_mm,
// moment_anisotropy): the contact zone along the tangential load, finite in both frames and linear in the
// material one.
void ReportWriter::finite_deformation(const nlohmann::json& entry) {
  std::ostringstream csv;
  csv.precision(10);
  const char* columns[] = {"area_mm2",     "equivalent_radius_mm", "front_edge_mm",
                           "back_edge_mm", "zone_centroid_x_mm",   "force_centroid_x_mm",
                           "anisotropy",   "moment_radius_mm",     "moment_anisotropy"};
  csv << "model,frame,ratio,tangential_force_N,indentation_um";
  for (const char* c : columns) csv << "," << c;
  csv << "\n";
  for (const char* model : {"linear", "finite"})
    for (const char* frame : {"material", "spatial"})
      for (const nlohmann::json& p : entry.at("path").at(model)) {
        if (!p.contains(frame)) continue;
        csv << model << "," << frame << "," << p.at("ratio").get<double>() << ","
            << p.at("tangential_force_N").get<double>() << "," << p.at("indentation_um").get<double>();
        for (const char* c : columns) csv << "," << p.at(frame).at(c).get<double>();
        csv << "\n";
      }
  std::filesystem::create_directories(out_ + "/contact");
  write_text_atomic(out_ + "/contact/finite_path.csv", csv.str());
}

void ReportWriter::hole_budget(const pipeline::HoleBudget& b, const validation::Crosscheck& x) {
  write_hole_budget(scene_, b, x, out_ + "/crosscheck");
}

void ReportWriter::perception(const pipeline::ReportPerception& p, const nlohmann::json& entry) {
  std::filesystem::create_directories(out_ + "/perception");
  write_perception(scene_, p, entry, out_ + "/perception");
}

void ReportWriter::chain_done() { figures_.go(); }

void ReportWriter::chain_study(const std::vector<pipeline::ChainLevel>& levels, const nlohmann::json& study) {
  write_chain_study(levels, study, out_ + "/study", false);
}

void ReportWriter::k_sweep(const validation::KTargetAnswer& a) { write_k_sweep(a, out_ + "/kfit"); }

void ReportWriter::post_design(const pipeline::PostDesign& p, const nlohmann::json& entry) {
  write_post_design(p, entry, out_ + "/green");
}

int ReportWriter::finish(pipeline::ReportResult& run) {
  // Those of the later stages (kfit/k_sweep.csv with the mesh levels, study/chain_study.csv,
  // green/post_design.csv) at the end.
  std::vector<std::string> last;
  if (!fast_ && !k_figure_with_contact_) last.push_back("k_sweep.png");
  if (coarse_levels_ > 0) last.push_back("pareto.png");
  if (!fast_) last.push_back("post_design.png");
  const Stopwatch clock;
  int stopped_by = 0;
  const int figures_rc = figures_.finish(last, &stopped_by);
  if (stopped_by != 0) {
    std::fprintf(stderr,
                 "skinfem: report: stopped by signal %d (%s) while drawing the figures; report.json and "
                 "index.html not written\n",
                 stopped_by, strsignal(stopped_by));
    return 128 + stopped_by;
  }
  nlohmann::json& report = run.json;
  report["figures_exit_code"] = figures_rc;
  run.wall["figures"] = clock.seconds();
  report["wall_s"] = run.wall;
  report["wall_total_s"] = run.seconds = total_.seconds();
  report["peak_rss_mb"] = run.peak_rss_mb = peak_rss_mb();
  write_json(out_ + "/report.json", report);
  write_index(out_, scene_, run);

  std::printf("report %s: %d DOFs, one factorization for the chain%s; %.1f s, peak %.0f MB\n",
              scene_.name.c_str(), run.dofs,
              run.error_bars.empty()
                  ? ""
                  : (" and " + std::to_string(coarse_levels_) + " coarser for the error bars").c_str(),
              total_.seconds(), peak_rss_mb());
  for (const ErrorBar& e : run.error_bars)
    std::printf("  %s: %s%s%s (%s)\n", e.what.c_str(), with_error(e.value, e.error).c_str(),
                e.unit.empty() ? "" : " ", e.unit.c_str(), e.method.c_str());
  if (!run.k_paper_answer.empty()) std::printf("  %s\n", run.k_paper_answer.c_str());
  if (run.front) std::printf("  %s\n", run.front->answer.c_str());
  if (figures_rc != 0)
    std::printf("  figures: scripts/figures.py exited with %d; index.html lists the figures written\n",
                figures_rc);
  if (!run.left_out.empty()) std::printf("  fast: left out the %s\n", run.left_out.c_str());
  // Where the time went, longest first.
  std::vector<std::pair<double, std::string>> stages;
  for (const auto& [stage, t] : run.wall) stages.push_back({t, stage});
  std::sort(stages.rbegin(), stages.rend());
  std::string line;
  for (const auto& [t, stage] : stages) line += (line.empty() ? "" : ", ") + stage + " " + fmt("%.1f", t);
  std::printf("  seconds per stage: %s\n", line.c_str());
  line.clear();
  for (const auto& [stage, t] : run.beside) line += (line.empty() ? "" : ", ") + stage + " " + fmt("%.1f", t);
  if (!line.empty()) std::printf("  beside them, on other threads or processes: %s\n", line.c_str());
  std::printf("  wrote %s/index.html, report.json\n", out_.c_str());
  return 0;
}

}  // namespace skinfem::app
