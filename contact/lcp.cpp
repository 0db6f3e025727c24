#include "contact/lcp.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace skinfem::contact {

ContactLcp::ContactLcp(Eigen::MatrixXd M, Eigen::VectorXd q, Eigen::VectorXd m)
    : M_(std::move(M)), q_(std::move(q)), m_(std::move(m)) {
  if (M_.rows() != M_.cols() || M_.rows() != q_.size() || q_.size() != m_.size())
    throw std::invalid_argument("ContactLcp: M must be n×n with q and m of size n");
  if (!M_.allFinite() || !q_.allFinite() || !m_.allFinite())
    throw std::invalid_argument("ContactLcp: non-finite entries in M, q or m");
}

LcpSolution ContactLcp::solve_force(double F, const std::vector<char>& excluded,
                                    const std::vector<int>& warm) const {
  return solve(true, F, excluded, warm);
}
LcpSolution ContactLcp::solve_depth(double delta, const std::vector<char>& excluded,
                                    const std::vector<int>& warm) const {
  return solve(false, delta, excluded, warm);
}

bool ContactLcp::principal(bool force_control, double value, const std::vector<int>& A,
                           Eigen::VectorXd& lambda_a, double& delta) const {
  const int k = static_cast<int>(A.size());
  const int n = k + (force_control ? 1 : 0);
  Eigen::MatrixXd K(n, n);
  Eigen::VectorXd b(n);
  for (int r = 0; r < k; ++r) {
    for (int c = 0; c < k; ++c) K(r, c) = M_(A[r], A[c]);
    b[r] = -q_[A[r]] + (force_control ? 0.0 : value * m_[A[r]]);
    if (force_control) K(r, k) = -m_[A[r]], K(k, r) = m_[A[r]];
  }
  if (force_control) K(k, k) = 0, b[k] = value;
  if (n == 0) {
    lambda_a.resize(0);
    if (!force_control) delta = value;
    return true;
  }
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(K);
  Eigen::VectorXd x = lu.solve(b);
  x += lu.solve(b - K * x);  // one step of iterative refinement
  if (!x.allFinite()) return false;
  lambda_a = x.head(k);
  delta = force_control ? x[k] : value;
  return true;
}

void ContactLcp::set_reference(const std::vector<int>& active) {
  ref_ = active;
  std::sort(ref_.begin(), ref_.end());
  ref_pos_.assign(size(), -1);
  const int k = static_cast<int>(ref_.size());
  for (int r = 0; r < k; ++r) ref_pos_[ref_[r]] = r;
  Eigen::MatrixXd K(k + 1, k + 1);
  for (int r = 0; r < k; ++r) {
    for (int c = 0; c < k; ++c) K(r, c) = M_(ref_[r], ref_[c]);
    K(r, k) = -m_[ref_[r]];
    K(k, r) = m_[ref_[r]];
  }
  K(k, k) = 0;
  Z_ = K.partialPivLu().inverse();
  if (!Z_.allFinite()) throw std::runtime_error("ContactLcp: the reference principal system is singular");
}

