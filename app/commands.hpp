// One function per subcommand; each returns the process exit code.
#pragma once

#include <string>
#include <vector>

#include "skinfem/fem/mixed_solver.hpp"
#include "skinfem/pipeline/inversion.hpp"
#include "skinfem/pipeline/perception.hpp"
#include "skinfem/pipeline/sensor_greens.hpp"
#include "skinfem/scene/scene.hpp"
#include "skinfem/scene/sweep.hpp"

namespace skinfem::app {

int run_mesh(const Scene& scene, const std::string& out_dir);
int run_solve(const Scene& scene, const std::string& out_dir, SolverKind solver);
int run_green(const Scene& scene, const std::string& out_dir, double grid_dx, pipeline::GreenPath path);
int run_kfit(const Scene& scene, const std::string& out_dir, const std::string& load,
             pipeline::GreenPath path);
int run_contact(const Scene& scene, const std::string& out_dir, const std::string& friction,
                pipeline::GreenPath path);
// error_scales: coarser mesh levels (every size × s, s > 1) for the error bars (defect: of the largest
// sliding signal; report: of the headline numbers); empty: none.
int run_defect(const Scene& scene, const std::string& out_dir, const std::vector<double>& error_scales);
// superpose: also the holes one at a time (the linear prediction).
int run_scan(const Scene& scene, const std::string& out_dir, bool superpose);
int run_perceive(const Scene& scene, const std::string& out_dir, const pipeline::PerceptionOptions& options);
// signals_path: scan.csv's columns; case_name: the rows of that case when the file has a case column;
// dictionary_dir: an earlier invert's output directory whose dictionary to reuse ("" builds it).
int run_invert(const Scene& scene, const std::string& signals_path, const std::string& out_dir,
               const pipeline::InversionOptions& options, const std::string& case_name,
               const std::string& dictionary_dir);
// fast: without the error bars' levels, the hypothesis budget and the post design sweep.
int run_report(const Scene& scene, const std::string& out_dir, const std::vector<double>& error_scales,
               bool fast = false);
int run_study(const Scene& scene, const std::string& out_dir, const std::vector<double>& scales);
// per_period: mesh elements per ridge period on the pattern, one level each (at least 3).
int run_ridge_study(const Scene& scene, const std::string& out_dir, std::vector<double> per_period);
// A parameter sweep (scene/sweep.hpp) on Snakemake: `cores` locally, or through a Snakemake `profile` (a
// cluster) when it is not empty; dry_run writes the members and the manifest only. out_dir empty:
// out/<sweep name>.
int run_sweep(const std::string& spec_path, const std::string& out_dir, int cores, const std::string& profile,
              bool dry_run);
int run_chain_study(const Scene& scene, const std::string& out_dir, const std::vector<double>& scales);

}  // namespace skinfem::app
