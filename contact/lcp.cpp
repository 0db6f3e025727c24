#include "skinfem/contact/lcp.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>

namespace skinfem::contact {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

constexpr double kEps = std::numeric_limits<double>::epsilon();
// Round-off allowance of the feasibility tests: a principal solve is accurate to ~κ·ε, κ ≲ 1e3 here.
constexpr double kFeasible = 1e-12;
// Full exchanges allowed after the infeasibility count stopped falling (Kim & Park use 3).
constexpr int kBackup = 3;
// A stored factorization is updated rather than replaced while |R| + |P| ≤ this fraction of its size.
constexpr double kLowRank = 0.25;
// Residual of a refined low-rank solve above which the system is solved again by dense LU.
constexpr double kResidual = 1e-10;

std::string sci(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1e", x);
  return buf;
}

// Throws unless the LU of a principal system is regular to working precision: "<who>: singular principal
// system (N unknowns, reciprocal condition r)<context>".
void require_regular(const Eigen::PartialPivLU<MatrixXd>& lu, const std::string& who,
                     const std::string& context) {
  const double rcond = lu.rcond(), unknowns = static_cast<double>(lu.rows());
  if (!(rcond > kEps * unknowns))
    throw std::runtime_error(who + ": singular principal system (" + std::to_string(lu.rows()) +
                             " unknowns, reciprocal condition " + sci(rcond) + ")" + context);
}

// Principal systems live on extended indices: 0..n−1 the multipliers, n the scaled approach δ/σ. The
// extended matrix is K = [M, −σm; σmᵀ, 0] and the right-hand side b = [−q + δm (depth only); σF (force)].
struct System {
  const MatrixXd& M;
  const VectorXd& q;
  const VectorXd& m;
  double sigma;
  bool force;
  double value;  // F or δ
  int n;

  double rhs(int i) const { return i < n ? -q[i] + (force ? 0.0 : value * m[i]) : sigma * value; }
  // K(rows, cols), gathered column by column.
  MatrixXd block(const std::vector<int>& rows, const std::vector<int>& cols) const {
    MatrixXd B(rows.size(), cols.size());
    for (size_t c = 0; c < cols.size(); ++c) {
      const int j = cols[c];
      if (j < n) {
        const double* col = M.col(j).data();
        for (size_t r = 0; r < rows.size(); ++r) B(r, c) = rows[r] < n ? col[rows[r]] : sigma * m[j];
      } else {
        for (size_t r = 0; r < rows.size(); ++r) B(r, c) = rows[r] < n ? -sigma * m[rows[r]] : 0.0;
      }
    }
    return B;
  }
};

// A factorization of K over `set` (ascending extended indices): the stored inverse Z of the reference, or a
// dense LU made during this solve. Columns it produces are cached by extended index for the whole solve.
struct Base {
  std::vector<int> set;
  std::vector<int> pos;  // extended index → position in set, −1 if absent
  const MatrixXd* Z = nullptr;
  // Indices whose rows and columns differ from the ones Z was made of: never common, always re-added.
  const std::vector<char>* dirty = nullptr;
  Eigen::PartialPivLU<MatrixXd> lu;
  std::vector<VectorXd> w_cache;  // j ∉ set: base⁻¹ K(set, j)
  std::vector<VectorXd> z_cache;  // j ∈ set (LU only): base⁻¹ e_pos(j)

