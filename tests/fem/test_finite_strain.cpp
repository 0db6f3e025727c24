// The finite-strain skin (fem/finite_strain.hpp, fem/newton.hpp) against: the linear Taylor–Hood system it
// must equal at rest (fem/assembly.hpp, exactly), its own residual by central differences (the tangent is
// consistent), the exact homogeneous simple shear of a neo-Hookean block (u = γ z eₓ, p = 0, shear force
// μ γ A whatever γ: Ogden, Non-linear Elastic Deformations, §5.3; docs/theory.md §References) and its Cauchy
// stress (fem/fields.hpp), and the linear solution as the load vanishes (first-order consistency).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "fixtures.hpp"
#include "skinfem/fem/fields.hpp"
#include "skinfem/fem/finite_strain.hpp"
#include "skinfem/fem/mixed_solver.hpp"
#include "skinfem/fem/neo_hookean.hpp"
#include "skinfem/fem/newton.hpp"

namespace skinfem {
namespace {

constexpr double kMu = 1.0;  // MPa (E = 3 MPa at ν = 0.5)

const TetMesh& block() {  // [−1, 1]² × [0, 1] mm, straight-sided elements
  static const TetMesh m = testing::box_mesh(1.0, 1.0, 0.5);
  return m;
}

double max_abs(const SparseMatrixd& M) { return Eigen::MatrixXd(M).cwiseAbs().maxCoeff(); }

std::vector<bool> held(const TetMesh& m, int markers) {
  std::vector<bool> fixed(3 * m.num_nodes(), false);
  for (int i = 0; i < m.num_nodes(); ++i)
    if (m.node_marker[i] & markers) fixed[3 * i] = fixed[3 * i + 1] = fixed[3 * i + 2] = true;
  return fixed;
}

TEST(FiniteStrain, AtRestItIsTheLinearIncompressibleSystem) {
  const TetMesh& m = block();
  const FiniteStrainSystem rest = assemble_finite_strain(m, kMu, Eigen::VectorXd::Zero(3 * m.num_nodes()),
                                                         Eigen::VectorXd::Zero(m.num_vertices));
  const MixedMatrices linear = assemble_mixed(m, Lame::from(3 * kMu, 0.5));
  // Both rules integrate these polynomial integrands exactly: equal to round-off.
  EXPECT_LT(max_abs(rest.tangent.A - linear.A), 1e-13 * max_abs(linear.A));
  EXPECT_LT(max_abs(rest.tangent.B - linear.B), 1e-13 * max_abs(linear.B));
  EXPECT_LT(max_abs(rest.tangent.Mp - linear.Mp), 1e-13 * max_abs(linear.Mp));
  EXPECT_LT(rest.internal_force.cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_LT(rest.constraint.cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_NEAR(rest.tangent.Mp.sum(), 4.0, 1e-12);  // ∫ 1 dV: the block's volume
}

TEST(FiniteStrain, TangentIsTheResidualsDerivative) {
  const TetMesh& m = block();
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> unit(-1, 1);
  // A strained state (|∇u| ~ 0.2, a smooth field) with a pressure, and a direction in (u, p).
  Eigen::VectorXd u(3 * m.num_nodes()), p(m.num_vertices), du(u.size()), dp(p.size());
  for (int i = 0; i < m.num_nodes(); ++i) {
    const Eigen::Vector3d x = m.nodes.row(i).transpose();
    u.segment<3>(3 * i) << 0.2 * x[2] * std::sin(x[0]), 0.1 * x[2] * x[1], -0.15 * x[2] * std::cos(x[1]);
  }
  for (int v = 0; v < m.num_vertices; ++v) p[v] = 0.3 * m.nodes(v, 0) + 0.1;
  for (int d = 0; d < du.size(); ++d) du[d] = unit(gen);
  for (int v = 0; v < dp.size(); ++v) dp[v] = unit(gen);
  const FiniteStrainSystem at = assemble_finite_strain(m, kMu, u, p);
  // Central differences, h = 1e-6 on O(1) quantities: truncation ≲ h² and round-off ≲ ε/h ≈ 1e-10 relative.
  const double h = 1e-6;
  const FiniteStrainSystem plus = assemble_finite_strain(m, kMu, u + h * du, p + h * dp);
  const FiniteStrainSystem minus = assemble_finite_strain(m, kMu, u - h * du, p - h * dp);
  const Eigen::VectorXd fd_force = (plus.internal_force - minus.internal_force) / (2 * h);
  const Eigen::VectorXd fd_constraint = (plus.constraint - minus.constraint) / (2 * h);
  const Eigen::VectorXd force = at.tangent.A * du + at.tangent.B.transpose() * dp;
  const Eigen::VectorXd constraint = at.tangent.B * du;
  EXPECT_LT((fd_force - force).norm(), 1e-7 * force.norm());
  EXPECT_LT((fd_constraint - constraint).norm(), 1e-7 * constraint.norm());
  // The energy's gradient is the internal force (the law is hyperelastic).
  const double fd_energy = (plus.energy - minus.energy) / (2 * h);
  EXPECT_NEAR(fd_energy, at.internal_force.dot(du) + at.constraint.dot(dp), 1e-7 * std::abs(fd_energy));
  // The tangent is symmetric.
  EXPECT_LT(max_abs(SparseMatrixd(at.tangent.A - SparseMatrixd(at.tangent.A.transpose()))),
            1e-13 * max_abs(at.tangent.A));
}

TEST(FiniteStrain, HomogeneousSimpleShearIsExactAtLargeStrain) {
  // Base held, top moved by γ·h along x, the four sides loaded by the homogeneous state's own dead traction
  // P₀N (p = 0): the exact solution is u = γ z eₓ, p = 0, which P2 represents exactly, and the force on the
  // top is μ γ times its area (4 mm²) whatever γ.
  const TetMesh& m = block();
  for (double gamma : {0.3, 1.0}) {
    Eigen::Matrix3d F0 = Eigen::Matrix3d::Identity();
    F0(0, 2) = gamma;
    const Eigen::Matrix3d P0 = neo_hookean(F0, 0, kMu).P;
    const Eigen::VectorXd f =
        traction_load(m, kSide, [&](const Eigen::Vector3d&, const Eigen::Vector3d& n) { return P0 * n; });
    const std::vector<bool> fixed = held(m, kBase | kTop);
    Eigen::VectorXd target = Eigen::VectorXd::Zero(3 * m.num_nodes());
    for (int i = 0; i < m.num_nodes(); ++i) target[3 * i] = gamma * m.nodes(i, 2);
    const FiniteStrainResult r = solve_finite_strain(m, kMu, fixed, f, target);
    EXPECT_LT((r.solution.u - target).cwiseAbs().maxCoeff(), 1e-9) << "gamma " << gamma;
    EXPECT_LT(r.solution.p.cwiseAbs().maxCoeff(), 1e-9) << "gamma " << gamma;
    double top_force_x = 0;
    for (int i = 0; i < m.num_nodes(); ++i)
      if ((m.node_marker[i] & kTop) && !(m.node_marker[i] & kBase)) top_force_x += r.internal_force[3 * i];
    EXPECT_NEAR(top_force_x, kMu * gamma * 4.0, 1e-8) << "gamma " << gamma;
  }
}

TEST(FiniteStrain, CauchyStressOfSimpleShearIsThePoyntingClosedForm) {
  // u = γ z eₓ with a uniform pressure p: B = F Fᵀ has B_xx = 1 + γ², B_xz = γ, so σ = μ (B − I) − p I gives
  // the shear stress μγ, the Poynting normal stress σ_xx = μγ² − p against σ_yy = σ_zz = −p (Ogden §5.3),
  // in every element and at every point (P2 holds the field exactly).
  const TetMesh& m = block();
  const double gamma = 0.8, p = 0.25;
  MixedSolution x;
  x.u = Eigen::VectorXd::Zero(3 * m.num_nodes());
  for (int i = 0; i < m.num_nodes(); ++i) x.u[3 * i] = gamma * m.nodes(i, 2);
  x.p = Eigen::VectorXd::Constant(m.num_vertices, p);
  Eigen::Matrix3d exact = -p * Eigen::Matrix3d::Identity();
  exact(0, 0) += kMu * gamma * gamma;
  exact(0, 2) = exact(2, 0) = kMu * gamma;
  for (int t = 0; t < m.num_tets(); t += 7)
    for (const Eigen::Vector3d& xi : {Eigen::Vector3d(0.25, 0.25, 0.25), Eigen::Vector3d(0.1, 0.6, 0.2)}) {
      const Eigen::Matrix3d sigma = element_stress(m, {kMu, 0.0}, x, t, xi, StressMeasure::neo_hookean);
      EXPECT_LT((sigma - exact).cwiseAbs().maxCoeff(), 1e-13) << "tet " << t;
    }
}

TEST(FiniteStrain, UniaxialStretchIsTreloarsAndNewtonConvergesQuadratically) {
  // The top pulled by the dead traction μ (λ − λ⁻²) (Treloar's uniaxial closed form), the base moved with
  // the body's lateral contraction λ^-1/2, the sides free: the exact state is u = ((t − 1) x, (t − 1) y,
  // (λ − 1) z) with t = λ^-1/2 and p = μ (1/λ − 1), which P2–P1 represents exactly. The linear first step
  // is far from it (its stretch is the load over 3μ), so Newton iterates.
  const TetMesh& m = block();
  for (double lambda : {1.5, 2.0}) {
    const double t = 1 / std::sqrt(lambda), pull = kMu * (lambda - 1 / (lambda * lambda));
    const Eigen::VectorXd f = traction_load(
        m, kTop, [&](const Eigen::Vector3d&, const Eigen::Vector3d&) { return Eigen::Vector3d(0, 0, pull); });
    Eigen::VectorXd exact(3 * m.num_nodes());
    for (int i = 0; i < m.num_nodes(); ++i)
      exact.segment<3>(3 * i) << (t - 1) * m.nodes(i, 0), (t - 1) * m.nodes(i, 1),
          (lambda - 1) * m.nodes(i, 2);
    const FiniteStrainResult r = solve_finite_strain(m, kMu, held(m, kBase), f, exact);
    EXPECT_LT((r.solution.u - exact).cwiseAbs().maxCoeff(), 1e-9) << "lambda " << lambda;
    EXPECT_LT((r.solution.p.array() - kMu * (1 / lambda - 1)).abs().maxCoeff(), 1e-9) << "lambda " << lambda;
    // Quadratic convergence on the consistent tangent: once the residual is below 1e-2, each iteration at
    // least squares it (up to a constant of order one; a linear rate would not), until round-off.
    int quadratic = 0;
    for (const NewtonStep& s : r.steps)
      for (size_t k = 1; k < s.residuals.size(); ++k)
        if (s.residuals[k - 1] < 1e-2 && s.residuals[k] > 1e-13) {
          EXPECT_LT(s.residuals[k], 10 * s.residuals[k - 1] * s.residuals[k - 1]) << "lambda " << lambda;
          ++quadratic;
        }
    EXPECT_GE(quadratic, 1) << "lambda " << lambda;
  }
}

TEST(FiniteStrain, SmallLoadsApproachTheLinearSolution) {
  // Base bonded, a uniform dead traction on the top (shear and pressure). u(ε)/ε = u_lin + ε u₂ + O(ε²), so
  // the relative gap to the linear solution halves with the load.
  const TetMesh& m = block();
  const Eigen::VectorXd f = traction_load(m, kTop, [](const Eigen::Vector3d&, const Eigen::Vector3d&) {
    return Eigen::Vector3d(0.3, 0.0, -0.2);
  });
  const std::vector<bool> fixed = held(m, kBase);
  const MixedMatrices matrices = assemble_mixed(m, Lame::from(3 * kMu, 0.5));  // the solver keeps a reference
  const MixedSolver linear(matrices, Lame::from(3 * kMu, 0.5), fixed, SolverKind::direct_ldlt);
  const Eigen::VectorXd u_lin = linear.solve(f).u;
  double gap[2];
  const double eps[2] = {1e-2, 5e-3};
  for (int i = 0; i < 2; ++i) {
    const FiniteStrainResult r = solve_finite_strain(m, kMu, fixed, eps[i] * f);
    gap[i] = (r.solution.u / eps[i] - u_lin).norm() / u_lin.norm();
  }
  EXPECT_GT(gap[1], 1e-6);  // above the Newton tolerance's reach: the ratio below is the physics'
  EXPECT_NEAR(gap[0] / gap[1], 2.0, 0.1);
}

}  // namespace
}  // namespace skinfem
