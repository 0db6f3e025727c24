#include "green/meridian.hpp"

#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "fem/mumps_ldlt.hpp"
#include "green/halfspace.hpp"
#include "mesh/gauss_legendre.hpp"
#include "mesh/surface_quadrature.hpp"

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
// 1D P2 Lagrange basis on u ∈ [0, 1] with nodes 0, 1/2, 1 (as ordered along an edge: end, middle, end), and
// its derivative.
void p2_line(double u, double L[3], double dL[3]) {
  L[0] = (1 - u) * (1 - 2 * u);
  L[1] = 4 * u * (1 - u);
  L[2] = u * (2 * u - 1);
  dL[0] = 4 * u - 3, dL[1] = 4 - 8 * u, dL[2] = 4 * u - 1;
}

// One Fourier mode's adjoint solve: returns (U, V, W) at the top nodes. mode 0: u_r = U, u_z = W (V = 0);
// mode 1: u_r = U cos θ, u_θ = V sin θ, u_z = W cos θ, p = P cos θ. w: the reading's base weights, imposed as
// the base displacement (mode 0: W = −w; mode 1: U = w, V = −w, the x displacement w).
struct ModeField {
  std::vector<double> U, V, W;
  int dofs = 0;
};

ModeField solve_mode(const MeridianMesh& m, double nu, int mode, const Eigen::VectorXd& w) {
  const int n = static_cast<int>(m.nodes.rows()), nc = mode == 0 ? 2 : 3;  // displacement components
  const int ndof = nc * n + m.num_vertices;
  const auto comp = [&](int node, int c) { return nc * node + c; };  // c: 0 U, then (mode 1) 1 V, last W
  const int cW = nc - 1;
  const double mu = 1, theta = mode == 0 ? 2 * M_PI : M_PI;  // ∫ cos² nθ dθ
  const double inv_lambda = nu >= 0.5 ? 0 : (1 - 2 * nu) / (2 * mu * nu);

  // Constraints. Base: every component prescribed. Axis: mode 0 U = 0; mode 1 W = 0, P = 0 and U + V = 0
  // (the displacement single-valued there), V tied to −U.
  std::vector<char> fixed(ndof, 0);
  Eigen::VectorXd value = Eigen::VectorXd::Zero(ndof);
  std::vector<int> tie(ndof, -1);
  for (size_t s = 0; s < m.base.size(); ++s) {
    for (int c = 0; c < nc; ++c) fixed[comp(m.base[s], c)] = 1;
    if (mode == 0) {
      value[comp(m.base[s], cW)] = -w[s];
    } else {
      value[comp(m.base[s], 0)] = w[s];
      value[comp(m.base[s], 1)] = -w[s];
    }
  }
  for (int k : m.axis) {
    if (mode == 0) {
      fixed[comp(k, 0)] = 1;
    } else {
      fixed[comp(k, cW)] = 1;
      if (!fixed[comp(k, 1)]) tie[comp(k, 1)] = comp(k, 0);
      if (k < m.num_vertices) fixed[nc * n + k] = 1;
    }
  }
  std::vector<int> index(ndof, -1);
  int nf = 0;
  for (int d = 0; d < ndof; ++d)
    if (!fixed[d] && tie[d] < 0) index[d] = nf++;
  std::vector<double> sign(ndof, 1.0);
  for (int d = 0; d < ndof; ++d)
    if (tie[d] >= 0) index[d] = index[tie[d]], sign[d] = -1;

  std::vector<Eigen::Triplet<double>> trip;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(nf);
  const int nl = 6 * nc + 3;  // local DOFs: displacements node by node, then the 3 vertex pressures
  trip.reserve(static_cast<size_t>(m.tris.rows()) * nl * nl);
  const int nrows = mode == 0 ? 4 : 6;  // ε_rr, ε_θθ, ε_zz, γ_rz (, γ_rθ, γ_θz)
  Eigen::VectorXd D(nrows);
  D << 2 * mu, 2 * mu, 2 * mu, mu, Eigen::VectorXd::Constant(nrows - 4, mu);
  for (int e = 0; e < m.tris.rows(); ++e) {
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(nl, nl);
    double dxi[6], deta[6];
    for (const auto& q : triangle_rule_degree5()) {
      const Eigen::Matrix<double, 6, 1> N = triangle_shape(q.s, q.t);
      triangle_shape_gradient(q.s, q.t, dxi, deta);
      double J[2][2] = {{0, 0}, {0, 0}}, r = 0;
      for (int a = 0; a < 6; ++a) {
        const int k = m.tris(e, a);
        J[0][0] += m.nodes(k, 0) * dxi[a], J[0][1] += m.nodes(k, 0) * deta[a];
        J[1][0] += m.nodes(k, 1) * dxi[a], J[1][1] += m.nodes(k, 1) * deta[a];
        r += m.nodes(k, 0) * N[a];
      }
      const double det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
      if (!(det > 0)) throw std::runtime_error("meridian mesh: an element is inverted");
      const double wq = q.w * 0.5 * det * theta * r;
      Eigen::MatrixXd B = Eigen::MatrixXd::Zero(nrows, nl);
      Eigen::RowVectorXd div = Eigen::RowVectorXd::Zero(nl);
      for (int a = 0; a < 6; ++a) {
        const double dr = (J[1][1] * dxi[a] - J[1][0] * deta[a]) / det;
        const double dz = (-J[0][1] * dxi[a] + J[0][0] * deta[a]) / det;
        const double nr = N[a] / r;
        const int u = nc * a, wz = nc * a + cW;
        B(0, u) = dr, B(1, u) = nr, B(3, u) = dz;
        B(2, wz) = dz, B(3, wz) = dr;
        div(u) = dr + nr, div(wz) = dz;
        if (mode == 1) {
          const int v = nc * a + 1;
          B(1, v) = nr;
          B(4, u) = -nr, B(4, v) = dr - nr;
          B(5, v) = dz, B(5, wz) = -nr;
          div(v) = nr;
        }
      }
      const Eigen::Vector3d P(1 - q.s - q.t, q.s, q.t);
      const int np = 6 * nc;
      A.topLeftCorner(np, np).noalias() += wq * B.leftCols(np).transpose() * D.asDiagonal() * B.leftCols(np);
      A.block(np, 0, 3, np).noalias() -= wq * P * div.head(np);
      A.block(0, np, np, 3).noalias() -= wq * div.head(np).transpose() * P.transpose();
      A.bottomRightCorner(3, 3).noalias() -= wq * inv_lambda * P * P.transpose();
    }
    int g[6 * 3 + 3];
    for (int a = 0; a < 6; ++a)
      for (int c = 0; c < nc; ++c) g[nc * a + c] = comp(m.tris(e, a), c);
    for (int p = 0; p < 3; ++p) g[6 * nc + p] = nc * n + m.tris(e, p);
    for (int i = 0; i < nl; ++i) {
      const int fi = index[g[i]];
      if (fi < 0) continue;
      for (int j = 0; j < nl; ++j) {
        const double a = sign[g[i]] * A(i, j);
        if (index[g[j]] >= 0)
          trip.emplace_back(fi, index[g[j]], a * sign[g[j]]);
        else
          rhs[fi] -= a * value[g[j]];
      }
    }
  }
  Eigen::SparseMatrix<double> K(nf, nf);
  K.setFromTriplets(trip.begin(), trip.end());
  trip = {};
  const Eigen::VectorXd y = MumpsLdlt(K).solve(rhs);
  const auto at = [&](int d) { return fixed[d] ? value[d] : sign[d] * y[index[d]]; };
  ModeField f;
  f.dofs = nf;
  for (int k : m.top) {
    f.U.push_back(at(comp(k, 0)));
    f.V.push_back(mode == 1 ? at(comp(k, 1)) : 0.0);
    f.W.push_back(at(comp(k, cW)));
  }
  return f;
}
}  // namespace