  void assign(std::vector<int> s, int n_ext) {
    set = std::move(s);
    pos.assign(n_ext, -1);
    for (size_t r = 0; r < set.size(); ++r) pos[set[r]] = static_cast<int>(r);
    w_cache.assign(n_ext, VectorXd());
    z_cache.assign(n_ext, VectorXd());
  }
  int size() const { return static_cast<int>(set.size()); }
  VectorXd solve(const VectorXd& b) const { return Z ? VectorXd(*Z * b) : VectorXd(lu.solve(b)); }
  MatrixXd solve(const MatrixXd& B) const { return Z ? MatrixXd(*Z * B) : MatrixXd(lu.solve(B)); }
  // Removed and added indices of a target set B (ascending).
  int difference(const std::vector<int>& B, std::vector<int>* R, std::vector<int>* P) const {
    int common = 0, added = 0;
    const auto stale = [&](int i) { return dirty && i < static_cast<int>(dirty->size()) && (*dirty)[i]; };
    for (int i : B) {
      if (pos[i] >= 0 && !stale(i)) {
        ++common;
      } else {
        ++added;
        if (P) P->push_back(i);
      }
    }
    if (R) {
      std::vector<char> in_b(pos.size(), 0);
      for (int i : B) in_b[i] = 1;
      for (int r = 0; r < size(); ++r)
        if (!in_b[set[r]] || stale(set[r])) R->push_back(r);
    }
    return size() - common + added;
  }
};

// Solves the principal systems K_BB x = b_B of one LCP solve, through a dense LU or a low-rank update of a
// base. With T = base ∪ P and the removed rows R (positions in the base):
//   [K0 K0P E_R; KP0 KPP 0; E_Rᵀ 0 0] [x0; xP; μ] = [b0; bP; 0]
// (μ frees the equations of R, the last rows pin x_R = 0). With y0 = K0⁻¹b0, W = K0⁻¹K0P, ZR = K0⁻¹E_R:
// x0 = y0 − W xP − ZR μ and the capacitance system [KPP − KP0 W, −KP0 ZR; W_R, ZR_R] [xP; μ] =
// [bP − KP0 y0; y0_R].
class Principal {
 public:
  Principal(const System& sys, const std::vector<int>* ref_set, const MatrixXd* Z,
            const std::vector<char>* dirty = nullptr)
      : sys_(sys) {
    if (Z) {
      ref_.assign(*ref_set, sys.n + 1);
      ref_.Z = Z;
      ref_.dirty = dirty;
      has_ref_ = true;
    }
  }

  // Prepares the system of B (ascending). Returns true if it is a low-rank update; throws if B is singular.
  bool prepare(const std::vector<int>& B, int pivot, bool allow_lowrank) {
    B_ = B;
    if (B.empty()) {
      base_ = nullptr;
      return false;
    }
    if (allow_lowrank) {
      Base* best = nullptr;
      int best_diff = 0;
      for (Base* b : {has_ref_ ? &ref_ : nullptr, has_own_ ? &own_ : nullptr}) {
        if (!b) continue;
        const int d = b->difference(B, nullptr, nullptr);
        if (d <= kLowRank * b->size() && (!best || d < best_diff)) best = b, best_diff = d;
      }
      if (best && update(*best)) return true;
    }
    const MatrixXd K = sys_.block(B, B);
    own_.lu.compute(K);
    require_regular(own_.lu, "contact LCP", " at pivot " + std::to_string(pivot) + ": M is not a P-matrix");
    own_.assign(B, sys_.n + 1);
    has_own_ = true;
    base_ = &own_;
    P_.clear();
    R_.clear();
    return false;
  }

  // x over the extended indices (0 off B) for the right-hand side b (extended, read on B).
  VectorXd solve(const VectorXd& b) const {
    VectorXd x = VectorXd::Zero(sys_.n + 1);
    if (!base_) return x;
    const Base& base = *base_;
    const int k0 = base.size(), np = static_cast<int>(P_.size()), nr = static_cast<int>(R_.size());
    VectorXd b0(k0);
    for (int r = 0; r < k0; ++r) b0[r] = b[base.set[r]];
    for (int r : R_) b0[r] = 0.0;  // the equations of R are dropped: any value
    const VectorXd y0 = base.solve(b0);
    if (np + nr == 0) {
      for (int r = 0; r < k0; ++r) x[base.set[r]] = y0[r];
      return x;
    }
    VectorXd rhs(np + nr);
    for (int j = 0; j < np; ++j) rhs[j] = b[P_[j]];
    if (np > 0) rhs.head(np) -= KP0_ * y0;
    for (int a = 0; a < nr; ++a) rhs[np + a] = y0[R_[a]];
    const VectorXd z = small_.solve(rhs);
    VectorXd x0 = y0;
    if (np > 0) x0 -= W_ * z.head(np);
    if (nr > 0) x0 -= ZR_ * z.tail(nr);
    for (int r = 0; r < k0; ++r) x[base.set[r]] = x0[r];
    for (int a : R_) x[base.set[a]] = 0.0;
    for (int j = 0; j < np; ++j) x[P_[j]] = z[j];
    return x;
  }

