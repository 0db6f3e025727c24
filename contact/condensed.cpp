#include "skinfem/contact/condensed.hpp"

#include <algorithm>
#include <chrono>
#include <optional>
#include <stdexcept>

namespace skinfem::contact {

namespace {
// Right-hand sides per MUMPS call: 64 is ~10 % faster per column than 32; the right-hand sides, their
// solutions and MUMPS's copies are ~4 dense blocks of 3N × 64 doubles (200 MB at 100k DOFs).
constexpr int kBlock = 64;
}  // namespace

CondenseColumns condense_columns(const TetMesh& m, const MortarZone& zone, const Eigen::MatrixXd& weights,
                                 const Vec2& direction, const std::vector<int>& watch_faces) {
  CondenseColumns c;
  const int N = m.num_nodes();
  const Eigen::Vector2d t = Eigen::Vector2d(direction[0], direction[1]).normalized();
  c.nc = zone.size();
  c.nr = static_cast<int>(weights.cols());
  std::vector<char> seen(N, 0);
  for (int f : watch_faces)
    for (int k = 0; k < 6; ++k)
      if (!seen[m.faces(f, k)]) {
        seen[m.faces(f, k)] = 1;
        c.watched.push_back(m.faces(f, k));
      }
  c.nw = static_cast<int>(c.watched.size());
  const int a0 = 0, b0 = c.nc, ez0 = 2 * c.nc, et0 = ez0 + c.nw, c0 = et0 + c.nw;
  std::vector<Eigen::Triplet<double>> f, u;
  using RowSparse = Eigen::SparseMatrix<double, Eigen::RowMajor>;
  for (int i = 0; i < c.nc; ++i)
    for (RowSparse::InnerIterator it(zone.D, i); it; ++it) {
      const int n = static_cast<int>(it.col());
      f.emplace_back(3 * n + 2, a0 + i, -it.value());
      f.emplace_back(3 * n, b0 + i, t.x() * it.value());
      f.emplace_back(3 * n + 1, b0 + i, t.y() * it.value());
    }
  for (int w = 0; w < c.nw; ++w) {
    f.emplace_back(3 * c.watched[w] + 2, ez0 + w, -1.0);
    f.emplace_back(3 * c.watched[w], et0 + w, t.x());
    f.emplace_back(3 * c.watched[w] + 1, et0 + w, t.y());
  }
  for (int r = 0; r < c.nr; ++r)
    for (int d = 0; d < weights.rows(); ++d)
      if (weights(d, r) != 0) u.emplace_back(d, c0 + r, -weights(d, r));
  c.coupling.F.resize(3 * N, c.size());
  c.coupling.F.setFromTriplets(f.begin(), f.end());
  c.coupling.U_fixed.resize(3 * N, c.size());
  c.coupling.U_fixed.setFromTriplets(u.begin(), u.end());
  c.coupling.solves_instead = c.nc + c.nw + c.nr;  // the sources a, ez, c
  return c;
}

CondensedContact condense(const ElasticModel& model, const MortarZone& zone, const Indenter& indenter,
                          const SensorReadings& readings, const Vec2& direction,
                          const std::function<void(double, const std::string&)>& progress,
                          const std::vector<int>& watch_faces, const CondenseColumns* bordered,
                          const std::function<void(const CondensedContact&)>& before_path) {
  return condense(model.mesh(), model.solver(), model.fixed(), zone, indenter, readings, direction, progress,
                  watch_faces, bordered, before_path);
}

CondensedContact condense(const TetMesh& m, const MixedSolver& solver, const std::vector<bool>& fixed,
                          const MortarZone& zone, const Indenter& indenter, const SensorReadings& readings,
                          const Vec2& direction,
                          const std::function<void(double, const std::string&)>& progress,
                          const std::vector<int>& watch_faces, const CondenseColumns* bordered,
                          const std::function<void(const CondensedContact&)>& before_path) {
  const auto start = std::chrono::steady_clock::now();
  CondensedContact c;
  c.zone = zone;
  c.direction = Eigen::Vector2d(direction[0], direction[1]).normalized();
  c.gap0 = zone.weighted(m, [&](const Eigen::Vector3d& x) { return indenter.gap_at_rest(x); });
  std::optional<CondenseColumns> own;
  if (!bordered) own = condense_columns(m, zone, readings.weight_block(), direction, watch_faces);
  const CondenseColumns& cols = bordered ? *bordered : *own;
  const int nc = cols.nc, nw = cols.nw, nr = cols.nr, nread = 2 * nc + 2 * nw;
  if (nc != zone.size() || nr != 2 * readings.size())
    throw std::logic_error("condense: the bordered columns are not this zone's and these sensors'");

  c.C_zz.resize(nc, nc);
  c.C_zt.resize(nc, nc);
  c.S_p.resize(nr, nc);
  c.S_t.resize(nr, nc);
  if (!watch_faces.empty()) {
    PathCompliance& p = c.path.emplace();
    p.indenter = std::make_shared<const Indenter>(indenter);
    p.nodes = cols.watched;
    std::vector<int> watch(m.num_nodes(), -1),
        mult(m.num_nodes(), -1);  // mesh node → watched index, multiplier
    for (int w = 0; w < nw; ++w) watch[p.nodes[w]] = w;
    for (int i = 0; i < nc; ++i) mult[zone.vertices[i]] = i;
    for (int f : watch_faces) {
      PathCompliance::Face face;
      for (int k = 0; k < 6; ++k) {
        face.x[k] = m.nodes.row(m.faces(f, k)).transpose();
        face.watched[k] = watch[m.faces(f, k)];
      }
      for (int k = 0; k < 3; ++k) face.multiplier[k] = mult[m.faces(f, k)];
      p.faces.push_back(face);
    }
    std::vector<Eigen::Triplet<double>> dw;
    p.watched_hat.assign(nc, 1);
    for (int i = 0; i < nc; ++i)
      for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(zone.D, i); it; ++it) {
        if (watch[it.col()] < 0)
          p.watched_hat[i] = 0;
        else
          dw.emplace_back(i, watch[it.col()], it.value());
      }
    p.Dw.resize(nc, nw);
    p.Dw.setFromTriplets(dw.begin(), dw.end());
    p.Wz.resize(nw, nc);
    p.Ut.resize(nw, nc);
    p.Rz.resize(nw, nr);
    p.Rt.resize(nw, nr);
    p.Gzz.resize(nw, nw);
    p.Gtz.resize(nw, nw);
    p.DtG.resize(nc, nw);
  }

