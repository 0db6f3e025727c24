// The dense contact complementarity solver (contact/lcp.hpp): against enumeration of every active set
// (symmetric, non-symmetric positive definite, and P-matrices that are not positive definite), force and
// depth control consistent, excluded multipliers equal to the reduced problem, a discretised half-space
// converging to Hertz, a hole swept through the contact by the low-rank reference path against warm and cold
// dense solves (with timings), the non-symmetric coupled-friction case, and the failures.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "skinfem/contact/lcp.hpp"

namespace skinfem::contact {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kPi = 3.14159265358979323846;

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// The principal matrix of active set A, under force control bordered by σm, σ = max M_ii / max m (the
// solver's scaling of the unknown δ and of the force equation, lcp.hpp: it fixes the border's units).
MatrixXd principal_matrix(const MatrixXd& M, const VectorXd& m, const std::vector<int>& A, bool force) {
  const int k = static_cast<int>(A.size()), e = force ? 1 : 0;
  const double sigma = M.diagonal().cwiseAbs().maxCoeff() / m.maxCoeff();
  MatrixXd K = MatrixXd::Zero(k + e, k + e);
  for (int r = 0; r < k; ++r) {
    for (int c = 0; c < k; ++c) K(r, c) = M(A[r], A[c]);
    if (force) K(r, k) = -sigma * m[A[r]], K(k, r) = sigma * m[A[r]];
  }
  return K;
}

// Two solutions of the same principal system K (size k), each with backward error ≲ √k·ε (rounding errors
// of sums accumulate like √k ε: Higham & Mary, SIAM J. Sci. Comput. 41 (2019) A2815), differ by at most
// 2κ∞(K)√k·ε relative; ×4 for the refinement's residual. Tolerance on max|Δλ| / max λ.
double solve_tolerance(const MatrixXd& M, const VectorXd& m, const std::vector<int>& A, bool force) {
  const MatrixXd K = principal_matrix(M, m, A, force);
  if (K.rows() == 0) return 0.0;
  const double kappa = K.cwiseAbs().rowwise().sum().maxCoeff() *
                       K.partialPivLu().inverse().cwiseAbs().rowwise().sum().maxCoeff();
  return 8 * kappa * std::sqrt(static_cast<double>(K.rows())) * kEps;
}

double max_rel_diff(const VectorXd& a, const VectorXd& b) {
  return (a - b).cwiseAbs().maxCoeff() / std::max(b.cwiseAbs().maxCoeff(), 1e-300);
}

// Complementarity bound after one step of refinement: on the active set |g_i| is a residual, computed to
// γ_{n+2}(|M||λ| + |q| + |δ|m)_i, and the refined solution's own residual is of the same order; ×4 for both
// and the correction's error. Returns the bound on LcpSolution::complementarity.
double complementarity_bound(const MatrixXd& M, const VectorXd& q, const VectorXd& m, const LcpSolution& s) {
  const double n = static_cast<double>(q.size());
  const double gamma = (n + 2) * kEps / (1 - (n + 2) * kEps);
  const VectorXd size = M.cwiseAbs() * s.lambda.cwiseAbs() + q.cwiseAbs() + std::abs(s.delta) * m;
  const double g_scale = q.cwiseAbs().maxCoeff() + std::abs(s.delta) * m.maxCoeff();
  return 4 * gamma * size.maxCoeff() / g_scale;
}

// ---------------------------------------------------------------------------------------------------------
// 1. Enumeration of all 2^n active sets.

struct Enumerated {
  int solutions = 0;
  std::vector<int> active;
  VectorXd lambda;
  double margin = 0;  // min over the solution of λ_A and g off A, relative: how strictly complementary
};

Enumerated enumerate(const MatrixXd& M, const VectorXd& q, const VectorXd& m, bool force, double value) {
  const int n = static_cast<int>(q.size());
  Enumerated out;
  for (int mask = force ? 1 : 0; mask < (1 << n); ++mask) {
    std::vector<int> A;
    for (int i = 0; i < n; ++i)
      if (mask >> i & 1) A.push_back(i);
    const int k = static_cast<int>(A.size());
    const MatrixXd K = principal_matrix(M, m, A, force);
    VectorXd b(K.rows());
    for (int r = 0; r < k; ++r) b[r] = -q[A[r]] + (force ? 0.0 : value * m[A[r]]);
    const double sigma = M.diagonal().cwiseAbs().maxCoeff() / m.maxCoeff();
    if (force) b[k] = sigma * value;
    const VectorXd x = k + force > 0 ? VectorXd(K.fullPivLu().solve(b)) : VectorXd(0);
    VectorXd lambda = VectorXd::Zero(n);
    for (int r = 0; r < k; ++r) lambda[A[r]] = x[r];
    const double delta = force ? sigma * x[k] : value;
    const VectorXd g = M * lambda + q - delta * m;
    const double l_scale = std::max(lambda.maxCoeff(), 1e-300);
    const double g_scale = q.cwiseAbs().maxCoeff() + std::abs(delta) * m.maxCoeff();
    double margin = 1e300;
    for (int i = 0; i < n; ++i)
      margin = std::min(margin, (mask >> i & 1) ? lambda[i] / l_scale : g[i] / g_scale);
    if (margin > -1e-12) {
      ++out.solutions;
      out.active = A;
      out.lambda = lambda;
      out.margin = margin;
    }
  }
  return out;
}

bool all_principal_minors_positive(const MatrixXd& M) {
  const int n = static_cast<int>(M.rows());
  for (int mask = 1; mask < (1 << n); ++mask) {
    std::vector<int> A;
    for (int i = 0; i < n; ++i)
      if (mask >> i & 1) A.push_back(i);
    if (!(principal_matrix(M, VectorXd::Ones(n), A, false).determinant() > 0)) return false;
  }
  return true;
}

TEST(ContactLcp, MatchesEnumerationOfEveryActiveSet) {
  std::mt19937 rng(11);
  std::normal_distribution<double> N;
  int checked[3] = {0, 0, 0}, indefinite = 0;
  double max_tol = 0;
  for (int trial = 0; trial < 180; ++trial) {
    const int kind = trial % 3;  // 0 SPD, 1 non-symmetric positive definite, 2 P-matrix, not definite
    const int n = 1 + (trial / 3) % 10;
    MatrixXd B(n, n), S(n, n);
    for (int i = 0; i < n * n; ++i) B.data()[i] = N(rng), S.data()[i] = N(rng);
    MatrixXd M;
    if (kind < 2) {
      M = B * B.transpose() / n + MatrixXd::Identity(n, n);            // B Bᵀ + cI
      if (kind == 1) M += (S - S.transpose()) / std::sqrt(double(n));  // + skew: M + Mᵀ unchanged, ≻ 0
    } else {
      // Unit-diagonal lower triangle with large entries (a P-matrix whose symmetric part is indefinite) plus
      // a small upper part; kept only if every principal minor is positive.
      M = MatrixXd::Identity(n, n);
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
          if (i > j) {
            M(i, j) = 1.5 * B(i, j);
          } else if (i < j) {
            M(i, j) = 0.1 * S(i, j);
          }
      if (!all_principal_minors_positive(M)) continue;
      indefinite += (M + M.transpose()).selfadjointView<Eigen::Lower>().eigenvalues().minCoeff() < 0;
    }
    VectorXd q(n), m(n);
    for (int i = 0; i < n; ++i) q[i] = N(rng), m[i] = 0.5 + std::abs(N(rng));
    // Force control is only claimed for M + Mᵀ ≻ 0 (lcp.hpp); depth control for every P-matrix.
    for (const bool force : {true, false}) {
      if (force && kind == 2) continue;
      const double value = force ? 1.0 : 0.7;
      const Enumerated e = enumerate(M, q, m, force, value);
      ASSERT_EQ(e.solutions, 1) << "trial " << trial;  // a P-matrix: exactly one solution
      if (e.margin < 1e-8) continue;  // not strictly complementary: the active set is not well defined
      const ContactLcp lcp(M, q, m);
      const LcpSolution s = force ? lcp.solve_force(value) : lcp.solve_depth(value);
      EXPECT_EQ(s.active, e.active) << "trial " << trial << " force " << force;
      // Both solve the same principal system: max|Δλ| ≤ 8κ√(k+1)ε max λ, and these systems are conditioned
      // well enough (checked) for that bound to be below 1e-12.
      const double tol = solve_tolerance(M, m, e.active, force);
      ASSERT_LE(tol, 1e-12) << "trial " << trial;
      max_tol = std::max(max_tol, tol);
      EXPECT_LE(max_rel_diff(s.lambda, e.lambda), tol) << "trial " << trial;
      if (force) {
        EXPECT_NEAR(m.dot(s.lambda), value, tol * value);
      }
      EXPECT_LE(s.complementarity, complementarity_bound(M, q, m, s));
      ++checked[kind];
    }
  }
  // Enough cases of every kind were compared, and the third kind does contain indefinite P-matrices.
  EXPECT_GE(checked[0], 80);
  EXPECT_GE(checked[1], 80);
  EXPECT_GE(checked[2], 20);
  EXPECT_GE(indefinite, 10);
  std::printf("compared %d + %d + %d cases (%d indefinite P-matrices), largest tolerance %.1e\n", checked[0],
              checked[1], checked[2], indefinite, max_tol);
}

// Block exchanges cycle on M = I + aC (C the cyclic shift, a > 1): for odd n a P-matrix (proper principal
// submatrices are triangular with unit diagonal, det M = 1 + aⁿ) whose symmetric part is indefinite. Only
// Murty's single-index fallback gets out; the answer is still the enumerated one.
TEST(ContactLcp, MurtyFallbackSolvesWhereBlockExchangesCycle) {
  std::mt19937 rng(1);
  std::normal_distribution<double> N;
  int fallbacks = 0, cases = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const int n = 3 + 2 * (trial % 3);
    const double a = 1 + 3 * std::abs(N(rng));
    MatrixXd M = MatrixXd::Identity(n, n);
    for (int i = 0; i < n; ++i) M(i, (i + 1) % n) = a;
    VectorXd q(n);
    for (int i = 0; i < n; ++i) q[i] = N(rng);
    const VectorXd m = VectorXd::Ones(n);
    std::vector<int> warm;
    for (int i = 0; i < n; ++i)
      if (rng() % 2) warm.push_back(i);
    const Enumerated e = enumerate(M, q, m, false, 0.0);
    ASSERT_EQ(e.solutions, 1) << "trial " << trial;
    if (e.margin < 1e-8) continue;
    const LcpSolution s = ContactLcp(M, q, m).solve_depth(0.0, {}, warm);
    ++cases;
    fallbacks += s.single > 0;
    EXPECT_EQ(s.active, e.active) << "trial " << trial;
    const double tol = solve_tolerance(M, m, e.active, false);
    ASSERT_LE(tol, 1e-12);
    EXPECT_LE(max_rel_diff(s.lambda, e.lambda), tol) << "trial " << trial;
  }
  EXPECT_GE(cases, 250);
  EXPECT_GE(fallbacks, 10);
  std::printf("%d cases, %d needed single-index exchanges\n", cases, fallbacks);
}