 private:
  bool update(Base& base) {
    P_.clear();
    R_.clear();
    base.difference(B_, &R_, &P_);
    const int k0 = base.size(), np = static_cast<int>(P_.size()), nr = static_cast<int>(R_.size());
    base_ = &base;
    if (np + nr == 0) return true;
    // Columns W = K0⁻¹ K(set, P), new ones in one block product.
    std::vector<int> fresh;
    for (int j : P_)
      if (base.w_cache[j].size() == 0) fresh.push_back(j);
    if (!fresh.empty()) {
      const MatrixXd Wf = base.solve(sys_.block(base.set, fresh));
      for (size_t c = 0; c < fresh.size(); ++c) base.w_cache[fresh[c]] = Wf.col(c);
    }
    W_.resize(k0, np);
    for (int j = 0; j < np; ++j) W_.col(j) = base.w_cache[P_[j]];
    ZR_.resize(k0, nr);
    if (base.Z) {
      for (int a = 0; a < nr; ++a) ZR_.col(a) = base.Z->col(R_[a]);
    } else {
      std::vector<int> missing;
      for (int a : R_)
        if (base.z_cache[base.set[a]].size() == 0) missing.push_back(a);
      if (!missing.empty()) {
        MatrixXd E = MatrixXd::Zero(k0, missing.size());
        for (size_t c = 0; c < missing.size(); ++c) E(missing[c], c) = 1.0;
        const MatrixXd Zm = base.solve(E);
        for (size_t c = 0; c < missing.size(); ++c) base.z_cache[base.set[missing[c]]] = Zm.col(c);
      }
      for (int a = 0; a < nr; ++a) ZR_.col(a) = base.z_cache[base.set[R_[a]]];
    }
    KP0_ = sys_.block(P_, base.set);
    MatrixXd G(np + nr, np + nr);
    if (np > 0) {
      G.topLeftCorner(np, np) = sys_.block(P_, P_) - KP0_ * W_;
      G.topRightCorner(np, nr) = -KP0_ * ZR_;
    }
    for (int a = 0; a < nr; ++a) {
      for (int j = 0; j < np; ++j) G(np + a, j) = W_(R_[a], j);
      for (int c = 0; c < nr; ++c) G(np + a, np + c) = ZR_(R_[a], c);
    }
    small_.compute(G);
    // A singular capacitance matrix means B itself is singular (or nearly): the dense LU decides.
    return G.allFinite() && small_.rcond() > kEps * static_cast<double>(np + nr);
  }

  const System& sys_;
  Base ref_, own_;
  bool has_ref_ = false, has_own_ = false;
  const Base* base_ = nullptr;
  std::vector<int> B_, P_, R_;
  MatrixXd W_, ZR_, KP0_;
  Eigen::PartialPivLU<MatrixXd> small_;
};

}  // namespace

ContactLcp::ContactLcp(Eigen::MatrixXd M, Eigen::VectorXd q, Eigen::VectorXd m)
    : M_(std::move(M)), q_(std::move(q)), m_(std::move(m)) {
  if (M_.rows() != M_.cols() || M_.rows() != q_.size() || q_.size() != m_.size())
    throw std::invalid_argument("ContactLcp: M must be n×n with q and m of size n, got M " +
                                std::to_string(M_.rows()) + "×" + std::to_string(M_.cols()) + ", q " +
                                std::to_string(q_.size()) + ", m " + std::to_string(m_.size()));
  if (!M_.allFinite() || !q_.allFinite() || !m_.allFinite())
    throw std::invalid_argument("ContactLcp: non-finite entries in M, q or m");
  if (m_.size() > 0 && !(m_.minCoeff() > 0))
    throw std::invalid_argument("ContactLcp: every m_i must be > 0, got min " +
                                std::to_string(m_.minCoeff()));
  if (m_.size() > 0) {
    const double d = M_.diagonal().cwiseAbs().maxCoeff();
    sigma_ = d > 0 ? d / m_.maxCoeff() : 1.0;
  }
}

