// skinfem — finite-element verification toolkit for tactile sensors under an elastomer skin.
// Subcommands: mesh, solve, study, kfit, green, contact, defect, scan, perceive, invert, report, sweep, with
// their options in the command table (scene/commands.cpp); each cmd_*.cpp says what it computes and writes.
// Exit codes: 0 success, 2 bad input (scene or arguments), 1 any other failure.
#include <CLI/CLI.hpp>
#include <functional>
#include <iostream>
#include <map>

#include "app/command_line.hpp"
#include "app/commands.hpp"
#include "app/common.hpp"
#include "skinfem/fem/blas_threads.hpp"
#include "skinfem/mesh/surface.hpp"
#include "skinfem/pipeline/progress.hpp"
#include "skinfem/pipeline/resources.hpp"
#include "skinfem/pipeline/skin_setup.hpp"
#include "skinfem/scene/load.hpp"

namespace {

using skinfem::Scene;
using skinfem::app::ParsedOptions;

// What a command of the table (scene/commands.cpp) runs: its checks of the options among themselves, before
// the scene is read, then its run on the scene. The sweep, which runs on a spec, is main's own case.
struct Handler {
  std::function<void(const ParsedOptions&)> check;
  std::function<int(const Scene&, const std::string& out, const ParsedOptions&)> run;
};

// --error-scales unless --no-error-bars or report's --fast leaves the error bars out.
std::vector<double> error_levels(const ParsedOptions& o) {
  const bool fast = o.has("fast") && o.flag("fast");
  return o.flag("no_error_bars") || fast ? std::vector<double>{} : o.numbers("error_scales");
}

const std::map<std::string, Handler>& handlers() {
  namespace app = skinfem::app;
  const auto none = [](const ParsedOptions&) {};
  const auto path = [](const ParsedOptions& o) {
    return skinfem::pipeline::green_path_named(o.text("path"));
  };
  const auto error_scales_check = [](const ParsedOptions& o) {
    if (o.has("fast") && o.flag("fast") && o.given("error_scales"))
      throw skinfem::SceneError("--error-scales: --fast draws no error bars; give one or the other");
    if (const std::vector<double> levels = error_levels(o); !levels.empty())
      app::check_levels("--error-scales", levels, true);
  };
  static const std::map<std::string, Handler> table{
      {"mesh",
       {none,
        [](const Scene& s, const std::string& out, const ParsedOptions&) { return app::run_mesh(s, out); }}},
      {"solve",
       {none,
        [](const Scene& s, const std::string& out, const ParsedOptions& o) {
          return app::run_solve(s, out,
                                o.text("solver") == "schur_cg" ? skinfem::SolverKind::schur_cg
                                                               : skinfem::SolverKind::direct_ldlt);
        }}},
      {"study",
       {[](const ParsedOptions& o) {
          app::check_levels("--scales", o.numbers("scales"), true);
          app::check_levels("--ridges", o.numbers("ridges"), false);
          for (double l : o.numbers("ridges"))
            if (l < 3)
              throw skinfem::SceneError("--ridges: " + std::to_string(l) +
                                        ": a level must give at least 3 mesh elements per ridge period");
        },
        [](const Scene& s, const std::string& out, const ParsedOptions& o) {
          return !o.numbers("ridges").empty() ? app::run_ridge_study(s, out, o.numbers("ridges"))
                 : o.flag("chain")            ? app::run_chain_study(s, out, o.numbers("scales"))
                                              : app::run_study(s, out, o.numbers("scales"));
        }}},
      {"kfit",
       {none, [path](const Scene& s, const std::string& out,
                     const ParsedOptions& o) { return app::run_kfit(s, out, o.text("load"), path(o)); }}},
      {"green",
       {none, [path](const Scene& s, const std::string& out,
                     const ParsedOptions& o) { return app::run_green(s, out, o.number("grid"), path(o)); }}},
      {"contact",
       {none,
        [path](const Scene& s, const std::string& out, const ParsedOptions& o) {
          return app::run_contact(s, out, o.text("friction"), path(o));
        }}},
      {"defect",
       {error_scales_check, [](const Scene& s, const std::string& out,
                               const ParsedOptions& o) { return app::run_defect(s, out, error_levels(o)); }}},
      {"scan",
       {none, [](const Scene& s, const std::string& out,
                 const ParsedOptions& o) { return app::run_scan(s, out, !o.flag("no_superposition")); }}},
      {"perceive",
       {none,
        [](const Scene& s, const std::string& out, const ParsedOptions& o) {
          skinfem::pipeline::PerceptionOptions p;
          p.noise.passages = static_cast<int>(o.number("passages"));
          p.noise.sigma_z_kPa = o.number("noise_z");
          p.noise.sigma_x_kPa = o.number("noise_x");
          p.sample_mm = o.number("sample_mm");
          p.scan_mm = o.number("scan_mm");
          p.scan_trials = static_cast<int>(o.number("scan_trials"));
          return app::run_perceive(s, out, p);
        }}},
      {"invert",
       {none,
        [](const Scene& s, const std::string& out, const ParsedOptions& o) {
          skinfem::pipeline::InversionOptions p;
          p.noise.passages = static_cast<int>(o.number("passages"));
          p.noise.sigma_z_kPa = o.number("noise_z");
          p.noise.sigma_x_kPa = o.number("noise_x");
          p.offset_range = o.number("offset_range");
          p.mode = o.text("case") == "static" ? skinfem::FrictionMode::static_residual
                                              : skinfem::FrictionMode::coupled;
          return app::run_invert(s, o.text("signals"), out, p, o.text("case"), o.text("dictionary"));
        }}},
      {"report",
       {error_scales_check,
        [](const Scene& s, const std::string& out, const ParsedOptions& o) {
          return app::run_report(s, out, error_levels(o), o.flag("fast"));
        }}},
  };
  return table;
}

}  // namespace

int main(int argc, char** argv) {
  skinfem::blas_threads_sleep_when_idle();
  skinfem::pipeline::set_progress_sink(skinfem::app::progress);
  CLI::App cli{"skinfem: FE verification toolkit for biomimetic tactile sensors (units: mm, N, MPa)"};
  cli.require_subcommand(1);
  cli.set_version_flag(
      "--version", [] { return "skinfem " SKINFEM_VERSION "\nfigures: " + skinfem::app::figures_script(); },
      "print the version and the figure script the report runs, and exit");
  const skinfem::app::CommandLine line(cli);
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
    const std::string command = line.command().name;
    const ParsedOptions& o = line.options();
    if (command == "sweep")
      return skinfem::app::run_sweep(o.text("spec"), o.given("out") ? o.text("out") : "",
                                     static_cast<int>(o.number("cores")), o.text("profile"),
                                     o.flag("dry_run"));
    const Handler& handler = handlers().at(command);
    handler.check(o);
    Scene scene = skinfem::load_scene(o.text("scene"));
    if (command != "mesh" && command != "solve" && command != "green" && command != "contact" &&
        command != "defect" && command != "report")
      skinfem::pipeline::require_linear(scene, command);
    scene.limits.max_dofs = o.number("max_dofs");
    // An --out without a default is out/<scene name>.
    const std::string out = o.given("out") || !o.text("out").empty() ? o.text("out") : "out/" + scene.name;
    skinfem::app::check_output_dir(out);
    skinfem::app::check_run_record(out, command);
    const int rc = handler.run(scene, out, o);
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
