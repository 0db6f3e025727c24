#include "skinfem/contact/exponential_interface.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace skinfem::contact {

namespace {
constexpr int kMaxSteps = 100, kMaxHalvings = 40;
constexpr double kStepCap = 4.0;      // largest |Δx| per step: λ changes at most e⁴-fold
constexpr double kDropped = 60.0;     // columns with x below x_max − 60 leave the Newton matrix
constexpr double kLoaded = 1e-6;      // λ ≥ 1e-6 max λ counts as touching (the active set)
constexpr double kTolerance = 1e-11;  // of the separation scale, on every equation
}  // namespace

LcpSolution solve_exponential(const Eigen::MatrixXd& M, const Eigen::VectorXd& q, const Eigen::VectorXd& m,
                              const ExponentialLaw& law, bool force_control, double value,
                              const std::vector<char>& excluded, const LcpSolution& hard) {
  const int n = static_cast<int>(q.size());
  std::vector<int> F;  // free multipliers (not under a hole)
  for (int i = 0; i < n; ++i)
    if (excluded.empty() || !excluded[i]) F.push_back(i);
  const int nf = static_cast<int>(F.size());
  const double u0 = law.u0, p_ref = law.p_ref;

  // Start: the hard contact, its pressure floored at 1e-3 of its peak inside, the rigid law's tail outside.
  double lmax = 0, loaded_area = 0, force_hard = 0;
  for (int i : F) {
    lmax = std::max(lmax, hard.lambda[i]);
    if (hard.lambda[i] > 0) loaded_area += m[i], force_hard += m[i] * hard.lambda[i];
  }
  double delta = force_control ? hard.delta : value;
  if (force_control && loaded_area > 0) delta += u0 * std::log(force_hard / loaded_area / p_ref);
  Eigen::VectorXd x(nf);
  for (int a = 0; a < nf; ++a) {
    const int i = F[a];
    if (lmax <= 0)
      x[a] = -((q[i] - delta * m[i]) / m[i]) / u0;
    else if (hard.lambda[i] > 0)
      x[a] = std::log(std::max(hard.lambda[i], 1e-3 * lmax) / p_ref);
    else
      x[a] = std::log(1e-3 * lmax / p_ref) - (hard.gap[i] / m[i]) / u0;
  }

  double qscale = 0;
  for (int i : F) qscale = std::max(qscale, std::abs(q[i] / m[i]));
  const auto lambda_of = [&](const Eigen::VectorXd& xs) {
    Eigen::VectorXd l = Eigen::VectorXd::Zero(n);
    for (int a = 0; a < nf; ++a) l[F[a]] = p_ref * std::exp(xs[a]);
    return l;
  };
  // Residuals in mm: e_a = ḡ + u0 x, and the force's, scaled to a separation by the current scale.
  struct State {
    Eigen::VectorXd lambda, gap, e;
    double h = 0, scale = 1, merit = 0;
  };
  const auto evaluate = [&](const Eigen::VectorXd& xs, double d) {
    State s;
    s.lambda = lambda_of(xs);
    s.gap = M * s.lambda + q - d * m;
    s.scale = qscale + std::abs(d) + u0;
    s.e.resize(nf);
    for (int a = 0; a < nf; ++a) s.e[a] = s.gap[F[a]] / m[F[a]] + u0 * xs[a];
    s.h = force_control ? (m.dot(s.lambda) - value) / value * s.scale : 0.0;
    s.merit = s.e.squaredNorm() + s.h * s.h;
    return s;
  };
  const auto converged = [&](const State& s) {
    return (nf == 0 || s.e.cwiseAbs().maxCoeff() <= kTolerance * s.scale) &&
           std::abs(s.h) <= kTolerance * s.scale;
  };

  State s = evaluate(x, delta);
  int steps = 0;
  for (; !converged(s); ++steps) {
    if (steps == kMaxSteps) {
      char buf[256];
      std::snprintf(buf, sizeof buf,
                    "contact: the exponential interface (u0 = %.4g mm, p_ref = %.4g MPa) did not converge in "
                    "%d Newton steps (largest separation residual %.3g mm)",
                    u0, p_ref, kMaxSteps, s.e.size() ? s.e.cwiseAbs().maxCoeff() : 0.0);
      throw std::runtime_error(buf);
    }
    const double xmax = nf ? x.maxCoeff() : 0.0;
    std::vector<int> S, R;  // positions in F: loaded (in the Newton matrix) and the rest
    for (int a = 0; a < nf; ++a) (x[a] >= xmax - kDropped ? S : R).push_back(a);
    const int ns = static_cast<int>(S.size()), nb = ns + (force_control ? 1 : 0);
    Eigen::MatrixXd J = Eigen::MatrixXd::Zero(nb, nb);
    Eigen::VectorXd rhs(nb);
    for (int a = 0; a < ns; ++a) {
      const int i = F[S[a]];
      for (int b = 0; b < ns; ++b) J(a, b) = M(i, F[S[b]]) * s.lambda[F[S[b]]] / m[i];
      J(a, a) += u0;
      rhs[a] = -s.e[S[a]];
      if (force_control) {
        J(a, ns) = -1.0;
        J(ns, a) = m[i] * s.lambda[i] / value * s.scale;
      }
    }
    if (force_control) rhs[ns] = -s.h;
    const Eigen::VectorXd step = J.partialPivLu().solve(rhs);
    Eigen::VectorXd dx = Eigen::VectorXd::Zero(nf);
    for (int a = 0; a < ns; ++a) dx[S[a]] = step[a];
    const double dd = force_control ? step[ns] : 0.0;
    for (int a : R) {
      const int i = F[a];
      double coupling = 0;
      for (int b = 0; b < ns; ++b) coupling += M(i, F[S[b]]) * s.lambda[F[S[b]]] * step[b];
      dx[a] = -(s.e[a] + coupling / m[i] - dd) / u0;
    }
    double alpha = std::min(1.0, kStepCap / std::max(dx.cwiseAbs().maxCoeff(), 1e-300));
    for (int k = 0;; ++k) {
      const State trial = evaluate(x + alpha * dx, delta + alpha * dd);
      if (trial.merit <= (1 - 1e-4 * alpha) * s.merit || converged(trial)) {
        x += alpha * dx;
        delta += alpha * dd;
        s = trial;
        break;
      }
      if (k == kMaxHalvings)
        throw std::runtime_error("contact: the exponential interface's Newton step found no descent after " +
                                 std::to_string(kMaxHalvings) + " halvings");
      alpha *= 0.5;
    }
  }

  LcpSolution out;
  out.lambda = s.lambda;
  out.gap = s.gap;
  out.delta = delta;
  out.pivots = steps;
  const double peak = out.lambda.size() ? out.lambda.maxCoeff() : 0.0;
  bool first = true;
  for (int i : F) {
    if (out.lambda[i] >= kLoaded * peak && peak > 0) out.active.push_back(i);
    out.min_lambda = first ? out.lambda[i] : std::min(out.min_lambda, out.lambda[i]);
    out.min_gap = first ? out.gap[i] : std::min(out.min_gap, out.gap[i]);
    first = false;
  }
  out.complementarity = nf ? s.e.cwiseAbs().maxCoeff() / s.scale : 0.0;
  return out;
}

}  // namespace skinfem::contact
