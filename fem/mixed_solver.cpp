#include "skinfem/fem/mixed_solver.hpp"

#include <Eigen/CholmodSupport>
#include <Eigen/SparseCholesky>
#include <chrono>
#include <cmath>

#include "skinfem/fem/mumps_ldlt.hpp"

namespace skinfem {

const char* to_string(SolverKind kind) { return kind == SolverKind::schur_cg ? "schur_cg" : "direct_ldlt"; }

namespace {
// Rows/columns `keep` of M (a map old → new index, −1 dropped).
SparseMatrixd restrict(const SparseMatrixd& M, const std::vector<int>& row_map, int rows,
                       const std::vector<int>& col_map, int cols) {
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(M.nonZeros());
  for (int c = 0; c < M.outerSize(); ++c) {
    const int nc = col_map.empty() ? c : col_map[c];
    if (nc < 0) continue;
    for (SparseMatrixd::InnerIterator it(M, c); it; ++it) {
      const int nr = row_map.empty() ? static_cast<int>(it.row()) : row_map[it.row()];
      if (nr >= 0) t.emplace_back(nr, nc, it.value());
    }
  }
  SparseMatrixd R(rows, cols);
  R.setFromTriplets(t.begin(), t.end());
  return R;
}
}  // namespace

namespace {
// The factorization's flop rate over the solve phase's (64 right-hand sides a block), measured on the
// default scene's half (2 cores, OpenBLAS): 58 GF factored in 2.4 s, 515 right-hand sides of 50.1M factor
// entries (1.03e11 flops) in 5.3 s. It weights a solve's flops against a factorization's.
constexpr double kFactorOverSolveRate = 1.2;
}  // namespace

struct MixedSolver::Impl {
  const MixedMatrices& M;
  std::vector<int> free_index;  // 3N → free index or −1
  std::vector<int> free_dofs;   // free index → DOF
  std::vector<int> p_index;     // vertex → pressure unknown, −1 when pinned
  int nf = 0, np = 0, pinned_pressures = 0;
  double tolerance = 1e-10;
  double sigma = 1;   // 2μ, MPa: the unknowns' scale (residual_norm)
  SparseMatrixd Aff;  // schur_cg only: the direct path reads A_ff out of M.A (one copy of A, not two)
  SparseMatrixd Bf, C;
  // schur_cg
  Eigen::CholmodSupernodalLLT<SparseMatrixd> chol;
  Eigen::SimplicialLLT<SparseMatrixd> mass;  // the Schur preconditioner's M_p
  double precond_scale = 1;
  // direct_ldlt
  std::unique_ptr<MumpsLdlt> ldlt;
  double released_flops = 0;  // the factorization's, once released
  Eigen::MatrixXd coupling_products;
  std::optional<BorderChoice> border_choice;
  Reuse* reuse = nullptr;  // given the factorization back when the solver goes

  explicit Impl(const MixedMatrices& m) : M(m) {}

  // A_ff x, through the whole A when A_ff is not kept.
  Eigen::VectorXd apply_Aff(const Eigen::VectorXd& x) const {
    if (Aff.rows() == nf) return Aff * x;
    Eigen::VectorXd whole = Eigen::VectorXd::Zero(M.A.rows());
    for (int i = 0; i < nf; ++i) whole[free_dofs[i]] = x[i];
    const Eigen::VectorXd Ax = M.A * whole;
    Eigen::VectorXd out(nf);
    for (int i = 0; i < nf; ++i) out[i] = Ax[free_dofs[i]];
    return out;
  }

