// Refinement study of one normal-load scene: every mesh size (h_min, h_max, region sizes and the
// grading g − 1) is scaled by the same factor, so the whole mesh refines; the
// scene is solved with both saddle-point solvers, and each level reports DOFs, time per stage, time
// per extra right-hand side, memory and center_ratio (base traction below the load / 3F/(2πh²)).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "skinfem/fem/mixed_solver.hpp"
#include "skinfem/scene/scene.hpp"

namespace skinfem {

struct SolverTiming {
  SolverKind kind;
  double factor_s = 0;
  double first_solve_s = 0;  // the scene's load, punches included (one solve per punch + one)
  double extra_rhs_s = 0;    // one more right-hand side on the same factorization
  double residual = 0;
  int iterations = 0;  // CG iterations of the extra right-hand side (schur_cg)
  double rss_mb = 0;   // resident memory right after the factorization
};

struct StudyLevel {
  double scale = 1;  // multiplies every mesh size of the scene
  int nodes = 0, elements = 0, dofs = 0;
  double mesh_s = 0, assemble_s = 0;
  std::vector<SolverTiming> solvers;
  double center_ratio = 0;
  double force_balance_rel = 0;
};

struct StudyResult {
  std::vector<StudyLevel> levels;
  // Observed order of center_ratio from successive differences (levels ≥ 3), and the Richardson
  // estimate of its limit and of the finest level's error.
  std::vector<double> observed_order;
  double extrapolated = 0, finest_error_estimate = 0;
  // Flat layers: the exact layer value (Hankel transforms) for the same load profile — the half-space
  // rigid-punch pressure for a punch, uniform for a patch — with each level's error and the observed
  // order fitted by least squares over all levels.
  std::optional<double> exact;
  std::vector<double> error_vs_exact;
  double order_vs_exact = 0;
};

StudyResult refinement_study(const Scene& scene, const std::vector<double>& scales,
                             const std::vector<SolverKind>& solvers,
                             const std::function<void(const std::string&)>& progress = {});

double current_rss_mb();

}  // namespace skinfem
