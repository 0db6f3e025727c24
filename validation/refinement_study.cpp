#include "skinfem/validation/refinement_study.hpp"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <stdexcept>

#include "skinfem/fem/elastic_model.hpp"
#include "skinfem/green/layer_exact.hpp"
#include "skinfem/mesh/build.hpp"
#include "skinfem/mesh/sizing.hpp"
#include "skinfem/validation/load_metrics.hpp"

namespace skinfem {

namespace {
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

double current_rss_mb() {
  std::ifstream statm("/proc/self/statm");
  long pages = 0, resident = 0;
  statm >> pages >> resident;
  return resident * static_cast<double>(sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

StudyResult refinement_study(const Scene& base_scene, const std::vector<double>& scales,
                             const std::vector<SolverKind>& solvers,
                             const std::function<void(const std::string&)>& progress) {
  if (base_scene.loads.punches.empty() && base_scene.loads.patches.empty())
    throw std::invalid_argument("refinement study needs a load in the scene");
  if (const std::string why = center_ratio_unavailable(base_scene); !why.empty())
    throw std::invalid_argument("refinement study: no center_ratio to converge: " + why);
  StudyResult out;
  for (double scale : scales) {
    const Scene scene = scaled_scene(base_scene, scale);
    StudyLevel level;
    level.scale = scale;
    auto t0 = std::chrono::steady_clock::now();
    const TetMesh mesh = build_mesh(scene);
    level.mesh_s = seconds_since(t0);
    level.nodes = mesh.num_nodes();
    level.elements = mesh.num_tets();
    for (SolverKind kind : solvers) {
      if (progress) progress("level " + std::to_string(out.levels.size() + 1) + ": " + to_string(kind));
      const ElasticModel model(mesh, scene.material, scene.geometry.side, scene.loads.punches,
                               {kind, 1e-10, {}});
      SolverTiming timing{kind};
      timing.rss_mb = current_rss_mb();
      timing.factor_s = model.solver().factor_seconds();
      level.assemble_s = model.assemble_seconds();
      level.dofs = model.solver().free_dofs();
      Eigen::VectorXd f = Eigen::VectorXd::Zero(3 * mesh.num_nodes());
      for (const auto& patch : scene.loads.patches) f += model.patch_load(patch);
      t0 = std::chrono::steady_clock::now();
      const LoadCaseResult r = model.solve(f, scene.loads.punches);
      timing.first_solve_s = seconds_since(t0);
      timing.residual = r.solution.residual;
      // An extra load: a tangential unit patch at the load centre (a different right-hand side).
      const Vec2 c =
          scene.loads.punches.empty() ? scene.loads.patches[0].center : scene.loads.punches[0].center;
      const Eigen::VectorXd g = model.patch_load({c, 0.5, {1, 0, 0}, 1.0});
      t0 = std::chrono::steady_clock::now();
      timing.iterations = model.solver().solve(g).iterations;
      timing.extra_rhs_s = seconds_since(t0);
      level.solvers.push_back(timing);

      const LoadMetrics metrics = load_metrics(scene, mesh, r, BaseTraction(mesh, r.reactions));
      level.force_balance_rel = metrics.force_balance_rel;
      level.center_ratio = *metrics.center_ratio;
    }
    out.levels.push_back(level);
  }
  // Observed order from three consecutive levels: p = log(|c1 − c0| / |c2 − c1|) / log(s0 / s1).
  const auto& L = out.levels;
  for (size_t i = 2; i < L.size(); ++i) {
    const double d1 = L[i - 1].center_ratio - L[i - 2].center_ratio,
                 d2 = L[i].center_ratio - L[i - 1].center_ratio;
    out.observed_order.push_back(std::log(std::abs(d1 / d2)) / std::log(L[i - 1].scale / L[i].scale));
  }
  if (L.size() >= 2) {
    const double ratio = L[L.size() - 2].scale / L.back().scale;
    const double p = out.observed_order.empty() ? 2.0 : std::max(1.0, out.observed_order.back());
    const double d = L.back().center_ratio - L[L.size() - 2].center_ratio;
    out.finest_error_estimate = std::abs(d) / (std::pow(ratio, p) - 1);
    out.extrapolated = L.back().center_ratio + d / (std::pow(ratio, p) - 1);
  }
  if (base_scene.geometry.kind == GeometryKind::flat) {
    const double h = base_scene.geometry.flat.h;
    const bool punch = !base_scene.loads.punches.empty();
    const double a =
        0.5 * (punch ? base_scene.loads.punches[0].diameter : base_scene.loads.patches[0].diameter);
    const green::LayerGreen layer(h, base_scene.material.nu,
                                  punch ? green::LayerLoad::punch : green::LayerLoad::uniform, a);
    out.exact = layer.at(0, 0).zz / (3 / (2 * M_PI * h * h));
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (const auto& level : L) {
      out.error_vs_exact.push_back(level.center_ratio - *out.exact);
      const double x = std::log(level.scale), y = std::log(std::abs(out.error_vs_exact.back()));
      sx += x, sy += y, sxx += x * x, sxy += x * y;
    }
    const double n = L.size();
    if (L.size() >= 2) out.order_vs_exact = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  }
  return out;
}

}  // namespace skinfem