// ---------------------------------------------------------------------------------------------------------
// A sphere on an elastic half-space, pressure piecewise constant on square cells of side s.
// Love (1929; Johnson, Contact Mechanics §3.9): the deflection at (x, y) under a unit pressure on the cell
// [ξ1, ξ2] × [η1, η2] is (1/(πE*)) ∫∫ dξ dη / r, r = |(ξ − x, η − y)|, = (1/(πE*)) Σ± H(u, v) over the four
// corners (u = ξ − x, v = η − y), with ∂²H/∂u∂v = 1/√(u² + v²): H = u asinh(v/|u|) + v asinh(u/|v|), an
// antiderivative on every quadrant (the centre of a cell gets 4s ln(1 + √2)/(πE*)). The multipliers are the
// cell pressures, the gaps weighted by the cell area: M = s²·deflection, q = s² r²/(2R), m = s².
double love_H(double u, double v) {
  return (u == 0 ? 0.0 : u * std::asinh(v / std::abs(u))) + (v == 0 ? 0.0 : v * std::asinh(u / std::abs(v)));
}

struct HalfSpace {
  MatrixXd M, X;  // n×n, n×2 cell centres
  VectorXd q, m;
  int side = 0;
  double s = 0;
  int mirror(int i) const { return (i / side) * side + (side - 1 - i % side); }  // x → −x
};

