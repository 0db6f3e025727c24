#include "skinfem/fem/assembly.hpp"

#include <algorithm>
#include <vector>

#include "skinfem/fem/sparse_pattern.hpp"
#include "skinfem/mesh/p2_tet.hpp"
#include "skinfem/mesh/quality.hpp"
#include "skinfem/mesh/surface_quadrature.hpp"

namespace skinfem {

bool is_affine(const TetMesh& m, int t) {
  const double tol = 1e-12 * tet_longest_edge(m, t);
  for (int e = 0; e < 6; ++e) {
    const auto mid =
        0.5 * (m.nodes.row(m.tets(t, p2::kEdge[e][0])) + m.nodes.row(m.tets(t, p2::kEdge[e][1])));
    if ((m.nodes.row(m.tets(t, 4 + e)) - mid).norm() > tol) return false;
  }
  return true;
}

MixedMatrices assemble_mixed(const TetMesh& m, const Lame& lame) {
  const int n = m.num_nodes(), nv = m.num_vertices;
  const auto adj = pattern::node_adjacency(m);
  MixedMatrices out;
  out.A = pattern::block_pattern(adj, 3 * n, 3, n);
  out.B = pattern::block_pattern(adj, nv, 1, nv);
  Eigen::Matrix<double, 30, 30> Ae;
  Eigen::Matrix<double, 4, 30> Be;
  for (int t = 0; t < m.num_tets(); ++t) {
    Ae.setZero();
    Be.setZero();
    Eigen::Matrix<double, 10, 3> X;
    for (int a = 0; a < 10; ++a) X.row(a) = m.nodes.row(m.tets(t, a));
    const auto& rule = is_affine(m, t) ? p2::quadrature_degree2() : p2::quadrature_degree5();
    for (const auto& q : rule) {
      const p2::Grad10 dref = p2::shape_gradient(q.xi);
      const Eigen::Matrix3d J = X.transpose() * dref;
      const double w = q.weight * J.determinant();
      const Eigen::Matrix<double, 10, 3> G = dref * J.inverse();  // ∂φ_a/∂x_k
      const auto L = p2::barycentric(q.xi);
      const Eigen::Matrix<double, 10, 10> GG = G * G.transpose();
      for (int a = 0; a < 10; ++a)
        for (int b = 0; b < 10; ++b)
          for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)  // 2μ ε(φ_a e_i):ε(φ_b e_j) = μ(δ_ij ∇φ_a·∇φ_b + ∂_jφ_a ∂_iφ_b)
              Ae(3 * a + i, 3 * b + j) += w * lame.mu * ((i == j ? GG(a, b) : 0.0) + G(a, j) * G(b, i));
      for (int r = 0; r < 4; ++r)
        for (int a = 0; a < 10; ++a)
          for (int i = 0; i < 3; ++i) Be(r, 3 * a + i) -= w * L[r] * G(a, i);
    }
    pattern::add_element(m, t, Ae, Be, out.A, out.B);
  }
  out.Mp = pressure_mass(m);
  return out;
}

SparseMatrixd pressure_mass(const TetMesh& m) {
  std::vector<Eigen::Triplet<double>> mp;
  mp.reserve(16 * m.num_tets());
  for (int t = 0; t < m.num_tets(); ++t) {
    Eigen::Matrix<double, 10, 3> X;
    for (int a = 0; a < 10; ++a) X.row(a) = m.nodes.row(m.tets(t, a));
    Eigen::Matrix4d Me = Eigen::Matrix4d::Zero();
    for (const auto& q : is_affine(m, t) ? p2::quadrature_degree2() : p2::quadrature_degree5()) {
      const p2::Grad10 dref = p2::shape_gradient(q.xi);
      const Eigen::Matrix3d J = X.transpose() * dref;
      const double w = q.weight * J.determinant();
      const auto L = p2::barycentric(q.xi);
      for (int r = 0; r < 4; ++r)
        for (int s = 0; s < 4; ++s) Me(r, s) += w * L[r] * L[s];
    }
    for (int r = 0; r < 4; ++r)
      for (int s = 0; s < 4; ++s) mp.emplace_back(m.tets(t, r), m.tets(t, s), Me(r, s));
  }
  SparseMatrixd Mp(m.num_vertices, m.num_vertices);
  Mp.setFromTriplets(mp.begin(), mp.end());
  return Mp;
}

Eigen::VectorXd body_load(const TetMesh& m, const VectorField& f) {
  Eigen::VectorXd F = Eigen::VectorXd::Zero(3 * m.num_nodes());
  for (int t = 0; t < m.num_tets(); ++t) {
    Eigen::Matrix<double, 10, 3> X;
    for (int a = 0; a < 10; ++a) X.row(a) = m.nodes.row(m.tets(t, a));
    for (const auto& q : p2::quadrature_degree5()) {
      const p2::Vec10 N = p2::shape(q.xi);
      const p2::Grad10 dref = p2::shape_gradient(q.xi);
      const Eigen::Matrix3d J = X.transpose() * dref;
      const double w = q.weight * J.determinant();
      const Eigen::Vector3d fx = f(X.transpose() * N);
      for (int a = 0; a < 10; ++a) F.segment<3>(3 * m.tets(t, a)) += w * N[a] * fx;
    }
  }
  return F;
}

Eigen::VectorXd traction_load(const TetMesh& m, int markers, const TractionField& t) {
  Eigen::VectorXd F = Eigen::VectorXd::Zero(3 * m.num_nodes());
  for (int f = 0; f < m.faces.rows(); ++f) {
    if (!(m.face_marker(f) & markers)) continue;
    for (const auto& q : face_quadrature(m, f)) {
      const Eigen::Vector3d tx = t(q.x, q.normal);
      for (int a = 0; a < 6; ++a) F.segment<3>(3 * m.faces(f, a)) += q.weight * q.N[a] * tx;
    }
  }
  return F;
}

Eigen::VectorXd nodal_traction_load(const TetMesh& m, int markers, const Eigen::MatrixX3d& traction) {
  Eigen::VectorXd F = Eigen::VectorXd::Zero(3 * m.num_nodes());
  for (int f = 0; f < m.faces.rows(); ++f) {
    if (!(m.face_marker(f) & markers)) continue;
    for (const auto& q : face_quadrature(m, f)) {
      Eigen::Vector3d tq = Eigen::Vector3d::Zero();
      for (int a = 0; a < 6; ++a) tq += q.N[a] * traction.row(m.faces(f, a)).transpose();
      for (int a = 0; a < 6; ++a) F.segment<3>(3 * m.faces(f, a)) += q.weight * q.N[a] * tq;
    }
  }
  return F;
}

}  // namespace skinfem
