// skinfem — finite-element verification toolkit for tactile sensors under an elastomer skin.
// Subcommands: mesh, solve, study, kfit, green, contact, defect, report, sweep (see each cmd_*.cpp for what
// it computes and writes). Exit codes: 0 success, 2 bad input (scene or arguments), 1 any other failure.
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdlib>
#include <iostream>

#include "app/commands.hpp"
#include "app/common.hpp"
#include "skinfem/mesh/surface.hpp"
#include "skinfem/pipeline/progress.hpp"
#include "skinfem/pipeline/resources.hpp"
#include "skinfem/scene/laws.hpp"
#include "skinfem/scene/load.hpp"

namespace {
// A number option's check: CLI11's PositiveNumber and NonNegativeNumber print DBL_MAX in 309 digits and call
// a subnormal "not in range". Says what the value is and what is allowed.
CLI::Validator number_check(bool strictly_positive) {
  return CLI::Validator(
      [strictly_positive](std::string& text) -> std::string {
        char* end = nullptr;
        const double v = std::strtod(text.c_str(), &end);
        if (text.empty() || end != text.c_str() + text.size()) return text + ": must be a number";
        if (!std::isfinite(v)) return text + ": must be a finite number";
        if (strictly_positive && !(v > 0)) return text + ": must be a number > 0";
        if (!strictly_positive && v < 0) return text + ": must be a number >= 0";
        return "";
      },
      strictly_positive ? "POSITIVE" : "NONNEGATIVE");
}
}  // namespace

