#include "skinfem/green/meridian_mode.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "skinfem/fem/mumps_ldlt.hpp"
#include "skinfem/mesh/gauss_legendre.hpp"
#include "skinfem/mesh/surface_quadrature.hpp"

namespace skinfem {

void meridian_p2_line(double u, double L[3], double dL[3]) {
  L[0] = (1 - u) * (1 - 2 * u);
  L[1] = 4 * u * (1 - u);
  L[2] = u * (2 * u - 1);
  dL[0] = 4 * u - 3, dL[1] = 4 - 8 * u, dL[2] = 4 * u - 1;
}

double meridian_edge_parameter(double r0, double r1, double r2, double rho) {
  double u = (rho - r0) / (r2 - r0);
  for (int it = 0; it < 30; ++it) {
    double L[3], dL[3];
    meridian_p2_line(u, L, dL);
    const double step = (L[0] * r0 + L[1] * r1 + L[2] * r2 - rho) / (dL[0] * r0 + dL[1] * r1 + dL[2] * r2);
    u -= step;
    if (std::abs(step) < 1e-15) break;
  }
  return u;
}

size_t meridian_p2_weights(const std::vector<double>& r, double rho, double L[3]) {
  rho = std::clamp(rho, r.front(), r.back());
  size_t lo = 0, hi = (r.size() - 1) / 2;  // vertex numbers: r(2 lo) <= rho <= r(2 hi)
  while (hi - lo > 1) {
    const size_t mid = (lo + hi) / 2;
    (r[2 * mid] <= rho ? lo : hi) = mid;
  }
  const size_t s = 2 * lo;
  double dL[3];
  meridian_p2_line(meridian_edge_parameter(r[s], r[s + 1], r[s + 2], rho), L, dL);
  return s;
}

double meridian_interpolate(const std::vector<double>& r, const Eigen::Ref<const Eigen::VectorXd>& f,
                            double rho) {
  double L[3];
  const size_t s = meridian_p2_weights(r, rho, L);
  return L[0] * f[s] + L[1] * f[s + 1] + L[2] * f[s + 2];
}

namespace {
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Mode `mode`'s element matrices over the meridian (the integral over θ done: `theta`), scattered by the
// unknowns' numbering: the free block's lower triangle into MUMPS's coordinate arrays (it sums duplicates),
// and the rows of constrained DOFs (right-hand sides of prescribed values, reactions) as triplets: no
// assembled copy of the whole matrix.
void assemble_mode(const MeridianMesh& m, int mode, double mu, double inv_lambda,
                   const std::vector<int>& index, const std::vector<double>& sign, MumpsLdlt::Triplets& lower,
                   std::vector<Eigen::Triplet<double>>& constrained) {
  const int nc = mode == 0 ? 2 : 3, n = static_cast<int>(m.nodes.rows()), cW = nc - 1;
  const auto comp = [&](int node, int c) { return nc * node + c; };
  const double theta = mode == 0 ? 2 * M_PI : M_PI;  // ∫ cos² nθ dθ
  const int nl = 6 * nc + 3;  // local DOFs: displacements node by node, then the 3 vertex pressures
  const size_t reserve = static_cast<size_t>(m.tris.rows()) * nl * (nl + 1) / 2;
  lower.row.reserve(reserve), lower.col.reserve(reserve), lower.value.reserve(reserve);
  const int nrows = mode == 0 ? 4 : 6;  // ε_rr, ε_θθ, ε_zz, γ_rz (, γ_rθ, γ_θz)
  Eigen::VectorXd D(nrows);
  D << 2 * mu, 2 * mu, 2 * mu, mu, Eigen::VectorXd::Constant(nrows - 4, mu);
  Eigen::MatrixXd A(nl, nl), B(nrows, nl);
  Eigen::RowVectorXd div(nl);
  for (int e = 0; e < m.tris.rows(); ++e) {
    A.setZero();
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
      B.setZero();
      div.setZero();
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
      for (int j = 0; j < nl; ++j) {
        if (fi < 0) {
          constrained.emplace_back(g[i], g[j], A(i, j));
          continue;
        }
        const int fj = index[g[j]];
        if (fj >= 0 && fi >= fj) {  // both (i, j) and (j, i) land here when fi == fj (a tied pair)
          lower.row.push_back(fi), lower.col.push_back(fj);
          lower.value.push_back(sign[g[i]] * sign[g[j]] * A(i, j));
        }
      }
    }
  }
}
}  // namespace

