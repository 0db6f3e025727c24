#include "green/meridian.hpp"

#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "fem/mumps_ldlt.hpp"

namespace skinfem {

MeridianMesh meridian_mesh(const std::function<double(double)>& top, double radius, int nr, int nz,
                           double axis_grading, double layer_grading) {
  if (nr < 1 || nz < 1 || !(radius > 0) || axis_grading < 0 || layer_grading < 0 || layer_grading >= 1)
    throw std::invalid_argument("meridian_mesh: need nr, nz >= 1, radius > 0, gradings >= 0 and < 1");
  const int ni = 2 * nr + 1, nj = 2 * nz + 1;  // the P2 node grid
  MeridianMesh m;
  m.num_vertices = (nr + 1) * (nz + 1);
  m.nodes.resize(ni * nj, 2);
  std::vector<int> id(ni * nj);
  int next_vertex = 0, next_mid = m.num_vertices;
  for (int i = 0; i < ni; ++i)
    for (int j = 0; j < nj; ++j) {
      const int k = (i % 2 == 0 && j % 2 == 0) ? next_vertex++ : next_mid++;
      id[i * nj + j] = k;
      const double s = double(i) / (ni - 1), t = double(j) / (nj - 1);
      const double r =
          axis_grading > 0 ? radius * std::expm1(axis_grading * s) / std::expm1(axis_grading) : radius * s;
      const double tau = t - layer_grading * std::sin(2 * M_PI * t) / (2 * M_PI);
      m.nodes(k, 0) = r;
      m.nodes(k, 1) = top(r) * tau;
    }
  const auto at = [&](int i, int j) { return id[i * nj + j]; };
  m.tris.resize(2 * nr * nz, 6);
  int t = 0;
  for (int a = 0; a < nr; ++a)
    for (int b = 0; b < nz; ++b) {
      const int i = 2 * a, j = 2 * b;
      m.tris.row(t++) << at(i, j), at(i + 2, j), at(i + 2, j + 2), at(i + 1, j), at(i + 2, j + 1),
          at(i + 1, j + 1);
      m.tris.row(t++) << at(i, j), at(i + 2, j + 2), at(i, j + 2), at(i + 1, j + 1), at(i + 1, j + 2),
          at(i, j + 1);
    }
  for (int i = 0; i < ni; ++i) {
    m.base.push_back(at(i, 0));
    m.top.push_back(at(i, nj - 1));
  }
  for (int j = 0; j < nj; ++j) m.axis.push_back(at(0, j));
  return m;
}

namespace {
// Degree-5 rule on the reference triangle (Radon's 7 points), weights summing to 1.
struct TriPoint {
  double xi, eta, w;
};
std::vector<TriPoint> triangle_rule() {
  const double s = std::sqrt(15.0);
  const double a1 = (6 - s) / 21, b1 = (9 + 2 * s) / 21, w1 = (155 - s) / 1200;
  const double a2 = (6 + s) / 21, b2 = (9 - 2 * s) / 21, w2 = (155 + s) / 1200;
  return {{1.0 / 3, 1.0 / 3, 9.0 / 40},
          {a1, a1, w1},
          {b1, a1, w1},
          {a1, b1, w1},
          {a2, a2, w2},
          {b2, a2, w2},
          {a2, b2, w2}};
}

// P2 shape functions and their (ξ, η) derivatives, VTK quadratic-triangle order.
void p2_shape(double x, double y, double N[6], double dx[6], double dy[6]) {
  const double l0 = 1 - x - y, l1 = x, l2 = y;
  N[0] = l0 * (2 * l0 - 1), N[1] = l1 * (2 * l1 - 1), N[2] = l2 * (2 * l2 - 1);
  N[3] = 4 * l0 * l1, N[4] = 4 * l1 * l2, N[5] = 4 * l2 * l0;
  dx[0] = -(4 * l0 - 1), dx[1] = 4 * l1 - 1, dx[2] = 0, dx[3] = 4 * (l0 - l1), dx[4] = 4 * l2,
  dx[5] = -4 * l2;
  dy[0] = -(4 * l0 - 1), dy[1] = 0, dy[2] = 4 * l2 - 1, dy[3] = -4 * l1, dy[4] = 4 * l1,
  dy[5] = 4 * (l0 - l2);
}

// 1D P2 Lagrange basis on u ∈ [0, 1] with nodes 0, 1/2, 1 (as ordered along an edge: end, middle, end).
void p2_line(double u, double L[3]) {
  L[0] = (1 - u) * (1 - 2 * u);
  L[1] = 4 * u * (1 - u);
  L[2] = u * (2 * u - 1);
}
}  // namespace

MeridianGreen::MeridianGreen(const MeridianMesh& m, double nu) {
  const int n = static_cast<int>(m.nodes.rows()), nv = m.num_vertices;
  const int ndof = 2 * n + nv;
  const double mu = 1;  // g does not depend on the modulus
  const bool incompressible = nu >= 0.5;
  const double inv_lambda = incompressible ? 0 : (1 - 2 * nu) / (2 * mu * nu);
  std::vector<Eigen::Triplet<double>> trip;
  const auto rule = triangle_rule();
  trip.reserve(static_cast<size_t>(m.tris.rows()) * (144 + 72 + 9));
  for (int e = 0; e < m.tris.rows(); ++e) {
    Eigen::Matrix<double, 12, 12> A = Eigen::Matrix<double, 12, 12>::Zero();
    Eigen::Matrix<double, 3, 12> Bp = Eigen::Matrix<double, 3, 12>::Zero();  // −∫ p div v
    Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
    double N[6], dxi[6], deta[6];
    for (const auto& q : rule) {
      p2_shape(q.xi, q.eta, N, dxi, deta);
      double J[2][2] = {{0, 0}, {0, 0}}, r = 0;
      for (int a = 0; a < 6; ++a) {
        const int k = m.tris(e, a);
        J[0][0] += m.nodes(k, 0) * dxi[a], J[0][1] += m.nodes(k, 0) * deta[a];
        J[1][0] += m.nodes(k, 1) * dxi[a], J[1][1] += m.nodes(k, 1) * deta[a];
        r += m.nodes(k, 0) * N[a];
      }
      const double det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
      if (!(det > 0)) throw std::runtime_error("meridian mesh: an element is inverted");
      const double w = q.w * 0.5 * det * 2 * M_PI * r;
      // Strain rows (ε_rr, ε_θθ, ε_zz, γ_rz) of each displacement DOF (U then W per node), and its
      // divergence.
      Eigen::Matrix<double, 4, 12> B = Eigen::Matrix<double, 4, 12>::Zero();
      Eigen::Matrix<double, 1, 12> div;
      for (int a = 0; a < 6; ++a) {
        const double dr = (J[1][1] * dxi[a] - J[1][0] * deta[a]) / det;
        const double dz = (-J[0][1] * dxi[a] + J[0][0] * deta[a]) / det;
        B(0, 2 * a) = dr, B(1, 2 * a) = N[a] / r, B(3, 2 * a) = dz;
        B(2, 2 * a + 1) = dz, B(3, 2 * a + 1) = dr;
        div(2 * a) = dr + N[a] / r, div(2 * a + 1) = dz;
      }
      const Eigen::Vector4d D(2 * mu, 2 * mu, 2 * mu, mu);
      const Eigen::Vector3d P(1 - q.xi - q.eta, q.xi, q.eta);
      A.noalias() += w * B.transpose() * D.asDiagonal() * B;
      Bp.noalias() -= w * P * div;
      C.noalias() -= w * inv_lambda * P * P.transpose();
    }
    for (int i = 0; i < 12; ++i) {
      const int gi = 2 * m.tris(e, i / 2) + i % 2;
      for (int j = 0; j < 12; ++j) trip.emplace_back(gi, 2 * m.tris(e, j / 2) + j % 2, A(i, j));
      for (int p = 0; p < 3; ++p) {
        trip.emplace_back(gi, 2 * n + m.tris(e, p), Bp(p, i));
        trip.emplace_back(2 * n + m.tris(e, p), gi, Bp(p, i));
      }
    }
    if (!incompressible)
      for (int p = 0; p < 3; ++p)
        for (int s = 0; s < 3; ++s) trip.emplace_back(2 * n + m.tris(e, p), 2 * n + m.tris(e, s), C(p, s));
  }
  Eigen::SparseMatrix<double> K(ndof, ndof);
  K.setFromTriplets(trip.begin(), trip.end());

  // The reading's base weights w = M⁻¹ e_axis: M the base trace's mass matrix (weight 2πr), P2 along r.
  const int nb = static_cast<int>(m.base.size());
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(nb, nb);
  const double g[4] = {0.0694318442029737, 0.3300094782075719, 0.6699905217924281, 0.9305681557970263};
  const double gw[4] = {0.1739274225687269, 0.3260725774312731, 0.3260725774312731, 0.1739274225687269};
  for (int s = 0; s + 2 < nb; s += 2)
    for (int k = 0; k < 4; ++k) {
      double L[3], dL[3] = {4 * g[k] - 3, 4 - 8 * g[k], 4 * g[k] - 1};
      p2_line(g[k], L);
      double r = 0, drdu = 0;
      for (int a = 0; a < 3; ++a)
        r += L[a] * m.nodes(m.base[s + a], 0), drdu += dL[a] * m.nodes(m.base[s + a], 0);
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) M(s + a, s + b) += gw[k] * drdu * 2 * M_PI * r * L[a] * L[b];
    }
  const Eigen::VectorXd w = M.ldlt().solve(Eigen::VectorXd::Unit(nb, 0));

