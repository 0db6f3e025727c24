// The contact complementarity problem condensed onto n multipliers (contact/condensed.hpp):
//   λ_i ≥ 0,  g_i = (M λ + q − δ m)_i ≥ 0,  λ_i g_i = 0   for every multiplier not excluded,
//   λ_i = 0 (g_i free)                                    for excluded ones (under a hole),
// with either the depth δ given, or the force mᵀλ = F given and δ unknown. M (n×n) is the compliance,
// symmetric positive definite without friction and a non-symmetric P-matrix perturbation of it with coupled
// friction.
//
// Algorithm: block principal pivoting (Júdice & Pires 1994; Kim & Park 2011): guess the active set A (λ > 0),
// solve the principal system on A exactly, exchange every infeasible index while the number of
// infeasibilities decreases, else (after 3 tries) only the largest infeasible index (Murty's least-index
// rule, finite for P-matrices). The final active set's system is solved with one step of iterative
// refinement, so complementarity holds to round-off; there is no penalty and no tolerance on the answer.
// Repeated solves that differ from a reference active set by a few indices (a hole sweeping the contact)
// reuse the reference system's inverse through a low-rank (capacitance) update.
#pragma once

#include <Eigen/Dense>
#include <vector>

namespace skinfem::contact {

struct LcpSolution {
  Eigen::VectorXd lambda;  // n
  Eigen::VectorXd gap;     // n: M λ + q − δ m (any sign at excluded indices)
  double delta = 0;
  std::vector<int> active;  // indices with λ > 0 (the final principal set), ascending
  int pivots = 0;           // principal systems solved
  // max_i |λ_i g_i| / (max λ · (max |q| + |δ| max m)), min λ and min g over the non-excluded indices
  double complementarity = 0, min_lambda = 0, min_gap = 0;
};

class ContactLcp {
 public:
  ContactLcp(Eigen::MatrixXd M, Eigen::VectorXd q, Eigen::VectorXd m);

  // excluded: empty or n flags. warm: a starting active set (empty: start from every index with q ≤ 0 ...).
  // Throws std::runtime_error (one line) when pivoting does not converge or a principal system is singular.
  LcpSolution solve_force(double F, const std::vector<char>& excluded = {},
                          const std::vector<int>& warm = {}) const;
  LcpSolution solve_depth(double delta, const std::vector<char>& excluded = {},
                          const std::vector<int>& warm = {}) const;

  // Factor the force-controlled principal system of this active set once; later solve_force calls whose
  // active sets differ from it by at most a quarter of its size use low-rank updates of it.
  void set_reference(const std::vector<int>& active);

  int size() const { return static_cast<int>(q_.size()); }

 private:
  LcpSolution solve(bool force_control, double value, const std::vector<char>& excluded,
                    const std::vector<int>& warm) const;
  // Solves the principal system of `active` (λ_A and, under force control, δ). False if singular.
  bool principal(bool force_control, double value, const std::vector<int>& active, Eigen::VectorXd& lambda_a,
                 double& delta) const;
  bool principal_lowrank(double F, const std::vector<int>& active, Eigen::VectorXd& lambda_a,
                         double& delta) const;

  Eigen::MatrixXd M_;
  Eigen::VectorXd q_, m_;
  // Reference system for force control: inverse Z of [M_RR −m_R; m_Rᵀ 0] over ref_ (size |ref|+1).
  std::vector<int> ref_;
  std::vector<int> ref_pos_;  // index → position in ref_, −1 if absent
  Eigen::MatrixXd Z_;
};

}  // namespace skinfem::contact
