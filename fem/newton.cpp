#include "skinfem/fem/newton.hpp"

#include <cmath>
#include <optional>
#include <stdexcept>

#include "skinfem/fem/finite_strain.hpp"

namespace skinfem {

namespace {

struct State {
  Eigen::VectorXd u, p;
};

// The residual of equilibrium at a state, scaled: the free rows of f − internal force over the load's
// scale, and the constraint over the skin's volume (both dimensionless).
struct Residual {
  FiniteStrainSystem system;
  Eigen::VectorXd r_u;
  double norm = 0;
};

Residual residual_at(const TetMesh& mesh, double mu, const std::vector<bool>& fixed, const State& s,
                     const Eigen::VectorXd& f, double force_scale, double volume,
                     FiniteStrainParts parts = FiniteStrainParts::residual_and_tangent) {
  Residual r{assemble_finite_strain(mesh, mu, s.u, s.p, parts), {}, 0};
  r.norm = equilibrium_residual(r.system, f, fixed, force_scale, volume, &r.r_u);
  return r;
}

struct Converged {
  NewtonStep step;
  FiniteStrainSystem system;  // at the converged state (its tangent may be empty)
};

// One step's Newton iteration from `s` to the load factor `lambda`; nullopt when it fails.
std::optional<Converged> newton(const TetMesh& mesh, double mu, const std::vector<bool>& fixed,
                                const Eigen::VectorXd& f_full, const Eigen::VectorXd& u_fixed_full,
                                double lambda, double force_scale, double volume, const NewtonOptions& o,
                                State& s, MixedSolver::Reuse& factors) {
  const Eigen::VectorXd f = lambda * f_full;
  // The prescribed values are imposed by the first iteration's increment; the state moves there through
  // the solve, not by a jump that could fold the elements next to the held DOFs.
  Eigen::VectorXd du_fixed = Eigen::VectorXd::Zero(s.u.size());
  if (u_fixed_full.size())
    for (size_t d = 0; d < fixed.size(); ++d)
      if (fixed[d]) du_fixed[d] = lambda * u_fixed_full[d] - s.u[d];
  NewtonStep step;
  step.load_factor = lambda;
  std::optional<Residual> r;
  try {
    r = residual_at(mesh, mu, fixed, s, f, force_scale, volume);
  } catch (const std::domain_error&) {
    return std::nullopt;
  }
  const Lame incompressible{mu, 0.0};
  for (int it = 0; it <= o.max_iterations; ++it) {
    step.residuals.push_back(r->norm);
    if (r->norm <= o.tolerance && du_fixed.isZero()) return Converged{std::move(step), std::move(r->system)};
    if (it == o.max_iterations) return std::nullopt;
    MixedSolution dx;
    try {
      const MixedSolver solver(r->system.tangent, incompressible, fixed, SolverKind::direct_ldlt, 1e-9, {},
                               nullptr, &factors);
      dx = solver.solve(r->r_u, du_fixed, -r->system.constraint);
    } catch (const SolverError&) {
      return std::nullopt;
    }
    // Backtracking: the full step unless it folds an element or raises the residual. The prescribed
    // increment is taken whole on the first try only; later halvings keep it (it is part of the load).
    // The full step is usually taken, so it is assembled with its tangent; shorter trials with their
    // residual alone, and the tangent of the one taken is assembled when the iteration goes on.
    double alpha = 1;
    std::optional<Residual> next;
    for (int cut = 0; cut < 6 && !next; ++cut, alpha *= 0.5) {
      const State trial{s.u + alpha * dx.u, s.p + alpha * dx.p};
      try {
        const auto parts = cut == 0 ? FiniteStrainParts::residual_and_tangent : FiniteStrainParts::residual;
        Residual t = residual_at(mesh, mu, fixed, trial, f, force_scale, volume, parts);
        if (!du_fixed.isZero() || t.norm < r->norm) {
          s = trial;
          next = std::move(t);
          break;
        }
      } catch (const std::domain_error&) {
        if (!du_fixed.isZero()) return std::nullopt;  // the prescribed increment alone folds an element
      }
    }
    if (!next) return std::nullopt;
    step.line_steps.push_back(alpha);
    du_fixed.setZero();
    r = std::move(next);
    if (alpha < 1 && r->norm > o.tolerance && it + 1 < o.max_iterations)
      r = residual_at(mesh, mu, fixed, s, f, force_scale, volume);
  }
  return std::nullopt;
}

}  // namespace

FiniteStrainResult solve_finite_strain(const TetMesh& mesh, double mu, const std::vector<bool>& fixed,
                                       const Eigen::VectorXd& f, const Eigen::VectorXd& u_fixed,
                                       const NewtonOptions& o) {
  if (!(o.first_step > 0 && o.first_step <= 1))
    throw std::invalid_argument("NewtonOptions::first_step must be in (0, 1]");
  Eigen::VectorXd f_free = f;
  for (size_t d = 0; d < fixed.size(); ++d)
    if (fixed[d]) f_free[d] = 0;
  // The residual's scales: the load (or, under prescribed displacements alone, the force of the linear
  // response to them) and the skin's volume (∫ 1 = the sum of the pressure mass).
  const FiniteStrainSystem rest = assemble_finite_strain(
      mesh, mu, Eigen::VectorXd::Zero(3 * mesh.num_nodes()), Eigen::VectorXd::Zero(mesh.num_vertices));
  const double volume = rest.tangent.Mp.sum();
  double force_scale = f_free.norm();
  if (u_fixed.size() && force_scale == 0) {
    Eigen::VectorXd held = Eigen::VectorXd::Zero(u_fixed.size());
    for (size_t d = 0; d < fixed.size(); ++d)
      if (fixed[d]) held[d] = u_fixed[d];
    force_scale = (rest.tangent.A * held).norm();
  }
  if (force_scale == 0) force_scale = 1;

  FiniteStrainResult out;
  State s{Eigen::VectorXd::Zero(3 * mesh.num_nodes()), Eigen::VectorXd::Zero(mesh.num_vertices)};
  FiniteStrainSystem at;
  MixedSolver::Reuse factors;  // every tangent has the rest's pattern: one analysis for the whole path
  double reached = 0, step = o.first_step;
  const double smallest = o.first_step / std::pow(2.0, o.max_halvings);
  while (reached < 1) {
    const double target = std::min(1.0, reached + step);
    State trial = s;
    if (auto done =
            newton(mesh, mu, fixed, f_free, u_fixed, target, force_scale, volume, o, trial, factors)) {
      s = std::move(trial);
      reached = target;
      out.steps.push_back(std::move(done->step));
      at = std::move(done->system);
      // A step that converged quickly lets the next one grow back.
      if (out.steps.back().residuals.size() <= 5) step = std::min(1.0, 2 * step);
      continue;
    }
    ++out.rejected_steps;
    step *= 0.5;
    if (step < smallest)
      throw SolverError("finite strain: Newton failed to converge beyond load factor " +
                        std::to_string(reached) + " (steps down to " + std::to_string(2 * step) + ")");
  }
  out.solution.u = s.u;
  out.solution.p = s.p;
  out.solution.residual = out.steps.back().residuals.back();
  out.internal_force = at.internal_force;
  out.energy = at.energy;
  return out;
}

}  // namespace skinfem