HalfSpace sphere_on_half_space(int side, double s, double R, double E_star) {
  HalfSpace g;
  g.side = side;
  g.s = s;
  const int n = side * side, c = (side - 1) / 2;
  g.X.resize(n, 2);
  for (int i = 0; i < n; ++i) g.X.row(i) << (i % side - c) * s, (i / side - c) * s;
  g.M.resize(n, n);
  const double h = 0.5 * s;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double u1 = g.X(j, 0) - h - g.X(i, 0), u2 = g.X(j, 0) + h - g.X(i, 0);
      const double v1 = g.X(j, 1) - h - g.X(i, 1), v2 = g.X(j, 1) + h - g.X(i, 1);
      g.M(i, j) =
          s * s * (love_H(u2, v2) - love_H(u1, v2) - love_H(u2, v1) + love_H(u1, v1)) / (kPi * E_star);
    }
  g.q = s * s * g.X.rowwise().squaredNorm().transpose() / (2 * R);
  g.m = VectorXd::Constant(n, s * s);
  return g;
}

std::vector<char> disc(const HalfSpace& g, double cx, double cy, double radius) {
  std::vector<char> out(g.q.size(), 0);
  for (int i = 0; i < g.q.size(); ++i) out[i] = std::hypot(g.X(i, 0) - cx, g.X(i, 1) - cy) < radius;
  return out;
}