MeridianMode::MeridianMode(const MeridianMesh& m, int mode, double nu, double mu, SideCondition side,
                           std::vector<int> held, const std::vector<int>& compliance_nodes)
    : mode_(mode),
      nc_(mode == 0 ? 2 : 3),
      n_(static_cast<int>(m.nodes.rows())),
      nv_(m.num_vertices),
      held_(std::move(held)) {
  if (mode != 0 && mode != 1) throw std::invalid_argument("MeridianMode: mode must be 0 or 1");
  auto clock = std::chrono::steady_clock::now();
  const int nc = nc_, n = n_, ndof = nc * n + m.num_vertices;
  const auto comp = [&](int node, int c) { return nc * node + c; };  // c: 0 U, then (mode 1) 1 V, last W
  const int cW = nc - 1;
  const double inv_lambda = nu >= 0.5 ? 0 : (1 - 2 * nu) / (2 * mu * nu);

  // Constraints. Held nodes and a held side: every component. Axis: mode 0 U = 0; mode 1 W = 0, P = 0 and
  // U + V = 0 (the displacement single-valued there), V tied to −U.
  fixed_.assign(ndof, 0);
  std::vector<int> tie(ndof, -1);
  if (side == SideCondition::fixed)
    for (int k : m.side)
      for (int c = 0; c < nc; ++c) fixed_[comp(k, c)] = 1;
  for (int k : held_)
    for (int c = 0; c < nc; ++c) fixed_[comp(k, c)] = 1;
  for (int k : m.axis) {
    if (mode == 0) {
      fixed_[comp(k, 0)] = 1;
    } else {
      fixed_[comp(k, cW)] = 1;
      if (!fixed_[comp(k, 1)]) tie[comp(k, 1)] = comp(k, 0);
      if (k < m.num_vertices) fixed_[nc * n + k] = 1;
    }
  }
  index_.assign(ndof, -1);
  std::vector<char> last(ndof, 0);  // the compliance nodes' free W unknowns, numbered after the others
  for (int k : compliance_nodes)
    if (!fixed_[comp(k, cW)] && tie[comp(k, cW)] < 0) last[comp(k, cW)] = 1;
  for (int d = 0; d < ndof; ++d)
    if (!fixed_[d] && tie[d] < 0 && !last[d]) index_[d] = free_++;
  for (int k : compliance_nodes)
    if (const int d = comp(k, cW); last[d])
      index_[d] = free_++, ++schur_, last[d] = 0;  // once if listed twice
  std::vector<int> schur_position;  // per compliance node: its W's position in the Schur block, −1 if held
  for (int k : compliance_nodes) {
    const int i = index_[comp(k, cW)];
    schur_position.push_back(i >= free_ - schur_ ? i - (free_ - schur_) : -1);
  }
  sign_.assign(ndof, 1.0);
  for (int d = 0; d < ndof; ++d)
    if (tie[d] >= 0) index_[d] = index_[tie[d]], sign_[d] = -1;

  MumpsLdlt::Triplets lower;
  std::vector<Eigen::Triplet<double>> constrained;
  assemble_mode(m, mode, mu, inv_lambda, index_, sign_, lower, constrained);
  Kc_.resize(ndof, ndof);
  Kc_.setFromTriplets(constrained.begin(), constrained.end());
  cost_.assemble_s += seconds_since(clock);
  clock = std::chrono::steady_clock::now();
  if (schur_ > 0) {
    const int ni = free_ - schur_;
    std::vector<Eigen::Triplet<double>> c;
    for (size_t t = 0; t < lower.row.size(); ++t)
      if (lower.row[t] >= ni && lower.col[t] < ni)
        c.emplace_back(lower.col[t], lower.row[t] - ni, lower.value[t]);
    coupling_.resize(ni, schur_);
    coupling_.setFromTriplets(c.begin(), c.end());
  }
  const std::vector<int> order =  // mumps_ldlt.hpp: with a Schur block MUMPS's own order fills 1.5× more here
      schur_ > 0 ? MumpsLdlt::min_degree_order(free_ - schur_, lower) : std::vector<int>{};
  solver_ = std::make_unique<MumpsLdlt>(free_, std::move(lower), schur_, FactorProgress{}, 5, true, order);
  if (schur_ > 0) {
    schur_ldlt_.compute(solver_->schur());
    if (schur_ldlt_.info() != Eigen::Success)
      throw std::runtime_error("MeridianMode: singular Schur complement");
    const Eigen::MatrixXd inverse = schur_ldlt_.solve(Eigen::MatrixXd::Identity(schur_, schur_));
    const int nn = static_cast<int>(compliance_nodes.size());
    compliance_ = Eigen::MatrixXd::Zero(nn, nn);  // a held node's row and column stay zero
    for (int i = 0; i < nn; ++i)
      for (int j = 0; j < nn; ++j)
        if (schur_position[i] >= 0 && schur_position[j] >= 0)
          compliance_(i, j) = inverse(schur_position[i], schur_position[j]);
  }
  cost_.factor_s += seconds_since(clock);
}

MeridianMode::~MeridianMode() = default;
MeridianMode::MeridianMode(MeridianMode&&) noexcept = default;

Eigen::MatrixXd MeridianMode::gather(const Fields& f, int columns, const std::vector<int>* nodes) const {
  Eigen::MatrixXd full = Eigen::MatrixXd::Zero(Kc_.rows(), columns);
  const int rows = nodes ? static_cast<int>(nodes->size()) : n_;
  const auto check = [&](const Eigen::MatrixXd& p, int expected) {
    if (p.size() != 0 && (p.rows() != expected || p.cols() != columns))
      throw std::invalid_argument("MeridianMode: a field block has the wrong shape");
    return p.size() != 0;
  };
  const Eigen::MatrixXd* parts[3] = {&f.U, &f.V, &f.W};
  for (int c = 0; c < nc_; ++c) {
    const Eigen::MatrixXd& p = *parts[c == nc_ - 1 ? 2 : c];
    if (!check(p, rows)) continue;
    for (int j = 0; j < columns; ++j)
      for (int i = 0; i < rows; ++i) full(nc_ * (nodes ? (*nodes)[i] : i) + c, j) = p(i, j);
  }
  if (!nodes && check(f.P, nv_)) full.bottomRows(nv_) = f.P;
  return full;
}