namespace {
VectorXd shifted(const VectorXd& q, const VectorXd& shift) {
  if (shift.size() == 0) return q;
  if (shift.size() != q.size() || !shift.allFinite())
    throw std::invalid_argument("ContactLcp: q_shift must hold " + std::to_string(q.size()) +
                                " finite values, got " + std::to_string(shift.size()));
  return q + shift;
}

// The multipliers excluded (under a hole) and bilateral (held in contact), as flags over the n multipliers.
struct Flags {
  const std::vector<char>& excluded;
  const std::vector<char>& bilateral;
  bool is_excluded(int i) const { return !excluded.empty() && excluded[i] != 0; }
  bool is_bilateral(int i) const { return !bilateral.empty() && bilateral[i] != 0 && !is_excluded(i); }
  bool unilateral(int i) const { return !is_excluded(i) && !is_bilateral(i); }  // complementarity holds
};

// The principal set to start from: the warm start's multipliers; cold, the rigid overlap (displacement
// control) or the overlap of a local model (force control). Bilateral multipliers are always in.
std::vector<char> starting_set(int n, const MatrixXd& M, const VectorXd& q, const VectorXd& m, bool force,
                               double value, const std::vector<int>& warm, const Flags& flags) {
  std::vector<char> in(n, 0);  // the current principal set S
  int allowed = 0;
  for (int i = 0; i < n; ++i) allowed += !flags.is_excluded(i);
  if (force && allowed == 0)
    throw std::runtime_error(
        "contact LCP: every multiplier is excluded (the hole covers the zone) at pivot 0");
  for (int i : warm) {
    if (i < 0 || i >= n)
      throw std::invalid_argument("ContactLcp: warm-start index " + std::to_string(i) + " outside [0, " +
                                  std::to_string(n) + ")");
    if (!flags.is_excluded(i)) in[i] = 1;
  }
  const bool cold = std::find(in.begin(), in.end(), 1) == in.end();
  if (cold && !force) {  // the rigid overlap
    for (int i = 0; i < n; ++i) in[i] = !flags.is_excluded(i) && q[i] < value * m[i];
  } else if (cold) {
    // The overlap of the local model λ_i = (δ m_i − q_i)/M_ii, whose force Σ m_i λ_i over the overlap is
    // piecewise linear in δ: exact in one pass over q_i/m_i ascending. Without M's coupling it is stiffer
    // than M, so its overlap is usually smaller than the contact; the first exchanges grow it (n = 1521: 326
    // → 1490 → … → 1006 in 7 exchanges, 3 of them dense).
    std::vector<int> order;
    for (int i = 0; i < n; ++i)
      if (!flags.is_excluded(i)) order.push_back(i);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return q[a] / m[a] < q[b] / m[b]; });
    double sa = 0, sb = 0;  // Σ m_i²/M_ii, Σ m_i q_i/M_ii over the overlap
    size_t k = 0;
    for (; k < order.size(); ++k) {
      const int i = order[k];
      const double d = std::max(std::abs(M(i, i)), kEps);
      if (k > 0 && (value + sb) / sa <= q[i] / m[i]) break;
      sa += m[i] * m[i] / d;
      sb += m[i] * q[i] / d;
    }
    for (size_t c = 0; c < std::max<size_t>(k, 1); ++c) in[order[c]] = 1;
  }
  for (int i = 0; i < n; ++i)
    if (flags.is_bilateral(i)) in[i] = 1;
  return in;
}

// The solution's active set and how well it meets the complementarity conditions (LcpSolution's fields).
void judge(LcpSolution& s, const std::vector<char>& in, const Flags& flags, double q_scale, double m_max) {
  const int n = static_cast<int>(in.size());
  s.active.clear();
  for (int i = 0; i < n; ++i)
    if (in[i]) s.active.push_back(i);
  double lambda_max = 0, product = 0;
  s.min_lambda = 0;
  s.min_gap = 0;
  bool first = true;
  for (int i = 0; i < n; ++i) {
    if (!flags.unilateral(i)) continue;
    lambda_max = std::max(lambda_max, s.lambda[i]);
    product = std::max(product, std::abs(s.lambda[i] * s.gap[i]));
    s.min_lambda = first ? s.lambda[i] : std::min(s.min_lambda, s.lambda[i]);
    s.min_gap = first ? s.gap[i] : std::min(s.min_gap, s.gap[i]);
    first = false;
  }
  const double g_scale = q_scale + std::abs(s.delta) * m_max;
  s.complementarity = lambda_max > 0 && g_scale > 0 ? product / (lambda_max * g_scale) : 0.0;
}
}  // namespace