// The principal system of A = (ref \ R) ∪ P through the reference inverse Z (size k0 + 1, last row δ):
// with T = ref ∪ P, K_TT = [K0 B; C D] is solved by block elimination (S = D − C Z B), and the rows of R are
// released by a capacitance correction that forces λ_R = 0.
bool ContactLcp::principal_lowrank(double F, const std::vector<int>& A, Eigen::VectorXd& lambda_a,
                                   double& delta) const {
  const int k0 = static_cast<int>(ref_.size());
  std::vector<char> in_a(size(), 0);
  for (int i : A) in_a[i] = 1;
  std::vector<int> P, R;
  for (int i : A)
    if (ref_pos_[i] < 0) P.push_back(i);
  for (int r = 0; r < k0; ++r)
    if (!in_a[ref_[r]]) R.push_back(r);
  const int np = static_cast<int>(P.size()), nr = static_cast<int>(R.size());
  // Border of the reference system by P: B = K(ref ∪ δ, P), C = K(P, ref ∪ δ), D = M_PP.
  Eigen::MatrixXd B(k0 + 1, np), C(np, k0 + 1), D(np, np);
  for (int j = 0; j < np; ++j) {
    for (int r = 0; r < k0; ++r) B(r, j) = M_(ref_[r], P[j]), C(j, r) = M_(P[j], ref_[r]);
    B(k0, j) = m_[P[j]];
    C(j, k0) = -m_[P[j]];
    for (int l = 0; l < np; ++l) D(j, l) = M_(P[j], P[l]);
  }
  const Eigen::MatrixXd ZB = Z_ * B;
  const Eigen::PartialPivLU<Eigen::MatrixXd> S(np > 0 ? Eigen::MatrixXd(D - C * ZB) : Eigen::MatrixXd(0, 0));
  // y = K_TT⁻¹ [r0; rP] given Z r0.
  const auto solve_T = [&](const Eigen::VectorXd& Zr0, const Eigen::VectorXd& rP, Eigen::VectorXd& y0,
                           Eigen::VectorXd& yP) {
    yP = np > 0 ? Eigen::VectorXd(S.solve(rP - C * Zr0)) : Eigen::VectorXd(0);
    y0 = Zr0 - (np > 0 ? Eigen::VectorXd(ZB * yP) : Eigen::VectorXd::Zero(k0 + 1));
  };
  Eigen::VectorXd r0(k0 + 1), rP(np);
  for (int r = 0; r < k0; ++r) r0[r] = -q_[ref_[r]];
  r0[k0] = F;
  for (int j = 0; j < np; ++j) rP[j] = -q_[P[j]];
  Eigen::VectorXd y0, yP;
  solve_T(Z_ * r0, rP, y0, yP);
  if (nr > 0) {
    // Columns of K_TT⁻¹ for unit residuals in the rows R, then λ_R = 0.
    Eigen::MatrixXd U0(k0 + 1, nr), UP(np, nr);
    for (int c = 0; c < nr; ++c) {
      Eigen::VectorXd u0, uP;
      solve_T(Z_.col(R[c]), Eigen::VectorXd::Zero(np), u0, uP);
      U0.col(c) = u0;
      UP.col(c) = uP;
    }
    Eigen::MatrixXd H(nr, nr);
    Eigen::VectorXd h(nr);
    for (int a = 0; a < nr; ++a) {
      h[a] = y0[R[a]];
      for (int c = 0; c < nr; ++c) H(a, c) = U0(R[a], c);
    }
    const Eigen::VectorXd mu = H.partialPivLu().solve(-h);
    y0 += U0 * mu;
    yP += UP * mu;
  }
  if (!y0.allFinite() || !yP.allFinite()) return false;
  lambda_a.resize(A.size());
  for (size_t a = 0; a < A.size(); ++a) {
    const int i = A[a];
    lambda_a[a] = ref_pos_[i] >= 0 ? y0[ref_pos_[i]] : yP[std::find(P.begin(), P.end(), i) - P.begin()];
  }
  delta = y0[k0];
  return true;
}