// The coupled-friction matrix M = W − μV: V_ij = 0.1 W_ij tanh((x_i − x_j)/ℓ), smooth and antisymmetric in x
// (the normal gap at i caused by a shear traction at j changes sign with the side), so V is skew, M + Mᵀ =
// 2W ≻ 0 and M is a P-matrix for every μ.
MatrixXd coupled(const HalfSpace& g, double mu, double ell) {
  MatrixXd M = g.M;
  for (int j = 0; j < M.cols(); ++j)
    for (int i = 0; i < M.rows(); ++i)
      M(i, j) -= mu * 0.1 * g.M(i, j) * std::tanh((g.X(i, 0) - g.X(j, 0)) / ell);
  return M;
}

constexpr double kR = 10, kEstar = 4;  // mm, MPa

// ---------------------------------------------------------------------------------------------------------
// 2. Force control gives δ; depth control at that δ gives the same λ and force.
TEST(ContactLcp, ForceAndDepthControlAgree) {
  const HalfSpace g = sphere_on_half_space(25, 0.08, kR, kEstar);
  const double F = 0.4;
  for (const double mu : {0.0, 2.0}) {
    for (const bool hole : {false, true}) {
      const MatrixXd M = coupled(g, mu, 0.8);
      const ContactLcp lcp(M, g.q, g.m);
      const std::vector<char> ex = hole ? disc(g, 0.2, 0.1, 0.3) : std::vector<char>{};
      const LcpSolution f = lcp.solve_force(F, ex);
      const LcpSolution d = lcp.solve_depth(f.delta, ex);
      EXPECT_EQ(d.active, f.active) << mu << hole;
      // Both solve the principal system of the same set (bordered, then not), to its round-off.
      const double tol =
          std::max(solve_tolerance(M, g.m, f.active, true), solve_tolerance(M, g.m, f.active, false));
      EXPECT_LE(max_rel_diff(d.lambda, f.lambda), tol) << mu << hole;
      std::printf("mu = %.0f, hole %d: |A| = %zu, max |Δλ| / max λ = %.1e (bound %.1e)\n", mu, hole,
                  f.active.size(), max_rel_diff(d.lambda, f.lambda), tol);
      EXPECT_NEAR(g.m.dot(f.lambda), F, 1e-13 * F);
      EXPECT_NEAR(g.m.dot(d.lambda), F, tol * F);
      EXPECT_EQ(d.delta, f.delta);
    }
  }
}

// ---------------------------------------------------------------------------------------------------------
// 3. Excluded multipliers carry nothing and their gaps are free; the others are complementary to round-off,
// and the whole equals the reduced problem without the excluded rows and columns.
TEST(ContactLcp, ExcludedMultipliersCarryNothingAndTheRestIsComplementary) {
  const HalfSpace g = sphere_on_half_space(25, 0.08, kR, kEstar);
  const int n = static_cast<int>(g.q.size());
  const double F = 0.4;
  const std::vector<char> hole = disc(g, 0.1, 0.0, 0.3);  // through the centre of the contact
  const LcpSolution s = ContactLcp(g.M, g.q, g.m).solve_force(F, hole);
  double neg_gap = 0, l_max = 0, product = 0;
  for (int i = 0; i < n; ++i) {
    if (hole[i]) {
      EXPECT_EQ(s.lambda[i], 0.0);
      neg_gap = std::min(neg_gap, s.gap[i]);
    } else {
      l_max = std::max(l_max, s.lambda[i]);
      product = std::max(product, std::abs(s.lambda[i] * s.gap[i]));
    }
  }
  EXPECT_LT(neg_gap, 0.0);  // the skin would penetrate the missing indenter: no constraint there
  const double g_scale = g.q.cwiseAbs().maxCoeff() + std::abs(s.delta) * g.m.maxCoeff();
  const double bound = complementarity_bound(g.M, g.q, g.m, s);
  EXPECT_LE(bound, 1e-11);
  EXPECT_LE(s.complementarity, bound);
  EXPECT_DOUBLE_EQ(s.complementarity, product / (l_max * g_scale));
  EXPECT_GE(s.min_lambda, -1e-12 * l_max);
  EXPECT_GE(s.min_gap, -1e-12 * g_scale);
  for (int i : s.active) EXPECT_FALSE(hole[i]);

  // The reduced problem.
  std::vector<int> keep;
  for (int i = 0; i < n; ++i)
    if (!hole[i]) keep.push_back(i);
  const int k = static_cast<int>(keep.size());
  MatrixXd Mr(k, k);
  VectorXd qr(k), mr(k);
  for (int a = 0; a < k; ++a) {
    qr[a] = g.q[keep[a]];
    mr[a] = g.m[keep[a]];
    for (int b = 0; b < k; ++b) Mr(a, b) = g.M(keep[a], keep[b]);
  }
  const LcpSolution r = ContactLcp(Mr, qr, mr).solve_force(F);
  ASSERT_EQ(r.active.size(), s.active.size());
  double diff = 0;
  for (int a = 0; a < k; ++a) diff = std::max(diff, std::abs(r.lambda[a] - s.lambda[keep[a]]));
  EXPECT_LE(diff / l_max, solve_tolerance(g.M, g.m, s.active, true));
}

