// Symmetric-indefinite sparse LDLᵀ with pivoting (MUMPS 5, sequential; PORD ordering, approximate minimum
// fill below 5000 unknowns: mumps_ldlt.cpp): factor once, then each right-hand side costs one forward/back
// substitution. Not copyable; not thread-safe.
#pragma once

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <memory>
#include <vector>

#include "skinfem/fem/factor_progress.hpp"

namespace skinfem {

class MumpsLdlt {
 public:
  // K: symmetric matrix; only its lower triangle is read. Throws std::runtime_error on failure
  // (with MUMPS's INFOG(1) code: −9/−13 out of memory, −10 singular). progress (may be empty) is called
  // every `every_s` seconds during the factorization phase, and once at its end.
  explicit MumpsLdlt(const Eigen::SparseMatrix<double>& K, const FactorProgress& progress = {},
                     double every_s = 5);
  // The lower triangle (row ≥ col, 0-based) as coordinate arrays, taken over so that no second copy of a
  // large matrix is alive while MUMPS factors it. n: the matrix's order.
  struct Triplets {
    std::vector<int> row, col;
    std::vector<double> value;
  };
  MumpsLdlt(int n, Triplets lower, const FactorProgress& progress = {}, double every_s = 5);
  // The last `schur_size` unknowns kept out of the factorization (MUMPS ICNTL(19)): it factors the leading
  // block A₁₁ only, returns the Schur complement S = A₂₂ − A₂₁ A₁₁⁻¹ A₁₂ (schur(), dense, symmetric), and
  // solve() solves A₁₁ x = b (b of order n − schur_size). With factor_now false only MUMPS's analysis runs
  // (ordering, symbolic factorization): analysis() says what factoring would cost, factor() factors.
  // leading_order (optional, n − schur_size long): the leading block's pivot order, each unknown's 0-based
  // position (pivot_order() of the leading block analysed alone); else MUMPS orders it.
  MumpsLdlt(int n, Triplets lower, int schur_size, const FactorProgress& progress = {}, double every_s = 5,
            bool factor_now = true, const std::vector<int>& leading_order = {});
  static Triplets lower_triangle(const Eigen::SparseMatrix<double>& K);
  // MUMPS's quasi-dense approximate-minimum-degree pivot order (ICNTL(7) = 6; deterministic) of the leading
  // n × n block of the matrix whose lower triangle is `lower` (entries beyond it ignored): a leading_order
  // for a Schur factorization, which MUMPS would order by its own minimum degree, filling more (on
  // hertz_layer's meridian 4.37 M factor entries against 2.94 M; SuiteSparse's AMD gives 3.45 M).
  static std::vector<int> min_degree_order(int n, const Triplets& lower);
  struct Estimate {
    double flops = 0;           // RINFOG(1)
    double factor_entries = 0;  // INFOG(20)
    double memory_mb = 0;       // INFOG(17)
  };
  Estimate analysis() const;
  // Throws as the constructor does (also when the estimated memory exceeds what is available).
  void factor(const FactorProgress& progress = {}, double every_s = 5);
  // Keeps the analysed pattern after factoring (its index arrays, 8 bytes an entry), so that
  // refactor() may factor new values on the same analysis. Call before factor().
  void keep_pattern();
  // The matrix's new values, factored on the analysis already done (no ordering, no symbolic factorization:
  // a Newton iteration's tangent, whose pattern does not change). `lower` must have the analysed pattern,
  // entry for entry (throws std::invalid_argument otherwise, or std::logic_error without keep_pattern());
  // the factors, and a Schur complement, are then those of the new values. Throws as factor() does.
  void refactor(Triplets lower, const FactorProgress& progress = {}, double every_s = 5);
  // Whether the first `entries` of lower are the kept pattern, entry for entry (refactor() takes them).
  bool same_pattern(const Triplets& lower, size_t entries) const;
  ~MumpsLdlt();
  MumpsLdlt(const MumpsLdlt&) = delete;
  MumpsLdlt& operator=(const MumpsLdlt&) = delete;

  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
  // Many right-hand sides at once (B: n×k, dense): MUMPS blocks them (ICNTL(27)), so each column costs
  // far less than a separate solve. Same results as column-by-column solves up to round-off.
  // B is taken by value and overwritten with the solution: move a block in to hold it once.
  Eigen::MatrixXd solve(Eigen::MatrixXd B) const;
  const Eigen::MatrixXd& schur() const;  // schur_size × schur_size (empty without a Schur complement)
  double factor_entries() const;         // entries in the factors (INFOG(29))
  std::vector<int> pivot_order() const;  // each unknown's 0-based position in the analysis's pivot order
  double estimated_flops() const;        // the analysis's estimate of the factorization's flops (RINFOG(1))
  // The analysis's estimate of the factorization's memory, MB (INFOG(17)); construction refuses (throws)
  // when it exceeds the machine's available memory.
  double estimated_memory_mb() const;

 private:
  void factor_locked(const FactorProgress& progress, double every_s);
  // icntl7 < 0: the automatic choice (the public constructors).
  MumpsLdlt(int n, Triplets lower, int schur_size, const FactorProgress& progress, double every_s,
            bool factor_now, const std::vector<int>& leading_order, int icntl7);
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace skinfem
