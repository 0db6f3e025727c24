// The contact complementarity problem condensed onto n multipliers (contact/condensed.hpp): find λ (n) with
//   λ_i ≥ 0,  g_i = (M λ + q − δ m)_i ≥ 0,  λ_i g_i = 0   for every index not excluded,
//   λ_i = 0 (g_i free)                                    for excluded ones (under a hole of the indenter),
//   λ_i free, g_i = 0                                     for bilateral ones (always in contact),
// with either the depth δ given (depth control), or δ unknown and mᵀλ = F > 0 (force control).
// Shapes and meaning: M (n×n) the compliance between multipliers (weighted gap per unit multiplier), q (n)
// the initial weighted gaps, m (n, all > 0) the multipliers' areas, so mᵀλ is the force and δ m the rigid
// approach. M is symmetric positive definite without friction and M = W − μV, not symmetric, with coupled
// friction.
//
// Algorithm: block principal pivoting (Júdice & Pires 1994; Kim & Park 2011). Guess the active set S
// (λ > 0), solve the principal system on S (with δ as an extra unknown under force control), exchange every
// infeasible index (λ_i < 0 in S, g_i < 0 outside) while their number keeps falling, with 3 further tries
// after it stops; then exchange only the infeasible index of lowest number (Murty 1974) until the count
// falls below its best again. Why finite: full exchanges happen at most 4 times per value of the best count
// (≤ n + 1 values), and a run of single exchanges is Murty's least-index method, finite for every P-matrix
// under depth control. Under force control Murty's induction needs, for λ_k = t fixed, the remaining gap
// g_k(t) strictly increasing in t; with mᵀλ = F fixed, Δg_k Δt ≥ Δλᵀ M Δλ, so it holds when M + Mᵀ is
// positive definite (frictionless, and M = W − μV whenever V's symmetric part is small next to W). Outside
// these classes a pivot bound of 10n + 20 turns a cycle into an error, never into an answer. Feasibility is
// judged with a round-off allowance of 1e-12 relative (λ against max λ, g against the gap scale max|q| + |δ|
// max m). Every principal system gets one step of iterative refinement (a product with M and one more solve
// with the same factors), so complementarity holds to round-off; the low-rank path needs it, since a solve
// through an explicit inverse is only accurate to ~κ²ε (1e-10 of max λ measured at n = 1521 without it, 4e-14
// with). Same input, same output bit for bit (no threads, fixed orderings).
//
// Repeated solves (a hole swept through the contact: ~400 problems sharing M, q, m): set_reference(A0)
// stores the inverse Z of the force-control principal system K0 = [M_A0A0, −m_A0; m_A0ᵀ, 0] (size |A0| + 1).
// A later principal set S = (A0 \ R) ∪ P is solved without refactoring: border K0 by the added set P (columns
// W = Z K(A0, P)) and pin λ_R = 0 by multipliers on the removed rows; the capacitance system left is of
// size |P| + |R|. Cost O(|A0|²(1 + |P|) + (|P| + |R|)³) against O(|S|³) for a dense LU; depth control uses
// it too (δ joins R). Within one solve the first dense LU is reused the same way for the later exchanges.
// Sets that differ from every stored factorization by more than a quarter of its size get a dense LU.
#pragma once

#include <Eigen/Dense>
#include <vector>

namespace skinfem::contact {

struct LcpSolution {
  Eigen::VectorXd lambda;   // n: multipliers, exactly 0 off `active` (so at every excluded index)
  Eigen::VectorXd gap;      // n: M λ + q − δ m (any sign at excluded indices)
  double delta = 0;         // the given depth, or the solved one under force control
  std::vector<int> active;  // the final principal set S, ascending
  int pivots = 0;           // principal systems solved, one per exchange
  int lowrank = 0;          // how many of them went through a low-rank update instead of a dense LU
  int single = 0;           // how many exchanges were single-index (Murty's fallback) rather than blocks
  // Over the non-excluded indices: max_i |λ_i g_i| / (max λ · (max|q| + |δ| max m)), a relative measure that
  // does not shrink with the solution's own gaps; min λ and min g (≥ −1e-12 of their scales).
  double complementarity = 0, min_lambda = 0, min_gap = 0;
};

class ContactLcp {
 public:
  // Throws std::invalid_argument on mismatched sizes, non-finite entries or m_i ≤ 0.
  ContactLcp(Eigen::MatrixXd M, Eigen::VectorXd q, Eigen::VectorXd m);

