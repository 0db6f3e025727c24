// skinfem kfit — the k correction of the paper (§III (iii)), computed rather than quoted.
//
//   $ skinfem kfit scenes/flat_layer.json --out out/kfit
//   kfit flat_layer, headline sensor #1 of 1: h 3.040 mm, nu 0.5, punch load; meridian path (the unbounded
//   layer h = 3.04 mm (meridian radius 60.8 mm = 20 h, traction-free there)): 47027 DOFs, 1.08 s (...)
//     k_central 1.54995, k_lsq_line 1.60863 (exact layer: 1.54996, 1.60856); FE vs exact, ...
//
// Definitions and the fit: pipeline/kfit.hpp (also in docs/k_correction.md and kfit.json). The Green tensor
// comes from adjoint solves (reciprocity): on the meridian where the skin is a body of revolution with every
// sensor on its axis (pipeline/sensor_greens.hpp; --path auto, the default), else on the 3D mesh. Writes
// DIR/kfit.json.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "app/commands.hpp"
#include "app/common.hpp"
#include "app/stages.hpp"
#include "skinfem/pipeline/adjoint_setup.hpp"
#include "skinfem/pipeline/kfit.hpp"
#include "skinfem/pipeline/sensor_greens.hpp"

namespace skinfem::app {

using green::LayerLoad;

void write_kfit(const Scene& scene, const KfitResult& r, const nlohmann::json& file,
                const std::string& out_dir) {
  prepare_output_dir(out_dir);
  write_json(out_dir + "/kfit.json", file);
  const KfitSensor& first = r.sensors.at(0);
  std::printf(
      "kfit %s, headline sensor #1 of %zu: h %.3f mm, nu %.3g, %s load; %s path (%s): %d DOFs, %.2f s (mesh "
      "%.2f, "
      "assemble %.2f, factor %.2f, adjoint %.2f)\n",
      scene.name.c_str(), r.sensors.size(), first.h_mm, r.nu, r.load == LayerLoad::point ? "point" : "punch",
      r.path.c_str(), r.path_model.c_str(), r.dofs, r.wall.total(), r.wall.at("mesh"), r.wall.at("assemble"),
      r.wall.at("factor"), r.wall.at("adjoint_solves"));
  std::printf("  k_central %.5f, k_lsq_line %.5f", first.fe.k_central, first.fe.k_lsq_line);
  if (first.exact) {
    const auto& d = first.disc_max_diff_over_peak;
    std::printf(" (%s: %.5f, %.5f); %s max |difference| / peak: zz %.1e zx %.1e xz %.1e xx %.1e",
                r.ridged ? "the smooth exact layer of equal mean thickness"
                : r.post ? "the exact layer's disc reading"
                         : "exact layer",
                first.exact->k_central, first.exact->k_lsq_line,
                r.ridged ? "ridged vs smooth readings,"
                : r.post ? "post vs disc readings,"
                         : "FE vs exact,",
                d[0], d[1], d[2], d[3]);
  }
  std::printf("\n  %s\n", r.verdict.c_str());
  if (r.sensors.size() > 1) {
    const KfitRanges k = k_ranges(r);
    std::printf("  over all %zu sensors: k_central %.4f–%.4f, k_lsq_line %.4f–%.4f\n", r.sensors.size(),
                k.k_central[0], k.k_central[1], k.k_lsq_line[0], k.k_lsq_line[1]);
  }
  if (r.meridian_check) std::printf("  %s\n", meridian_check_line(*r.meridian_check).c_str());
  if (!r.explanation.empty()) std::printf("  %s\n", r.explanation.c_str());
  std::printf("  wrote %s/kfit.json\n", out_dir.c_str());
}

int run_kfit(const Scene& scene, const std::string& out_dir, const std::string& load_name, GreenPath path) {
  check_output_dir(out_dir);
  const KfitResult r =
      kfit(scene, green_path(scene, path), load_name == "point" ? LayerLoad::point : LayerLoad::punch);
  write_kfit(scene, r, kfit_json(r), out_dir);
  return 0;
}

}  // namespace skinfem::app
