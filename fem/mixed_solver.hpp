// Saddle-point solver for the Taylor–Hood system with Dirichlet displacement DOFs eliminated.
// It factors once per mesh and constraint set; every further load costs triangular solves.
//
// Two roads (docs/theory.md §Base tractions), selectable and compared by `skinfem study`:
//  - schur_cg:  CHOLMOD supernodal LLᵀ of the free displacement block A_ff, and preconditioned CG on
//               the pressure Schur complement S = B A⁻¹ Bᵀ + C with preconditioner (1/2μ + 1/λ) M_p
//               (spectrally equivalent to S for inf-sup stable pairs: mesh-independent iterations);
//  - direct_ldlt: MUMPS symmetric-indefinite LDLᵀ of the whole free saddle-point matrix, one
//               forward/back substitution per load.
#pragma once

#include <Eigen/Sparse>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "skinfem/fem/assembly.hpp"
#include "skinfem/fem/factor_progress.hpp"

namespace skinfem {

class MumpsLdlt;

enum class SolverKind { schur_cg, direct_ldlt };
const char* to_string(SolverKind kind);

// Thrown when a solve misses its tolerance or a factorization fails; never a silent result.
struct SolverError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct MixedSolution {
  Eigen::VectorXd u;    // 3N, mm
  Eigen::VectorXd p;    // Nv, MPa
  double residual = 0;  // ‖K x − b‖ / ‖b‖ of the full constrained system
  int iterations = 0;   // CG iterations (schur_cg), 0 for direct_ldlt
};

class MixedSolver {
 public:
  // Columns coupled to the system before it is factored, so that the one factorization also gives all
  // their products (MUMPS's Schur complement of the system bordered by them; direct_ldlt only). Column j is
  // a load F.col(j) (3N, free DOFs read) with prescribed values U_fixed.col(j) (3N, fixed DOFs read; U_fixed
  // may be empty).
  struct Coupling {
    Eigen::SparseMatrix<double> F, U_fixed;  // 3N × m each
    // The right-hand sides the caller would solve instead: where MUMPS's analysis says the bordered
    // factorization costs more than the plain one and these solves, the plain one is factored
    // (coupling_products() then empty; border_choice() says why). 0: always bordered.
    int solves_instead = 0;
    // The memory the bordered factorization may take, MB (MUMPS's estimate): above it the plain one, which
    // needs less, is factored whatever the flops say. 0: no bound.
    double memory_limit_mb = 0;
  };
  // The estimates the choice was made on (flops; a solve costs 4 flops per factor entry and right-hand side,
  // weighted by the factorization's rate over the solves', measured: mixed_solver.cpp), and the choice.
  struct BorderChoice {
    bool bordered = false;
    double bordered_flops = 0, plain_flops = 0, solve_flops = 0;  // estimates
    double bordered_mb = 0, plain_mb = 0;                         // MUMPS's memory estimates
    double memory_limit_mb = 0;                                   // Coupling::memory_limit_mb
    int solves = 0;                                               // Coupling::solves_instead
    bool cheaper() const { return bordered_flops < plain_flops + solve_flops; }
    bool fits() const { return memory_limit_mb <= 0 || bordered_mb <= memory_limit_mb; }
  };

  // A direct factorization handed from one solver to the next of a matrix with the same pattern (the
  // tangents of a Newton iteration: one mesh, one set of held DOFs, one coupling): the first analyses and
  // factors, each later one factors its own values on that analysis (MUMPS's ordering and symbolic
  // factorization, a fifth of the factor stage on the default scene's half), with the first one's border
  // choice. A solver takes it when built and gives it back when it goes: one solver at a time. A matrix of
  // another pattern is analysed afresh (and becomes the kept one).
  class Reuse {
   public:
    Reuse();
    ~Reuse();
    Reuse(const Reuse&) = delete;
    Reuse& operator=(const Reuse&) = delete;
    int analyses() const { return analyses_; }  // fresh analyses so far

   private:
    friend class MixedSolver;
    std::unique_ptr<MumpsLdlt> ldlt_;
    std::optional<BorderChoice> choice_;
    int border_ = 0;  // the kept factorization's border columns (0: the plain one)
    int analyses_ = 0;
  };

  // fixed: 3N flags, true where the displacement DOF is prescribed. Factors immediately; progress (may be
  // empty) hears from the direct_ldlt factorization every few seconds. reuse: see Reuse (direct_ldlt).
  MixedSolver(const MixedMatrices& matrices, const Lame& lame, const std::vector<bool>& fixed,
              SolverKind kind, double tolerance = 1e-10, const FactorProgress& progress = {},
              const Coupling* coupling = nullptr, Reuse* reuse = nullptr);
  // It keeps a reference to the matrices, which must outlive it (a temporary does not compile).
  MixedSolver(MixedMatrices&&, const Lame&, const std::vector<bool>&, SolverKind, double = 1e-10,
              const FactorProgress& = {}, const Coupling* = nullptr, Reuse* = nullptr) = delete;

  // The coupling's products, m × m (empty without a coupling): G(i, j) = F.col(i) · u_j over the free DOFs,
  // u_j = solve_block(F.col(j), U_fixed.col(j)). Between two loads it is their compliance, symmetric by
  // Maxwell–Betti; a load's entry on a column with prescribed values is that load's reading of its solution;
  // between two columns with prescribed values it reads nothing. mm/N per N (or the columns' units).
  const Eigen::MatrixXd& coupling_products() const;
  // With a coupling: the choice between the bordered and the plain factorization.
  const std::optional<BorderChoice>& border_choice() const;
  ~MixedSolver();

  // f: 3N load vector (entries at fixed DOFs ignored); u_fixed: 3N prescribed values (only fixed DOFs
  // read; pass an empty vector for zero); g: Nv right-hand side of the pressure rows, B u − C p = g (empty:
  // zero; a Newton step's constraint residual, fem/finite_strain.hpp). Throws SolverError if the relative
  // residual exceeds the tolerance.
  MixedSolution solve(const Eigen::VectorXd& f, const Eigen::VectorXd& u_fixed = {},
                      const Eigen::VectorXd& g = {}) const;

  // Displacements (3N×k) for k load vectors F (3N×k) and prescribed values U_fixed (3N×k, only fixed
  // DOFs read; empty for zero), solved as one block (direct_ldlt; schur_cg goes column by column).
  // Same residual check as solve(), on a weighted combination of the columns; `residual`, if given,
  // receives that combination's relative residual.
  Eigen::MatrixXd solve_block(const Eigen::MatrixXd& F, const Eigen::MatrixXd& U_fixed = {},
                              double* residual = nullptr) const;

  // Reactions at the fixed DOFs, K x − f restricted to them (3N vector, zero at free DOFs): the force
  // the supports exert on the body, N.
  Eigen::VectorXd reactions(const MixedSolution& x, const Eigen::VectorXd& f) const;

  // Frees the direct factorization (most of the solver's memory) once no more solves are coming: a caller
  // done with its solves keeps the solver's counts and choices. Any solve after it throws SolverError.
  void release_factorization();
  double factor_seconds() const { return factor_seconds_; }
  double factor_flops() const;  // the direct factorization's estimated flops (0 for schur_cg)
  int free_dofs() const;        // free displacement DOFs + pressure DOFs
  // Pressures coupled to no free displacement (all-held corner tets at ν = 0.5), fixed at 0.
  int pinned_pressures() const;
  SolverKind kind() const { return kind_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  SolverKind kind_;
  double factor_seconds_ = 0;
};

}  // namespace skinfem