  // The system is solved in the scaled unknowns (σu, p), σ = 2μ: [A_ff/σ  B_fᵀ; B_f  −σC] [σu; p] =
  // [b; σg] has O(1) entries for any E, where the unscaled one spans E and 1/E (MUMPS fails beyond about
  // E ∈ [1e-5, 1e8] MPa unscaled). Its residual, ‖[A_ff u + B_fᵀ p − b; σ(B_f u − C p − g)]‖, is in force
  // units in both rows. us = σu, gs = σg.
  double residual_norm(const Eigen::VectorXd& us, const Eigen::VectorXd& p, const Eigen::VectorXd& bf,
                       const Eigen::VectorXd& gs) const {
    const Eigen::VectorXd r1 = apply_Aff(us) / sigma + Bf.transpose() * p - bf;
    const Eigen::VectorXd r2 = Bf * us - sigma * (C * p) - gs;
    return std::sqrt(r1.squaredNorm() + r2.squaredNorm());
  }
};

MixedSolver::Reuse::Reuse() = default;
MixedSolver::Reuse::~Reuse() = default;

MixedSolver::MixedSolver(const MixedMatrices& matrices, const Lame& lame, const std::vector<bool>& fixed,
                         SolverKind kind, double tolerance, const FactorProgress& progress,
                         const Coupling* coupling, Reuse* reuse)
    : impl_(new Impl(matrices)), kind_(kind) {
  if (coupling && kind != SolverKind::direct_ldlt)
    throw std::invalid_argument("MixedSolver: a coupling needs the direct_ldlt solver");
  if (reuse && kind != SolverKind::direct_ldlt)
    throw std::invalid_argument("MixedSolver: a kept factorization needs the direct_ldlt solver");
  const auto start = std::chrono::steady_clock::now();
  Impl& s = *impl_;
  s.tolerance = tolerance;
  const int n3 = matrices.A.rows();
  s.free_index.assign(n3, -1);
  for (int d = 0; d < n3; ++d)
    if (!fixed[d]) {
      s.free_index[d] = s.nf++;
      s.free_dofs.push_back(d);
    }
  // A pressure DOF coupled to no free displacement (a corner tet whose nodes are all held, possible
  // with fixed sides) is undetermined at ν = 0.5: pin it to 0. It only acts on held DOFs.
  const int nv = matrices.Mp.rows();
  std::vector<double> coupling_to_free(nv, 0.0);
  for (int c = 0; c < matrices.B.outerSize(); ++c)
    if (s.free_index[c] >= 0)
      for (SparseMatrixd::InnerIterator it(matrices.B, c); it; ++it)
        coupling_to_free[it.row()] += std::abs(it.value());
  s.p_index.assign(nv, -1);
  for (int q = 0; q < nv; ++q)
    if (coupling_to_free[q] > 0 || lame.inv_lambda > 0) s.p_index[q] = s.np++;
  s.pinned_pressures = nv - s.np;
  s.Bf = restrict(matrices.B, s.p_index, s.np, s.free_index, s.nf);
  const SparseMatrixd Mp = restrict(matrices.Mp, s.p_index, s.np, s.p_index, s.np);
  s.C = lame.inv_lambda * Mp;
  s.sigma = 2 * lame.mu;

  if (kind == SolverKind::schur_cg) {
    s.Aff = restrict(matrices.A, s.free_index, s.nf, s.free_index, s.nf);
    s.chol.compute(s.Aff);
    if (s.chol.info() != Eigen::Success)
      throw SolverError("CHOLMOD could not factor the displacement block (is every rigid motion fixed?)");
    s.mass.compute(Mp);
    if (s.mass.info() != Eigen::Success) throw SolverError("pressure mass matrix is singular");
    s.precond_scale = 1.0 / (1.0 / (2 * lame.mu) + lame.inv_lambda);
  } else {
    // Lower triangle of [A_ff/σ  Bᵀ; B  −σC] is all MUMPS reads, built straight into its arrays.
    MumpsLdlt::Triplets t;
    const size_t nnz = matrices.A.nonZeros() / 2 + s.nf + s.Bf.nonZeros() + s.C.nonZeros();
    t.row.reserve(nnz);
    t.col.reserve(nnz);
    t.value.reserve(nnz);
    const auto add = [&t](int r, int c, double v) {
      t.row.push_back(r);
      t.col.push_back(c);
      t.value.push_back(v);
    };
    for (int c = 0; c < matrices.A.outerSize(); ++c)
      if (const int fc = s.free_index[c]; fc >= 0)
        for (SparseMatrixd::InnerIterator it(matrices.A, c); it; ++it)
          if (const int fr = s.free_index[it.row()]; fr >= fc) add(fr, fc, it.value() / s.sigma);
    for (int c = 0; c < s.Bf.outerSize(); ++c)
      for (SparseMatrixd::InnerIterator it(s.Bf, c); it; ++it) add(s.nf + it.row(), c, it.value());
    for (int c = 0; c < s.C.outerSize(); ++c)
      for (SparseMatrixd::InnerIterator it(s.C, c); it; ++it)
        if (it.row() >= c) add(s.nf + it.row(), s.nf + c, -s.sigma * it.value());
    // The coupling borders the system: [K R; Rᵀ 0], R's columns the coupling's right-hand sides as solve()
    // lifts them. Its Schur complement is −Rᵀ K⁻¹ R, and Rᵢᵀ K⁻¹ R_j = σ F_iᵀ u_j for a load column i
    // (K is in the scaled unknowns (σu, p)).
    int m = coupling ? static_cast<int>(coupling->F.cols()) : 0;
    const size_t plain_entries = t.value.size();
    if (m > 0) {
      if (coupling->F.rows() != n3 ||
          (coupling->U_fixed.size() && (coupling->U_fixed.rows() != n3 || coupling->U_fixed.cols() != m)))
        throw std::invalid_argument(
            "MixedSolver: the coupling's columns are not 3N long, or F and U_fixed differ");
      std::vector<Eigen::Triplet<double>> r;
      for (int j = 0; j < m; ++j)
        for (SparseMatrixd::InnerIterator it(coupling->F, j); it; ++it)
          if (const int f = s.free_index[it.row()]; f >= 0) r.emplace_back(f, j, it.value());
      if (coupling->U_fixed.size()) {
        SparseMatrixd Uc = coupling->U_fixed;
        Uc.prune([&](int row, int, double) { return s.free_index[row] < 0; });
        const SparseMatrixd AU = matrices.A * Uc, BU = matrices.B * Uc;
        for (int j = 0; j < m; ++j) {
          for (SparseMatrixd::InnerIterator it(AU, j); it; ++it)
            if (const int f = s.free_index[it.row()]; f >= 0) r.emplace_back(f, j, -it.value());
          for (SparseMatrixd::InnerIterator it(BU, j); it; ++it)
            if (const int q = s.p_index[it.row()]; q >= 0) r.emplace_back(s.nf + q, j, -s.sigma * it.value());
        }
      }
      SparseMatrixd R(s.nf + s.np, m);
      R.setFromTriplets(r.begin(), r.end());
      for (int j = 0; j < m; ++j)
        for (SparseMatrixd::InnerIterator it(R, j); it; ++it)
          if (it.value() != 0) add(s.nf + s.np + j, static_cast<int>(it.row()), it.value());
    }
    // The kept analysis, where this matrix has its pattern (with its border, or the plain part alone).
    bool kept = false;
    if (reuse && reuse->ldlt_) {
      const size_t entries = reuse->border_ == 0 ? plain_entries : reuse->border_ == m ? t.value.size() : 0;
      if (reuse->ldlt_->same_pattern(t, entries)) {
        t.row.resize(entries);
        t.col.resize(entries);
        t.value.resize(entries);
        s.ldlt = std::move(reuse->ldlt_);
        s.border_choice = reuse->choice_;
        m = reuse->border_;
        s.reuse = reuse;
        kept = true;
      } else {
        reuse->ldlt_.reset();  // another pattern: analysed afresh below, and kept instead
      }
    }
    try {
      if (kept) {
        s.ldlt->refactor(std::move(t), progress);
      } else {
        if (m > 0) {
          // The plain matrix (the bordered one's leading entries) is analysed first: its PORD order, the
          // border appended last, orders the bordered matrix too (mumps_ldlt.cpp).
          MumpsLdlt::Triplets plain;
          plain.row.assign(t.row.begin(), t.row.begin() + plain_entries);
          plain.col.assign(t.col.begin(), t.col.begin() + plain_entries);
          plain.value.assign(t.value.begin(), t.value.begin() + plain_entries);
          auto unbordered = std::make_unique<MumpsLdlt>(s.nf + s.np, std::move(plain), 0, progress, 5, false);
          auto bordered = std::make_unique<MumpsLdlt>(s.nf + s.np + m, std::move(t), m, progress, 5, false,
                                                      unbordered->pivot_order());
          BorderChoice& c = s.border_choice.emplace();
          c.bordered = true;
          if (coupling->solves_instead > 0) {
            // Both analysed, the cheaper factored.
            const auto b = bordered->analysis(), p = unbordered->analysis();
            c.bordered_flops = b.flops, c.bordered_mb = b.memory_mb;
            c.plain_flops = p.flops, c.plain_mb = p.memory_mb;
            c.solves = coupling->solves_instead;
            c.solve_flops = kFactorOverSolveRate * 4 * p.factor_entries * c.solves;
            c.memory_limit_mb = coupling->memory_limit_mb;
            c.bordered = c.cheaper() && c.fits();
          }
          s.ldlt = c.bordered ? std::move(bordered) : std::move(unbordered);
          if (!c.bordered) m = 0;
        } else {
          s.ldlt = std::make_unique<MumpsLdlt>(s.nf + s.np, std::move(t), 0, progress, 5, false);
        }
        if (reuse) {
          s.ldlt->keep_pattern();
          ++reuse->analyses_;
          reuse->choice_ = s.border_choice;
          reuse->border_ = m;
          s.reuse = reuse;
        }
        s.ldlt->factor(progress);
      }
    } catch (const std::runtime_error& e) {
      throw SolverError(std::string("cannot factor the saddle-point matrix: ") + e.what());
    }
    if (m > 0) {
      s.coupling_products = -s.ldlt->schur() / s.sigma;
      if (!s.coupling_products.allFinite())
        throw SolverError("the coupling's Schur complement is not finite");
    }
  }
  factor_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

MixedSolver::~MixedSolver() {
  // The factors go back with the analysis (MUMPS 5.5 frees them only with it, JOB = −2): until the next
  // solver refactors, they stay beside the next tangent (the default scene's finite contact peaks 10 %
  // higher, 1.12 against 1.02 GB, and takes 13 % less time).
  if (impl_ && impl_->reuse && impl_->ldlt) impl_->reuse->ldlt_ = std::move(impl_->ldlt);
}

const Eigen::MatrixXd& MixedSolver::coupling_products() const { return impl_->coupling_products; }
const std::optional<MixedSolver::BorderChoice>& MixedSolver::border_choice() const {
  return impl_->border_choice;
}

void MixedSolver::release_factorization() {
  if (!impl_->ldlt) return;
  impl_->released_flops = impl_->ldlt->estimated_flops();
  impl_->ldlt.reset();
}

double MixedSolver::factor_flops() const {
  return impl_->ldlt ? impl_->ldlt->estimated_flops() : impl_->released_flops;
}

int MixedSolver::free_dofs() const { return impl_->nf + impl_->np; }
int MixedSolver::pinned_pressures() const { return impl_->pinned_pressures; }

MixedSolution MixedSolver::solve(const Eigen::VectorXd& f, const Eigen::VectorXd& u_fixed,
                                 const Eigen::VectorXd& g_given) const {
  const Impl& s = *impl_;
  const int n3 = s.M.A.rows();
  // Lift the prescribed values: b_f = f_f − A_fc u_c, g = g_given − B_c u_c.
  Eigen::VectorXd uc = Eigen::VectorXd::Zero(n3);
  if (u_fixed.size())
    for (int d = 0; d < n3; ++d)
      if (s.free_index[d] < 0) uc[d] = u_fixed[d];
  const Eigen::VectorXd Au = s.M.A * uc, Bu = s.M.B * uc;
  Eigen::VectorXd bf(s.nf);
  for (int i = 0; i < s.nf; ++i) bf[i] = f[s.free_dofs[i]] - Au[s.free_dofs[i]];
  Eigen::VectorXd g(s.np);
  for (size_t q = 0; q < s.p_index.size(); ++q)
    if (s.p_index[q] >= 0) g[s.p_index[q]] = g_given.size() ? g_given[q] - Bu[q] : -Bu[q];

  MixedSolution out;
  Eigen::VectorXd uf, p;
  if (kind_ == SolverKind::schur_cg) {
    // S p = B A⁻¹ b_f − g, then A u = b_f − Bᵀ p
    auto apply_S = [&](const Eigen::VectorXd& q) -> Eigen::VectorXd {
      return s.Bf * s.chol.solve(s.Bf.transpose() * q) + s.C * q;
    };
    const Eigen::VectorXd rhs = s.Bf * s.chol.solve(bf) - g;
    p = Eigen::VectorXd::Zero(s.np);
    Eigen::VectorXd r = rhs, z = s.mass.solve(r) * s.precond_scale, d = z;
    double rz = r.dot(z);
    const double rhs_norm = rhs.norm();
    // Stop well below the outer tolerance: the Schur residual is amplified by ‖Bᵀ‖ in the full system.
    const double cg_tol = 1e-3 * s.tolerance;
    int it = 0;
    while (rhs_norm > 0 && r.norm() > cg_tol * rhs_norm && it < 1000) {
      const Eigen::VectorXd Sd = apply_S(d);
      const double alpha = rz / d.dot(Sd);
      p += alpha * d;
      r -= alpha * Sd;
      z = s.mass.solve(r) * s.precond_scale;
      const double rz_new = r.dot(z);
      d = z + (rz_new / rz) * d;
      rz = rz_new;
      ++it;
    }
    out.iterations = it;
    uf = s.chol.solve(bf - s.Bf.transpose() * p);
  } else {
    if (!s.ldlt) throw SolverError("direct_ldlt solve after the factorization was released");
    Eigen::VectorXd b(s.nf + s.np);
    b << bf, s.sigma * g;
    const Eigen::VectorXd x = s.ldlt->solve(b);
    uf = x.head(s.nf) / s.sigma;
    p = x.tail(s.np);
  }
  // Residual of the full constrained system (scaled, residual_norm).
  const double bnorm = std::sqrt(bf.squaredNorm() + s.sigma * s.sigma * g.squaredNorm());
  out.residual = bnorm > 0 ? s.residual_norm(s.sigma * uf, p, bf, s.sigma * g) / bnorm : 0.0;
  if (!std::isfinite(out.residual) || out.residual > s.tolerance)
    throw SolverError(std::string(to_string(kind_)) + " solve missed its tolerance: relative residual " +
                      std::to_string(out.residual) + " > " + std::to_string(s.tolerance));
  out.u = uc;
  for (int i = 0; i < s.nf; ++i) out.u[s.free_dofs[i]] = uf[i];
  out.p = Eigen::VectorXd::Zero(s.p_index.size());
  for (size_t q = 0; q < s.p_index.size(); ++q)
    if (s.p_index[q] >= 0) out.p[q] = p[s.p_index[q]];
  return out;
}

Eigen::MatrixXd MixedSolver::solve_block(const Eigen::MatrixXd& F, const Eigen::MatrixXd& U_fixed,
                                         double* residual) const {
  const Impl& s = *impl_;
  const int n3 = s.M.A.rows(), k = F.cols();
  // The prescribed values on the held rows, zero elsewhere: the solution's frame.
  const auto held = [&] {
    Eigen::MatrixXd U = Eigen::MatrixXd::Zero(n3, k);
    if (U_fixed.size())
      for (int d = 0; d < n3; ++d)
        if (s.free_index[d] < 0) U.row(d) = U_fixed.row(d);
    return U;
  };
  if (kind_ == SolverKind::schur_cg) {
    Eigen::MatrixXd U = held();
    double worst = 0;
    for (int j = 0; j < k; ++j) {
      const MixedSolution x = solve(F.col(j), U.col(j));
      U.col(j) = x.u;
      worst = std::max(worst, x.residual);
    }
    if (residual) *residual = worst;
    return U;
  }
  if (!s.ldlt) throw SolverError("direct_ldlt block solve after the factorization was released");
  // Lift the prescribed values as in solve(): b_f = f_f − A_fc u_c, g = −B_c u_c; rows of g scaled by σ.
  Eigen::MatrixXd b = Eigen::MatrixXd::Zero(s.nf + s.np, k);
  for (int j = 0; j < k; ++j)  // column by column: the blocks are column-major and large
    for (int i = 0; i < s.nf; ++i) b(i, j) = F(s.free_dofs[i], j);
  if (U_fixed.size()) {
    // A U and B U over the held columns whose values are not all 0 (a few hundred of the 3N): the sums
    // Eigen's sparse products would form, term by term in the same order, without their 3N × k blocks.
    std::vector<int> a_slot(n3, -1), b_slot(s.M.B.rows(), -1);
    std::vector<int> a_rows, b_rows;
    std::vector<int> columns;
    for (int c = 0; c < n3; ++c) {
      if (s.free_index[c] >= 0 || (U_fixed.row(c).array() == 0).all()) continue;
      columns.push_back(c);
      for (SparseMatrixd::InnerIterator it(s.M.A, c); it; ++it)
        if (a_slot[it.row()] < 0)
          a_slot[it.row()] = static_cast<int>(a_rows.size()), a_rows.push_back(it.row());
      for (SparseMatrixd::InnerIterator it(s.M.B, c); it; ++it)
        if (b_slot[it.row()] < 0)
          b_slot[it.row()] = static_cast<int>(b_rows.size()), b_rows.push_back(it.row());
    }
    Eigen::MatrixXd AU = Eigen::MatrixXd::Zero(a_rows.size(), k),
                    BU = Eigen::MatrixXd::Zero(b_rows.size(), k);
    for (const int c : columns) {
      for (SparseMatrixd::InnerIterator it(s.M.A, c); it; ++it)
        for (int j = 0; j < k; ++j) AU(a_slot[it.row()], j) += it.value() * U_fixed(c, j);
      for (SparseMatrixd::InnerIterator it(s.M.B, c); it; ++it)
        for (int j = 0; j < k; ++j) BU(b_slot[it.row()], j) += it.value() * U_fixed(c, j);
    }
    for (size_t r = 0; r < a_rows.size(); ++r)
      if (const int f = s.free_index[a_rows[r]]; f >= 0) b.row(f) -= AU.row(r);
    // Every pressure row set as −σ (B U) sets it: −σ · 0 = −0 in the rows no held column reaches.
    for (size_t q = 0; q < s.p_index.size(); ++q)
      if (s.p_index[q] >= 0) {
        if (b_slot[q] >= 0)
          b.row(s.nf + s.p_index[q]) = -s.sigma * BU.row(b_slot[q]);
        else
          b.row(s.nf + s.p_index[q]).setConstant(-s.sigma * 0.0);
      }
  }
  // The residual of every column would cost as much as the solve itself (a sparse product per column);
  // check one combination instead, Σ w_j x_j with w_j = c_j/‖b_j‖, c_j ∈ {1, 2, 3}: if every column meets
  // the tolerance, the combination meets tol·Σ c_j, and a failed factorization or solve (MUMPS's failure
  // modes: lost pivots, overflow) spoils every column alike, which no deterministic weighting cancels.
  Eigen::VectorXd w = Eigen::VectorXd::Zero(k);
  double bound = 0;
  for (int j = 0; j < k; ++j) {
    const double bnorm = b.col(j).norm();
    if (bnorm > 0) w[j] = (1 + j % 3) / bnorm, bound += 1 + j % 3;
  }
  const Eigen::VectorXd bw = b * w;
  const Eigen::MatrixXd x = s.ldlt->solve(std::move(b));  // b's block becomes x's
  if (!x.allFinite()) throw SolverError("direct_ldlt block solve returned non-finite values");
  const Eigen::VectorXd xw = x * w;
  const double res =
      bound > 0 ? s.residual_norm(xw.head(s.nf), xw.tail(s.np), bw.head(s.nf), bw.tail(s.np)) / bound : 0.0;
  if (!std::isfinite(res) || res > s.tolerance)
    throw SolverError("direct_ldlt block solve missed its tolerance: relative residual " +
                      std::to_string(res) + " > " + std::to_string(s.tolerance) +
                      " (weighted combination of " + std::to_string(k) + " columns)");
  if (residual) *residual = res;
  Eigen::MatrixXd U = held();  // allocated after the solve: one block fewer at the peak
  for (int j = 0; j < k; ++j)
    for (int i = 0; i < s.nf; ++i) U(s.free_dofs[i], j) = x(i, j) / s.sigma;
  return U;
}

Eigen::VectorXd MixedSolver::reactions(const MixedSolution& x, const Eigen::VectorXd& f) const {
  const Impl& s = *impl_;
  Eigen::VectorXd r = s.M.A * x.u + s.M.B.transpose() * x.p;
  for (int d = 0; d < r.size(); ++d) r[d] = s.free_index[d] < 0 ? r[d] - (f.size() ? f[d] : 0.0) : 0.0;
  return r;
}

}  // namespace skinfem