  // Prescribed: the base (U = 0, W = −w) and the axis (U = 0); the rest is free.
  Eigen::VectorXd fixed_value = Eigen::VectorXd::Zero(ndof);
  std::vector<char> fixed(ndof, 0);
  for (int s = 0; s < nb; ++s) {
    fixed[2 * m.base[s]] = fixed[2 * m.base[s] + 1] = 1;
    fixed_value[2 * m.base[s] + 1] = -w[s];
  }
  for (int k : m.axis) fixed[2 * k] = 1;
  std::vector<int> free_index(ndof, -1);
  int nf = 0;
  for (int d = 0; d < ndof; ++d)
    if (!fixed[d]) free_index[d] = nf++;
  std::vector<Eigen::Triplet<double>> kff;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(nf);
  for (int c = 0; c < K.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(K, c); it; ++it) {
      const int fr = free_index[it.row()];
      if (fr < 0) continue;
      if (free_index[it.col()] >= 0)
        kff.emplace_back(fr, free_index[it.col()], it.value());
      else
        rhs[fr] -= it.value() * fixed_value[it.col()];
    }
  Eigen::SparseMatrix<double> Kff(nf, nf);
  Kff.setFromTriplets(kff.begin(), kff.end());
  const MumpsLdlt ldlt(Kff);
  const Eigen::VectorXd y = ldlt.solve(rhs);
  dofs_ = nf;
  // A unit force pressing into the top (−e_z) at a top node: J = y·f = −W there.
  for (int k : m.top) {
    r_.push_back(m.nodes(k, 0));
    g_.push_back(-y[free_index[2 * k + 1]]);
  }
}

double MeridianGreen::zz(double rho) const {
  rho = std::clamp(rho, r_.front(), r_.back());
  size_t s = 0;  // the top edge (nodes s, s+1, s+2) that holds rho
  while (s + 4 < r_.size() && rho > r_[s + 2]) s += 2;
  // Invert the edge's quadratic map r(u) by Newton from the linear guess, then interpolate g.
  double u = (rho - r_[s]) / (r_[s + 2] - r_[s]);
  for (int it = 0; it < 30; ++it) {
    double L[3], dL[3] = {4 * u - 3, 4 - 8 * u, 4 * u - 1};
    p2_line(u, L);
    const double f = L[0] * r_[s] + L[1] * r_[s + 1] + L[2] * r_[s + 2] - rho;
    const double df = dL[0] * r_[s] + dL[1] * r_[s + 1] + dL[2] * r_[s + 2];
    u -= f / df;
  }
  double L[3];
  p2_line(u, L);
  return L[0] * g_[s] + L[1] * g_[s + 1] + L[2] * g_[s + 2];
}

}  // namespace skinfem
