// skinfem study --ridges — how ridges change the Green tensor and k, with the discretization error
// cancelled: at each ridge resolution (period/L on the pattern) the ridged skin is meshed and solved, then
// the same mesh with its ridges scaled down to 2 % of their height (mesh/scale_ridges.hpp) is solved: the
// difference of the two is the ridges' effect on identical elements.
//
//   $ skinfem study scenes/ridged_layer.json --ridges 4,5,6,8 --out out/ridge_study
//   L 8 (ridge h 0.0275 mm): 348358 DOFs, 0 straightened, 155.3 s (mesh 1.2, factor 74.6 + 69.1), peak 5757
//   MB
//     k_central ridged 1.55432 control 1.54565: +0.561 %; k_lsq_line 1.60983 / 1.60368: +0.383 %
//     ...
//   k_central_change: +0.561 % ± 0.015 % (last change: the levels are not asymptotic; + 0.011 % for ...)
//
// Per level, sensor #1's calibration scan (the scene's punch, green/calibration.hpp) on both meshes:
// k_central, k_lsq_line, the peaks of the four components, their max |ridged − control| / peak over the scan
// (disc readings), DOFs, seconds per stage and peak memory; on a flat layer also the control mesh's k against
// the exact smooth layer (its own discretization error). The observed order and Richardson limit of each
// difference over the three finest levels (validation/richardson.hpp). Writes DIR/ridge_study.json and
// DIR/ridge_study.csv. The study is pipeline/ridge_study.hpp's; this file writes and prints it.
#include <cstdio>
#include <sstream>

#include "app/commands.hpp"
#include "app/common.hpp"
#include "skinfem/pipeline/ridge_study.hpp"

