#include "app/report_run.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <functional>

#include "app/chain_study.hpp"
#include "app/common.hpp"
#include "app/report_outputs.hpp"
#include "skinfem/fem/blas_threads.hpp"
#include "skinfem/mesh/mirror.hpp"
#include "skinfem/pipeline/crosscheck.hpp"
#include "skinfem/pipeline/symmetry.hpp"
#include "skinfem/scene/parallel.hpp"
#include "skinfem/validation/text.hpp"

namespace skinfem::app {

using validation::fmt;

ReportRun::ReportRun(const Scene& scene, std::string out_dir, std::vector<double> error_scales, bool fast)
    : scene_(scene),
      out_(std::move(out_dir)),
      error_scales_(std::move(error_scales)),
      fast_(fast),
      k_figure_with_contact_(!fast && error_scales_.empty() && scene.contact),
      figures_(out_) {}

void ReportRun::factor_chain() {
  // The meridian's frictionless contact, which checks the 3D one, is solved first: beside the 3D
  // factorization its own would add 35 MB to the report's peak. A fast report, 200 MB below the full one's,
  // solves it on a thread from the start, with the green stage's meridian scan of the axis sensor where the
  // scene alone says which and how far (their MUMPS calls take turns with the 3D ones).
  const bool meridian_contact =
      scene_.contact && pipeline::meridian_contact_unavailable(scene_, FrictionMode::none, false).empty();
  if (fast_)
    meridian_run_ = std::async(std::launch::async, [this, meridian_contact] {
      const Stopwatch own;
      MeridianChecks m;
      if (meridian_contact) m.contact = pipeline::meridian_contact_run(scene_, FrictionMode::none);
      if (const auto plan = pipeline::planned_axis_scan(scene_))
        m.axis = pipeline::meridian_scan(scene_, plan->first, green::LayerLoad::punch,
                                         0.5 * scene_.calibration.punch_diameter, plan->second);
      meridian_seconds_ = own.seconds();
      return m;
    });
  else if (meridian_contact)
    meridian_check_ = pipeline::meridian_contact_run(scene_, FrictionMode::none);
  // One factorization for every stage: with a contact, bordered by its condensation's columns where that is
  // cheaper (green and kfit solve on its interior block). The hole budget sweeps its interface hypotheses
  // resolved: the path's compliance, whatever the scene's; a fast report, without the budget, borders only
  // what the scene needs (on the default scene 8.9e10 flops and 980 MB against 1.5e11 and 1,182 MB).
  factored_ = pipeline::chain_skin(scene_, fast_ ? HolePath::as_scene : HolePath::always);
  skin_ = factored_.skin;
  wall_ = skin_->wall;
  dofs_ = skin_->model->solver().free_dofs();
  report_["dofs"] = dofs_;
  adjoints_ = adjoint_setup(scene_, skin_);
  wall_["green_adjoints"] = adjoints_->wall.at("adjoint_solves");
}

void ReportRun::green() {
  // A half skin is shown, and its quality and volume checked, as the whole it stands for: on a thread,
  // beside the green stage (after the adjoint solves, whose peak its VTK copies would raise); its lines are
  // printed first, where they belong.
  std::string mesh_lines;
  std::future<nlohmann::json> mesh_summary = std::async(std::launch::async, [&] {
    const TetMesh& m = skin_->mesh;
    const double seconds = skin_->wall.at("mesh");
    if (!is_half_y(m)) return mesh_stage(scene_, m, seconds, out_ + "/mesh", &mesh_lines);
    return mesh_stage(scene_, mirror_half(m), seconds, out_ + "/mesh", &mesh_lines);
  });
  const Stopwatch clock;
  greens_ = sensor_greens(scene_, *adjoints_);
  // The exact layer's k sweep needs no FE, only the headline sensor's thickness: it runs on a thread (the
  // layer's closed forms, no MUMPS) beside the stages to come, whose main thread leaves a core free. A fast
  // report leaves it out.
  if (!fast_)
    k_sweep_ = std::async(std::launch::async, [this] {
      const ThreadCap one(1);
      const Stopwatch own;
      auto a = k_paper_sweep(scene_, greens_->thickness.at(0));
      k_sweep_seconds_ = own.seconds();
      return a;
    });
  if (meridian_run_.valid()) {
    MeridianChecks m = meridian_run_.get();
    beside_["meridian_checks"] = meridian_seconds_;
    meridian_check_ = std::move(m.contact);
    axis_scan_ = std::move(m.axis);
  }
  std::string green_lines;
  auto green = green_stage(scene_, *greens_, adjoints_.get(), out_ + "/green", 0,
                           axis_scan_ ? &*axis_scan_ : nullptr, &green_lines);
  report_["mesh"] = mesh_summary.get();
  std::fputs((mesh_lines + green_lines).c_str(), stdout);
  report_["green"] = std::move(green.summary);
  axis_check_ = green.result.meridian_check;
  wall_["green_profiles"] = clock.seconds();
  // kfit's scans and fits read the 3D maps only: they run on threads beside the contact and the defect
  // sweep, which do not need them (the green stage's meridian check is reused: no MUMPS there).
  kfit_run_ = std::async(std::launch::async, [this] {
    const Stopwatch own;
    auto r = pipeline::kfit(scene_, *greens_, green::LayerLoad::punch, axis_check_ ? &*axis_check_ : nullptr,
                            !fast_);
    kfit_seconds_ = own.seconds();
    return r;
  });
}

// kfit's end: its outputs, and the calibration's figures drawn beside the stages still to come. The
// contact's are drawn after the crosscheck (and the budget), by an interpreter started now that waits for
// the word; the rest at the end.
void ReportRun::finish_kfit() {
  if (kfit_) return;
  const Stopwatch own;
  kfit_ = kfit_stage(scene_, kfit_run_.get(), out_ + "/kfit");
  report_["kfit"] = kfit_->summary;
  index_.kfit_verdict = kfit_->result.verdict;
  beside_["kfit"] = kfit_seconds_;
  wall_["kfit_wait"] = own.seconds();
  const std::vector<std::string> calibration{"fig1_calibration.png", "green_vs_halfspace.png"};
  figures_.draw_now(calibration);
  if (scene_.contact) {
    std::vector<std::string> later = calibration;
    later.insert(later.end(), {"pareto.png", "post_design.png"});
    if (!k_figure_with_contact_) later.push_back("k_sweep.png");
    figures_.draw_on_go(later);
  }
}

// The k sweep's answer, with the FE's mesh levels (mesh_rows) when the error bars bring them.
void ReportRun::finish_k_sweep(const std::vector<validation::KSweepPoint>& mesh_rows) {
  const Stopwatch own;
  validation::KTargetAnswer k_answer = k_sweep_.get();
  write_k_paper_answer(k_answer, mesh_rows, out_ + "/kfit", report_["k_paper"]);
  index_.k_paper_answer = k_answer.answer;
  beside_["k_sweep"] = k_sweep_seconds_;
  wall_["k_sweep_wait"] = own.seconds();
}

void ReportRun::contact_chain() {
  contact_ = contact_setup(scene_, std::move(factored_));
  wall_["condense"] = contact_->wall.at("condense");
  Stopwatch clock;
  double force = 0;  // the chosen mode's; the run is dropped here, its set-up released with `contact_`
  std::optional<contact::MeridianContactResult> meridian;  // frictionless, where the skin has one
  {
    const auto run = contact_stage(scene_, contact_, out_ + "/contact", scene_.contact->friction, "",
                                   meridian_check_ ? &*meridian_check_ : nullptr);
    report_["contact"] = run.summary;
    force = run.result.result().force_N;
    if (run.result.meridian_check) meridian = run.result.meridian_check->frictionless;
  }
  wall_["contact"] = clock.seconds();
  // Its volume solution was the chain's last solve: the rest works on the condensed contact and the
  // adjoints' maps, so the factorization (most of the peak) goes.
  skin_->model->release_factorization();
  if (!scene_.contact->sweep) return;
  clock = Stopwatch();
  // Every position's frame: the crosscheck convolves each one's tractions.
  defect_ = defect_stage(scene_, contact_, out_ + "/defect", {}, pipeline::DefectFrames::every, !fast_);
  wall_["defect"] = clock.seconds();
  finish_kfit();
  clock = Stopwatch();
  x_ = crosscheck_run(scene_, *adjoints_, *contact_, *defect_, scene_.contact->force.value_or(force),
                      kfit_->result.sensors.at(0).fe.k_lsq_line, meridian ? &*meridian : nullptr);
  write_crosscheck(*x_, scene_.sensors, out_ + "/crosscheck");
  index_.front = validation::front_sensor_answer(
      *x_, validation::front_sensors(scene_.sensors, contact_center(scene_), scene_.contact->direction),
      scene_.contact->direction);
  report_["front_sensors"] = front_sensor_json(*index_.front);
  wall_["crosscheck"] = clock.seconds();
  if (fast_) return;
  clock = Stopwatch();
  auto budget = hole_budget_stage(scene_, *contact_, *x_, out_ + "/crosscheck",
                                  pipeline::paper_reading_scale(kfit_->result));
  report_["hole_budget"] = std::move(budget.summary);
  index_.budget = std::move(budget.result);
  wall_["hole_budget"] = clock.seconds();
}

// The chain's headline quantities on this mesh and on coarser ones (every mesh size scaled), Richardson
// through the three finest. The coarse levels come after this level's memory is released.
void ReportRun::error_levels() {
  finish_kfit();
  if (!fast_ && error_scales_.empty()) finish_k_sweep({});
  figures_.go();
  if (error_scales_.empty()) return;
  const Stopwatch clock;
  const BlasThreads one(1);
  levels_.push_back(chain_values(scene_, *adjoints_, contact_.get()));
  // The defect run holds the contact set-up too (its solver, its condensed blocks): without it, the paper's
  // skin with posts kept 1.65 GB resident through the levels and peaked there, 350 MB above its own chain.
  if (defect_) defect_->setup.reset();
  contact_.reset();
  adjoints_.reset();
  skin_.reset();
  factored_.skin.reset();  // without a contact it was never handed on
  release_freed_memory();
  std::vector<double> scales = error_scales_;
  std::sort(scales.begin(), scales.end(), std::greater<>());
  for (size_t i = 0; i < scales.size(); ++i) {
    progress("error bars: level " + std::to_string(i + 1) + " of " + std::to_string(scales.size()) +
             " (mesh sizes x" + fmt("%g", scales[i]) + ")");
    levels_.insert(levels_.end() - 1, chain_level(scene_, scales[i]));
  }
  report_["chain_study"] = write_chain_study(scene_, levels_, out_ + "/study");
  report_["chain_study"].erase("scene");
  index_.error_bars = error_bars(chain_errors(levels_), scales);
  index_.levels = &levels_;
  index_.exponents = time_vs_dofs_exponent(levels_);
  report_["error_bars"] = error_bars_json(index_.error_bars);
  wall_["error_levels"] = clock.seconds();
  std::vector<validation::KSweepPoint> mesh_rows;
  for (const ChainLevel& l : levels_) mesh_rows.push_back({"mesh_scale", l.scale, l.value[0], l.value[1]});
  finish_k_sweep(mesh_rows);
}

void ReportRun::post_design() {
  if (!fast_) {
    const Stopwatch clock;
    post_ = post_design_stage(scene_, out_ + "/green");
    report_["post_design"] = post_.summary;
    if (post_.summary.contains("answer")) {
      index_.post = &post_.result;
      index_.post_answer = post_.summary["answer"];
    }
    wall_["post_design"] = clock.seconds();
    return;
  }
  std::vector<std::string> out{"error bars (the coarser levels)"};
  if (scene_.contact && scene_.contact->sweep)
    out.insert(out.end(), {"the hole-signal budget of hypotheses", "the defect sweep's VTK frames"});
  out.push_back("the post design sweep");
  out.push_back("the k sweep (which protocol reading gives the paper's k)");
  if (scene_.geometry.kind == GeometryKind::cap)
    out.push_back("the cap's effective-thickness fits (kfit.json)");
  for (size_t i = 0; i < out.size(); ++i)
    index_.left_out += (i == 0 ? "" : i + 1 < out.size() ? ", " : " and ") + out[i];
  report_["fast"] = {{"left_out", index_.left_out}};
}

int ReportRun::figures() {
  // Those of the later stages (kfit/k_sweep.csv with the mesh levels, study/chain_study.csv,
  // green/post_design.csv) at the end.
  std::vector<std::string> last;
  if (!fast_ && !k_figure_with_contact_) last.push_back("k_sweep.png");
  if (!error_scales_.empty()) last.push_back("pareto.png");
  if (!fast_) last.push_back("post_design.png");
  const Stopwatch clock;
  int stopped_by = 0;
  figures_rc_ = figures_.finish(last, &stopped_by);
  if (stopped_by != 0) {
    std::fprintf(stderr,
                 "skinfem: report: stopped by signal %d (%s) while drawing the figures; report.json and "
                 "index.html not written\n",
                 stopped_by, strsignal(stopped_by));
    return 128 + stopped_by;
  }
  report_["figures_exit_code"] = figures_rc_;
  wall_["figures"] = clock.seconds();
  return 0;
}

void ReportRun::write_and_print() {
  report_["scene"] = scene_json(scene_);
  report_["wall_s"] = wall_;
  report_["wall_beside_s"] = beside_;
  report_["wall_total_s"] = index_.wall_total_s = total_.seconds();
  report_["peak_rss_mb"] = index_.peak_rss_mb = peak_rss_mb();
  report_["units"] = {
      {"length", "mm"}, {"force", "N"}, {"stress", "kPa in tables and CSV, MPa in the model"}};
  write_json(out_ + "/report.json", report_);
  index_.dofs = dofs_;
  index_.wall = &wall_;
  index_.wall_beside = &beside_;
  index_.x = x_ ? &*x_ : nullptr;
  write_index(out_, scene_, index_);
  std::printf("report %s: %d DOFs, one factorization for the chain%s; %.1f s, peak %.0f MB\n",
              scene_.name.c_str(), dofs_,
              index_.error_bars.empty()
                  ? ""
                  : (" and " + std::to_string(error_scales_.size()) + " coarser for the error bars").c_str(),
              total_.seconds(), peak_rss_mb());
  for (const ErrorBar& e : index_.error_bars)
    std::printf("  %s: %s%s%s (%s)\n", e.what.c_str(), with_error(e.value, e.error).c_str(),
                e.unit.empty() ? "" : " ", e.unit.c_str(), e.method.c_str());
  if (!index_.k_paper_answer.empty()) std::printf("  %s\n", index_.k_paper_answer.c_str());
  if (index_.front) std::printf("  %s\n", index_.front->answer.c_str());
  if (figures_rc_ != 0)
    std::printf("  figures: scripts/figures.py exited with %d; index.html lists the figures written\n",
                figures_rc_);
  if (!index_.left_out.empty()) std::printf("  fast: left out the %s\n", index_.left_out.c_str());
  // Where the time went, longest first.
  std::vector<std::pair<double, std::string>> stages;
  for (const auto& [stage, t] : wall_) stages.push_back({t, stage});
  std::sort(stages.rbegin(), stages.rend());
  std::string line;
  for (const auto& [t, stage] : stages) line += (line.empty() ? "" : ", ") + stage + " " + fmt("%.1f", t);
  std::printf("  seconds per stage: %s\n", line.c_str());
  line.clear();
  for (const auto& [stage, t] : beside_) line += (line.empty() ? "" : ", ") + stage + " " + fmt("%.1f", t);
  if (!line.empty()) std::printf("  beside them, on another thread: %s\n", line.c_str());
  std::printf("  wrote %s/index.html, report.json\n", out_.c_str());
}

}  // namespace skinfem::app