LcpSolution ContactLcp::solve(bool force_control, double value, const std::vector<char>& excluded,
                              const std::vector<int>& warm) const {
  const int n = size();
  const auto is_excluded = [&](int i) { return !excluded.empty() && excluded[i]; };
  std::vector<char> in_a(n, 0);
  if (!warm.empty()) {
    for (int i : warm)
      if (!is_excluded(i)) in_a[i] = 1;
  } else {  // the first touch: the smallest initial gap among the allowed multipliers
    int first = -1;
    for (int i = 0; i < n; ++i)
      if (!is_excluded(i) && (first < 0 || q_[i] < q_[first])) first = i;
    if (first < 0)
      throw std::runtime_error("contact LCP: every multiplier is excluded (the hole covers the zone)");
    in_a[first] = 1;
  }
  const int max_pivots = 10 * n + 10;
  int best = n + 1, backup = 3;
  LcpSolution s;
  s.lambda = Eigen::VectorXd::Zero(n);
  for (s.pivots = 1; s.pivots <= max_pivots; ++s.pivots) {
    std::vector<int> A;
    for (int i = 0; i < n; ++i)
      if (in_a[i]) A.push_back(i);
    Eigen::VectorXd la;
    double delta = 0;
    const int diff = ref_.empty() ? n : [&] {
      int d = 0;
      for (int i = 0; i < n; ++i) d += (in_a[i] != 0) != (!ref_pos_.empty() && ref_pos_[i] >= 0);
      return d;
    }();
    const bool lowrank = force_control && !ref_.empty() && 4 * diff <= static_cast<int>(ref_.size());
    bool ok = lowrank && principal_lowrank(value, A, la, delta);
    if (!ok) ok = principal(force_control, value, A, la, delta);
    if (!ok)
      throw std::runtime_error("contact LCP: singular principal system after " + std::to_string(s.pivots) +
                               " pivots");
    s.lambda.setZero();
    for (size_t a = 0; a < A.size(); ++a) s.lambda[A[a]] = la[a];
    s.delta = delta;
    s.gap = M_ * s.lambda + q_ - delta * m_;
    // Infeasible indices, with a round-off allowance relative to the problem's own scales.
    const double tol_l = 1e-13 * std::max(1e-300, s.lambda.cwiseAbs().maxCoeff());
    const double tol_g =
        1e-13 * std::max({1e-300, q_.cwiseAbs().maxCoeff(), std::abs(delta) * m_.cwiseAbs().maxCoeff()});
    std::vector<int> bad;
    for (int i = 0; i < n; ++i) {
      if (is_excluded(i)) continue;
      if ((in_a[i] && s.lambda[i] < -tol_l) || (!in_a[i] && s.gap[i] < -tol_g)) bad.push_back(i);
    }
    if (bad.empty()) {
      s.active = A;
      double ml = 0, mg = 0, prod = 0;
      s.min_lambda = s.lambda.size() ? 1e300 : 0;
      s.min_gap = 1e300;
      for (int i = 0; i < n; ++i) {
        if (is_excluded(i)) continue;
        ml = std::max(ml, std::abs(s.lambda[i]));
        mg = std::max(mg, std::abs(s.gap[i]));
        prod = std::max(prod, std::abs(s.lambda[i] * s.gap[i]));
        s.min_lambda = std::min(s.min_lambda, s.lambda[i]);
        s.min_gap = std::min(s.min_gap, s.gap[i]);
      }
      // Scaled by the problem's own gap scale (initial gaps and the rigid approach), not the solution's.
      const double g_scale = q_.cwiseAbs().maxCoeff() + std::abs(s.delta) * m_.cwiseAbs().maxCoeff();
      s.complementarity = ml > 0 && g_scale > 0 ? prod / (ml * g_scale) : 0.0;
      (void)mg;
      for (int i = 0; i < n; ++i)
        if (!in_a[i]) s.lambda[i] = 0.0;
      return s;
    }
    const int count = static_cast<int>(bad.size());
    if (count < best) {
      best = count;
      backup = 3;
      for (int i : bad) in_a[i] = !in_a[i];
    } else if (backup > 0) {
      --backup;
      for (int i : bad) in_a[i] = !in_a[i];
    } else {
      in_a[bad.back()] = !in_a[bad.back()];
    }
  }
  throw std::runtime_error(
      "contact LCP: no convergence after " + std::to_string(max_pivots) +
      " pivots (is the friction coefficient so large that the problem loses uniqueness?)");
}

}  // namespace skinfem::contact