// Bilateral multipliers (a small hole's bulge keeps the hole-free contact set, contact/holes/dimple.hpp):
// held at zero gap with a free sign, the rest complementary. A dimple that opens the gaps of a few central
// multipliers by far more than their pressure closes makes them pull (λ < 0) instead of lifting off; the
// answer is the principal system of the bilateral set solved directly (second method).
TEST(ContactLcp, BilateralMultipliersHoldZeroGapWithAFreeSign) {
  const HalfSpace g = sphere_on_half_space(25, 0.08, kR, kEstar);
  const int n = static_cast<int>(g.q.size());
  const double F = 0.4;
  const ContactLcp lcp(g.M, g.q, g.m);
  const LcpSolution free = lcp.solve_force(F);
  std::vector<char> bilateral(n, 0), out(n, 1);
  for (int i : free.active) bilateral[i] = 1, out[i] = 0;
  const std::vector<char> dimple = disc(g, 0.0, 0.0, 0.15);
  VectorXd shift = VectorXd::Zero(n);
  for (int i = 0; i < n; ++i)
    if (dimple[i]) shift[i] = 20 * g.M(i, i) * free.lambda.maxCoeff();
  const LcpSolution s = lcp.solve_force(F, out, free.active, shift, bilateral);
  const double g_scale = g.q.cwiseAbs().maxCoeff() + std::abs(s.delta) * g.m.maxCoeff();
  double worst_gap = 0;
  for (int i : free.active) worst_gap = std::max(worst_gap, std::abs(s.gap[i]));
  EXPECT_LE(worst_gap, 1e-12 * g_scale);
  EXPECT_LT(s.lambda.minCoeff(), 0.0) << "the dimple's multipliers pull rather than lift off";
  EXPECT_EQ(s.active, free.active);
  // The principal system of the bilateral set, with force control.
  const std::vector<int>& A = free.active;
  const int k = static_cast<int>(A.size());
  MatrixXd K = MatrixXd::Zero(k + 1, k + 1);
  VectorXd b = VectorXd::Zero(k + 1);
  for (int a = 0; a < k; ++a) {
    for (int c = 0; c < k; ++c) K(a, c) = g.M(A[a], A[c]);
    K(a, k) = -g.m[A[a]];
    K(k, a) = g.m[A[a]];
    b[a] = -(g.q[A[a]] + shift[A[a]]);
  }
  b[k] = F;
  const VectorXd x = K.partialPivLu().solve(b);
  double diff = 0;
  for (int a = 0; a < k; ++a) diff = std::max(diff, std::abs(x[a] - s.lambda[A[a]]));
  EXPECT_LE(diff / s.lambda.cwiseAbs().maxCoeff(), solve_tolerance(g.M, g.m, A, true));
  EXPECT_NEAR(x[k], s.delta, 1e-10 * std::abs(s.delta));
}

