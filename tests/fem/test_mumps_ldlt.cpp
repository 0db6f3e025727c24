// MUMPS LDLᵀ: the factorization's flop estimate against the dense closed form n³/3, and the progress it
// reports while factoring (fem/factor_progress.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "skinfem/fem/mumps_ldlt.hpp"

namespace skinfem {
namespace {

// Dense SPD matrix stored sparse: n·I plus the Hilbert matrix.
Eigen::SparseMatrix<double> dense_spd(int n) {
  std::vector<Eigen::Triplet<double>> t;
  for (int j = 0; j < n; ++j)
    for (int i = j; i < n; ++i) t.emplace_back(i, j, (i == j ? n : 0) + 1.0 / (1 + i + j));
  Eigen::SparseMatrix<double> K(n, n);
  K.setFromTriplets(t.begin(), t.end());
  return K;
}

// 5-point Laplacian on an m×m grid (Dirichlet): SPD, sparse, factors in a fraction of a second.
Eigen::SparseMatrix<double> laplacian(int m) {
  std::vector<Eigen::Triplet<double>> t;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) {
      const int k = j * m + i;
      t.emplace_back(k, k, 4.0);
      if (i > 0) t.emplace_back(k, k - 1, -1.0);
      if (j > 0) t.emplace_back(k, k - m, -1.0);
    }
  Eigen::SparseMatrix<double> K(m * m, m * m);
  K.setFromTriplets(t.begin(), t.end());
  return K;
}

TEST(MumpsLdlt, FlopEstimateOfADenseMatrixIsNCubedOverThree) {
  // LDLᵀ of a dense n×n matrix: Σ_k (n−k)² ≈ n³/3 multiply-adds plus lower-order terms (n²/2 + n/6 for the
  // multiplier scaling and the sums' remainder): the count lies in [n³/3, n³/3 (1 + 3/n)].
  const int n = 300;
  const MumpsLdlt ldlt(dense_spd(n));
  const double closed = static_cast<double>(n) * n * n / 3;
  EXPECT_GE(ldlt.estimated_flops(), closed);
  EXPECT_LE(ldlt.estimated_flops(), closed * (1 + 3.0 / n));
  // Its memory estimate holds at least the factor's n(n+1)/2 doubles.
  EXPECT_GE(ldlt.estimated_memory_mb(), n * (n + 1) / 2 * 8.0 / (1024 * 1024));
}

TEST(MumpsLdlt, ProgressRisesBelowOneThenEndsAtOne) {
  std::vector<FactorStatus> calls;
  const auto K = laplacian(300);
  const MumpsLdlt ldlt(
      K, [&](const FactorStatus& s) { calls.push_back(s); }, 1e-3);
  ASSERT_FALSE(calls.empty());
  EXPECT_EQ(calls.back().fraction, 1.0);
  EXPECT_EQ(calls.back().estimated_flops, ldlt.estimated_flops());
  EXPECT_GT(calls.back().estimated_s, 0.0);
  for (size_t i = 0; i + 1 < calls.size(); ++i) {
    EXPECT_GE(calls[i].fraction, 0.0);
    EXPECT_LE(calls[i].fraction, 0.99);
    if (i > 0) {
      EXPECT_GE(calls[i].fraction, calls[i - 1].fraction);
    }
    EXPECT_LE(calls[i].elapsed_s, calls.back().elapsed_s);
  }
  // The factors still solve: K x = K·1 gives 1.
  const Eigen::VectorXd one = Eigen::VectorXd::Ones(K.rows());
  const Eigen::SparseMatrix<double> full = K.selfadjointView<Eigen::Lower>();
  EXPECT_LT((ldlt.solve(Eigen::VectorXd(full * one)) - one).norm(), 1e-10 * one.norm());
}

TEST(MumpsLdlt, FailedFactorizationNeverReportsDone) {
  // Two identical rows: singular. MUMPS refuses; the progress must not claim completion.
  std::vector<Eigen::Triplet<double>> t{{0, 0, 1.0}, {1, 0, 1.0}, {1, 1, 1.0}};
  Eigen::SparseMatrix<double> K(2, 2);
  K.setFromTriplets(t.begin(), t.end());
  std::vector<FactorStatus> calls;
  EXPECT_THROW(MumpsLdlt(
                   K, [&](const FactorStatus& s) { calls.push_back(s); }, 1e-3),
               std::runtime_error);
  for (const auto& c : calls) EXPECT_LT(c.fraction, 1.0);
}

// [K G; Gᵀ 0]'s lower triangle: K's, then G's columns as the last rows.
MumpsLdlt::Triplets bordered_lower(const Eigen::SparseMatrix<double>& K, const Eigen::MatrixXd& G) {
  const int n = static_cast<int>(K.rows());
  MumpsLdlt::Triplets t = MumpsLdlt::lower_triangle(K);
  for (int j = 0; j < G.cols(); ++j)
    for (int i = 0; i < n; ++i)
      if (G(i, j) != 0) t.row.push_back(n + j), t.col.push_back(i), t.value.push_back(G(i, j));
  return t;
}

TEST(MumpsLdlt, SchurComplementOfABorderedLaplacianIsTheDenseOne) {
  // [K G; Gᵀ 0] with K the Laplacian on a 40 × 40 grid and G five sparse columns: the Schur complement on
  // the last five unknowns is −Gᵀ K⁻¹ G, here against Eigen's dense LDLᵀ of K (a second method); the
  // interior solves are K's own.
  const int m = 40, n = m * m, s = 5;
  const Eigen::SparseMatrix<double> K = laplacian(m);
  Eigen::MatrixXd G = Eigen::MatrixXd::Zero(n, s);
  for (int j = 0; j < s; ++j)
    for (int k = 0; k < 7; ++k) G((37 * j + 211 * k) % n, j) = 1.0 + 0.1 * k - 0.3 * j;
  const MumpsLdlt ldlt(n + s, bordered_lower(K, G), s);
  const Eigen::MatrixXd full =
      Eigen::MatrixXd(Eigen::SparseMatrix<double>(K.selfadjointView<Eigen::Lower>()));
  const Eigen::LDLT<Eigen::MatrixXd> dense(full);
  const Eigen::MatrixXd expected = -G.transpose() * dense.solve(G);
  ASSERT_EQ(ldlt.schur().rows(), s);
  EXPECT_LT((ldlt.schur() - expected).cwiseAbs().maxCoeff(), 1e-12 * expected.cwiseAbs().maxCoeff());
  const Eigen::VectorXd one = Eigen::VectorXd::Ones(n);
  EXPECT_LT((ldlt.solve(Eigen::VectorXd(full * one)) - one).norm(), 1e-10 * one.norm());
  const Eigen::MatrixXd X = ldlt.solve(Eigen::MatrixXd(full * G));
  EXPECT_EQ(X.rows(), n);
  EXPECT_LT((X - G).norm(), 1e-10 * G.norm());
}

TEST(MumpsLdlt, BorderedMatrixTakesThePlainMatrixsPivotOrder) {
  // A Schur block makes MUMPS order by minimum degree whatever it is asked; the plain matrix's nested
  // dissection, the border last, is given instead (ICNTL(7) = 1). Same Schur complement as −Gᵀ K⁻¹ G by
  // solves of the plain factorization (a second method), and no more fill than MUMPS's own order.
  const int m = 90, n = m * m, s = 6;  // n above the size where MUMPS gets PORD
  const Eigen::SparseMatrix<double> K = laplacian(m);
  Eigen::MatrixXd G = Eigen::MatrixXd::Zero(n, s);
  for (int j = 0; j < s; ++j)
    for (int k = 0; k < 40; ++k) G((53 * j + 197 * k) % n, j) = 1.0 + 0.01 * k - 0.2 * j;
  MumpsLdlt plain(n, MumpsLdlt::lower_triangle(K), 0, {}, 5, false);
  const std::vector<int> order = plain.pivot_order();
  ASSERT_EQ(static_cast<int>(order.size()), n);
  EXPECT_THROW(MumpsLdlt(n + s, bordered_lower(K, G), s, {}, 5, false, std::vector<int>(n - 1, 0)),
               std::invalid_argument);
  const MumpsLdlt own(n + s, bordered_lower(K, G), s, {}, 5, false);
  const MumpsLdlt ordered(n + s, bordered_lower(K, G), s, {}, 5, true, order);
  EXPECT_LE(ordered.analysis().factor_entries, own.analysis().factor_entries);
  plain.factor();
  const Eigen::MatrixXd expected = -G.transpose() * plain.solve(G);
  EXPECT_LT((ordered.schur() - expected).cwiseAbs().maxCoeff(), 1e-12 * expected.cwiseAbs().maxCoeff());
  std::printf("bordered %d × %d grid: factor entries %.4g (own order) against %.4g (plain order)\n", m, m,
              own.analysis().factor_entries, ordered.analysis().factor_entries);
}

// A Newton iteration's tangents share one pattern: refactor() factors new values on the first analysis.
// Its factors and Schur complement are those of a fresh factorization of the new values (analysis and
// all), to the last bit: the analysis reads the pattern only. Another pattern is refused.
TEST(MumpsLdlt, RefactoredValuesSolveAsAFreshFactorizationToTheLastBit) {
  const int m = 80, n = m * m, s = 4;  // above the size where MUMPS gets PORD
  const Eigen::SparseMatrix<double> K1 = laplacian(m);
  Eigen::SparseMatrix<double> K2 = K1;
  for (int c = 0; c < K2.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(K2, c); it; ++it)
      it.valueRef() *= it.row() == it.col() ? 1.0 + 0.37 * std::sin(0.1 * c) : 0.9;
  Eigen::MatrixXd G = Eigen::MatrixXd::Zero(n, s);
  for (int j = 0; j < s; ++j)
    for (int k = 0; k < 30; ++k) G((41 * j + 173 * k) % n, j) = 1.0 + 0.02 * k - 0.25 * j;
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0);
  for (const int border : {0, s}) {
    const auto lower = [&](const Eigen::SparseMatrix<double>& K) {
      return border > 0 ? bordered_lower(K, G) : MumpsLdlt::lower_triangle(K);
    };
    MumpsLdlt kept(n + border, lower(K1), border, {}, 5, false);
    kept.keep_pattern();
    kept.factor();
    const Eigen::VectorXd x1 = kept.solve(b);
    kept.refactor(lower(K2));
    const MumpsLdlt fresh(n + border, lower(K2), border);
    const Eigen::VectorXd x2 = kept.solve(b);
    EXPECT_TRUE(x2 == fresh.solve(b)) << "border " << border;
    EXPECT_FALSE(x2 == x1);
    EXPECT_TRUE(kept.schur() == fresh.schur()) << "border " << border;
    MumpsLdlt::Triplets other = lower(K2);
    std::swap(other.row[1], other.row[2]);
    EXPECT_THROW(kept.refactor(other), std::invalid_argument);
  }
  MumpsLdlt unkept(n, MumpsLdlt::lower_triangle(K1));
  EXPECT_THROW(unkept.refactor(MumpsLdlt::lower_triangle(K2)), std::logic_error);
}

}  // namespace
}  // namespace skinfem
