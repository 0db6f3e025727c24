// skinfem report — the main job: the whole chain on one mesh and one factorization, and the paper's
// convolution model checked against it assumption by assumption (validation/crosscheck.hpp).
//
//   $ skinfem report scenes/candelier2011.json
//   report candelier2011: 95898 DOFs, one factorization for the chain and 2 coarser for the error bars;
//   25.9 s, peak 1185 MB
//
// The stages run in order on the main thread. Beside it, on threads: kfit's scans and fits, the k sweep and
// the mesh's files (no MUMPS), and in a fast report the meridian checks (their MUMPS calls take turns with
// the 3D ones). The figures are drawn by background processes as their inputs become final.
//
// A scene mirror-symmetric about y = 0, contact included (pipeline/symmetry.hpp), is solved on its half y ≥ 0
// and every output is written for the whole skin (mesh.vtu, maps, pressure, fields).
//
// Stages, each writing its own folder under DIR (default out/<scene name>): mesh/ (mesh.vtu, boundary.vtu),
// green/ (green.csv, green_maps.vtp, post_design.csv: an isolated post against a disc at the skin's axis and
// a design sweep, app/post_design_stage.cpp), kfit/ (kfit.json, and k_sweep.csv: the exact layer's k as each
// reading of the calibration protocol changes, validation/k_sweep.hpp), and with a contact: contact/
// (pressure.vtp, fields.vtu, sensors.csv, modes.csv), defect/ (defect.csv, defect.pvd + frames/) and
// crosscheck/ (readings.csv, defect.csv, pressure.csv, attribution.csv with columns
// case,variant,sensor,component,amplitude_ratio,peak_shift_mm,shape_error). Then figures/*.png
// (scripts/figures.py, matplotlib) and DIR/report.json (the headline numbers with units, wall seconds per
// stage, peak memory) and DIR/index.html (figures, tables, links to every VTK file).
#include <signal.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <future>
#include <optional>
#include <sstream>
#include <string>
#include <utility>

#include "app/chain_study.hpp"
#include "app/commands.hpp"
#include "app/common.hpp"
#include "app/report_page.hpp"
#include "app/stages.hpp"
#include "fem/blas_threads.hpp"
#include "green/kfit.hpp"
#include "mesh/mirror.hpp"
#include "pipeline/crosscheck.hpp"
#include "pipeline/symmetry.hpp"
#include "scene/parallel.hpp"
#include "validation/crosscheck.hpp"
#include "validation/k_sweep.hpp"
#include "validation/text.hpp"

