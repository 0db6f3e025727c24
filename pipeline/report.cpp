#include "skinfem/pipeline/report.hpp"

#include <algorithm>
#include <functional>
#include <future>

#include "skinfem/fem/blas_threads.hpp"
#include "skinfem/mesh/mirror.hpp"
#include "skinfem/pipeline/adjoint_setup.hpp"
#include "skinfem/pipeline/contact_setup.hpp"
#include "skinfem/pipeline/crosscheck.hpp"
#include "skinfem/pipeline/finite_deformation.hpp"
#include "skinfem/pipeline/meridian_contact.hpp"
#include "skinfem/pipeline/progress.hpp"
#include "skinfem/pipeline/scene_json.hpp"
#include "skinfem/pipeline/skin_setup.hpp"
#include "skinfem/scene/parallel.hpp"
#include "skinfem/validation/text.hpp"

namespace skinfem::pipeline {

namespace {

using validation::fmt;

// One report's state between its stages; report_run calls the steps in order.
class Chain {
 public:
  // scene: the linear skin's; finite: the scene as given when its material.model is neo_hookean, else null.
  Chain(const Scene& scene, const Scene* finite, const ReportOptions& options, ReportSink& sink)
      : scene_(scene), finite_(finite), options_(options), fast_(options.fast), sink_(sink) {}
  Chain(const Chain&) = delete;
  Chain& operator=(const Chain&) = delete;
  void factor();        // the meridian checks, the one factorization and the sensors' adjoints
  void green();         // the green stage, the mesh's summary beside it; starts kfit and the k sweep
  void contact();       // contact, defect sweep, crosscheck, hole budget (a scene with a contact), and
                        // with a neo-Hookean scene its finite deformation
  void perception();    // the perception section; then the chain's set-up goes, before the dictionary's
  void error_levels();  // kfit's and the k sweep's ends, then the coarser levels of the error bars
  void post_design();   // or, in a fast report, what it left out
  ReportResult finish();

 private:
  void finish_kfit();
  void release_chain();  // this level's values for the error bars, then the chain's set-up and adjoints
  void finish_k_sweep(const std::vector<validation::KSweepPoint>& mesh_rows);

  const Scene& scene_;
  const Scene* finite_;
  const ReportOptions& options_;
  const bool fast_;
  ReportSink& sink_;
  Stopwatch total_;
  ReportResult out_;
  nlohmann::json& report_ = out_.json;

  std::optional<MeridianContactRun> meridian_check_;  // the 3D frictionless contact's check
  std::optional<MeridianScan> axis_scan_;
  ContactSkin factored_;
  std::shared_ptr<Skin> skin_;
  std::unique_ptr<AdjointSetup> adjoints_;
  std::optional<SensorGreens> greens_;
  std::optional<MeridianCheck> axis_check_;  // the green stage's, which kfit would otherwise solve again
  std::shared_ptr<ContactSetup> contact_;
  std::optional<DefectRun> defect_;
  std::optional<KfitResult> kfit_;
  std::optional<PostDesignRun> post_run_;  // its processes killed if the report stops before it is waited for
  std::optional<ChainLevel> finite_level_;  // the finite sliding state's headline values, for its error bars