  // Readouts [a | b | ez | et] (rows of G) of k sources from j0 on, placed where they belong.
  enum Source { multiplier, adjoint, watched };
  const auto place = [&](Source src, int j0, const Eigen::MatrixXd& G) {
    const int k = static_cast<int>(G.cols());
    const auto a = G.topRows(nc), b = G.middleRows(nc, nc), ez = G.middleRows(2 * nc, nw),
               et = G.bottomRows(nw);
    PathCompliance* p = c.path ? &*c.path : nullptr;
    if (src == multiplier) {
      c.C_zz.middleCols(j0, k) = a;
      c.C_zt.middleRows(j0, k) = b.transpose();
      if (p) p->Wz.middleCols(j0, k) = ez, p->Ut.middleCols(j0, k) = et;
    } else if (src == adjoint) {
      c.S_p.middleRows(j0, k) = a.transpose();
      c.S_t.middleRows(j0, k) = b.transpose();
      if (p) p->Rz.middleCols(j0, k) = ez, p->Rt.middleCols(j0, k) = et;
    } else {
      p->Gzz.middleCols(j0, k) = ez;
      p->Gtz.middleCols(j0, k) = et;
      p->DtG.middleCols(j0, k) = b;
    }
  };
  const struct {
    Source src;
    int first, count;
    std::string what;
  } sources[] = {
      {adjoint, nread, nr, "adjoint solves for " + std::to_string(readings.size()) + " sensors"},
      {multiplier, 0, nc, "condensing onto " + std::to_string(nc) + " contact multipliers"},
      {watched, 2 * nc, nw, "compliance of the " + std::to_string(nw) + " nodes a swept hole can reach"}};
  // The hole-free problem, as soon as its multipliers and adjoints are known (before the path's solves).
  const auto hole_free = [&] {
    if (!before_path || !c.path) return;
    CondensedContact pre;
    pre.zone = c.zone;
    pre.direction = c.direction;
    pre.C_zz = 0.5 * (c.C_zz + c.C_zz.transpose());
    pre.C_zt = c.C_zt;
    pre.gap0 = c.gap0;
    pre.S_p = c.S_p;
    pre.S_t = c.S_t;
    before_path(pre);
  };
  if (bordered && solver.coupling_products().size() > 0) {
    const Eigen::MatrixXd& G = solver.coupling_products();
    if (G.rows() != cols.size())
      throw std::logic_error("condense: the model was not factored with these columns");
    if (progress) progress(0.0, "condensing onto " + std::to_string(nc) + " contact multipliers (bordered)");
    for (const auto& s : sources)
      if (s.count > 0) place(s.src, 0, G.block(0, s.first, nread, s.count));
    hole_free();
  } else {
    // Readouts on the free DOFs only (the products' definition), as sparse rows.
    Eigen::SparseMatrix<double> R = cols.coupling.F.leftCols(nread);
    R.prune([&](int row, int, double) { return !fixed[row]; });
    const Eigen::SparseMatrix<double, Eigen::RowMajor> Rt = R.transpose();
    for (const auto& s : sources) {
      if (s.src == watched) hole_free();
      for (int j0 = 0; j0 < s.count; j0 += kBlock) {
        const int k = std::min(kBlock, s.count - j0);
        if (progress) progress(double(j0) / s.count, s.what);
        const Eigen::MatrixXd F = cols.coupling.F.middleCols(s.first + j0, k);
        const Eigen::MatrixXd U = s.src == adjoint
                                      ? Eigen::MatrixXd(cols.coupling.U_fixed.middleCols(s.first + j0, k))
                                      : Eigen::MatrixXd();
        place(s.src, j0, Rt * solver.solve_block(F, U));
        c.block_solves += k;
        if (s.src == watched) c.path->block_solves += k;
      }
    }
  }
  // Symmetric by reciprocity up to the solver's round-off; make them exactly so for the LCP.
  c.C_zz = 0.5 * (c.C_zz + c.C_zz.transpose()).eval();
  if (c.path) c.path->Gzz = 0.5 * (c.path->Gzz + c.path->Gzz.transpose()).eval();
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
  // C_zz' = C_zz − B Wz − (B Wz)ᵀ + B Gzz Bᵀ on rows T (holes/cut.hpp), with X = B_T Wz, Y = B_T Gzz B_Tᵀ.
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
    // r is sparse (the hat's nodes): every product below costs its few nodes' rows, not n_w of them.
    const Eigen::SparseMatrix<double, Eigen::RowMajor> r = P.Dw.row(i) - BT.row(a);  // 1 × n_w
    const Eigen::VectorXd wr = P.Gzz * r.transpose();
    out.zz.row(a) = r * P.Wz;
    const Eigen::VectorXd bw = BT * wr;
    for (int b = 0; b < t; ++b) out.zz(a, T[b]) -= bw[b];
    out.zz(a, i) = (r * wr)(0);
    out.sp.col(a) = (r * P.Rz).transpose();
    if (tangential) {
      const Eigen::VectorXd tr = P.Gtz * r.transpose(), ttr = P.Gtz.transpose() * r.transpose();
      const Eigen::RowVectorXd whole = r * P.DtG.transpose();
      const Eigen::VectorXd gr = BT * tr, gc = BT * ttr;
      out.zt_whole.row(a) = whole;
      out.zt_rows.row(a) = whole;
      out.zt_cols.row(a) = r * P.Ut;
      for (int b = 0; b < t; ++b) out.zt_rows(a, T[b]) -= gr[b], out.zt_cols(a, T[b]) -= gc[b];
      out.zt_rows(a, i) = out.zt_cols(a, i) = (r * tr)(0);
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