// ---------------------------------------------------------------------------------------------------------
// 4a. The discretised half-space tends to Hertz: a³ = 3FR/(4E*), p0 = 3F/(2πa²), δ = a²/R.
TEST(ContactLcp, HalfSpaceSphereTendsToHertz) {
  const double F = 0.5;
  const double a = std::cbrt(3 * F * kR / (4 * kEstar)), p0 = 3 * F / (2 * kPi * a * a), delta = a * a / kR;
  std::vector<double> e_a, e_p;
  for (const int per_radius : {4, 8, 16}) {
    const double s = a / per_radius, h = s / a;
    const HalfSpace g =
        sphere_on_half_space(2 * static_cast<int>(std::ceil(1.25 * per_radius)) + 1, s, kR, kEstar);
    const LcpSolution sol = ContactLcp(g.M, g.q, g.m).solve_force(F);
    const double a_area = std::sqrt(static_cast<double>(sol.active.size()) * s * s / kPi);
    const double p_centre = sol.lambda[(g.q.size() - 1) / 2];
    e_a.push_back(std::abs(a_area / a - 1));
    e_p.push_back(std::abs(p_centre / p0 - 1));
    // The contact edge is resolved to a cell: |Δa| ≤ s. Love's coefficients are exact for piecewise constant
    // pressure, so the collocation error is second order: p0 and δ within (s/a)²/4 (the cell-mean variation
    // of the Hertz profile over the central cell alone is (s/a)²/12).
    EXPECT_LE(e_a.back(), h);
    EXPECT_LE(e_p.back(), 0.25 * h * h);
    EXPECT_LE(std::abs(sol.delta / delta - 1), 0.25 * h * h);
    EXPECT_LE(sol.complementarity, complementarity_bound(g.M, g.q, g.m, sol));
    std::printf("a/s = %2d: n = %4d, |A| = %3zu, pivots %d: a_area %+.2e, p0 %+.2e, delta %+.2e vs Hertz\n",
                per_radius, static_cast<int>(g.q.size()), sol.active.size(), sol.pivots, a_area / a - 1,
                p_centre / p0 - 1, sol.delta / delta - 1);
  }
  EXPECT_LT(e_a[1], e_a[0]);
  EXPECT_LT(e_a[2], e_a[1]);
  EXPECT_LT(e_p[1], e_p[0]);
  EXPECT_LT(e_p[2], e_p[1]);
}

// 4b. A hole (≈ 60 cells) swept across a contact of ≈ 1000 cells, n = 1521: the reference (low-rank) path
// with warm starts, warm starts alone and cold dense solves give the same answer. Times are printed.
TEST(ContactLcp, HoleSweepLowRankEqualsWarmAndColdSolves) {
  const double s = 0.05, a = 17.8 * s, F = 4 * kEstar * a * a * a / (3 * kR);  // Hertz: |A| ≈ π·17.8² ≈ 1000
  const HalfSpace g = sphere_on_half_space(39, s, kR, kEstar);
  const int n = static_cast<int>(g.q.size());
  ContactLcp fast(g.M, g.q, g.m);
  const ContactLcp plain(g.M, g.q, g.m);
  auto t0 = std::chrono::steady_clock::now();
  const LcpSolution base = plain.solve_force(F);
  const double t_cold = seconds_since(t0);
  t0 = std::chrono::steady_clock::now();
  fast.set_reference(base.active);
  const double t_ref = seconds_since(t0);
  EXPECT_NEAR(static_cast<double>(base.active.size()), 1000, 60);

  std::vector<int> warm_fast = base.active, warm_plain = base.active;
  double t_fast = 0, t_warm = 0, t_cold_hole = 0, max_diff = 0;
  int positions = 0, colds = 0, pivots = 0, hole_min = n, hole_max = 0;
  for (int p = 0; p <= 24; ++p, ++positions) {
    const double cx = -1.2 * a + 0.1 * a * p;
    const std::vector<char> hole = disc(g, cx, 0.3 * a, 4.4 * s);
    int holes = 0;
    for (char c : hole) holes += c;
    hole_min = std::min(hole_min, holes), hole_max = std::max(hole_max, holes);
    t0 = std::chrono::steady_clock::now();
    const LcpSolution f = fast.solve_force(F, hole, warm_fast);
    t_fast += seconds_since(t0);
    t0 = std::chrono::steady_clock::now();
    const LcpSolution w = plain.solve_force(F, hole, warm_plain);
    t_warm += seconds_since(t0);
    warm_fast = f.active;
    warm_plain = w.active;
    pivots += f.pivots;
    EXPECT_EQ(f.lowrank, f.pivots) << p;  // every principal system went through the reference
    EXPECT_EQ(f.active, w.active) << p;
    EXPECT_LE(max_rel_diff(f.lambda, w.lambda), 1e-10) << p;
    EXPECT_LE(f.complementarity, complementarity_bound(g.M, g.q, g.m, f)) << p;
    max_diff = std::max(max_diff, max_rel_diff(f.lambda, w.lambda));
    if (p % 6 == 3) {
      t0 = std::chrono::steady_clock::now();
      const LcpSolution c = plain.solve_force(F, hole);
      t_cold_hole += seconds_since(t0);
      ++colds;
      EXPECT_EQ(f.active, c.active) << p;
      EXPECT_LE(max_rel_diff(f.lambda, c.lambda), 1e-10) << p;
      max_diff = std::max(max_diff, max_rel_diff(f.lambda, c.lambda));
      // Depth control through the same reference (δ joins the removed set).
      const LcpSolution d = fast.solve_depth(c.delta, hole, warm_fast);
      EXPECT_GT(d.lowrank, 0);
      EXPECT_EQ(d.active, c.active);
      EXPECT_LE(max_rel_diff(d.lambda, c.lambda), 1e-10) << p;
    }
  }
  std::printf(
      "n = %d, |A0| = %zu, hole %d..%d cells: cold %.3f s (%d pivots), set_reference %.3f s, cold with "
      "hole %.3f s; per position: warm %.1f ms, reference path %.1f ms (%.2f pivots); max diff %.1e\n",
      n, base.active.size(), hole_min, hole_max, t_cold, base.pivots, t_ref, t_cold_hole / colds,
      1e3 * t_warm / positions, 1e3 * t_fast / positions, double(pivots) / positions, max_diff);
}