namespace skinfem::app {

namespace {

nlohmann::json level_json(const RidgeLevel& l) {
  nlohmann::json jl = {{"per_period", l.per_period},
                       {"ridge_h_mm", l.ridge_h_mm},
                       {"dofs", l.dofs},
                       {"straightened_elements", l.straightened},
                       {"wall_s", {{"ridged", l.wall_ridged}, {"control", l.wall_control}}},
                       {"peak_rss_mb", l.peak_rss_mb},
                       {"k_central", {{"ridged", l.ridged.k_central}, {"control", l.control.k_central}}},
                       {"k_lsq_line", {{"ridged", l.ridged.k_lsq_line}, {"control", l.control.k_lsq_line}}},
                       {"k_central_change", l.k_central_change},
                       {"k_lsq_line_change", l.k_lsq_line_change}};
  for (size_t c = 0; c < 4; ++c) {
    const char* name = green::component_name(green::kComponents[c]);
    jl["peak_point_per_mm2"][name] = {{"ridged", l.peak_ridged[c]}, {"control", l.peak_control[c]}};
    jl["disc_max_diff_over_peak"][name] = l.disc_max_diff_over_peak[c];
  }
  if (l.exact_smooth) {
    jl["control_vs_exact"] = {{"k_central", l.control.k_central / l.exact_smooth->k_central - 1},
                              {"k_lsq_line", l.control.k_lsq_line / l.exact_smooth->k_lsq_line - 1}};
    jl["k_exact_smooth"] = {{"k_central", l.exact_smooth->k_central},
                            {"k_lsq_line", l.exact_smooth->k_lsq_line}};
  }
  return jl;
}

void print_level(const RidgeLevel& l) {
  const auto& d = l.disc_max_diff_over_peak;
  std::printf(
      "L %g (ridge h %.4f mm): %d DOFs, %d straightened, %.1f s (mesh %.1f, factor %.1f + %.1f), peak %.0f "
      "MB\n  k_central ridged %.5f control %.5f: %+.3f %%; k_lsq_line %.5f / %.5f: %+.3f %%\n"
      "  peaks zz %+.2f %%, zx %+.2f %%, xz %+.2f %%, xx %+.2f %%; max |ridged - control| / peak "
      "zz %.2f %%, zx %.2f %%, xz %.2f %%, xx %.2f %%\n",
      l.per_period, l.ridge_h_mm, l.dofs, l.straightened, l.wall_ridged.total() + l.wall_control.total(),
      l.mesh_s, l.wall_ridged.at("factor"), l.wall_control.at("factor"), l.peak_rss_mb, l.ridged.k_central,
      l.control.k_central, 100 * l.k_central_change, l.ridged.k_lsq_line, l.control.k_lsq_line,
      100 * l.k_lsq_line_change, 100 * l.peak_change[0], 100 * l.peak_change[1], 100 * l.peak_change[2],
      100 * l.peak_change[3], 100 * d[0], 100 * d[1], 100 * d[2], 100 * d[3]);
  std::fflush(stdout);
}

}  // namespace

int run_ridge_study(const Scene& scene, const std::string& out_dir, std::vector<double> per_period) {
  check_output_dir(out_dir);
  const RidgeStudy study = ridge_study(scene, std::move(per_period), print_level);

  nlohmann::json levels = nlohmann::json::array();
  std::ostringstream csv;
  csv << "per_period,ridge_h_mm,dofs,straightened,mesh_s,assemble_s,factor_s,adjoint_s,peak_rss_mb,"
         "k_central_ridged,k_central_control,k_lsq_line_ridged,k_lsq_line_control,diff_zz,diff_zx,"
         "diff_xz,diff_xx\n";
  for (const RidgeLevel& l : study.levels) {
    levels.push_back(level_json(l));
    const auto& w = l.wall_ridged;
    const auto& d = l.disc_max_diff_over_peak;
    csv << l.per_period << "," << l.ridge_h_mm << "," << l.dofs << "," << l.straightened << ","
        << w.at("mesh") << "," << w.at("assemble") << "," << w.at("factor") << "," << w.at("adjoint_solves")
        << "," << l.peak_rss_mb << "," << l.ridged.k_central << "," << l.control.k_central << ","
        << l.ridged.k_lsq_line << "," << l.control.k_lsq_line << "," << d[0] << "," << d[1] << "," << d[2]
        << "," << d[3] << "\n";
  }
  nlohmann::json limits;
  for (const RidgeLimit& lim : study.limits) {
    const validation::Richardson& R = lim.richardson;
    limits[lim.name] = {{"finest", lim.finest},
                        {"asymptotic", R.asymptotic},
                        {"order", R.order},
                        {"limit", R.limit},
                        {R.asymptotic ? "mesh_error_richardson" : "mesh_error_last_change", lim.mesh_error},
                        {"control_ridges_bound", lim.control_error},
                        {"error", lim.error()}};
    std::printf("%s: %+.3f %% ± %.3f %% (%s; + %.3f %% for the control's own ridges)\n", lim.name.c_str(),
                100 * lim.finest, 100 * lim.error(),
                R.asymptotic ? ("Richardson, observed order " + std::to_string(R.order).substr(0, 4)).c_str()
                             : "last change: the levels are not asymptotic",
                100 * lim.control_error);
  }
  prepare_output_dir(out_dir);
  write_json(out_dir + "/ridge_study.json",
             {{"scene", scene_json(scene)},
              {"sensor", 1},
              {"definitions",
               {{"change", "ridged / control - 1 on the same mesh, the control's ridges " +
                               std::to_string(kRidgeControl) + " x as high (mesh/scale_ridges.hpp)"},
                {"disc_max_diff_over_peak", "max over the scan of |ridged - control| / max |control|"}}},
              {"levels", levels},
              {"ridge_effect", limits}});
  write_text_atomic(out_dir + "/ridge_study.csv", csv.str());
  std::printf("wrote %s/ridge_study.json, ridge_study.csv\n", out_dir.c_str());
  return 0;
}

}  // namespace skinfem::app
