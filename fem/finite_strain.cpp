#include "skinfem/fem/finite_strain.hpp"

#include <cmath>

#include "skinfem/fem/neo_hookean.hpp"
#include "skinfem/fem/sparse_pattern.hpp"
#include "skinfem/mesh/p2_tet.hpp"

namespace skinfem {

FiniteStrainSystem assemble_finite_strain(const TetMesh& m, double mu, const Eigen::VectorXd& u,
                                          const Eigen::VectorXd& p, FiniteStrainParts parts) {
  const int n = m.num_nodes(), nv = m.num_vertices;
  const bool tangent = parts == FiniteStrainParts::residual_and_tangent;
  FiniteStrainSystem out;
  if (tangent) {
    const auto adj = pattern::node_adjacency(m);
    out.tangent.A = pattern::block_pattern(adj, 3 * n, 3, n);
    out.tangent.B = pattern::block_pattern(adj, nv, 1, nv);
    out.tangent.Mp = pressure_mass(m);
  }
  out.internal_force = Eigen::VectorXd::Zero(3 * n);
  out.constraint = Eigen::VectorXd::Zero(nv);

  Eigen::Matrix<double, 30, 30> Ae;
  Eigen::Matrix<double, 4, 30> Be;
  for (int t = 0; t < m.num_tets(); ++t) {
    Ae.setZero();
    Be.setZero();
    Eigen::Matrix<double, 10, 3> X, U;
    for (int a = 0; a < 10; ++a) {
      X.row(a) = m.nodes.row(m.tets(t, a));
      U.row(a) = u.segment<3>(3 * m.tets(t, a)).transpose();
    }
    Eigen::Vector4d pe;
    for (int r = 0; r < 4; ++r) pe[r] = p[m.tets(t, r)];
    for (const auto& q : p2::quadrature_degree5()) {
      const p2::Grad10 dref = p2::shape_gradient(q.xi);
      const Eigen::Matrix3d dX = X.transpose() * dref;
      const double w = q.weight * dX.determinant();
      const Eigen::Matrix<double, 10, 3> G = dref * dX.inverse();  // ∂φ_a/∂X_J
      const auto L = p2::barycentric(q.xi);
      double pq = 0;
      for (int r = 0; r < 4; ++r) pq += L[r] * pe[r];
      const Eigen::Matrix3d F = Eigen::Matrix3d::Identity() + U.transpose() * G;
      const NeoHookeanPoint pt = neo_hookean(F, pq, mu);
      out.energy += w * pt.energy;
      // ∇φ_a e_i : T = Σ_J T_iJ ∂φ_a/∂X_J, so a node's rows of P : ∇φ are P G_aᵀ.
      const Eigen::Matrix<double, 10, 3> PG = G * pt.P.transpose();  // (a, i) = Σ_J P_iJ G_aJ
      for (int a = 0; a < 10; ++a)
        out.internal_force.segment<3>(3 * m.tets(t, a)) += w * PG.row(a).transpose();
      for (int r = 0; r < 4; ++r) out.constraint[m.tets(t, r)] -= w * L[r] * (pt.J - 1);
      if (!tangent) continue;
      const Eigen::Matrix<double, 10, 3> dPG = G * pt.dP_dp.transpose();
      // 𝔸 contracted with the gradients: for each node a and component i, the row (3i+J) of 𝔸 times G_aJ.
      Eigen::Matrix<double, 30, 9> GA;  // (3a + i, 3k + L) = Σ_J G_aJ 𝔸(3i + J, 3k + L)
      for (int a = 0; a < 10; ++a)
        for (int i = 0; i < 3; ++i) GA.row(3 * a + i) = G.row(a) * pt.A.block<3, 9>(3 * i, 0);
      for (int b = 0; b < 10; ++b)
        for (int k = 0; k < 3; ++k) Ae.col(3 * b + k) += w * GA.middleCols<3>(3 * k) * G.row(b).transpose();
      for (int r = 0; r < 4; ++r)
        for (int b = 0; b < 10; ++b)
          for (int k = 0; k < 3; ++k) Be(r, 3 * b + k) += w * L[r] * dPG(b, k);
    }
    if (tangent) pattern::add_element(m, t, Ae, Be, out.tangent.A, out.tangent.B);
  }
  return out;
}

double equilibrium_residual(const FiniteStrainSystem& s, const Eigen::VectorXd& f,
                            const std::vector<bool>& fixed, double force_scale, double volume,
                            Eigen::VectorXd* r_u) {
  Eigen::VectorXd r = f - s.internal_force;
  for (size_t d = 0; d < fixed.size(); ++d)
    if (fixed[d]) r[d] = 0;
  const double norm = std::hypot(r.norm() / force_scale, s.constraint.norm() / volume);
  if (r_u) *r_u = std::move(r);
  return norm;
}

}  // namespace skinfem