  // Declared after what they read, so that they are waited for before it goes.
  struct MeridianChecks {
    std::optional<MeridianContactRun> contact;
    std::optional<MeridianScan> axis;
  };
  std::future<MeridianChecks> meridian_run_;
  double meridian_seconds_ = 0, k_sweep_seconds_ = 0, kfit_seconds_ = 0;
  std::future<validation::KTargetAnswer> k_sweep_;
  std::future<KfitResult> kfit_run_;
};

void Chain::factor() {
  // The post design (2D solves, a fifth of the report's work) runs beside the whole chain, in processes
  // forked now (before any thread of ours is in the BLAS) at the lowest priority: they take what the chain
  // leaves idle (its meshing, assembly and analysis, its one-thread stages) and rarely delay it.
  if (!fast_ && post_design_unavailable(scene_).empty())
    post_run_.emplace(report_post_design(scene_, worker_threads()));
  // The meridian's frictionless contact, which checks the 3D one, is solved first: beside the 3D
  // factorization its own would add 35 MB to the report's peak. A fast report, 200 MB below the full one's,
  // solves it on a thread from the start, with the green stage's meridian scan of the axis sensor where the
  // scene alone says which and how far (their MUMPS calls take turns with the 3D ones).
  const bool meridian_contact =
      scene_.contact && meridian_contact_unavailable(scene_, FrictionMode::none, false).empty();
  if (fast_)
    meridian_run_ = std::async(std::launch::async, [this, meridian_contact] {
      const Stopwatch own;
      MeridianChecks m;
      if (meridian_contact) m.contact = meridian_contact_run(scene_, FrictionMode::none);
      if (const auto plan = planned_axis_scan(scene_))
        m.axis = meridian_scan(scene_, plan->first, green::LayerLoad::punch,
                               0.5 * scene_.calibration.punch_diameter, plan->second);
      meridian_seconds_ = own.seconds();
      return m;
    });
  else if (meridian_contact)
    meridian_check_ = meridian_contact_run(scene_, FrictionMode::none);
  // One factorization for every stage: with a contact, bordered by its condensation's columns where that is
  // cheaper (green and kfit solve on its interior block). The hole budget sweeps its interface hypotheses
  // resolved: the path's compliance, whatever the scene's; a fast report, without the budget, borders only
  // what the scene needs (on the default scene 8.9e10 flops and 980 MB against 1.5e11 and 1,182 MB).
  factored_ = chain_skin(scene_, fast_ ? HolePath::as_scene : HolePath::always);
  skin_ = factored_.skin;
  out_.wall = skin_->wall;
  out_.dofs = skin_->model->solver().free_dofs();
  report_["dofs"] = out_.dofs;
  adjoints_ = adjoint_setup(scene_, skin_);
  out_.wall["green_adjoints"] = adjoints_->wall.at("adjoint_solves");
}

void Chain::green() {
  // A half skin is summarized, and handed on, as the whole it stands for: on a thread, beside the green
  // stage (after the adjoint solves, whose peak a front end's copies of it would raise).
  std::future<nlohmann::json> mesh_summary_run = std::async(std::launch::async, [&] {
    const TetMesh& half_or_whole = skin_->mesh;
    const std::optional<TetMesh> mirrored =
        is_half_y(half_or_whole) ? std::optional<TetMesh>(mirror_half(half_or_whole)) : std::nullopt;
    const TetMesh& m = mirrored ? *mirrored : half_or_whole;
    const MeshSummary s = mesh_summary(scene_, m, skin_->wall.at("mesh"));
    nlohmann::json summary = mesh_json(scene_, s);
    sink_.mesh(m, s, summary);
    return summary;
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
    out_.beside["meridian_checks"] = meridian_seconds_;
    meridian_check_ = std::move(m.contact);
    axis_scan_ = std::move(m.axis);
  }
  const GreenRun run = green_run(scene_, *greens_, adjoints_.get(), 0, axis_scan_ ? &*axis_scan_ : nullptr);
  nlohmann::json summary = green_json(scene_, *greens_, run, 0);
  report_["mesh"] = mesh_summary_run.get();
  sink_.green(*greens_, run, summary);
  report_["green"] = std::move(summary);
  axis_check_ = run.meridian_check;
  out_.wall["green_profiles"] = clock.seconds();
  // kfit's scans and fits read the 3D maps only: they run on threads beside the contact and the defect
  // sweep, which do not need them (the green stage's meridian check is reused: no MUMPS there).
  kfit_run_ = std::async(std::launch::async, [this] {
    const Stopwatch own;
    auto r = kfit(scene_, *greens_, green::LayerLoad::punch, axis_check_ ? &*axis_check_ : nullptr, !fast_);
    kfit_seconds_ = own.seconds();
    return r;
  });
}

void Chain::finish_kfit() {
  if (kfit_) return;
  const Stopwatch own;
  kfit_ = kfit_run_.get();
  nlohmann::json entry = kfit_json(*kfit_);
  sink_.kfit(*kfit_, entry);
  add_k_ranges(*kfit_, entry);
  report_["kfit"] = std::move(entry);
  out_.kfit_verdict = kfit_->verdict;
  out_.beside["kfit"] = kfit_seconds_;
  out_.wall["kfit_wait"] = own.seconds();
}

void Chain::finish_k_sweep(const std::vector<validation::KSweepPoint>& mesh_rows) {
  const Stopwatch own;
  validation::KTargetAnswer a = k_sweep_.get();
  validation::add_points(a, mesh_rows);
  sink_.k_sweep(a);
  report_["k_paper"] = k_paper_json(a);
  out_.k_paper_answer = a.answer;
  out_.beside["k_sweep"] = k_sweep_seconds_;
  out_.wall["k_sweep_wait"] = own.seconds();
}

void Chain::contact() {
  contact_ = contact_setup(scene_, std::move(factored_));
  out_.wall["condense"] = contact_->wall.at("condense");
  Stopwatch clock;
  double force = 0;  // the chosen mode's; the run is dropped here, its set-up released with `contact_`
  std::optional<contact::MeridianContactResult> meridian;  // frictionless, where the skin has one
  {
    const ContactRun run = contact_run(scene_, contact_, scene_.contact->friction,
                                       meridian_check_ ? &*meridian_check_ : nullptr);
    nlohmann::json summary = contact_json(scene_, run);
    sink_.contact(run, summary);
    report_["contact"] = std::move(summary);
    force = run.result().force_N;
    if (run.meridian_check) meridian = run.meridian_check->frictionless;
  }
  out_.wall["contact"] = clock.seconds();
  // Its volume solution was the chain's last solve: the rest works on the condensed contact and the
  // adjoints' maps, so the factorization (most of the peak) goes.
  skin_->model->release_factorization();
  if (!scene_.contact->sweep) return;
  clock = Stopwatch();
  // Every position's frame: the crosscheck convolves each one's tractions.
  defect_ = defect_run(scene_, contact_, {}, DefectFrames::every);
  {
    nlohmann::json summary = defect_json(scene_, *defect_);
    sink_.defect(*defect_, summary);
  }
  out_.wall["defect"] = clock.seconds();
  finish_kfit();
  clock = Stopwatch();
  out_.crosscheck =
      crosscheck_run(scene_, *adjoints_, *contact_, *defect_, scene_.contact->force.value_or(force),
                     kfit_->sensors.at(0).fe.k_lsq_line, meridian ? &*meridian : nullptr);
  const validation::Crosscheck& x = *out_.crosscheck;
  sink_.crosscheck(x);
  out_.front = validation::front_sensor_answer(
      x, validation::front_sensors(scene_.sensors, contact_center(scene_), scene_.contact->direction),
      scene_.contact->direction);
  report_["front_sensors"] = front_sensor_json(*out_.front);
  out_.wall["crosscheck"] = clock.seconds();
  if (fast_) return;
  clock = Stopwatch();
  out_.budget = hole_budget(scene_, *contact_, x, paper_reading_scale(*kfit_));
  out_.wall["hole_budget"] = clock.seconds();
  if (finite_) {
    // The factorization is gone; the finite states' own (1.2 GB on the default scene) come one at a time.
    clock = Stopwatch();
    progress(
        "finite deformation: the static and sliding states on the neo-Hookean skin and their hole sweeps");
    const FiniteDeformation f = finite_deformation(*finite_, *defect_);
    add_finite_row(*out_.budget, *finite_, f.run);
    if (f.shear) add_finite_row(*out_.budget, *f.shear_scene, *f.shear);
    if (!f.shear_failed.empty() && out_.budget->unavailable.empty())
      out_.budget->skipped.push_back(
          {{"shear_strength_finite", "the shear strength on the neo-Hookean skin in finite strain",
            *finite_->contact},
           f.shear_failed});
    report_["finite_deformation"] = finite_deformation_json(*finite_, f, &*out_.budget);
    sink_.finite_deformation(report_["finite_deformation"]);
    finite_level_ = finite_sliding_level(f.run);
    out_.wall["finite_deformation"] = clock.seconds();
    clock = Stopwatch();
  }
  sink_.hole_budget(*out_.budget, x);
  report_["hole_budget"] = hole_budget_json(scene_, *out_.budget);
  out_.wall["hole_budget"] += clock.seconds();
}

void Chain::release_chain() {
  if (!adjoints_) return;
  if (!options_.error_scales.empty()) {
    const BlasThreads one(1);
    out_.levels.push_back(chain_values(scene_, *adjoints_, contact_.get()));
  }
  // The defect run holds the contact set-up too (its solver, its condensed blocks): without it, the paper's
  // skin with posts kept 1.65 GB resident through the levels and peaked there, 350 MB above its own chain.
  if (defect_) defect_->setup.reset();
  contact_.reset();
  adjoints_.reset();
  skin_.reset();
  factored_.skin.reset();  // without a contact it was never handed on
  release_freed_memory();
}

void Chain::perception() {
  if (fast_ || !scene_.contact) return;
  if (const std::string why = perception_unavailable(scene_); !why.empty()) {
    report_["perception"] = {{"skipped", why}};
    return;
  }
  Stopwatch clock;
  ReportPerception p = report_perception_scans(scene_, contact_);
  out_.wall["perception_scans"] = clock.seconds();
  // The inversion's dictionary has its own factorization: the chain's set-up goes first.
  release_chain();
  clock = Stopwatch();
  report_perception_inversion(scene_, p);
  out_.wall["perception_inversion"] = clock.seconds();
  nlohmann::json entry = report_perception_json(scene_, p);
  sink_.perception(p, entry);
  report_["perception"] = std::move(entry);
}

// The chain's headline quantities on this mesh and on coarser ones (every mesh size scaled), Richardson
// through the three finest. The coarse levels come after this level's memory is released.
void Chain::error_levels() {
  finish_kfit();
  const std::vector<double>& scales_given = options_.error_scales;
  if (!fast_ && scales_given.empty()) finish_k_sweep({});
  sink_.chain_done();
  if (scales_given.empty()) return;
  const Stopwatch clock;
  const BlasThreads one(1);
  std::vector<ChainLevel>& levels = out_.levels;
  release_chain();
  std::vector<double> scales = scales_given;
  std::sort(scales.begin(), scales.end(), std::greater<>());
  for (size_t i = 0; i < scales.size(); ++i) {
    progress("error bars: level " + std::to_string(i + 1) + " of " + std::to_string(scales.size()) +
             " (mesh sizes x" + fmt("%g", scales[i]) + ")");
    levels.insert(levels.end() - 1, chain_level(scene_, scales[i]));
  }
  const nlohmann::json study = chain_study_json(scene_, levels);
  sink_.chain_study(levels, study);
  report_["chain_study"] = study;
  report_["chain_study"].erase("scene");
  out_.error_bars = error_bars(chain_errors(levels), scales);
  out_.exponents = time_vs_dofs_exponent(levels);
  report_["error_bars"] = error_bars_json(out_.error_bars);
  out_.wall["error_levels"] = clock.seconds();
  if (finite_level_) {
    // The finite sliding state on the same coarser meshes: its own error bars, beside the linear ones.
    const Stopwatch finite_clock;
    std::vector<ChainLevel> finite = finite_sliding_levels(*finite_, scales);
    finite.push_back(*finite_level_);
    report_["finite_deformation"]["error_bars"] = error_bars_json(error_bars(chain_errors(finite), scales));
    report_["finite_deformation"]["levels"] = chain_study_json(*finite_, finite).at("levels");
    out_.wall["finite_error_levels"] = finite_clock.seconds();
  }
  std::vector<validation::KSweepPoint> mesh_rows;
  for (const ChainLevel& l : levels) mesh_rows.push_back({"mesh_scale", l.scale, l.value[0], l.value[1]});
  finish_k_sweep(mesh_rows);
}

void Chain::post_design() {
  if (!fast_) {
    const Stopwatch clock;
    if (const std::string why = post_design_unavailable(scene_); !why.empty()) {
      report_["post_design"] = {{"skipped", "no meridian at the skin's axis: " + why}};
    } else {
      progress(
          "post design: a post against a disc at the skin's axis, and a sweep of post height and diameter");
      out_.post = post_run_->finish();
      nlohmann::json entry = post_design_json(*out_.post);
      sink_.post_design(*out_.post, entry);
      out_.post_answer = entry.at("answer").get<std::string>();
      report_["post_design"] = std::move(entry);
    }
    out_.wall["post_design_wait"] = clock.seconds();
    if (out_.post) out_.beside["post_design"] = out_.post->seconds;
    return;
  }
  std::vector<std::string> left{"error bars (the coarser levels)"};
  if (scene_.contact && scene_.contact->sweep)
    left.insert(left.end(), {"the hole-signal budget of hypotheses", "the defect sweep's VTK frames"});
  if (scene_.contact && scene_.contact->sweep) left.push_back("the perception section");
  left.push_back("the post design sweep");
  if (finite_) left.push_back("the finite deformation (material.model neo_hookean)");
  left.push_back("the k sweep (which protocol reading gives the paper's k)");
  if (scene_.geometry.kind == GeometryKind::cap)
    left.push_back("the cap's effective-thickness fits (kfit.json)");
  for (size_t i = 0; i < left.size(); ++i)
    out_.left_out += (i == 0 ? "" : i + 1 < left.size() ? ", " : " and ") + left[i];
  report_["fast"] = {{"left_out", out_.left_out}};
}

ReportResult Chain::finish() {
  report_["scene"] = scene_json(finite_ ? *finite_ : scene_);
  report_["wall_s"] = out_.wall;
  report_["wall_beside_s"] = out_.beside;
  report_["units"] = {
      {"length", "mm"}, {"force", "N"}, {"stress", "kPa in tables and CSV, MPa in the model"}};
  out_.seconds = total_.seconds();
  out_.peak_rss_mb = peak_rss_mb();
  return std::move(out_);
}

}  // namespace

void check_report(const Scene& scene, const ReportOptions& options) {
  check_error_scales(options.error_scales);
  if (options.fast && !options.error_scales.empty())
    throw SceneError("error_scales: a fast report draws no error bars; give one or the other");
  if (scene.material.model == MaterialModel::neo_hookean && !options.fast)
    check_finite_defect(scene, {FrictionMode::static_residual, FrictionMode::coupled});
}

ReportResult report_run(const Scene& scene, const ReportOptions& options, ReportSink& sink) {
  check_report(scene, options);
  // A neo-Hookean scene: the chain (Green tensors, k, the linear contact and budget) on the linear skin, its
  // small-signal model, then the finite deformation beside it.
  const bool finite = scene.material.model == MaterialModel::neo_hookean;
  Scene linear = scene;
  linear.material.model = MaterialModel::linear;
  Chain chain(linear, finite ? &scene : nullptr, options, sink);
  chain.factor();
  chain.green();
  if (scene.contact) {
    chain.contact();
    chain.perception();
  }
  chain.error_levels();
  chain.post_design();
  return chain.finish();
}

}  // namespace skinfem::pipeline