namespace skinfem::app {

namespace {
using validation::fmt;

void write_crosscheck(const validation::Crosscheck& x, const Sensors& sensors, const std::string& dir) {
  prepare_output_dir(dir);
  const char* cases[2] = {"static", "sliding"};
  const int ns = static_cast<int>(sensors.positions.size());
  std::ostringstream r, d, p, a;
  for (auto* s : {&r, &d, &p, &a}) s->precision(10);
  r << "case,variant,sensor,x_mm,sigma_z_kPa,sigma_x_kPa\n";
  for (size_t v = 0; v < x.readings.size(); ++v)
    for (int c = 0; c < 2; ++c)
      for (int k = 0; k < ns; ++k)
        r << cases[c] << "," << x.reading_variants[v].name << "," << k + 1 << "," << sensors.positions[k][0]
          << "," << 1e3 * x.readings[v][c][2 * k] << "," << 1e3 * x.readings[v][c][2 * k + 1] << "\n";
  d << "case,variant,u_mm,sensor,varsigma_z_kPa,varsigma_x_kPa\n";
  for (size_t v = 0; v < x.signals.size(); ++v)
    for (int c = 0; c < 2; ++c)
      for (size_t i = 0; i < x.u.size(); ++i)
        for (int k = 0; k < ns; ++k)
          d << cases[c] << "," << x.signal_variants[v].name << "," << x.u[i] << "," << k + 1 << ","
            << 1e3 * x.signals[v][c](i, 2 * k) << "," << 1e3 * x.signals[v][c](i, 2 * k + 1) << "\n";
  p << "x_mm,p_hertz_halfspace_kPa,p_layer_exact_kPa,p_fe_frictionless_kPa,p_fe_coupled_kPa,q_fe_coupled_"
       "kPa,p_meridian_frictionless_kPa\n";
  for (const auto& row : x.pressure_profile) {
    p << row[0];
    for (int j = 1; j < 7; ++j) {
      p << ",";
      if (std::isfinite(row[j])) p << 1e3 * row[j];
    }
    p << "\n";
  }
  a << "case,variant,sensor,component,amplitude_ratio,peak_shift_mm,shape_error\n";
  for (size_t v = 0; v < x.metrics.size(); ++v)
    for (int c = 0; c < 2; ++c)
      for (int k = 0; k < ns; ++k)
        for (int b = 0; b < 2; ++b) {
          const auto& m = x.metrics[v][c][k][b];
          a << cases[c] << "," << x.signal_variants[v].name << "," << k + 1 << "," << (b ? "x" : "z") << ","
            << m.amplitude_ratio << "," << m.peak_shift_mm << "," << m.shape_error << "\n";
        }
  write_text_atomic(dir + "/readings.csv", r.str());
  write_text_atomic(dir + "/defect.csv", d.str());
  write_text_atomic(dir + "/pressure.csv", p.str());
  write_text_atomic(dir + "/attribution.csv", a.str());
}

// report.json's front_sensors entry (validation::front_sensor_answer).
nlohmann::json front_sensor_json(const validation::FrontSensorAnswer& a) {
  nlohmann::json j;
  std::string front;
  for (const int k : a.front) front += (front.empty() ? "#" : ", #") + std::to_string(k + 1);
  j["front_sensors"] = front;
  if (!a.front.empty()) {
    j["coupling_amplitude_factor_z"] = {a.coupling_lo[0], a.coupling_hi[0]};
    j["coupling_amplitude_factor_x"] = {a.coupling_lo[1], a.coupling_hi[1]};
  }
  if (a.model_lo) {
    j["fe_over_paper_model_amplitude_z"] = {(*a.model_lo)[0], (*a.model_hi)[0]};
    j["fe_over_paper_model_amplitude_x"] = {(*a.model_lo)[1], (*a.model_hi)[1]};
  }
  j["answer"] = a.answer;
  return j;
}

// The exact layer's k as each reading of the calibration protocol changes about the scene's (thickness h at
// the headline sensor): which single change gives the paper's k (validation/k_sweep.hpp).
validation::KTargetAnswer k_paper_sweep(const Scene& scene, double h) {
  validation::KProtocol base;
  base.h = h;
  base.nu = scene.material.nu;
  base.punch_diameter = scene.calibration.punch_diameter;
  return validation::k_target_answer(base, green::kPaperK);
}

// The sweep with the FE k of sensor #1 per mesh scale (mesh_rows) as one more axis; writes DIR/k_sweep.csv
// and its report.json entry.
void write_k_paper_answer(validation::KTargetAnswer& a, const std::vector<validation::KSweepPoint>& mesh_rows,
                          const std::string& dir, nlohmann::json& entry) {
  validation::add_points(a, mesh_rows);
  std::ostringstream csv;
  csv.precision(10);
  csv << "parameter,value,k_central,k_lsq_line\n";
  for (const auto& p : a.points)
    csv << p.parameter << "," << p.value << "," << p.k_central << "," << p.k_lsq_line << "\n";
  write_text_atomic(dir + "/k_sweep.csv", csv.str());
  nlohmann::json j;
  for (const auto& n : a.near)
    j["within_0.01"].push_back(
        {{"parameter", n.parameter}, {"value", n.value}, {"criterion", n.criterion}, {"k", n.k}});
  for (const auto& c : a.crossings)
    j["crossings"].push_back({{"parameter", c.parameter},
                              {"criterion", c.criterion},
                              {"value", c.value},
                              {"linear_interpolation", c.interpolated}});
  j["answer"] = a.answer;
  entry = j;
}

std::vector<ErrorBar> error_bars(const std::vector<ChainError>& errors,
                                 const std::vector<double>& coarse_scales) {
  struct Display {
    const char* name;
    const char* what;
    const char* unit;
    double factor;
  };
  const Display table[] = {
      {"k_central", "k, central criterion (sensor #1)", "", 1},
      {"k_lsq_line", "k, line fit (sensor #1)", "", 1},
      {"contact_radius", "contact radius (coupled friction)", "mm", 1},
      {"contact_p0", "central pressure (coupled friction)", "kPa", 1e3},
      {"indentation", "indentation (coupled friction)", "um", 1e3},
      {"hole_signal", "largest sliding |varsigma_z| over sensors and hole positions", "kPa", 1e3}};
  std::string levels;
  for (double s : coarse_scales) levels += fmt("%g", s) + ", ";
  levels += "1";
  std::vector<ErrorBar> out;
  for (const ChainError& e : errors)
    for (const Display& d : table)
      if (e.name == d.name)
        out.push_back({e.name, d.what, d.unit,
                       e.asymptotic ? "|value - Richardson limit| over mesh scales " + levels +
                                          ", observed order " + fmt("%.2f", e.order)
                                    : "last change between mesh scales " + fmt("%g", coarse_scales.back()) +
                                          " and 1; no asymptotic regime over " + levels + " (" + e.why_not +
                                          "), so an order of magnitude only",
                       d.factor * e.value, d.factor * e.error, e.error / std::abs(e.value)});
  return out;
}

nlohmann::json error_bars_json(const std::vector<ErrorBar>& bars) {
  nlohmann::json j = nlohmann::json::array();
  for (const ErrorBar& e : bars)
    j.push_back({{"quantity", e.quantity},
                 {"what", e.what},
                 {"unit", e.unit},
                 {"value", e.value},
                 {"error", e.error},
                 {"relative_error", e.relative_error},
                 {"method", e.method}});
  return j;
}

}  // namespace

int run_report(const Scene& scene, const std::string& out_dir, const std::vector<double>& error_scales,
               bool fast) {
  pipeline::check_error_scales(error_scales);
  check_output_dir(out_dir);
  Stopwatch total;
  nlohmann::json report, wall, beside = nlohmann::json::object();  // beside: stages on another thread
  // The meridian's frictionless contact, which checks the 3D one, is solved first: beside the 3D
  // factorization its own would add 35 MB to the report's peak. A fast report, 200 MB below the full one's,
  // solves it on a thread from the start, with the green stage's meridian scan of the axis sensor where the
  // scene alone says which and how far (their MUMPS calls take turns with the 3D ones).
  std::optional<pipeline::MeridianContactRun> meridian_check;
  const bool meridian_contact =
      scene.contact && pipeline::meridian_contact_unavailable(scene, FrictionMode::none, false).empty();
  struct MeridianChecks {
    std::optional<pipeline::MeridianContactRun> contact;
    std::optional<pipeline::MeridianScan> axis;
  };
  std::future<MeridianChecks> meridian_run;
  double meridian_seconds = 0;
  if (fast)
    meridian_run = std::async(std::launch::async, [&scene, meridian_contact, &meridian_seconds] {
      const Stopwatch own;
      MeridianChecks m;
      if (meridian_contact) m.contact = pipeline::meridian_contact_run(scene, FrictionMode::none);
      if (const auto plan = pipeline::planned_axis_scan(scene))
        m.axis = pipeline::meridian_scan(scene, plan->first, green::LayerLoad::punch,
                                         0.5 * scene.calibration.punch_diameter, plan->second);
      meridian_seconds = own.seconds();
      return m;
    });
  else if (meridian_contact)
    meridian_check = pipeline::meridian_contact_run(scene, FrictionMode::none);
  // One factorization for every stage: with a contact, bordered by its condensation's columns where that is
  // cheaper (green and kfit solve on its interior block). The hole budget sweeps its interface hypotheses
  // resolved: the path's compliance, whatever the scene's; a fast report, without the budget, borders only
  // what the scene needs (on the default scene 8.9e10 flops and 980 MB against 1.5e11 and 1,182 MB).
  pipeline::ContactSkin factored = pipeline::chain_skin(scene, fast ? HolePath::as_scene : HolePath::always);
  auto skin = factored.skin;
  wall = skin->wall;
  const int dofs = skin->model->solver().free_dofs();
  report["dofs"] = dofs;

  Stopwatch clock;
  auto adjoints = adjoint_setup(scene, skin);
  wall["green_adjoints"] = adjoints->wall["adjoint_solves"];
  // A half skin is shown, and its quality and volume checked, as the whole it stands for: on a thread,
  // beside the green stage (after the adjoint solves, whose peak its VTK copies would raise); its lines are
  // printed first, where they belong.
  std::string mesh_lines;
  std::future<nlohmann::json> mesh_summary = std::async(std::launch::async, [&] {
    const TetMesh& m = skin->mesh;
    const double seconds = skin->wall["mesh"].get<double>();
    if (!is_half_y(m)) return mesh_stage(scene, m, seconds, out_dir + "/mesh", &mesh_lines);
    return mesh_stage(scene, mirror_half(m), seconds, out_dir + "/mesh", &mesh_lines);
  });
  clock = Stopwatch();
  const SensorGreens greens = sensor_greens(scene, *adjoints);
  // The exact layer's k sweep needs no FE, only the headline sensor's thickness: it runs on a thread (the
  // layer's closed forms, no MUMPS) beside the stages to come, whose main thread leaves a core free. A fast
  // report leaves it out.
  double k_sweep_seconds = 0;
  std::future<validation::KTargetAnswer> k_sweep;
  if (!fast)
    k_sweep = std::async(std::launch::async, [&] {
      const ThreadCap one(1);
      const Stopwatch own;
      auto a = k_paper_sweep(scene, greens.thickness.at(0));
      k_sweep_seconds = own.seconds();
      return a;
    });
  // k_sweep.png is drawn with the contact's figures, or at the end when the mesh levels join the sweep.
  const bool k_figure_with_contact = !fast && error_scales.empty() && scene.contact;
  std::optional<pipeline::MeridianScan> axis_scan;
  if (meridian_run.valid()) {
    MeridianChecks m = meridian_run.get();
    beside["meridian_checks"] = meridian_seconds;
    meridian_check = std::move(m.contact);
    axis_scan = std::move(m.axis);
  }
  std::optional<MeridianCheck> axis_check;  // the green stage's, which kfit would otherwise solve again
  {
    std::string green_lines;
    auto green = green_stage(scene, greens, adjoints.get(), out_dir + "/green", 0,
                             axis_scan ? &*axis_scan : nullptr, &green_lines);
    report["mesh"] = mesh_summary.get();
    std::fputs((mesh_lines + green_lines).c_str(), stdout);
    report["green"] = std::move(green.summary);
    axis_check = green.result.meridian_check;
  }
  wall["green_profiles"] = clock.seconds();
  // kfit's scans and fits read the 3D maps only: they run on threads beside the contact and the defect
  // sweep, which do not need them (the green stage's meridian check is reused: no MUMPS there).
  double kfit_seconds = 0;
  std::future<pipeline::KfitResult> kfit_run = std::async(std::launch::async, [&] {
    const Stopwatch own;
    auto r =
        pipeline::kfit(scene, greens, green::LayerLoad::punch, axis_check ? &*axis_check : nullptr, !fast);
    kfit_seconds = own.seconds();
    return r;
  });

  IndexInput index;
  std::optional<StageOutput<pipeline::KfitResult>> kf;
  const pipeline::KfitSensor* headline = nullptr;
  std::vector<int> figure_children;
  int contact_figures_go = -1;  // their interpreter's stdin, told "go" once their inputs are written
  const std::string script = figures_script();

  // The k sweep's answer, with the FE's mesh levels (mesh_rows) when the error bars bring them.
  const auto finish_k_sweep = [&](const std::vector<validation::KSweepPoint>& mesh_rows) {
    const Stopwatch own;
    validation::KTargetAnswer k_answer = k_sweep.get();
    write_k_paper_answer(k_answer, mesh_rows, out_dir + "/kfit", report["k_paper"]);
    index.k_paper_answer = k_answer.answer;
    beside["k_sweep"] = k_sweep_seconds;
    wall["k_sweep_wait"] = own.seconds();
  };
  // kfit's end: its outputs, and the calibration's figures drawn in a background process beside the stages
  // still to come. The contact's are drawn after the crosscheck (and the budget), by an interpreter started
  // now that waits for the word; the rest at the end.
  const auto finish_kfit = [&] {
    if (kf) return;
    const Stopwatch own;
    kf = kfit_stage(scene, kfit_run.get(), out_dir + "/kfit");
    report["kfit"] = kf->summary;
    headline = &kf->result.sensors.at(0);
    index.kfit_verdict = kf->result.verdict;
    beside["kfit"] = kfit_seconds;
    wall["kfit_wait"] = own.seconds();
    progress("figures: " + script + ", beside the stages to come");
    figure_children.push_back(start_background_child(
        {"/usr/bin/python3", script, out_dir, "--only", "fig1_calibration.png,green_vs_halfspace.png"}));
    if (scene.contact)
      figure_children.push_back(start_background_child(
          {"/usr/bin/python3", script, out_dir, "--except",
           std::string("fig1_calibration.png,green_vs_halfspace.png,pareto.png,post_design.png") +
               (k_figure_with_contact ? "" : ",k_sweep.png"),
           "--wait-for-go"},
          &contact_figures_go));
  };

  std::shared_ptr<ContactSetup> contact;
  std::optional<DefectRun> defect;
  std::optional<validation::Crosscheck> x;
  if (scene.contact) {
    contact = contact_setup(scene, std::move(factored));
    wall["condense"] = contact->wall["condense"];
    clock = Stopwatch();
    double force = 0;  // the chosen mode's; the run is dropped here, its set-up released with `contact`
    std::optional<contact::MeridianContactResult> meridian;  // frictionless, where the skin has one
    {
      const auto run = contact_stage(scene, contact, out_dir + "/contact", scene.contact->friction, "",
                                     meridian_check ? &*meridian_check : nullptr);
      report["contact"] = run.summary;
      force = run.result.result().force_N;
      if (run.result.meridian_check) meridian = run.result.meridian_check->frictionless;
    }
    wall["contact"] = clock.seconds();
    // Its volume solution was the chain's last solve: the rest works on the condensed contact and the
    // adjoints' maps, so the factorization (most of the peak) goes.
    skin->model->release_factorization();
    if (scene.contact->sweep) {
      clock = Stopwatch();
      // Every position's frame: the crosscheck convolves each one's tractions.
      defect = defect_stage(scene, contact, out_dir + "/defect", {}, pipeline::DefectFrames::every, !fast);
      wall["defect"] = clock.seconds();
      finish_kfit();
      clock = Stopwatch();
      x = crosscheck_run(scene, *adjoints, *contact, *defect, scene.contact->force.value_or(force),
                         headline->fe.k_lsq_line, meridian ? &*meridian : nullptr);
      write_crosscheck(*x, scene.sensors, out_dir + "/crosscheck");
      index.front = validation::front_sensor_answer(
          *x, validation::front_sensors(scene.sensors, contact_center(scene), scene.contact->direction),
          scene.contact->direction);
      report["front_sensors"] = front_sensor_json(*index.front);
      wall["crosscheck"] = clock.seconds();
      if (!fast) {
        clock = Stopwatch();
        auto budget = hole_budget_stage(scene, *contact, *x, out_dir + "/crosscheck",
                                        pipeline::paper_reading_scale(kf->result));
        report["hole_budget"] = std::move(budget.summary);
        index.budget = std::move(budget.result);
        wall["hole_budget"] = clock.seconds();
      }
    }
  }

  finish_kfit();
  if (!fast && error_scales.empty()) finish_k_sweep({});
  tell_background_child(contact_figures_go, "go");
  // Figures of the later stages (kfit/k_sweep.csv with the mesh levels, study/chain_study.csv,
  // green/post_design.csv) at the end.
  std::vector<std::string> late;
  if (!fast && !k_figure_with_contact) late.push_back("k_sweep.png");
  if (!error_scales.empty()) late.push_back("pareto.png");
  if (!fast) late.push_back("post_design.png");
  std::string late_figures;
  for (const std::string& name : late) late_figures += (late_figures.empty() ? "" : ",") + name;

  // Error bars: the chain's headline quantities on this mesh and on coarser ones (every mesh size scaled),
  // Richardson through the three finest. The coarse levels come after this level's memory is released.
  std::vector<validation::KSweepPoint> mesh_rows;
  std::vector<ChainLevel> levels;
  if (!error_scales.empty()) {
    clock = Stopwatch();
    const BlasThreads one(1);
    levels.push_back(chain_values(scene, *adjoints, contact.get()));
    // The defect run holds the contact set-up too (its solver, its condensed blocks): without it, the
    // paper's skin with posts kept 1.65 GB resident through the levels and peaked there, 350 MB above its
    // own chain.
    if (defect) defect->setup.reset();
    contact.reset();
    adjoints.reset();
    skin.reset();
    factored.skin.reset();  // without a contact it was never handed on
    release_freed_memory();
    std::vector<double> scales = error_scales;
    std::sort(scales.begin(), scales.end(), std::greater<>());
    for (size_t i = 0; i < scales.size(); ++i) {
      progress("error bars: level " + std::to_string(i + 1) + " of " + std::to_string(scales.size()) +
               " (mesh sizes x" + fmt("%g", scales[i]) + ")");
      levels.insert(levels.end() - 1, chain_level(scene, scales[i]));
    }
    report["chain_study"] = write_chain_study(scene, levels, out_dir + "/study");
    report["chain_study"].erase("scene");
    index.error_bars = error_bars(chain_errors(levels), scales);
    index.levels = &levels;
    index.exponents = time_vs_dofs_exponent(levels);
    report["error_bars"] = error_bars_json(index.error_bars);
    for (const ChainLevel& l : levels) mesh_rows.push_back({"mesh_scale", l.scale, l.value[0], l.value[1]});
    wall["error_levels"] = clock.seconds();
  }
  if (!error_scales.empty()) finish_k_sweep(mesh_rows);

  clock = Stopwatch();
  StageOutput<pipeline::PostDesign> post;
  if (!fast) {
    post = post_design_stage(scene, out_dir + "/green");
    report["post_design"] = post.summary;
    if (post.summary.contains("answer")) {
      index.post = &post.result;
      index.post_answer = post.summary["answer"];
    }
    wall["post_design"] = clock.seconds();
  } else {
    std::vector<std::string> out{"error bars (the coarser levels)"};
    if (scene.contact && scene.contact->sweep)
      out.insert(out.end(), {"the hole-signal budget of hypotheses", "the defect sweep's VTK frames"});
    out.push_back("the post design sweep");
    out.push_back("the k sweep (which protocol reading gives the paper's k)");
    if (scene.geometry.kind == GeometryKind::cap)
      out.push_back("the cap's effective-thickness fits (kfit.json)");
    for (size_t i = 0; i < out.size(); ++i)
      index.left_out += (i == 0 ? "" : i + 1 < out.size() ? ", " : " and ") + out[i];
    report["fast"] = {{"left_out", index.left_out}};
  }

  clock = Stopwatch();
  progress(late_figures.empty() ? "figures: the end of those drawn beside"
                                : "figures: the last ones, and the end of the others");
  int stopped_by = 0, rc = 0;
  if (!late_figures.empty())
    rc = run_child({"/usr/bin/python3", script, out_dir, "--only", late_figures}, &stopped_by);
  if (stopped_by != 0)
    for (const int child : figure_children) kill(child, stopped_by);
  for (const int child : figure_children)
    if (const int c = wait_background_child(child); rc == 0) rc = c;
  if (stopped_by != 0) {
    std::fprintf(stderr,
                 "skinfem: report: stopped by signal %d (%s) while drawing the figures; report.json and "
                 "index.html not written\n",
                 stopped_by, strsignal(stopped_by));
    return 128 + stopped_by;
  }
  report["figures_exit_code"] = rc;
  wall["figures"] = clock.seconds();

  report["scene"] = scene_json(scene);
  report["wall_s"] = wall;
  report["wall_beside_s"] = beside;
  report["wall_total_s"] = index.wall_total_s = total.seconds();
  report["peak_rss_mb"] = index.peak_rss_mb = peak_rss_mb();
  report["units"] = {{"length", "mm"}, {"force", "N"}, {"stress", "kPa in tables and CSV, MPa in the model"}};
  write_json(out_dir + "/report.json", report);
  index.dofs = dofs;
  index.wall = &wall;
  index.wall_beside = &beside;
  index.x = x ? &*x : nullptr;
  write_index(out_dir, scene, index);
  std::printf("report %s: %d DOFs, one factorization for the chain%s; %.1f s, peak %.0f MB\n",
              scene.name.c_str(), dofs,
              index.error_bars.empty()
                  ? ""
                  : (" and " + std::to_string(error_scales.size()) + " coarser for the error bars").c_str(),
              total.seconds(), peak_rss_mb());
  for (const ErrorBar& e : index.error_bars)
    std::printf("  %s: %s%s%s (%s)\n", e.what.c_str(), with_error(e.value, e.error).c_str(),
                e.unit.empty() ? "" : " ", e.unit.c_str(), e.method.c_str());
  if (!index.k_paper_answer.empty()) std::printf("  %s\n", index.k_paper_answer.c_str());
  if (index.front) std::printf("  %s\n", index.front->answer.c_str());
  if (rc != 0)
    std::printf("  figures: scripts/figures.py exited with %d; index.html lists the figures written\n", rc);
  if (!index.left_out.empty()) std::printf("  fast: left out the %s\n", index.left_out.c_str());
  // Where the time went, longest first.
  std::vector<std::pair<double, std::string>> stages;
  for (const auto& [stage, t] : wall.items()) stages.push_back({t.get<double>(), stage});
  std::sort(stages.rbegin(), stages.rend());
  std::string line;
  for (const auto& [t, stage] : stages) line += (line.empty() ? "" : ", ") + stage + " " + fmt("%.1f", t);
  std::printf("  seconds per stage: %s\n", line.c_str());
  line.clear();
  for (const auto& [stage, t] : beside.items())
    line += (line.empty() ? "" : ", ") + stage + " " + fmt("%.1f", t.get<double>());
  if (!line.empty()) std::printf("  beside them, on another thread: %s\n", line.c_str());
  std::printf("  wrote %s/index.html, report.json\n", out_dir.c_str());
  return 0;
}

}  // namespace skinfem::app