int main(int argc, char** argv) {
  skinfem::pipeline::set_progress_sink(skinfem::app::progress);
  CLI::App cli{"skinfem: FE verification toolkit for biomimetic tactile sensors (units: mm, N, MPa)"};
  cli.require_subcommand(1);
  cli.set_version_flag(
      "--version", [] { return "skinfem " SKINFEM_VERSION "\nfigures: " + skinfem::app::figures_script(); },
      "print the version and the figure script the report runs, and exit");
  std::string scene_path, out_dir = "out";

  auto* mesh =
      cli.add_subcommand("mesh", "mesh the scene's skin (writes mesh.vtu, boundary.vtu, summary.json)");
  auto* solve =
      cli.add_subcommand("solve", "solve the scene's loads (writes fields.vtu, sensors.csv, summary.json)");
  std::string solver_name = "direct_ldlt";
  solve->add_option("--solver", solver_name, "saddle-point solver")
      ->check(CLI::IsMember({"direct_ldlt", "schur_cg"}))
      ->capture_default_str();
  auto* study = cli.add_subcommand(
      "study", "refinement study of the scene's load with both solvers (study.json, study.csv)");
  std::vector<double> scales{2.0, 1.41, 1.0};
  bool chain = false;
  study->add_flag(
      "--chain", chain,
      "the whole chain (Green maps and k, contact, hole sweep) per level: chain_study.csv, .json");
  std::vector<double> ridge_levels;
  study
      ->add_option(
          "--ridges", ridge_levels,
          "ridge study: mesh elements per ridge period, one level each (>= 3, e.g. 4,5,6,8): the ridged "
          "skin against the same mesh with 2 % ridges (ridge_study.json, .csv)")
      ->delimiter(',')
      ->check(number_check(true));
  study->add_option("--scales", scales, "factors applied to h_min and h_max, coarse to fine")
      ->delimiter(',')
      ->check(number_check(true))
      ->capture_default_str();
  auto* kfit = cli.add_subcommand("kfit", "fit the k correction of the Green tensor (kfit.json)");
  std::string load_name = "punch";
  kfit->add_option("--load", load_name, "calibration load model")
      ->check(CLI::IsMember({"punch", "point"}))
      ->capture_default_str();
  std::string path_name = "auto";
  auto* green_cmd =
      cli.add_subcommand("green", "FE Green tensors of every sensor (green.csv, green_maps.vtp)");
  double grid_dx = 0;
  green_cmd
      ->add_option(
          "--grid", grid_dx,
          "also each sensor's kernel on a regular grid of this spacing (mm) over the top: kernel.h5, "
          "kernel.vti")
      ->check(number_check(true));
  for (auto* sub : {kfit, green_cmd})
    sub->add_option(
           "--path", path_name,
           "Green tensor solver: meridian (2D axisymmetric; flat layers and a cap's apex sensor), 3d, "
           "or auto (the meridian where it applies)")
        ->check(CLI::IsMember({"auto", "3d", "meridian"}))
        ->capture_default_str();
  auto* contact_cmd = cli.add_subcommand(
      "contact",
      "rigid indenter in contact with the skin (pressure.vtp, fields.vtu, sensors.csv, summary.json)");
  std::string friction = "scene";
  std::vector<std::string> friction_choices{"scene"};
  for (const std::string& mode : skinfem::friction_mode_names()) friction_choices.push_back(mode);
  contact_cmd
      ->add_option("--friction", friction, "friction mode (default: the scene's contact.friction.mode)")
      ->check(CLI::IsMember(friction_choices))
      ->capture_default_str();
  contact_cmd
      ->add_option("--path", path_name,
                   "contact solver: meridian (2D axisymmetric: a flat layer or a cap's apex, the indenter on "
                   "its axis; frictionless and uncoupled modes), 3d, or auto (the meridian where every mode "
                   "contact reports is exact there)")
      ->check(CLI::IsMember({"auto", "3d", "meridian"}))
      ->capture_default_str();
  auto* defect = cli.add_subcommand(
      "defect", "hole swept through the contact, static and sliding (defect.csv, defect.pvd, summary.json)");
  auto* report = cli.add_subcommand(
      "report",
      "the whole chain on one factorization and the paper's model against it (index.html, report.json)");
  std::vector<double> error_scales{2.0, 1.41};
  bool no_error_bars = false;
  report
      ->add_option("--error-scales", error_scales,
                   "coarser levels (mesh sizes x s, s > 1) for the headline numbers' error bars")
      ->delimiter(',')
      ->capture_default_str();
  auto* no_bars =
      report->add_flag("--no-error-bars", no_error_bars, "skip the coarser levels (no error bars)");
  bool fast = false;
  report
      ->add_flag(
          "--fast", fast,
          "headline numbers and the paper's figures only: no error bars, no hypothesis budget, no post "
          "design sweep (the page says what it left out)")
      ->excludes(no_bars);
  defect
      ->add_option("--error-scales", error_scales,
                   "coarser levels (mesh sizes x s, s > 1) for the largest sliding signal's error bar")
      ->delimiter(',')
      ->capture_default_str();
  defect->add_flag("--no-error-bars", no_error_bars, "skip the coarser levels (no error bar)");
  auto* sweep = cli.add_subcommand("sweep",
                                   "a family of scenes from a sweep spec, one run per member on Snakemake "
                                   "(results.csv, results.h5, plots/)");
  std::string spec_path, profile;
  int cores = 1;
  bool dry_run = false;
  sweep->add_option("spec", spec_path, "sweep spec JSON file (format: scene/sweep.cpp, docs/sweeps.md)")
      ->required();
  sweep->add_option("--out", out_dir, "output directory (default: out/<sweep name>)");
  sweep->add_option("--cores", cores, "cores Snakemake may use on this machine, one per member job")
      ->check(CLI::Range(1, 4096))
      ->capture_default_str();
  sweep->add_option("--profile", profile, "a Snakemake profile (a cluster, e.g. sweeps/profiles/slurm)")
      ->excludes("--cores");
  sweep->add_flag("--dry-run", dry_run, "write the member scenes and the manifest, run nothing");
  double max_dofs = 0;
  for (auto* sub : {mesh, solve, study, kfit, green_cmd, contact_cmd, defect, report}) {
    sub->add_option(
           "--max-dofs", max_dofs,
           "refuse scenes whose estimated mesh exceeds this many DOFs (default: available memory only)")
        ->check(number_check(false));
    sub->add_option("scene", scene_path, "scene JSON file")->required();
    sub->add_option("--out", out_dir,
                    sub == report ? "output directory (default: out/<scene name>)" : "output directory")
        ->capture_default_str();
  }
  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return cli.exit(e);  // --help
    std::string names;
    bool known = false;
    for (const auto* sub : cli.get_subcommands({})) {
      names += (names.empty() ? "" : ", ") + sub->get_name();
      known = known || (argc > 1 && sub->get_name() == argv[1]);
    }
    if (argc > 1 && argv[1][0] != '-' && !known)
      std::cerr << "skinfem: unknown subcommand '" << argv[1] << "'; one of: " << names << std::endl;
    else
      std::cerr << "skinfem: " << e.what() << std::endl;
    return 2;
  }
  try {
    if (study->parsed()) {
      skinfem::app::check_levels("--scales", scales, true);
      skinfem::app::check_levels("--ridges", ridge_levels, false);
      for (double l : ridge_levels)
        if (l < 3)
          throw skinfem::SceneError("--ridges: " + std::to_string(l) +
                                    ": a level must give at least 3 mesh elements per ridge period");
    }
    if (fast && report->count("--error-scales"))
      throw skinfem::SceneError("--error-scales: --fast draws no error bars; give one or the other");
    if ((report->parsed() || defect->parsed()) && !no_error_bars && !fast)
      skinfem::app::check_levels("--error-scales", error_scales, true);
    if (sweep->parsed())
      return skinfem::app::run_sweep(spec_path, sweep->count("--out") ? out_dir : "", cores, profile,
                                     dry_run);
    skinfem::Scene scene = skinfem::load_scene(scene_path);
    scene.limits.max_dofs = max_dofs;
    const std::string command = cli.get_subcommands().front()->get_name();
    const std::string out = report->parsed() && !report->count("--out") ? "out/" + scene.name : out_dir;
    skinfem::app::check_output_dir(out);
    skinfem::app::check_run_record(out, command);
    const auto path = skinfem::pipeline::green_path_named(path_name);
    const auto run = [&]() -> int {
      if (mesh->parsed()) return skinfem::app::run_mesh(scene, out);
      const auto solver =
          solver_name == "schur_cg" ? skinfem::SolverKind::schur_cg : skinfem::SolverKind::direct_ldlt;
      if (solve->parsed()) return skinfem::app::run_solve(scene, out, solver);
      if (green_cmd->parsed()) return skinfem::app::run_green(scene, out, grid_dx, path);
      if (kfit->parsed()) return skinfem::app::run_kfit(scene, out, load_name, path);
      if (contact_cmd->parsed()) return skinfem::app::run_contact(scene, out, friction, path);
      if (defect->parsed())
        return skinfem::app::run_defect(scene, out, no_error_bars ? std::vector<double>{} : error_scales);
      if (study->parsed())
        return !ridge_levels.empty() ? skinfem::app::run_ridge_study(scene, out, ridge_levels)
               : chain               ? skinfem::app::run_chain_study(scene, out, scales)
                                     : skinfem::app::run_study(scene, out, scales);
      return skinfem::app::run_report(scene, out,
                                      no_error_bars || fast ? std::vector<double>{} : error_scales, fast);
    };
    const int rc = run();
    if (rc == 0) skinfem::app::write_run_record(out, command, scene);
    return rc;
  } catch (const skinfem::SceneError& e) {
    std::cerr << "skinfem: " << e.what() << std::endl;
    return 2;
  } catch (const skinfem::SolverError& e) {
    std::cerr << "skinfem: solver: " << e.what() << std::endl;
    return 1;
  } catch (const skinfem::MeshError& e) {
    std::cerr << "skinfem: mesh: " << e.what() << std::endl;
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "skinfem: " << e.what() << std::endl;
    return 1;
  }
  return 1;
}