LcpSolution ContactLcp::solve_force(double F, const std::vector<char>& excluded, const std::vector<int>& warm,
                                    const VectorXd& q_shift, const std::vector<char>& bilateral) const {
  if (!(F > 0) || !std::isfinite(F))
    throw std::invalid_argument("ContactLcp::solve_force: F must be finite and > 0, got " +
                                std::to_string(F));
  return solve(true, F, excluded, warm, shifted(q_, q_shift), nullptr, bilateral);
}

LcpSolution ContactLcp::solve_depth(double delta, const std::vector<char>& excluded,
                                    const std::vector<int>& warm, const VectorXd& q_shift,
                                    const std::vector<char>& bilateral) const {
  if (!std::isfinite(delta)) throw std::invalid_argument("ContactLcp::solve_depth: delta must be finite");
  return solve(false, delta, excluded, warm, shifted(q_, q_shift), nullptr, bilateral);
}

LcpSolution ContactLcp::solve_changed(const MatrixXd& M, const VectorXd& q, const VectorXd& m,
                                      const std::vector<char>& dirty, bool force, double value,
                                      const std::vector<char>& excluded, const std::vector<int>& warm) const {
  const int n = size();
  if (M.rows() != n || M.cols() != n || q.size() != n || m.size() != n || static_cast<int>(dirty.size()) != n)
    throw std::invalid_argument("ContactLcp::solve_changed: sizes differ from the problem's " +
                                std::to_string(n));
  if (!M.allFinite() || !q.allFinite() || !(m.array() > 0).all())
    throw std::invalid_argument("ContactLcp::solve_changed: non-finite entries or an area <= 0");
  if (force && !(value > 0 && std::isfinite(value)))
    throw std::invalid_argument("ContactLcp::solve_changed: F must be finite and > 0");
  const Changed changed{&M, &m, &dirty};
  return solve(force, value, excluded, warm, q, &changed);
}

void ContactLcp::set_reference(const std::vector<int>& active) {
  const int n = size();
  std::vector<int> a = active;
  std::sort(a.begin(), a.end());
  a.erase(std::unique(a.begin(), a.end()), a.end());
  if (a.empty() || a.front() < 0 || a.back() >= n)
    throw std::invalid_argument(
        "ContactLcp::set_reference: the active set must be non-empty indices in [0, " + std::to_string(n) +
        ")");
  std::vector<int> set = a;
  set.push_back(n);
  const System sys{M_, q_, m_, sigma_, true, 1.0, n};
  const Eigen::PartialPivLU<MatrixXd> lu(sys.block(set, set));
  require_regular(lu, "ContactLcp::set_reference", "");
  Z_ = lu.inverse();
  ref_active_ = std::move(a);
  ref_set_ = std::move(set);
}

void ContactLcp::clear_reference() {
  ref_active_.clear();
  ref_set_.clear();
  Z_.resize(0, 0);
}

