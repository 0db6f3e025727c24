#include "contact/condensed.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>

namespace skinfem::contact {

namespace {
// Right-hand sides per MUMPS call: 64 is ~10 % faster per column than 32; the right-hand sides, their
// solutions and MUMPS's copies are ~4 dense blocks of 3N × 64 doubles (200 MB at 100k DOFs).
constexpr int kBlock = 64;
}  // namespace

CondensedContact condense(const ElasticModel& model, const MortarZone& zone, const Indenter& indenter,
                          const SensorReadings& readings, const Vec2& direction,
                          const std::function<void(double, const std::string&)>& progress,
                          const std::vector<int>& watch_faces) {
  const auto start = std::chrono::steady_clock::now();
  const TetMesh& m = model.mesh();
  const int nc = zone.size(), N = m.num_nodes();
  CondensedContact c;
  c.zone = zone;
  c.direction = Eigen::Vector2d(direction[0], direction[1]).normalized();
  c.gap0 = zone.weighted(
      m, [&](const Eigen::Vector3d& x) { return indenter.z_touch() + indenter.phi(x.x(), x.y()) - x.z(); });

  // D acting on one displacement component of a 3N vector: D_z picks u_z, D_t the slip direction's u_t.
  using RowSparse = Eigen::SparseMatrix<double, Eigen::RowMajor>;
  std::vector<Eigen::Triplet<double>> tz, tt;
  for (int i = 0; i < nc; ++i)
    for (RowSparse::InnerIterator it(zone.D, i); it; ++it) {
      tz.emplace_back(i, 3 * it.col() + 2, it.value());
      tt.emplace_back(i, 3 * it.col(), c.direction.x() * it.value());
      tt.emplace_back(i, 3 * it.col() + 1, c.direction.y() * it.value());
    }
  RowSparse D_z(nc, 3 * N), D_t(nc, 3 * N);
  D_z.setFromTriplets(tz.begin(), tz.end());
  D_t.setFromTriplets(tt.begin(), tt.end());

  // Adjoints of the sensor readings: base displacement −w, no load (fem/sensor_reading.hpp).
  const int ns = readings.size();
  const Eigen::MatrixXd W = -readings.weight_block();
  if (progress) progress(0.0, "adjoint solves for " + std::to_string(ns) + " sensors");
  const Eigen::MatrixXd Y = model.solver().solve_block(Eigen::MatrixXd::Zero(3 * N, 2 * ns), W);
  // reading = y·f: the pressure of multiplier i loads −e_z·(Dᵀe_i), its traction t·(Dᵀe_i).
  c.S_p = -(D_z * Y).transpose();
  c.S_t = (D_t * Y).transpose();
  c.block_solves += 2 * ns;

  // Watched nodes (hole_cut.hpp): where the multipliers' displacements and the adjoints are kept.
  std::vector<int> watch;  // mesh node → watched index, −1
  const auto t_of = [&](const Eigen::MatrixXd& X, int node, int col) {
    return c.direction.x() * X(3 * node, col) + c.direction.y() * X(3 * node + 1, col);
  };
  if (!watch_faces.empty()) {
    PathCompliance& p = c.path.emplace();
    p.indenter = std::make_shared<const Indenter>(indenter);
    watch.assign(N, -1);
    std::vector<int> mult(N, -1);
    for (int i = 0; i < nc; ++i) mult[zone.vertices[i]] = i;
    for (int f : watch_faces)
      for (int k = 0; k < 6; ++k)
        if (watch[m.faces(f, k)] < 0) {
          watch[m.faces(f, k)] = static_cast<int>(p.nodes.size());
          p.nodes.push_back(m.faces(f, k));
        }
    for (int f : watch_faces) {
      PathCompliance::Face face;
      for (int k = 0; k < 6; ++k) {
        face.x[k] = m.nodes.row(m.faces(f, k)).transpose();
        face.watched[k] = watch[m.faces(f, k)];
      }
      for (int k = 0; k < 3; ++k) face.multiplier[k] = mult[m.faces(f, k)];
      p.faces.push_back(face);
    }
    const int nw = static_cast<int>(p.nodes.size());
    std::vector<Eigen::Triplet<double>> dw;
    p.watched_hat.assign(nc, 1);
    for (int i = 0; i < nc; ++i)
      for (RowSparse::InnerIterator it(zone.D, i); it; ++it) {
        if (watch[it.col()] < 0)
          p.watched_hat[i] = 0;
        else
          dw.emplace_back(i, watch[it.col()], it.value());
      }
    p.Dw.resize(nc, nw);
    p.Dw.setFromTriplets(dw.begin(), dw.end());
    p.Wz.resize(nw, nc);
    p.Ut.resize(nw, nc);
    p.Rz.resize(nw, 2 * ns);
    p.Rt.resize(nw, 2 * ns);
    for (int k = 0; k < nw; ++k)
      for (int r = 0; r < 2 * ns; ++r) {
        p.Rz(k, r) = -Y(3 * p.nodes[k] + 2, r);  // reading = y·f, f = −e_z
        p.Rt(k, r) = t_of(Y, p.nodes[k], r);
      }
  }

  c.C_zz.resize(nc, nc);
  c.C_zt.resize(nc, nc);
  for (int j0 = 0; j0 < nc; j0 += kBlock) {
    const int k = std::min(kBlock, nc - j0);
    if (progress) progress(double(j0) / nc, "condensing onto " + std::to_string(nc) + " contact multipliers");
    Eigen::MatrixXd F = Eigen::MatrixXd::Zero(3 * N, k);
    for (int j = 0; j < k; ++j)
      for (RowSparse::InnerIterator it(D_z, j0 + j); it; ++it) F(it.col(), j) = -it.value();
    const Eigen::MatrixXd U = model.solver().solve_block(F);
    c.C_zz.middleCols(j0, k) = -(D_z * U);
    c.C_zt.middleRows(j0, k) = (D_t * U).transpose();
    c.block_solves += k;
    if (c.path)
      for (int w = 0; w < static_cast<int>(c.path->nodes.size()); ++w)
        for (int j = 0; j < k; ++j) {
          c.path->Wz(w, j0 + j) = -U(3 * c.path->nodes[w] + 2, j);
          c.path->Ut(w, j0 + j) = t_of(U, c.path->nodes[w], j);
        }
  }
  // A unit downward force at each watched node.
  if (c.path) {
    PathCompliance& p = *c.path;
    const int nw = static_cast<int>(p.nodes.size());
    p.Gzz.resize(nw, nw);
    p.Gtz.resize(nw, nw);
    p.DtG.resize(nc, nw);
    for (int j0 = 0; j0 < nw; j0 += kBlock) {
      const int k = std::min(kBlock, nw - j0);
      if (progress)
        progress(double(j0) / nw,
                 "compliance of the " + std::to_string(nw) + " nodes a swept hole can reach");
      Eigen::MatrixXd F = Eigen::MatrixXd::Zero(3 * N, k);
      for (int j = 0; j < k; ++j) F(3 * p.nodes[j0 + j] + 2, j) = -1.0;
      const Eigen::MatrixXd U = model.solver().solve_block(F);
      for (int j = 0; j < k; ++j)
        for (int w = 0; w < nw; ++w) {
          p.Gzz(w, j0 + j) = -U(3 * p.nodes[w] + 2, j);
          p.Gtz(w, j0 + j) = t_of(U, p.nodes[w], j);
        }
      p.DtG.middleCols(j0, k) = D_t * U;
      p.block_solves += k;
    }
    p.Gzz = 0.5 * (p.Gzz + p.Gzz.transpose()).eval();
    c.block_solves += p.block_solves;
  }
  // Symmetric by reciprocity up to the solver's round-off; make it exactly so for the LCP.
  c.C_zz = 0.5 * (c.C_zz + c.C_zz.transpose()).eval();
  if (progress) progress(1.0, "condensed");
  c.solve_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return c;
}

CutProblem cut_problem(const CondensedContact& c, const HoleCut& cut, bool tangential) {
  if (!c.path) throw std::logic_error("cut_problem: the condensed skin has no hole path");
  const PathCompliance& P = *c.path;
  const int n = c.zone.size();
  CutProblem out;
  out.gap0 = c.gap0 - cut.gap0;
  out.area = c.zone.area - cut.area;
  for (int i = 0; i < n; ++i)
    if (cut.B.row(i).nonZeros() > 0 || cut.area[i] != 0) out.rows.push_back(i);
  const auto& T = out.rows;
  const int t = static_cast<int>(T.size());
  // B's rows T (|T| × n_w, sparse: a row holds the nodes of the few faces the hole meets).
  std::vector<Eigen::Triplet<double>> bt;
  for (int a = 0; a < t; ++a)
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(cut.B, T[a]); it; ++it)
      bt.emplace_back(a, it.col(), it.value());
  Eigen::SparseMatrix<double, Eigen::RowMajor> BT(t, static_cast<int>(P.nodes.size()));
  BT.setFromTriplets(bt.begin(), bt.end());
  // C_zz' = C_zz − B Wz − (B Wz)ᵀ + B Gzz Bᵀ on rows T (hole_cut.hpp), with X = B_T Wz, Y = B_T Gzz B_Tᵀ.
  const Eigen::MatrixXd X = BT * P.Wz, Y = (BT * P.Gzz) * BT.transpose();
  out.zz.resize(t, n);
  out.sp.resize(c.S_p.rows(), t);
  for (int a = 0; a < t; ++a) out.zz.row(a) = c.C_zz.row(T[a]) - X.row(a);
  for (int a = 0; a < t; ++a)
    for (int b = 0; b < t; ++b) out.zz(a, T[b]) += -X(b, T[a]) + Y(a, b);
  const Eigen::MatrixXd BRz = BT * P.Rz, BRt = BT * P.Rt;
  for (int a = 0; a < t; ++a) out.sp.col(a) = c.S_p.col(T[a]) - BRz.row(a).transpose();
  // C_zt' = C_zt − (B Ut)ᵀ − B DtGᵀ + B Gtzᵀ Bᵀ, with Xt = B_T Ut, V = B_T DtGᵀ, Yt = B_T Gtzᵀ B_Tᵀ.
  Eigen::MatrixXd Xt, V, Yt;
  if (tangential) {
    Xt = BT * P.Ut;
    V = BT * P.DtG.transpose();
    Yt = (BT * P.Gtz.transpose()) * BT.transpose();
    out.zt_rows.resize(t, n);
    out.zt_cols.resize(t, n);
    out.zt_whole.resize(t, n);
    out.st.resize(c.S_t.rows(), t);
    for (int a = 0; a < t; ++a) {
      out.zt_whole.row(a) = c.C_zt.row(T[a]) - V.row(a);
      out.zt_rows.row(a) = out.zt_whole.row(a);
      out.zt_cols.row(a) = c.C_zt.col(T[a]).transpose() - Xt.row(a);
      out.st.col(a) = c.S_t.col(T[a]) - BRt.row(a).transpose();
    }
    for (int a = 0; a < t; ++a)
      for (int b = 0; b < t; ++b) {
        out.zt_rows(a, T[b]) += -Xt(b, T[a]) + Yt(a, b);
        out.zt_cols(b, T[a]) += -V(a, T[b]) + Yt(a, b);
      }
  }
  // Rows the hole leaves less than half of: from the cut load r = D_i − B_i itself, node by node, where the
  // hat lies on watched faces. The corrections above subtract O(1) terms to leave O(share^1.5) ones; these
  // have only r's own round-off, relative 1e-16 / share.
  std::vector<int> slivers;
  for (int a = 0; a < t; ++a) {
    const int i = T[a];
    if (!(out.area[i] < 0.5 * c.zone.area[i]) || !P.watched_hat[i]) continue;
    slivers.push_back(a);
    const Eigen::RowVectorXd r = Eigen::RowVectorXd(P.Dw.row(i)) - Eigen::RowVectorXd(BT.row(a));
    const Eigen::VectorXd wr = P.Gzz * r.transpose();
    out.zz.row(a) = r * P.Wz;
    const Eigen::VectorXd bw = BT * wr;
    for (int b = 0; b < t; ++b) out.zz(a, T[b]) -= bw[b];
    out.zz(a, i) = r.dot(wr);
    out.sp.col(a) = (r * P.Rz).transpose();
    if (tangential) {
      const Eigen::RowVectorXd whole = r * P.DtG.transpose();
      const Eigen::VectorXd gr = BT * (P.Gtz * r.transpose()), gc = BT * (P.Gtz.transpose() * r.transpose());
      out.zt_whole.row(a) = whole;
      out.zt_rows.row(a) = whole;
      out.zt_cols.row(a) = r * P.Ut;
      for (int b = 0; b < t; ++b) out.zt_rows(a, T[b]) -= gr[b], out.zt_cols(a, T[b]) -= gc[b];
      out.zt_rows(a, i) = out.zt_cols(a, i) = r * P.Gtz.transpose() * r.transpose();
      out.st.col(a) = (r * P.Rt).transpose();
    }
  }
  // A sliver's row is also every other cut row's entry in its column.
  for (int a : slivers)
    for (int b = 0; b < t; ++b) {
      out.zz(b, T[a]) = out.zz(a, T[b]);
      if (tangential) {
        out.zt_rows(b, T[a]) = out.zt_cols(a, T[b]);
        out.zt_cols(b, T[a]) = out.zt_rows(a, T[b]);
      }
    }
  return out;
}

Eigen::MatrixXd patched(Eigen::MatrixXd C, const std::vector<int>& rows, const Eigen::MatrixXd& new_rows,
                        const Eigen::MatrixXd& new_cols) {
  for (size_t a = 0; a < rows.size(); ++a) C.row(rows[a]) = new_rows.row(a);
  for (size_t a = 0; a < rows.size(); ++a) C.col(rows[a]) = new_cols.row(a).transpose();
  return C;
}

}  // namespace skinfem::contact
