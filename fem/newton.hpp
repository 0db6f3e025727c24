// Equilibrium of the finite-strain skin (fem/finite_strain.hpp) under a dead load and prescribed
// displacements, by Newton–Raphson on the consistent tangent with load stepping: the load is applied in
// steps, each solved from the last converged state; a step whose Newton iteration fails (no decrease after
// a backtracking line search, an inverted element, or too many iterations) is halved and retried. Every
// iteration factors the tangent afresh (MUMPS LDLᵀ: the tangent is symmetric). Units: mm, N, MPa.
#pragma once

#include <string>
#include <vector>

#include "skinfem/fem/mixed_solver.hpp"

namespace skinfem {

struct NewtonOptions {
  double tolerance = 1e-10;  // relative residual: ‖r_u‖ over the load's scale, ‖c‖ over the volume
  int max_iterations = 20;   // per step
  double first_step = 1;     // the first step's share of the load, (0, 1]
  int max_halvings = 12;     // a step cut below first_step / 2^max_halvings is a failure
};

struct NewtonStep {
  double load_factor = 0;          // the share of the load this step reached
  std::vector<double> residuals;   // the relative residual before each iteration and at the end
  std::vector<double> line_steps;  // the line search's step length per iteration (1: a full step)
};

struct FiniteStrainResult {
  MixedSolution solution;          // u (3N, mm), p (Nv, MPa) at the full load
  Eigen::VectorXd internal_force;  // 3N at the solution: at fixed DOFs the supports' reactions (N)
  std::vector<NewtonStep> steps;   // converged steps, in order
  int rejected_steps = 0;          // steps halved and retried
  double energy = 0;               // ∫ W dV at the solution, N·mm
};

// fixed: 3N flags of prescribed DOFs; f: 3N dead load (entries at fixed DOFs ignored); u_fixed: 3N
// prescribed values at the full load (only fixed DOFs read; empty for zero). Throws SolverError (one line,
// the load factor reached and why) when no step size converges.
FiniteStrainResult solve_finite_strain(const TetMesh& mesh, double mu, const std::vector<bool>& fixed,
                                       const Eigen::VectorXd& f, const Eigen::VectorXd& u_fixed = {},
                                       const NewtonOptions& options = {});

}  // namespace skinfem