MeridianGreen::MeridianGreen(const MeridianMesh& m, double nu) {
  // The reading's base weights w = M⁻¹ e_axis: M the base trace's mass matrix (weight 2πr), P2 along r. The
  // same M serves x readings: a traction τ(r) e_x has |e_x|² = 1 at every angle.
  const int nb = static_cast<int>(m.base.size());
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(nb, nb);
  const GaussRule1d g = gauss_legendre01(4);  // P2 × P2 × r: degree 5
  for (int s = 0; s + 2 < nb; s += 2)
    for (size_t k = 0; k < g.x.size(); ++k) {
      const double u = g.x[k];
      double L[3], dL[3];
      p2_line(u, L, dL);
      double r = 0, drdu = 0;
      for (int a = 0; a < 3; ++a)
        r += L[a] * m.nodes(m.base[s + a], 0), drdu += dL[a] * m.nodes(m.base[s + a], 0);
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) M(s + a, s + b) += g.w[k] * drdu * 2 * M_PI * r * L[a] * L[b];
    }
  const Eigen::VectorXd w = M.ldlt().solve(Eigen::VectorXd::Unit(nb, 0));
  // σ_z = t_z (the base's traction on the skin, whose outward normal is −e_z): impose −w along z. σ_x = −t_x:
  // impose +w along x.
  const ModeField z = solve_mode(m, nu, 0, w), x = solve_mode(m, nu, 1, w);
  dofs_ = z.dofs + x.dofs;
  for (size_t i = 0; i < m.top.size(); ++i) r_.push_back(m.nodes(m.top[i], 0));
  // Reciprocity (green/fe_green.hpp): g_ab(X) = f_a·y_b(X), f_z = −e_z (pressing), f_x = +e_x.
  zz_ = z.W, u0_ = z.U, w1_ = x.W, u1_ = x.U, v1_ = x.V;
  for (double& v : zz_) v = -v;
}

double MeridianGreen::interpolate(const std::vector<double>& f, double rho) const {
  rho = std::clamp(rho, r_.front(), r_.back());
  size_t s = 0;  // the top edge (nodes s, s+1, s+2) that holds rho
  while (s + 4 < r_.size() && rho > r_[s + 2]) s += 2;
  // Invert the edge's quadratic map r(u) by Newton from the linear guess, then interpolate.
  double u = (rho - r_[s]) / (r_[s + 2] - r_[s]);
  for (int it = 0; it < 30; ++it) {
    double L[3], dL[3];
    p2_line(u, L, dL);
    const double res = L[0] * r_[s] + L[1] * r_[s + 1] + L[2] * r_[s + 2] - rho;
    const double slope = dL[0] * r_[s] + dL[1] * r_[s + 1] + dL[2] * r_[s + 2];
    u -= res / slope;
  }
  double L[3], dL[3];
  p2_line(u, L, dL);
  return L[0] * f[s] + L[1] * f[s + 1] + L[2] * f[s + 2];
}

green::GreenSample MeridianGreen::at(double x, double y) const {
  const double rho = std::hypot(x, y);
  const double c = rho > 0 ? x / rho : 1, s = rho > 0 ? y / rho : 0;
  green::GreenSample g;
  g.zz = interpolate(zz_, rho);
  g.xz = interpolate(u0_, rho) * c;
  g.zx = -interpolate(w1_, rho) * c;
  g.xx = interpolate(u1_, rho) * c * c - interpolate(v1_, rho) * s * s;
  return g;
}

}  // namespace skinfem