// ---------------------------------------------------------------------------------------------------------
// 5. Coupled friction: M = W − μV is not symmetric. It converges and stays complementary; −μ gives the mirror
// image of μ (V changes sign under x → −x); the pressure centroid moves monotonically with μ; μ = 0 is the
// symmetric problem bit for bit; the reference path agrees with cold solves.
TEST(ContactLcp, CoupledFrictionIsNonSymmetricAndConsistent) {
  const HalfSpace g = sphere_on_half_space(25, 0.08, kR, kEstar);
  const int n = static_cast<int>(g.q.size());
  const double F = 0.4, ell = 0.8;
  const auto centroid = [&](const VectorXd& l) { return g.X.col(0).dot(l) / l.sum(); };
  const LcpSolution sym = ContactLcp(g.M, g.q, g.m).solve_force(F);
  const LcpSolution zero = ContactLcp(coupled(g, 0.0, ell), g.q, g.m).solve_force(F);
  EXPECT_TRUE((zero.lambda.array() == sym.lambda.array()).all());
  EXPECT_TRUE((zero.gap.array() == sym.gap.array()).all());
  EXPECT_EQ(zero.delta, sym.delta);
  EXPECT_EQ(zero.active, sym.active);
  EXPECT_LE(std::abs(centroid(sym.lambda)), 1e-12 * g.s);  // symmetric problem, centred pressure

  double previous = 0;
  for (const double mu : {1.0, 2.0, 3.0}) {
    const MatrixXd M = coupled(g, mu, ell);
    ASSERT_GT((M - M.transpose()).norm(), 0.01 * M.norm());  // genuinely non-symmetric
    const LcpSolution p = ContactLcp(M, g.q, g.m).solve_force(F);
    const LcpSolution m = ContactLcp(coupled(g, -mu, ell), g.q, g.m).solve_force(F);
    EXPECT_LE(p.complementarity, complementarity_bound(M, g.q, g.m, p)) << mu;
    EXPECT_NEAR(g.m.dot(p.lambda), F, 1e-13 * F);
    EXPECT_GE(p.min_lambda, -1e-12 * p.lambda.maxCoeff());
    double mirror_diff = 0;
    for (int i = 0; i < n; ++i)
      mirror_diff = std::max(mirror_diff, std::abs(m.lambda[g.mirror(i)] - p.lambda[i]));
    EXPECT_LE(mirror_diff / p.lambda.maxCoeff(), solve_tolerance(M, g.m, p.active, true)) << mu;
    EXPECT_NEAR(m.delta, p.delta, 1e-12 * p.delta);
    const double c = centroid(p.lambda);
    EXPECT_GT(std::abs(c), std::abs(previous)) << mu;  // the shear tilts the pressure more as μ grows
    if (previous != 0) {
      EXPECT_GT(c * previous, 0.0);
    }
    previous = c;
    std::printf("mu = %.0f: pressure centroid %+.4f mm, delta %.5f mm, pivots %d\n", mu, c, p.delta,
                p.pivots);

    // Reference path on the coupled matrix: holes at three places against cold solves.
    ContactLcp fast(M, g.q, g.m);
    fast.set_reference(p.active);
    std::vector<int> warm = p.active;
    for (const double cx : {-0.5, 0.0, 0.5}) {
      const std::vector<char> hole = disc(g, cx, 0.1, 0.25);
      const LcpSolution f = fast.solve_force(F, hole, warm);
      const LcpSolution cold = ContactLcp(M, g.q, g.m).solve_force(F, hole);
      warm = f.active;
      EXPECT_EQ(f.lowrank, f.pivots);
      EXPECT_EQ(f.active, cold.active) << mu << " " << cx;
      EXPECT_LE(max_rel_diff(f.lambda, cold.lambda), 1e-10) << mu << " " << cx;
    }
  }
}

