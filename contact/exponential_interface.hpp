// Contact through an exponential rough interface (scene.hpp, InterfaceLaw::exponential), condensed onto the
// multipliers as the hard contact is (contact/lcp.hpp): find λ (n) and δ with, for every index not excluded,
//   λ_i = p_ref exp(−ḡ_i / u0),   ḡ_i = (M λ + q − δ m)_i / m_i,
// the hat-mean separation of the mean planes (any sign: p > p_ref presses the asperities past them), and
// λ_i = 0 at excluded indices (under a hole); with either δ given or mᵀλ = F. The law is the mean-plane
// form of a rough surface's contact (Greenwood–Williamson with an exponential height distribution; the
// "softened contact" of commercial codes). Lumping the law on the hat means, as the linear interface does,
// keeps the problem on the n multipliers.
//
// Why Newton on x = ln(λ / p_ref): the equations become ḡ(λ(x)) + u0 x = 0, whose Jacobian
// M Λ + u0 diag(m) (rows scaled by m) is well conditioned even where λ underflows (far from the contact, x_i
// is just −ḡ_i / u0), and with M symmetric positive definite the problem is the minimum of the strictly
// convex ½λᵀMλ + (q − δm)ᵀλ + u0 Σ m_i λ_i (ln(λ_i/p_ref) − 1), so its solution is unique. Columns of
// multipliers below e^{−60} of the largest are left out of the Newton matrix (their residuals are exact), so
// each step costs one dense LU of the loaded multipliers. Steps are capped at |Δx| ≤ 4 and backtracked on
// the residual's norm; the start is the hard contact's solution. Same input, same output bit for bit.
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "skinfem/contact/lcp.hpp"

namespace skinfem::contact {

struct ExponentialLaw {
  double u0 = 0;     // mm
  double p_ref = 0;  // MPa
};

// The problem of ContactLcp (M, q, m as there; M need not be symmetric: coupled friction) under an
// exponential interface. `hard`: the same problem's hard solution (the start). Returns, in LcpSolution's
// terms: λ, gap = M λ + q − δ m (the weighted separation, any sign), δ, active = the multipliers carrying
// at least 1e-6 of the largest λ (the contact as a set: the zone must hold it,
// and what lies beyond carries under 1e-6 of the peak per hat), pivots = Newton steps, complementarity = the
// largest |ḡ_i + u0 ln(λ_i/p_ref)| over the separation scale max|q/m| + |δ| + u0, min_lambda, min_gap.
// Throws std::runtime_error (one line) when Newton does not converge in 100 steps.
LcpSolution solve_exponential(const Eigen::MatrixXd& M, const Eigen::VectorXd& q, const Eigen::VectorXd& m,
                              const ExponentialLaw& law, bool force_control, double value,
                              const std::vector<char>& excluded, const LcpSolution& hard);

}  // namespace skinfem::contact