LcpSolution ContactLcp::solve(bool force, double value, const std::vector<char>& excluded,
                              const std::vector<int>& warm, const VectorXd& q, const Changed* changed,
                              const std::vector<char>& bilateral) const {
  const int n = size();
  const MatrixXd& M = changed ? *changed->M : M_;  // the matrix and areas solved with
  const VectorXd& m = changed ? *changed->m : m_;
  if (!excluded.empty() && static_cast<int>(excluded.size()) != n)
    throw std::invalid_argument("ContactLcp: excluded has " + std::to_string(excluded.size()) +
                                " flags for " + std::to_string(n) + " multipliers");
  if (!bilateral.empty() && static_cast<int>(bilateral.size()) != n)
    throw std::invalid_argument("ContactLcp: bilateral has " + std::to_string(bilateral.size()) +
                                " flags for " + std::to_string(n) + " multipliers");
  const Flags flags{excluded, bilateral};
  std::vector<char> in = starting_set(n, M, q, m, force, value, warm, flags);  // the current principal set S
  const System sys{M, q, m, sigma_, force, value, n};
  Principal principal(sys, ref_set_.empty() ? nullptr : &ref_set_, ref_set_.empty() ? nullptr : &Z_,
                      changed ? changed->dirty : nullptr);
  VectorXd b(n + 1);
  for (int i = 0; i <= n; ++i) b[i] = i < n ? sys.rhs(i) : (force ? sys.rhs(n) : 0.0);
  const double q_scale = q.size() ? q.cwiseAbs().maxCoeff() : 0.0;
  const double m_max = m.size() ? m.maxCoeff() : 0.0;

  LcpSolution s;
  const int max_pivots = 10 * n + 20;
  int best = n + 2, backup = kBackup;
  std::vector<int> B, bad;
  for (s.pivots = 1; s.pivots <= max_pivots; ++s.pivots) {
    B.clear();
    for (int i = 0; i < n; ++i)
      if (in[i]) B.push_back(i);
    if (force) B.push_back(n);
    bool lowrank = principal.prepare(B, s.pivots, true);
    double delta = value, g_scale = 0;
    // Solve with one step of iterative refinement at every exchange (it costs a product with M and a solve
    // with the same factors, and keeps the feasibility tests at round-off also on the low-rank path). The
    // residual of the principal system is the gaps on S and the force error; a low-rank solve that leaves
    // more than round-off there is repeated by dense LU.
    for (;;) {
      VectorXd x = principal.solve(b);
      for (int refine = 0; refine < 2; ++refine) {
        s.lambda = x.head(n);
        delta = force ? sigma_ * x[n] : value;
        s.gap = M * s.lambda + q - delta * m;
        if (refine == 1) break;
        VectorXd r = VectorXd::Zero(n + 1);
        for (int i : B) r[i] = i < n ? -s.gap[i] : sigma_ * (value - m.dot(s.lambda));
        x += principal.solve(r);
      }
      g_scale = q_scale + std::abs(delta) * m_max;
      double gap_residual = 0;
      for (int i : B)
        if (i < n) gap_residual = std::max(gap_residual, std::abs(s.gap[i]));
      const double force_residual = force ? std::abs(value - m.dot(s.lambda)) / value : 0.0;
      if (!lowrank || (gap_residual <= kResidual * g_scale && force_residual <= kResidual)) break;
      lowrank = principal.prepare(B, s.pivots, false);
    }
    s.lowrank += lowrank;
    if (!s.lambda.allFinite() || !s.gap.allFinite() || !std::isfinite(delta))
      throw std::runtime_error("contact LCP: non-finite principal solution at pivot " +
                               std::to_string(s.pivots));
    s.delta = delta;

    double lambda_max = 0;
    for (int i = 0; i < n; ++i)
      if (in[i]) lambda_max = std::max(lambda_max, std::abs(s.lambda[i]));
    const double tol_l = kFeasible * lambda_max, tol_g = kFeasible * g_scale;
    bad.clear();
    for (int i = 0; i < n; ++i) {
      if (!flags.unilateral(i)) continue;
      if (in[i] ? s.lambda[i] < -tol_l : s.gap[i] < -tol_g) bad.push_back(i);
    }
    if (bad.empty()) break;
    const int count = static_cast<int>(bad.size());
    bool block = false;
    if (count < best) {
      best = count;
      backup = kBackup;
      block = true;
    } else if (backup > 0) {
      --backup;
      block = true;
    }
    if (block && force) {  // never leave force control without an unknown pressure
      int left = 0;
      for (int i = 0; i < n; ++i) left += in[i];
      for (int i : bad) left += in[i] ? -1 : 1;
      block = left > 0;
    }
    if (block) {
      for (int i : bad) in[i] = !in[i];
    } else {
      in[bad.front()] = !in[bad.front()];
      ++s.single;
    }
  }
  if (s.pivots > max_pivots)
    throw std::runtime_error("contact LCP: no convergence after " + std::to_string(max_pivots) +
                             " pivots (M is not a P-matrix, or is so far from positive definite that force "
                             "control loses uniqueness)");

  judge(s, in, flags, q_scale, m_max);
  return s;
}

}  // namespace skinfem::contact