// Same input, same output bit for bit, also through the reference path.
TEST(ContactLcp, RepeatedSolvesAreBitwiseIdentical) {
  const HalfSpace g = sphere_on_half_space(21, 0.1, kR, kEstar);
  const MatrixXd M = coupled(g, 2.0, 0.8);
  ContactLcp lcp(M, g.q, g.m);
  const LcpSolution base = lcp.solve_force(0.4);
  lcp.set_reference(base.active);
  const std::vector<char> hole = disc(g, 0.2, 0.1, 0.25);
  const LcpSolution a = lcp.solve_force(0.4, hole, base.active), b = lcp.solve_force(0.4, hole, base.active);
  EXPECT_TRUE((a.lambda.array() == b.lambda.array()).all());
  EXPECT_TRUE((a.gap.array() == b.gap.array()).all());
  EXPECT_EQ(a.delta, b.delta);
  EXPECT_EQ(a.pivots, b.pivots);
}

// ---------------------------------------------------------------------------------------------------------
// 6. Failures: one line naming the pivot, never a result.
TEST(ContactLcp, SingularOrNonPMatricesThrowOneLine) {
  const auto message = [](const auto& f) -> std::string {
    try {
      f();
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    return "";
  };
  // Singular principal system: M = 11ᵀ (positive semidefinite, not P), both indices overlap at this depth.
  {
    MatrixXd M(2, 2);
    M << 1, 1, 1, 1;
    const ContactLcp lcp(M, VectorXd::Zero(2), VectorXd::Ones(2));
    const std::string e = message([&] { lcp.solve_depth(1.0); });
    EXPECT_NE(e.find("singular principal system"), std::string::npos) << e;
    EXPECT_NE(e.find("at pivot 1"), std::string::npos) << e;
    EXPECT_EQ(e.find('\n'), std::string::npos);
  }
  // Not a P-matrix (negative diagonal): the LCP has no solution, every exchange makes another index
  // infeasible, and the pivot bound 10n + 20 ends it.
  {
    const int n = 4;
    const ContactLcp lcp(-MatrixXd::Identity(n, n), VectorXd::Zero(n), VectorXd::Ones(n));
    const std::string e = message([&] { lcp.solve_depth(1.0); });
    EXPECT_NE(e.find("no convergence after 60 pivots"), std::string::npos) << e;
    EXPECT_EQ(e.find('\n'), std::string::npos);
  }
  // A singular reference set, a zone entirely under the hole.
  {
    MatrixXd M(2, 2);
    M << 1, 1, 1, 1;
    ContactLcp lcp(M, VectorXd::Zero(2), VectorXd::Ones(2));
    EXPECT_THROW(lcp.set_reference({0, 1}), std::runtime_error);
    EXPECT_THROW(lcp.solve_force(1.0, std::vector<char>(2, 1)), std::runtime_error);
  }
  // Bad arguments.
  const HalfSpace g = sphere_on_half_space(5, 0.2, kR, kEstar);
  EXPECT_THROW(ContactLcp(g.M, g.q, g.m).solve_force(0.0), std::invalid_argument);
  EXPECT_THROW(ContactLcp(g.M, g.q, -g.m), std::invalid_argument);
  EXPECT_THROW(ContactLcp(g.M, g.q.head(3), g.m), std::invalid_argument);
  EXPECT_THROW(ContactLcp(g.M, g.q, g.m).solve_force(0.1, std::vector<char>(3, 0)), std::invalid_argument);
  EXPECT_THROW(ContactLcp(g.M, g.q, g.m).solve_force(0.1, {}, {25}), std::invalid_argument);
}

}  // namespace
}  // namespace skinfem::contact
