// skinfem study — refinement study of the scene's normal load with both saddle-point solvers.
//
//   $ skinfem study scenes/flat_layer.json --scales 2,1.41,1 --out out/study
//   level  scale   DOFs   mesh_s asm_s | direct_ldlt factor solve extra | schur_cg ... | center_ratio
//
// For every level: DOFs, seconds per stage (mesh, assemble, factor, solve), seconds per extra
// right-hand side, resident memory after the factorization, residuals and CG iterations, and
// center_ratio with its change from the previous level; then the observed order and the Richardson
// limit. Writes DIR/study.json and DIR/study.csv.
#include <algorithm>
#include <cstdio>
#include <sstream>

#include "app/commands.hpp"
#include "app/common.hpp"
#include "skinfem/mesh/sizing.hpp"
#include "skinfem/pipeline/resources.hpp"
#include "skinfem/scene/load.hpp"
#include "skinfem/validation/refinement_study.hpp"

namespace skinfem::app {

int run_study(const Scene& scene, const std::string& out_dir, const std::vector<double>& scales) {
  check_output_dir(out_dir);
  // The study's levels are scaled_scene's (mesh/sizing.hpp).
  check_resources(scaled_scene(scene, *std::min_element(scales.begin(), scales.end())));
  for (double sc : scales)  // the coarsest levels must still fit their loads on the skin
    check_load_placement(scaled_scene(scene, sc), "--scales " + std::to_string(sc).substr(0, 6));
  const std::vector<SolverKind> solvers{SolverKind::direct_ldlt, SolverKind::schur_cg};
  const StudyResult study = refinement_study(scene, scales, solvers, progress);

  nlohmann::json levels = nlohmann::json::array();
  std::ostringstream csv;
  csv << "scale,nodes,elements,dofs,mesh_s,assemble_s,solver,factor_s,solve_s,extra_rhs_s,rss_mb,residual,"
         "iterations,center_ratio\n";
  std::printf("%6s %8s %8s %7s | %-11s %8s %8s %8s %8s | %-8s %8s %8s %8s %5s | %12s %10s\n", "scale", "DOFs",
              "mesh_s", "asm_s", "solver", "factor_s", "solve_s", "extra_s", "rss_MB", "solver", "factor_s",
              "solve_s", "extra_s", "iters", "center_ratio", "change");
  for (size_t i = 0; i < study.levels.size(); ++i) {
    const auto& L = study.levels[i];
    nlohmann::json jl = {{"scale", L.scale},
                         {"nodes", L.nodes},
                         {"elements", L.elements},
                         {"dofs", L.dofs},
                         {"center_ratio", L.center_ratio},
                         {"base_force_balance_rel", L.force_balance_rel},
                         {"wall_s", {{"mesh", L.mesh_s}, {"assemble", L.assemble_s}}}};
    if (i > 0) jl["center_ratio_change"] = L.center_ratio - study.levels[i - 1].center_ratio;
    std::printf("%6.3f %8d %8.2f %7.2f", L.scale, L.dofs, L.mesh_s, L.assemble_s);
    for (const auto& s : L.solvers) {
      jl["solvers"][to_string(s.kind)] = {{"factor_s", s.factor_s},       {"solve_s", s.first_solve_s},
                                          {"extra_rhs_s", s.extra_rhs_s}, {"rss_mb", s.rss_mb},
                                          {"residual", s.residual},       {"iterations", s.iterations}};
      std::printf(" | %-11s %8.2f %8.2f %8.3f %8.0f", to_string(s.kind), s.factor_s, s.first_solve_s,
                  s.extra_rhs_s, s.rss_mb);
      if (s.kind == SolverKind::schur_cg) std::printf(" %5d", s.iterations);

      csv << L.scale << "," << L.nodes << "," << L.elements << "," << L.dofs << "," << L.mesh_s << ","
          << L.assemble_s << "," << to_string(s.kind) << "," << s.factor_s << "," << s.first_solve_s << ","
          << s.extra_rhs_s << "," << s.rss_mb << "," << s.residual << "," << s.iterations << ","
          << L.center_ratio << "\n";
    }
    std::printf(" | %12.6f", L.center_ratio);
    if (i > 0) std::printf(" %+10.2e", L.center_ratio - study.levels[i - 1].center_ratio);
    std::printf("\n");
    levels.push_back(jl);
  }
  nlohmann::json summary = {{"scene", scene_json(scene)}, {"levels", levels}, {"peak_rss_mb", peak_rss_mb()}};
  if (!study.observed_order.empty()) {
    // Successive differences of unstructured, non-nested meshes are noisy; with an exact reference
    // (flat layers) the least-squares order against it below is the one to read.
    summary["center_ratio_observed_order"] = study.observed_order;
    summary["center_ratio_extrapolated"] = study.extrapolated;
    summary["center_ratio_finest_error_estimate"] = study.finest_error_estimate;
    std::printf("center_ratio: observed order from successive differences");
    for (double p : study.observed_order) std::printf(" %.2f", p);
    std::printf("; Richardson limit %.6f, finest level error ≈ %.1e\n", study.extrapolated,
                study.finest_error_estimate);
  }
  if (study.exact) {
    summary["center_ratio_exact_layer"] = *study.exact;
    summary["center_ratio_error_vs_exact"] = study.error_vs_exact;
    summary["center_ratio_order_vs_exact"] = study.order_vs_exact;
    std::printf("exact layer (Hankel, %s profile): %.6f; errors",
                scene.loads.punches.empty() ? "uniform" : "rigid-punch", *study.exact);
    for (double e : study.error_vs_exact) std::printf(" %+.2e", e);
    std::printf("; least-squares order %.2f\n", study.order_vs_exact);
  }
  prepare_output_dir(out_dir);
  write_text_atomic(out_dir + "/study.csv", csv.str());
  write_json(out_dir + "/study.json", summary);
  std::printf("  wrote %s/study.json, study.csv\n", out_dir.c_str());
  return 0;
}

}  // namespace skinfem::app
