// skinfem report — the main job: the whole chain on one mesh and one factorization, and the paper's
// convolution model checked against it assumption by assumption (validation/crosscheck.hpp).
//
//   $ skinfem report scenes/candelier2011.json
//   report candelier2011: 101342 DOFs, one factorization for the chain and 2 coarser for the error bars;
//   50.3 s, peak 1407 MB
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

// Which single change of the calibration protocol gives the paper's k (validation/k_sweep.hpp), with the
// FE k of sensor #1 per mesh scale (mesh_rows) as one more axis; writes DIR/k_sweep.csv and its report.json
// entry.
validation::KTargetAnswer k_paper_answer(const Scene& scene, double h,
                                         const std::vector<validation::KSweepPoint>& mesh_rows,
                                         const std::string& dir, nlohmann::json& entry) {
  validation::KProtocol base;
  base.h = h;
  base.nu = scene.material.nu;
  base.punch_diameter = scene.calibration.punch_diameter;
  const validation::KTargetAnswer a = validation::k_target_answer(base, mesh_rows, green::kPaperK);
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
  return a;
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
  nlohmann::json report, wall;
  // The meridian's frictionless contact, which checks the 3D one, is solved first: beside the 3D
  // factorization its own would add 35 MB to the report's peak.
  std::optional<pipeline::MeridianContactRun> meridian_check;
  if (scene.contact && pipeline::meridian_contact_unavailable(scene, FrictionMode::none, false).empty())
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
  // A half skin is shown, and its quality and volume checked, as the whole it stands for.
  const bool half = is_half_y(skin->mesh);
  const TetMesh mirrored = half ? mirror_half(skin->mesh) : TetMesh{};
  report["mesh"] =
      mesh_stage(scene, half ? mirrored : skin->mesh, skin->wall["mesh"].get<double>(), out_dir + "/mesh");

  Stopwatch clock;
  auto adjoints = adjoint_setup(scene, skin);
  wall["green_adjoints"] = adjoints->wall["adjoint_solves"];
  clock = Stopwatch();
  const SensorGreens greens = sensor_greens(scene, *adjoints);
  std::optional<MeridianCheck> axis_check;  // the green stage's, which kfit would otherwise solve again
  {
    auto green = green_stage(scene, greens, adjoints.get(), out_dir + "/green");
    report["green"] = std::move(green.summary);
    axis_check = green.result.meridian_check;
  }
  const auto kf = kfit_stage(scene, greens, out_dir + "/kfit", "punch", axis_check ? &*axis_check : nullptr);
  report["kfit"] = kf.summary;
  const pipeline::KfitSensor& headline = kf.result.sensors.at(0);
  wall["green_kfit_profiles"] = clock.seconds();

  IndexInput index;
  index.kfit_verdict = kf.result.verdict;
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
      clock = Stopwatch();
      x = crosscheck_run(scene, *adjoints, *contact, *defect, scene.contact->force.value_or(force),
                         headline.fe.k_lsq_line, meridian ? &*meridian : nullptr);
      write_crosscheck(*x, scene.sensors, out_dir + "/crosscheck");
      index.front = validation::front_sensor_answer(
          *x, validation::front_sensors(scene.sensors, contact_center(scene), scene.contact->direction),
          scene.contact->direction);
      report["front_sensors"] = front_sensor_json(*index.front);
      wall["crosscheck"] = clock.seconds();
      if (!fast) {
        clock = Stopwatch();
        auto budget = hole_budget_stage(scene, *contact, *x, out_dir + "/crosscheck",
                                        pipeline::paper_reading_scale(kf.result));
        report["hole_budget"] = std::move(budget.summary);
        index.budget = std::move(budget.result);
        wall["hole_budget"] = clock.seconds();
      }
    }
  }

  // The figures whose inputs are final are drawn from here on, beside the stages still to come; those of
  // the later stages (kfit/k_sweep.csv, study/chain_study.csv, green/post_design.csv) at the end.
  const std::string script = figures_script(), late_figures = "k_sweep.png,pareto.png,post_design.png";
  progress("figures: " + script + ", beside the stages to come");
  const int early_figures =
      start_background_child({"/usr/bin/python3", script, out_dir, "--except", late_figures});

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
  clock = Stopwatch();
  progress("k sweep: which protocol reading gives the paper's k");
  index.k_paper_answer =
      k_paper_answer(scene, headline.h_mm, mesh_rows, out_dir + "/kfit", report["k_paper"]).answer;
  wall["k_sweep"] = clock.seconds();

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
    index.left_out = "error bars (the coarser levels)";
    if (scene.contact && scene.contact->sweep)
      index.left_out += ", the hole-signal budget of hypotheses, the defect sweep's VTK frames";
    index.left_out += " and the post design sweep";
    report["fast"] = {{"left_out", index.left_out}};
  }

  clock = Stopwatch();
  progress("figures: the last ones, and the end of the others");
  int stopped_by = 0;
  const int rc_late = run_child({"/usr/bin/python3", script, out_dir, "--only", late_figures}, &stopped_by);
  if (stopped_by != 0) kill(early_figures, stopped_by);
  const int rc_early = wait_background_child(early_figures);
  const int rc = rc_early != 0 ? rc_early : rc_late;
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
  report["wall_total_s"] = index.wall_total_s = total.seconds();
  report["peak_rss_mb"] = index.peak_rss_mb = peak_rss_mb();
  report["units"] = {{"length", "mm"}, {"force", "N"}, {"stress", "kPa in tables and CSV, MPa in the model"}};
  write_json(out_dir + "/report.json", report);
  index.dofs = dofs;
  index.wall = &wall;
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
  std::printf("  %s\n", index.k_paper_answer.c_str());
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
  std::printf("  wrote %s/index.html, report.json\n", out_dir.c_str());
  return 0;
}

}  // namespace skinfem::app
