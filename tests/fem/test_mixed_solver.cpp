// Taylor–Hood P2–P1 solves against closed forms: patch test, manufactured-solution convergence rates
// at ν = 0.5 and ν = 0.3, both saddle-point solvers, determinism.
#include <gtest/gtest.h>

#include <array>
#include <cstring>

#include "../common/convergence.hpp"
#include "fixtures.hpp"
#include "skinfem/fem/assembly.hpp"
#include "skinfem/fem/mixed_solver.hpp"
#include "skinfem/mesh/p2_tet.hpp"

namespace skinfem {
namespace {

using testing::box_mesh;
using testing::observed_order;
using testing::PlaneWaves;

// Solve with u = exact on the base (Dirichlet) and the exact traction σ·n on every other face.
MixedSolution solve_exact_bc(const TetMesh& m, const Lame& lame, const PlaneWaves& ex, SolverKind kind) {
  const MixedMatrices M = assemble_mixed(m, lame);
  std::vector<bool> fixed(3 * m.num_nodes(), false);
  Eigen::VectorXd g = Eigen::VectorXd::Zero(3 * m.num_nodes());
  for (int i = 0; i < m.num_nodes(); ++i)
    if (m.node_marker(i) & kBase) {
      const Eigen::Vector3d ui = ex.u(m.nodes.row(i).transpose());
      for (int c = 0; c < 3; ++c) fixed[3 * i + c] = true, g[3 * i + c] = ui[c];
    }
  Eigen::VectorXd f = body_load(m, [&](const Eigen::Vector3d& x) { return ex.body_force(x); });
  f += traction_load(m, kTop | kSide, [&](const Eigen::Vector3d& x, const Eigen::Vector3d& n) {
    return Eigen::Vector3d(ex.sigma(x) * n);
  });
  return MixedSolver(M, lame, fixed, kind).solve(f, g);
}

struct Errors {
  double u_l2, u_h1, p_l2;
};

// ‖u_h − u‖_L2, |u_h − u|_H1, ‖p_h − p‖_L2 by the degree-5 rule on every element.
Errors errors(const TetMesh& m, const MixedSolution& x, const PlaneWaves& ex) {
  Errors e{0, 0, 0};
  for (int t = 0; t < m.num_tets(); ++t) {
    Eigen::Matrix<double, 10, 3> X, U;
    for (int a = 0; a < 10; ++a) {
      X.row(a) = m.nodes.row(m.tets(t, a));
      U.row(a) = x.u.segment<3>(3 * m.tets(t, a)).transpose();
    }
    for (const auto& q : p2::quadrature_degree5()) {
      const p2::Vec10 N = p2::shape(q.xi);
      const p2::Grad10 dref = p2::shape_gradient(q.xi);
      const Eigen::Matrix3d J = X.transpose() * dref;
      const double w = q.weight * J.determinant();
      const Eigen::Vector3d xq = X.transpose() * N;
      const Eigen::Matrix3d gu = U.transpose() * dref * J.inverse();
      const auto L = p2::barycentric(q.xi);
      double ph = 0;
      for (int r = 0; r < 4; ++r) ph += L[r] * x.p[m.tets(t, r)];
      e.u_l2 += w * (U.transpose() * N - ex.u(xq)).squaredNorm();
      e.u_h1 += w * (gu - ex.grad_u(xq)).squaredNorm();
      e.p_l2 += w * std::pow(ph - ex.p(xq), 2);
    }
  }
  return {std::sqrt(e.u_l2), std::sqrt(e.u_h1), std::sqrt(e.p_l2)};
}

PlaneWaves incompressible_field(const Lame& lame) {
  PlaneWaves ex;
  // A ⊥ k: each wave is divergence-free.
  ex.k = {{1.1, 0.4, 0.7}, {-0.5, 0.9, 1.3}};
  ex.A = {Eigen::Vector3d(0.4, -0.2, -0.5), Eigen::Vector3d(0.3, 0.6, -0.3)};
  for (size_t m = 0; m < 2; ++m) ex.A[m] -= ex.A[m].dot(ex.k[m]) / ex.k[m].squaredNorm() * ex.k[m];
  ex.phase = {0.3, -0.7};
  ex.P = 0.8, ex.q = Eigen::Vector3d(0.6, -0.8, 0.5);
  ex.mu = lame.mu, ex.inv_lambda = 0;
  return ex;
}

PlaneWaves compressible_field(const Lame& lame) {
  PlaneWaves ex;
  ex.k = {{1.1, 0.4, 0.7}, {-0.5, 0.9, 1.3}};
  ex.A = {Eigen::Vector3d(0.4, -0.2, 0.5), Eigen::Vector3d(0.3, 0.6, -0.3)};
  ex.phase = {0.3, -0.7};
  ex.mu = lame.mu, ex.inv_lambda = lame.inv_lambda;
  return ex;
}

// Every DOF of the base's nodes held (the bonded base).
std::vector<bool> base_held(const TetMesh& m) {
  std::vector<bool> fixed(3 * m.num_nodes(), false);
  for (int i = 0; i < m.num_nodes(); ++i)
    if (m.node_marker(i) & kBase) fixed[3 * i] = fixed[3 * i + 1] = fixed[3 * i + 2] = true;
  return fixed;
}

TEST(MixedSolver, PatchTestReproducesLinearDisplacementToRoundOff) {
  // u = G x + c with constant σ: P2–P1 contains it exactly, so the discrete solution equals it.
  for (double nu : {0.5, 0.3}) {
    const Lame lame = Lame::from(3.0, nu);
    PlaneWaves ex;  // a single wave with tiny k is not linear; build the linear field directly instead
    const TetMesh m = box_mesh(1.0, 1.0, 0.6);
    Eigen::Matrix3d G;
    G << 0.01, 0.02, -0.03, 0.015, -0.02, 0.01, 0.005, 0.025, (nu == 0.5 ? 0.01 : 0.04);
    const Eigen::Vector3d c(0.1, -0.2, 0.05);
    const double p0 = nu == 0.5 ? 0.37 : -G.trace() / lame.inv_lambda;
    const Eigen::Matrix3d sigma = lame.mu * (G + G.transpose()) - p0 * Eigen::Matrix3d::Identity();
    const MixedMatrices M = assemble_mixed(m, lame);
    std::vector<bool> fixed(3 * m.num_nodes(), false);
    Eigen::VectorXd g = Eigen::VectorXd::Zero(3 * m.num_nodes());
    for (int i = 0; i < m.num_nodes(); ++i)
      if (m.node_marker(i) & kBase)
        for (int k = 0; k < 3; ++k)
          fixed[3 * i + k] = true, g[3 * i + k] = (G * m.nodes.row(i).transpose() + c)[k];
    const Eigen::VectorXd f = traction_load(
        m, kTop | kSide,
        [&](const Eigen::Vector3d&, const Eigen::Vector3d& n) { return Eigen::Vector3d(sigma * n); });
    for (SolverKind kind : {SolverKind::direct_ldlt, SolverKind::schur_cg}) {
      const MixedSolution x = MixedSolver(M, lame, fixed, kind).solve(f, g);
      double err = 0;
      for (int i = 0; i < m.num_nodes(); ++i)
        err = std::max(err, (x.u.segment<3>(3 * i) - G * m.nodes.row(i).transpose() - c).norm());
      EXPECT_LT(err, 1e-12) << "nu " << nu << " " << to_string(kind);
      EXPECT_LT((x.p.array() - p0).abs().maxCoeff(), 1e-11) << "nu " << nu << " " << to_string(kind);
    }
  }
}

void check_rates(double nu, const PlaneWaves& field) {
  // Taylor–Hood P2–P1 a priori estimates: ‖u − u_h‖_L2 = O(h³), |u − u_h|_H1 = O(h²), ‖p − p_h‖_L2 = O(h²).
  const Lame lame = Lame::from(3.0, nu);
  std::vector<double> h, eu, eh, ep;
  for (double size : {0.8, 0.56, 0.4}) {
    const TetMesh m = box_mesh(1.5, 1.5, size);
    const Errors e = errors(m, solve_exact_bc(m, lame, field, SolverKind::direct_ldlt), field);
    // the mesh size: mean longest edge, not the target (TetGen's elements are somewhat smaller)
    double mean_edge = 0;
    for (int t = 0; t < m.num_tets(); ++t)
      for (const auto& ed : p2::kEdge)
        mean_edge +=
            (m.nodes.row(m.tets(t, ed[0])) - m.nodes.row(m.tets(t, ed[1]))).norm() / (6.0 * m.num_tets());
    h.push_back(mean_edge);
    eu.push_back(e.u_l2), eh.push_back(e.u_h1), ep.push_back(e.p_l2);
    std::printf("nu %.2f h %.3f: |u|L2 %.3e |u|H1 %.3e |p|L2 %.3e\n", nu, mean_edge, e.u_l2, e.u_h1, e.p_l2);
  }
  const double ru = observed_order(h, eu), rh = observed_order(h, eh), rp = observed_order(h, ep);
  std::printf("nu %.2f observed orders: u L2 %.2f, u H1 %.2f, p L2 %.2f\n", nu, ru, rh, rp);
  EXPECT_NEAR(ru, 3.0, 0.3);
  EXPECT_NEAR(rh, 2.0, 0.3);
  EXPECT_NEAR(rp, 2.0, 0.3);
}

TEST(MixedSolver, ManufacturedSolutionConvergesAtTaylorHoodRatesIncompressible) {
  check_rates(0.5, incompressible_field(Lame::from(3.0, 0.5)));
}

TEST(MixedSolver, ManufacturedSolutionConvergesAtTaylorHoodRatesCompressible) {
  check_rates(0.3, compressible_field(Lame::from(3.0, 0.3)));
}

TEST(MixedSolver, SchurCgAndDirectLdltAgreeToSolverTolerance) {
  const Lame lame = Lame::from(3.0, 0.5);
  const PlaneWaves field = incompressible_field(lame);
  const TetMesh m = box_mesh(1.5, 1.5, 0.6);
  const MixedSolution a = solve_exact_bc(m, lame, field, SolverKind::direct_ldlt);
  const MixedSolution b = solve_exact_bc(m, lame, field, SolverKind::schur_cg);
  EXPECT_LT((a.u - b.u).norm() / a.u.norm(), 1e-9);
  EXPECT_LT((a.p - b.p).norm() / a.p.norm(), 1e-9);
  EXPECT_GT(b.iterations, 0);
}

TEST(MixedSolver, TwoRunsAreBitwiseIdentical) {
  const Lame lame = Lame::from(3.0, 0.5);
  const PlaneWaves field = incompressible_field(lame);
  // Element sizes 1.5 and 0.5: below and above the 5000 unknowns where MUMPS switches from approximate
  // minimum fill to PORD ordering (mumps_ldlt.cpp), each checked.
  for (const auto& [size, kind] :
       {std::pair{1.5, SolverKind::direct_ldlt}, std::pair{0.5, SolverKind::direct_ldlt},
        std::pair{0.5, SolverKind::schur_cg}}) {
    const TetMesh m1 = box_mesh(1.5, 1.5, size), m2 = box_mesh(1.5, 1.5, size);
    ASSERT_EQ(m1.num_nodes(), m2.num_nodes());
    // Unknowns: at most 4 per node (3 displacements, a pressure at vertices), at least 3 per free node.
    if (size > 1) {
      EXPECT_LT(4 * m1.num_nodes(), 5000);
    } else {
      EXPECT_GT(3 * m1.num_nodes() / 2, 5000);
    }
    const MixedSolution a = solve_exact_bc(m1, lame, field, kind), b = solve_exact_bc(m2, lame, field, kind);
    ASSERT_EQ(std::memcmp(a.u.data(), b.u.data(), sizeof(double) * a.u.size()), 0) << to_string(kind);
    ASSERT_EQ(std::memcmp(a.p.data(), b.p.data(), sizeof(double) * a.p.size()), 0) << to_string(kind);
  }
}

// Contact condensation solves hundreds of loads as one block: each column must equal its own solve.
TEST(MixedSolver, BlockSolveEqualsColumnByColumnSolves) {
  const Lame lame = Lame::from(3.0, 0.5);
  const TetMesh m = box_mesh(1.5, 1.5, 0.6);
  const MixedMatrices mm = assemble_mixed(m, lame);
  const std::vector<bool> fixed = base_held(m);
  const MixedSolver solver(mm, lame, fixed, SolverKind::direct_ldlt);
  Eigen::MatrixXd F = Eigen::MatrixXd::Zero(3 * m.num_nodes(), 40);  // 40 > one MUMPS block of 32
  int col = 0;
  for (int i = 0; i < m.num_nodes() && col < F.cols(); ++i)
    if (m.node_marker(i) == kTop) F(3 * i + col % 3, col) = 1.0 + col, ++col;
  ASSERT_EQ(col, F.cols());
  const Eigen::MatrixXd U = solver.solve_block(F);
  for (int j = 0; j < F.cols(); ++j) {
    const Eigen::VectorXd u = solver.solve(F.col(j)).u;
    EXPECT_LT((U.col(j) - u).norm(), 1e-12 * u.norm()) << "column " << j;
  }
}

// A released factorization refuses every later solve, loudly, and keeps what describes it.
TEST(MixedSolver, AReleasedFactorizationRefusesToSolve) {
  const Lame lame = Lame::from(3.0, 0.5);
  const TetMesh m = box_mesh(1.5, 1.5, 0.6);
  const MixedMatrices mm = assemble_mixed(m, lame);
  const std::vector<bool> fixed = base_held(m);
  MixedSolver solver(mm, lame, fixed, SolverKind::direct_ldlt);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(3 * m.num_nodes());
  for (int i = 0; i < m.num_nodes(); ++i)
    if (m.node_marker(i) == kTop) f[3 * i + 2] = -1e-3;
  EXPECT_GT(solver.solve(f).u.norm(), 0);
  const double flops = solver.factor_flops();
  const int dofs = solver.free_dofs();
  solver.release_factorization();
  EXPECT_THROW(solver.solve(f), SolverError);
  EXPECT_THROW(solver.solve_block(Eigen::MatrixXd(f)), SolverError);
  EXPECT_EQ(solver.factor_flops(), flops);
  EXPECT_EQ(solver.free_dofs(), dofs);
}

// A factorization bordered by columns (loads and prescribed base values) gives their products from MUMPS's
// Schur complement: each must equal the same product from a block solve of the unbordered system (a
// second method), and the bordered factorization's own solves must be the unbordered ones.
TEST(MixedSolver, BorderedProductsEqualBlockSolves) {
  const Lame lame = Lame::from(3.0, 0.5);
  const TetMesh m = box_mesh(1.5, 1.5, 0.4);
  const MixedMatrices mm = assemble_mixed(m, lame);
  const int n3 = 3 * m.num_nodes();
  std::vector<bool> fixed(n3, false);
  std::vector<int> base, top;
  for (int i = 0; i < m.num_nodes(); ++i) {
    if (m.node_marker(i) & kBase)
      fixed[3 * i] = fixed[3 * i + 1] = fixed[3 * i + 2] = true, base.push_back(i);
    if (m.node_marker(i) == kTop) top.push_back(i);
  }
  // 12 loads on top nodes (all three components), 4 columns of prescribed base values.
  const int nl = 12, np = 4;
  std::vector<Eigen::Triplet<double>> f, u;
  for (int j = 0; j < nl; ++j) {
    f.emplace_back(3 * top[(7 * j) % top.size()] + j % 3, j, 1.0 + j);
    f.emplace_back(3 * top[(7 * j + 3) % top.size()] + 2, j, -0.5);
  }
  for (int j = 0; j < np; ++j)
    for (int k = 0; k < 5; ++k)
      u.emplace_back(3 * base[(11 * j + 5 * k) % base.size()] + k % 3, nl + j, 0.1 * (k + 1));
  MixedSolver::Coupling c;
  c.F.resize(n3, nl + np);
  c.F.setFromTriplets(f.begin(), f.end());
  c.U_fixed.resize(n3, nl + np);
  c.U_fixed.setFromTriplets(u.begin(), u.end());
  const MixedSolver plain(mm, lame, fixed, SolverKind::direct_ldlt);
  const MixedSolver bordered(mm, lame, fixed, SolverKind::direct_ldlt, 1e-10, {}, &c);
  const Eigen::MatrixXd U = plain.solve_block(Eigen::MatrixXd(c.F), Eigen::MatrixXd(c.U_fixed));
  Eigen::MatrixXd Ff = Eigen::MatrixXd(c.F);
  for (int d = 0; d < n3; ++d)
    if (fixed[d]) Ff.row(d).setZero();
  const Eigen::MatrixXd expected = Ff.transpose() * U;
  const Eigen::MatrixXd& G = bordered.coupling_products();
  ASSERT_EQ(G.rows(), nl + np);
  const double scale = expected.topRows(nl).cwiseAbs().maxCoeff();
  EXPECT_LT((G.topRows(nl) - expected.topRows(nl)).cwiseAbs().maxCoeff(), 1e-10 * scale);
  EXPECT_LT((G.topLeftCorner(nl, nl) - G.topLeftCorner(nl, nl).transpose()).cwiseAbs().maxCoeff(),
            1e-10 * scale);
  EXPECT_LT((bordered.solve_block(Eigen::MatrixXd(c.F), Eigen::MatrixXd(c.U_fixed)) - U).norm(),
            1e-10 * U.norm());
}

// A Newton iteration's solvers share one analysis (MixedSolver::Reuse): a solver that factors its values on
// the kept analysis solves, and borders, as a fresh one to the last bit, plain and bordered; a matrix of
// another pattern is analysed afresh.
TEST(MixedSolver, AKeptAnalysisSolvesAsAFreshSolverToTheLastBit) {
  const Lame lame = Lame::from(3.0, 0.5);
  const TetMesh m1 = box_mesh(1.5, 1.5, 0.6);
  TetMesh m2 = m1;  // the same tets, other values
  for (int i = 0; i < m2.num_nodes(); ++i) m2.nodes(i, 0) *= 1.0 + 0.1 * m2.nodes(i, 2);
  const MixedMatrices a1 = assemble_mixed(m1, lame), a2 = assemble_mixed(m2, lame);
  const int n3 = 3 * m1.num_nodes();
  std::vector<bool> fixed(n3, false);
  std::vector<int> top;
  for (int i = 0; i < m1.num_nodes(); ++i) {
    if (m1.node_marker(i) & kBase) fixed[3 * i] = fixed[3 * i + 1] = fixed[3 * i + 2] = true;
    if (m1.node_marker(i) == kTop) top.push_back(i);
  }
  MixedSolver::Coupling c;
  std::vector<Eigen::Triplet<double>> f;
  for (int j = 0; j < 6; ++j) f.emplace_back(3 * top[(5 * j) % top.size()] + 2, j, -1.0 - j);
  c.F.resize(n3, 6);
  c.F.setFromTriplets(f.begin(), f.end());
  const Eigen::VectorXd load = Eigen::VectorXd(c.F.col(0)) + Eigen::VectorXd(c.F.col(3));
  const std::array<const MixedSolver::Coupling*, 2> couplings{nullptr, &c};
  for (const MixedSolver::Coupling* coupling : couplings) {
    MixedSolver::Reuse reuse;
    { const MixedSolver first(a1, lame, fixed, SolverKind::direct_ldlt, 1e-10, {}, coupling, &reuse); }
    const MixedSolver kept(a2, lame, fixed, SolverKind::direct_ldlt, 1e-10, {}, coupling, &reuse);
    const MixedSolver fresh(a2, lame, fixed, SolverKind::direct_ldlt, 1e-10, {}, coupling);
    EXPECT_EQ(reuse.analyses(), 1);
    EXPECT_TRUE(kept.solve(load).u == fresh.solve(load).u);
    EXPECT_TRUE(kept.coupling_products() == fresh.coupling_products());
  }
  MixedSolver::Reuse reuse;
  { const MixedSolver first(a1, lame, fixed, SolverKind::direct_ldlt, 1e-10, {}, nullptr, &reuse); }
  const TetMesh other = box_mesh(1.5, 1.5, 0.75);
  const MixedMatrices a3 = assemble_mixed(other, lame);
  std::vector<bool> fixed3(3 * other.num_nodes(), false);
  for (int i = 0; i < other.num_nodes(); ++i)
    if (other.node_marker(i) & kBase) fixed3[3 * i] = fixed3[3 * i + 1] = fixed3[3 * i + 2] = true;
  const Eigen::VectorXd g = Eigen::VectorXd::Constant(3 * other.num_nodes(), -0.01);
  const MixedSolver again(a3, lame, fixed3, SolverKind::direct_ldlt, 1e-10, {}, nullptr, &reuse);
  EXPECT_EQ(reuse.analyses(), 2);
  EXPECT_TRUE(again.solve(g).u == MixedSolver(a3, lame, fixed3, SolverKind::direct_ldlt).solve(g).u);
}

// Linear elasticity under force loads: u ∝ 1/E, p independent of E (scale invariance of the continuous
// problem). The solver's scaled unknowns must keep that exact from E = 1e-6 to 1e12 MPa, for both roads,
// ν = 0.5 and 0.3, point loads (block) and prescribed base displacements (single solve: u − u_c ∝ 1/E
// does not hold there, so that case scales the prescribed values with 1/E too).
TEST(MixedSolver, AnyYoungsModulusScalesTheSolutionExactly) {
  const TetMesh m = box_mesh(1.5, 1.5, 0.6);
  const std::vector<bool> fixed = base_held(m);
  Eigen::MatrixXd F = Eigen::MatrixXd::Zero(3 * m.num_nodes(), 3);
  int col = 0;
  for (int i = 0; i < m.num_nodes() && col < F.cols(); ++i)
    if (m.node_marker(i) == kTop) F(3 * i + col, col) = 1.0, ++col;
  Eigen::VectorXd uc = Eigen::VectorXd::Zero(3 * m.num_nodes());
  for (int i = 0; i < m.num_nodes(); ++i)
    if (m.node_marker(i) & kBase) uc[3 * i] = 1e-3 * m.nodes(i, 1);  // a base shear, scaled by 3/E below
  for (double nu : {0.5, 0.3})
    for (SolverKind kind : {SolverKind::direct_ldlt, SolverKind::schur_cg}) {
      const Lame ref_lame = Lame::from(3.0, nu);
      const MixedMatrices ref_matrices = assemble_mixed(m, ref_lame);  // the solver keeps a reference
      const MixedSolver ref(ref_matrices, ref_lame, fixed, kind);
      const Eigen::MatrixXd U3 = ref.solve_block(F);
      const MixedSolution s3 = ref.solve(F.col(0), uc);
      for (double E : {1e-6, 1e12}) {
        const Lame lame = Lame::from(E, nu);
        const MixedMatrices matrices = assemble_mixed(m, lame);
        const MixedSolver solver(matrices, lame, fixed, kind);
        const Eigen::MatrixXd U = solver.solve_block(F) * (E / 3.0);
        EXPECT_LT((U - U3).norm(), 1e-9 * U3.norm()) << "E " << E << " nu " << nu << " " << to_string(kind);
        const MixedSolution s = solver.solve(F.col(0) * (E / 3.0), uc);
        EXPECT_LT((s.u - s3.u).norm(), 1e-9 * s3.u.norm()) << "E " << E << " nu " << nu;
        EXPECT_LT((s.p * (3.0 / E) - s3.p).norm(), 1e-9 * s3.p.norm()) << "E " << E << " nu " << nu;
      }
    }
}

TEST(MixedSolver, SingularSystemIsAnErrorNotNaN) {
  // Nothing fixed: rigid motions make A singular; both roads must refuse rather than return NaN.
  const TetMesh m = box_mesh(1.0, 1.0, 0.8);
  const Lame lame = Lame::from(3.0, 0.5);
  const MixedMatrices M = assemble_mixed(m, lame);
  const std::vector<bool> fixed(3 * m.num_nodes(), false);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(3 * m.num_nodes());
  f[2] = 1.0;
  for (SolverKind kind : {SolverKind::direct_ldlt, SolverKind::schur_cg})
    EXPECT_THROW(MixedSolver(M, lame, fixed, kind).solve(f), SolverError) << to_string(kind);
}

}  // namespace
}  // namespace skinfem

namespace skinfem {
namespace {

TEST(Loads, NodalTractionMatchesTheSameFieldGivenAsAFunction) {
  // A quadratic traction field is reproduced exactly by P2 interpolation on flat faces, and both
  // routes use the same degree-5 face rule: the load vectors agree to round-off.
  const TetMesh m = testing::box_mesh(1.0, 1.0, 0.5);
  auto t = [](const Eigen::Vector3d& x) {
    return Eigen::Vector3d(0.1 * x.x() * x.y(), -0.2 * x.x(), 1 - x.y() * x.y());
  };
  Eigen::MatrixX3d nodal(m.num_nodes(), 3);
  for (int i = 0; i < m.num_nodes(); ++i) nodal.row(i) = t(m.nodes.row(i).transpose()).transpose();
  const Eigen::VectorXd a = nodal_traction_load(m, kTop, nodal);
  const Eigen::VectorXd b =
      traction_load(m, kTop, [&](const Eigen::Vector3d& x, const Eigen::Vector3d&) { return t(x); });
  EXPECT_LT((a - b).norm(), 1e-13 * b.norm());
}

}  // namespace
}  // namespace skinfem
