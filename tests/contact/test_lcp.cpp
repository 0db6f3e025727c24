// The dense contact complementarity solver (contact/lcp.hpp): exact against enumeration of every active set,
// force and depth control consistent, excluded multipliers, the low-rank sweep path against cold solves, and
// a discretised Boussinesq contact converging to Hertz.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "contact/lcp.hpp"

namespace skinfem::contact {
namespace {

// Every active set A of a small problem, its principal system solved; the LCP solution is the unique A
// with λ_A ≥ 0 and g ≥ 0 off A (P-matrix: exactly one).
Eigen::VectorXd enumerate(const Eigen::MatrixXd& M, const Eigen::VectorXd& q, const Eigen::VectorXd& m,
                          double F, int& solutions) {
  const int n = q.size();
  Eigen::VectorXd found;
  solutions = 0;
  for (int mask = 1; mask < (1 << n); ++mask) {
    std::vector<int> A;
    for (int i = 0; i < n; ++i)
      if (mask >> i & 1) A.push_back(i);
    const int k = A.size();
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(k + 1, k + 1);
    Eigen::VectorXd b(k + 1);
    for (int r = 0; r < k; ++r) {
      for (int c = 0; c < k; ++c) K(r, c) = M(A[r], A[c]);
      K(r, k) = -m[A[r]];
      K(k, r) = m[A[r]];
      b[r] = -q[A[r]];
    }
    b[k] = F;
    const Eigen::VectorXd x = K.fullPivLu().solve(b);
    Eigen::VectorXd lam = Eigen::VectorXd::Zero(n);
    for (int r = 0; r < k; ++r) lam[A[r]] = x[r];
    const Eigen::VectorXd g = M * lam + q - x[k] * m;
    bool ok = lam.minCoeff() > -1e-12;
    for (int i = 0; i < n; ++i)
      if (!(mask >> i & 1) && g[i] < -1e-12) ok = false;
    if (ok) ++solutions, found = lam;
  }
  return found;
}

TEST(ContactLcp, MatchesEnumerationForSymmetricAndNonSymmetricPMatrices) {
  std::mt19937 rng(3);
  std::normal_distribution<double> N;
  for (int trial = 0; trial < 100; ++trial) {
    const int n = 7;
    Eigen::MatrixXd B(n, n);
    for (int i = 0; i < n * n; ++i) B.data()[i] = N(rng);
    Eigen::MatrixXd M = B * B.transpose() + 0.5 * Eigen::MatrixXd::Identity(n, n);
    if (trial % 2) {  // positive definite non-symmetric (M + skew): a P-matrix, like coupled friction
      Eigen::MatrixXd S(n, n);
      for (int i = 0; i < n * n; ++i) S.data()[i] = 0.3 * N(rng);
      M += S - S.transpose();
    }
    Eigen::VectorXd q(n), m(n);
    for (int i = 0; i < n; ++i) q[i] = std::abs(N(rng)), m[i] = 0.5 + std::abs(N(rng));
    int solutions = 0;
    const Eigen::VectorXd expect = enumerate(M, q, m, 1.0, solutions);
    ASSERT_EQ(solutions, 1) << trial;
    const LcpSolution s = ContactLcp(M, q, m).solve_force(1.0);
    EXPECT_LT((s.lambda - expect).norm(), 1e-12 * expect.norm()) << trial;
    EXPECT_NEAR(m.dot(s.lambda), 1.0, 1e-12);
    EXPECT_LT(s.complementarity, 1e-14);
  }
}

// Discretised half-space (Boussinesq): cells of side s on a square grid, compliance between cell centres
// (1 − ν²)/(πE)·s²/r, self term that of a uniformly loaded square at its centre, (1 − ν²)/(πE)·4 s ln(1 + √2)
// (Johnson, Contact Mechanics §3.9). A sphere's gap r²/(2R): the solution tends to Hertz.
struct Grid {
  Eigen::MatrixXd M, X;
  Eigen::VectorXd q, m;
};
Grid boussinesq(int side, double s, double R, double E_star) {
  const int n = side * side;
  Grid g;
  g.X.resize(n, 2);
  for (int i = 0; i < n; ++i)
    g.X.row(i) << (i % side - 0.5 * (side - 1)) * s, (i / side - 0.5 * (side - 1)) * s;
  g.M.resize(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      g.M(i, j) = i == j ? 4 * s * std::log(1 + std::sqrt(2.0)) / (M_PI * E_star)
                         : s * s / (M_PI * E_star * (g.X.row(i) - g.X.row(j)).norm());
  g.M *= s * s;  // weighted gaps: per unit multiplier, gap integrated over the cell
  g.q = s * s * g.X.rowwise().squaredNorm().transpose() / (2 * R);
  g.m = Eigen::VectorXd::Constant(n, s * s);
  return g;
}

TEST(ContactLcp, DiscreteHalfSpaceTendsToHertz) {
  const double R = 10, E_star = 4, F = 0.5;
  const double a = std::cbrt(3 * F * R / (4 * E_star)), delta = a * a / R;  // Hertz: a = 1.05 mm
  std::vector<double> errors;
  for (double s : {0.4, 0.2, 0.1}) {
    const int side = static_cast<int>(std::ceil(3.0 * a / s)) | 1;
    const Grid g = boussinesq(side, s, R, E_star);
    const LcpSolution sol = ContactLcp(g.M, g.q, g.m).solve_force(F);
    errors.push_back(std::abs(sol.delta / delta - 1));
    EXPECT_LT(sol.complementarity, 1e-14);
  }
  // The indentation converges to Hertz's (collocation of 1/r between cell centres is first order at the
  // contact edge): the error falls at every halving of the cell, by at least 4× over two, and the finest grid
  // (10 cells per contact radius) is within 1 %.
  EXPECT_LT(errors[1], errors[0]);
  EXPECT_LT(errors[2], errors[1]);
  EXPECT_LT(errors[2], 0.25 * errors[0]);
  EXPECT_LT(errors[2], 0.01);
  std::printf("discrete Boussinesq indentation error vs Hertz: %.2e %.2e %.2e\n", errors[0], errors[1],
              errors[2]);
}

TEST(ContactLcp, ForceAndDepthControlAgreeAndExcludedCellsCarryNothing) {
  const Grid g = boussinesq(21, 0.15, 10, 4);
  const ContactLcp lcp(g.M, g.q, g.m);
  std::vector<char> hole(g.q.size(), 0);
  for (int i = 0; i < g.q.size(); ++i) hole[i] = std::hypot(g.X(i, 0) - 0.3, g.X(i, 1)) < 0.25;
  const LcpSolution f = lcp.solve_force(0.5, hole);
  for (int i = 0; i < g.q.size(); ++i)
    if (hole[i]) {
      EXPECT_EQ(f.lambda[i], 0.0);
    }
  EXPECT_LT(f.gap.minCoeff(), 0.0);  // the hole's cells would penetrate: no constraint there
  const LcpSolution d = lcp.solve_depth(f.delta, hole);
  EXPECT_LT((d.lambda - f.lambda).norm(), 1e-10 * f.lambda.norm());
  EXPECT_NEAR(g.m.dot(d.lambda), 0.5, 1e-10);
}

// A hole swept across: the reference-inverse path with warm starts equals cold dense solves.
TEST(ContactLcp, LowRankSweepEqualsColdSolves) {
  const Grid g = boussinesq(25, 0.12, 10, 4);
  Eigen::MatrixXd M = g.M;
  for (int i = 0; i < M.rows(); ++i)  // a smooth non-symmetric coupling, as with friction
    for (int j = 0; j < M.cols(); ++j) M(i, j) += 0.2 * g.M(i, j) * std::tanh(g.X(i, 0) - g.X(j, 0));
  ContactLcp fast(M, g.q, g.m);
  const LcpSolution base = fast.solve_force(0.5);
  fast.set_reference(base.active);
  std::vector<int> warm = base.active;
  for (double cx = -1.2; cx <= 1.2; cx += 0.3) {
    std::vector<char> hole(g.q.size(), 0);
    for (int i = 0; i < g.q.size(); ++i) hole[i] = std::hypot(g.X(i, 0) - cx, g.X(i, 1)) < 0.25;
    const LcpSolution a = fast.solve_force(0.5, hole, warm);
    const LcpSolution b = ContactLcp(M, g.q, g.m).solve_force(0.5, hole);
    warm = a.active;
    EXPECT_EQ(a.active, b.active) << cx;
    EXPECT_LT((a.lambda - b.lambda).norm(), 1e-10 * b.lambda.norm()) << cx;
    EXPECT_LT(a.complementarity, 1e-14);
  }
}

TEST(ContactLcp, EverythingExcludedIsAnError) {
  const Grid g = boussinesq(5, 0.2, 10, 4);
  EXPECT_THROW(ContactLcp(g.M, g.q, g.m).solve_force(0.5, std::vector<char>(25, 1)), std::runtime_error);
}

}  // namespace
}  // namespace skinfem::contact