  // excluded: empty (none) or n flags. warm: a starting active set (any order; excluded indices are dropped);
  // empty: the rigid overlap {q_i < δ m_i} under depth control, a one-pass estimate under force control.
  // Throws std::runtime_error (one line, naming the pivot count) when pivoting does not converge within
  // 10n + 20 pivots or a principal system is singular; std::invalid_argument on bad arguments (F ≤ 0).
  // q_shift: empty, or n weighted gaps added to q for this solve only (a load that does not depend on λ,
  // such as a shear strength's traction; the stored factorizations do not depend on q). bilateral: empty or
  // n flags, 1 where the multiplier stays in contact with a free sign (the hats a small hole's bulge opens,
  // contact/holes/dimple.hpp); they count in neither the feasibility tests nor the diagnostics.
  LcpSolution solve_force(double F, const std::vector<char>& excluded = {}, const std::vector<int>& warm = {},
                          const Eigen::VectorXd& q_shift = {}, const std::vector<char>& bilateral = {}) const;
  LcpSolution solve_depth(double delta, const std::vector<char>& excluded = {},
                          const std::vector<int>& warm = {}, const Eigen::VectorXd& q_shift = {},
                          const std::vector<char>& bilateral = {}) const;

  // The problem with the rows and columns of the `dirty` indices changed (M, q, m agree with this problem's
  // elsewhere; a hole cutting the hats, contact/holes/cut.hpp): solved with the stored reference for the
  // rest, the dirty indices joining the low-rank update as removed and re-added. Same throws as above.
  LcpSolution solve_changed(const Eigen::MatrixXd& M, const Eigen::VectorXd& q, const Eigen::VectorXd& m,
                            const std::vector<char>& dirty, bool force_control, double value,
                            const std::vector<char>& excluded = {}, const std::vector<int>& warm = {}) const;

  // Inverts the force-control principal system of `active` (typically the solution without a hole) once;
  // later solves whose principal sets differ from it by at most a quarter of its size use low-rank updates
  // of it. Costs 2(|A0| + 1)³ flops and (|A0| + 1)² doubles. Throws std::runtime_error if it is singular.
  void set_reference(const std::vector<int>& active);
  void clear_reference();
  const std::vector<int>& reference() const { return ref_active_; }

  int size() const { return static_cast<int>(q_.size()); }
  const Eigen::MatrixXd& matrix() const { return M_; }
  const Eigen::VectorXd& gaps() const { return q_; }
  const Eigen::VectorXd& areas() const { return m_; }

 private:
  struct Changed {
    const Eigen::MatrixXd* M;
    const Eigen::VectorXd* m;
    const std::vector<char>* dirty;
  };
  LcpSolution solve(bool force_control, double value, const std::vector<char>& excluded,
                    const std::vector<int>& warm, const Eigen::VectorXd& q, const Changed* changed = nullptr,
                    const std::vector<char>& bilateral = {}) const;

  Eigen::MatrixXd M_;
  Eigen::VectorXd q_, m_;
  // The δ row and column of every principal system are scaled by sigma_ (≈ max M_ii / max m) so that the
  // bordered matrices are as well conditioned as M's blocks; the unknown is then δ / sigma_.
  double sigma_ = 1;
  std::vector<int> ref_active_;  // A0, ascending
  std::vector<int> ref_set_;     // A0 and n (the δ unknown): the rows and columns of Z
  Eigen::MatrixXd Z_;            // inverse of the scaled bordered system over ref_set_
};

}  // namespace skinfem::contact