MeridianMode::Fields MeridianMode::scatter(const Eigen::MatrixXd& full) const {
  Fields f;
  const auto part = [&](int c) {
    Eigen::MatrixXd p(n_, full.cols());
    for (int j = 0; j < full.cols(); ++j)
      for (int i = 0; i < n_; ++i) p(i, j) = full(nc_ * i + c, j);
    return p;
  };
  f.U = part(0);
  if (mode_ == 1) f.V = part(1);
  f.W = part(nc_ - 1);
  f.P = full.bottomRows(nv_);
  return f;
}

MeridianMode::Fields MeridianMode::solve(const Fields& held_values, const Fields& load, int columns) const {
  const auto clock = std::chrono::steady_clock::now();
  Eigen::MatrixXd u = gather(held_values, columns, &held_);
  Eigen::MatrixXd residual = gather(load, columns, nullptr);
  // K's free rows times the prescribed values: by symmetry, K_c's columns (K(f, c) = K(c, f)).
  if (held_values.U.size() || held_values.V.size() || held_values.W.size()) residual -= Kc_.transpose() * u;
  // Column by column: the blocks are column-major, and a row-wise copy strides by their height.
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(free_, columns);
  for (int j = 0; j < columns; ++j)
    for (int d = 0; d < residual.rows(); ++d)
      if (index_[d] >= 0) rhs(index_[d], j) += sign_[d] * residual(d, j);
  Eigen::MatrixXd y;
  if (schur_ == 0) {
    y = solver_->solve(std::move(rhs));
  } else {
    // [K_ii K_is; K_si K_ss] y = b: y_s = S⁻¹ (b_s − K_si K_ii⁻¹ b_i), y_i = K_ii⁻¹ (b_i − K_is y_s).
    const int ni = free_ - schur_;
    const Eigen::MatrixXd zi = solver_->solve(Eigen::MatrixXd(rhs.topRows(ni)));
    y.resize(free_, columns);
    y.bottomRows(schur_) = schur_ldlt_.solve(rhs.bottomRows(schur_) - coupling_.transpose() * zi);
    y.topRows(ni) = solver_->solve(Eigen::MatrixXd(rhs.topRows(ni) - coupling_ * y.bottomRows(schur_)));
  }
  for (int j = 0; j < columns; ++j)
    for (int d = 0; d < u.rows(); ++d)
      if (index_[d] >= 0) u(d, j) = sign_[d] * y(index_[d], j);
  cost_.solve_s += seconds_since(clock);
  return scatter(u);
}

MeridianMode::Fields MeridianMode::reactions(const Fields& u, const Fields& load) const {
  const int columns = static_cast<int>(u.W.cols());
  Fields r = scatter(Kc_ * gather(u, columns, nullptr) - gather(load, columns, nullptr));
  r.P.resize(0, 0);
  return r;
}

MeridianTrace::MeridianTrace(const MeridianMesh& m, std::vector<int> nodes, double angular)
    : nodes_(std::move(nodes)) {
  const int nb = static_cast<int>(nodes_.size());
  if (nb < 3 || nb % 2 == 0) throw std::invalid_argument("MeridianTrace: needs whole P2 edges");
  for (int k : nodes_) r_.push_back(m.nodes(k, 0));
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(nb, nb);
  const GaussRule1d g = gauss_legendre01(4);  // P2 × P2 × r: degree 5
  for (int s = 0; s + 2 < nb; s += 2)
    for (size_t k = 0; k < g.x.size(); ++k) {
      double L[3], dL[3];
      meridian_p2_line(g.x[k], L, dL);
      const double r = L[0] * r_[s] + L[1] * r_[s + 1] + L[2] * r_[s + 2];
      const double drdu = dL[0] * r_[s] + dL[1] * r_[s + 1] + dL[2] * r_[s + 2];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) M(s + i, s + j) += g.w[k] * drdu * angular * r * L[i] * L[j];
    }
  mass_.compute(M);
}

Eigen::MatrixXd MeridianTrace::solve_mass(const Eigen::MatrixXd& b) const { return mass_.solve(b); }

Eigen::MatrixXd MeridianTrace::traction(const Eigen::MatrixXd& reactions) const {
  Eigen::MatrixXd b(nodes_.size(), reactions.cols());
  for (size_t i = 0; i < nodes_.size(); ++i) b.row(i) = reactions.row(nodes_[i]);
  return mass_.solve(b);
}

double MeridianTrace::value(const Eigen::Ref<const Eigen::VectorXd>& t, double rho) const {
  return meridian_interpolate(r_, t, rho);
}

}  // namespace skinfem
