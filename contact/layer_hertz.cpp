#include "skinfem/contact/layer_hertz.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "skinfem/mesh/gauss_legendre.hpp"

// Derivation (checked by tests/contact/test_layer_hertz.cpp: M(t) against an independent 4×4 solve, the
// half-space and lubrication limits, force balance, the literature's first-order thickness coefficient).
//
// 1. Surface compliance. With the Papkovich–Neuber representation of green/layer_exact.cpp,
//      2μu_z = κΨ − zΨ' − Φ',  σ_zz = 2(1−ν)Ψ' − zΨ'' − Φ'',  σ_xz ∝ −(1−2ν)Ψ + zΨ' + Φ'  (per cos/sin(sx)),
//    u = 0 at z = 0, σ_xz(h) = 0 and σ_zz(h) = cos(sx) solved symbolically (sympy) give
//      2μ u_z(h) = (2(1−ν)/s) M(sh),   M(t) = (2κ sinh 2t − 4t)/(2κ cosh 2t + 1 + κ² + 4t²),  κ = 3 − 4ν.
//    So a pressure p̃ (Hankel transform of order 0, p̃(s) = ∫ p J0(sr) r dr) deflects the surface by
//    w̃ = (1−ν)/(μs) M p̃ = [2/(E* s)] M(sh) p̃: the half-space (Boussinesq) compliance times M. The denominator
//    D = 2κ cosh 2t + 1 + κ² + 4t² ≥ (1 + κ)² > 0 on the real axis; its nearest complex zeros are ±0.739i
//    (ν = 0.5) to ±1.19i (ν = 0). Small t: M = 4(κ−1)t/(1+κ)² + O(t³) (ν < 0.5: a Winkler foundation of
//    modulus E(1−ν)/((1+ν)(1−2ν)h)), M = 2t³/3 + O(t⁵) at ν = 0.5 (w = −(h³/3μ)∇²p: lubrication).
//    Overflow-free forms with X = e^{−2t}:  M = [κ(1 − X²) − 4tX]/[κ(1 + X²) + (1 + κ² + 4t²)X],
//      M − 1 = −X[2κX + κ² + (1 + 2t)²]/[κ(1 + X²) + (1 + κ² + 4t²)X]   (no cancellation).
//
// 2. Integral equation. Write p̃(s) = ∫₀ᵃ g(τ) cos(sτ) dτ; then p(r) = g(a)/√(a²−r²) − ∫ᵣᵃ g'(τ)/√(τ²−r²) dτ
//    and F = 2π p̃(0) = 2π∫₀ᵃ g. With J0(sr) = (2/π)∫₀ʳ cos(st)/√(r²−t²) dt the deflection is
//      w(r) = (2/π) ∫₀ʳ W(t)/√(r² − t²) dt,  W(t) = (2/E*) ∫₀^∞ M(sh) cos(st) p̃(s) ds
//                                              = (2/E*) [ (π/2) g(t)·1(t < a) + ∫₀ᵃ K(t, τ) g(τ) dτ ],
//    using ∫₀^∞ cos(st) cos(sτ) ds = (π/2) δ(t − τ). Abel's inversion of w = δ − r²/(2R) on r < a gives
//    W = δ − t²/R on t < a, i.e. the Fredholm equation of layer_hertz.hpp. Half-space (K = 0):
//    g = (E*/π)(δ − t²/R), g(a) = 0 ⇒ δ = a²/R, F = 4E*a³/(3R): Hertz.
//
// 3. Scaling. x = t/a, λ = a/h, u = sh, f(u) = M(u) − 1, g(ax) = (E*a²/(2R)) γ(x), δ = d·a²/R:
//      (π/2) γ(x) + λ ∫₀¹ k(x, ξ) γ(ξ) dξ = d − x²,   k(x, ξ) = ∫₀^∞ f(u) cos(λux) cos(λuξ) du,
//    solved for γ₁ (right-hand side 1) and γ₂ (x²); γ = dγ₁ − γ₂ with d = γ₂(1)/γ₁(1) (edge condition), then
//      F = (πE*a³/R) ∫₀¹ γ,   p(aρ) = (E*a/(2R)) √(1−ρ²) ∫₀¹ [−γ'(x)/x] dv,  x = √(ρ² + (1−ρ²)v²)
//    (substituting x = √(ρ² + y²) removes the Abel singularity; γ is even and analytic, so γ'(x)/x is
//    smooth). Outside the contact (ρ > 1), W = (a²/R) λ Ŵ(x) with Ŵ(x) = ∫ f(u) cos(λux) P(u) du and
//    P(u) = ∫₀¹ γ cos(λuξ) dξ, so that
//      w(aρ) = (2/π)(a²/R) [ d·asin(1/ρ) − (ρ²/2) asin(1/ρ) + √(ρ² − 1)/2 + λ ∫ Ŵ(ρ sin θ) dθ ],
//    θ from asin(1/ρ) to π/2 (t = r sin θ removes the Abel singularity).
//
// 4. Numerics. k is analytic for |Im x| < 2/λ (f decays like u² e^{−2u}), and so is γ (γ = (2/π)(rhs − λkγ)),
//    so Gauss–Legendre Nyström on [0, 1] converges like ρ_B^{−2n}, ρ_B − 1/ρ_B = 8/λ (Bernstein ellipse
//    inside the strip): n = 24 + 4.5λ gives ≲ 1e-13 for every λ (test: doubling n). The u-integrals use
//    16-point Gauss–Legendre panels on [0, 24] (f(24) ~ 1e-18) of width min(max(1, u/2), 4, 2π/ω), ω the
//    highest frequency of the integrand (2λ for k): each panel then sees the poles of f (≥ 0.739 off the
//    axis) and at most one oscillation, Bernstein bound < 1e-16 (as in green/layer_exact.cpp). The matrix is
//    k = C diag(W f) Cᵀ with C = cos(λ u_m x_i), so it costs n²·m flops.

namespace skinfem::contact {

struct LayerHertzSolution {
  double a = 0, h = 0, R = 0, Estar = 0, kap = 0, lambda = 0, d = 0;
  double panel_scale = 1;
  std::vector<double> x, w, gamma;  // Nyström nodes/weights on [0, 1], γ = dγ₁ − γ₂ at the nodes
  std::vector<double> u, wf;        // wavenumber nodes (u = sh) on [0, 24], weight·f(u)
  std::vector<double> P;            // P(u) = ∫₀¹ γ cos(λuξ) dξ at the wavenumber nodes
  std::vector<double> v, wv;        // rule on [0, 1] for the pressure's Abel integral
};

namespace {

constexpr int kGauss = 16;
constexpr double kUMax = 24.0;
constexpr double kMaxRatio = 100.0;  // largest a/h accepted

std::string show(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

void check_positive(const char* who, const char* name, double value) {
  if (!(std::isfinite(value) && value > 0.0))
    throw std::invalid_argument(std::string(who) + ": " + name + " must be finite and > 0 (got " +
                                show(value) + ")");
}

void check_inputs(const char* who, double R, double h, double E, double nu) {
  check_positive(who, "R_mm", R);
  check_positive(who, "h_mm", h);
  check_positive(who, "E_MPa", E);
  if (!(nu >= 0.0 && nu <= 0.5))
    throw std::invalid_argument(std::string(who) + ": nu must be in [0, 0.5] (got " + show(nu) + ")");
}

void check_quadrature(const char* who, const LayerHertzQuadrature& q) {
  check_positive(who, "quadrature.node_scale", q.node_scale);
  check_positive(who, "quadrature.panel_scale", q.panel_scale);
}

// f(u) = M(u) − 1, cancellation-free (derivation point 1).
double compliance_minus_one(double u, double kap) {
  const double X = std::exp(-2.0 * u);
  const double den = kap * (1.0 + X * X) + (1.0 + kap * kap + 4.0 * u * u) * X;
  return -X * (2.0 * kap * X + kap * kap + (1.0 + 2.0 * u) * (1.0 + 2.0 * u)) / den;
}

// Composite 16-point Gauss–Legendre nodes on [0, kUMax] for integrands f(u)·(oscillation of frequency ≤
// omega); returns nodes and weight·f(u).
void wavenumber_nodes(double omega, double kap, double panel_scale, std::vector<double>& u,
                      std::vector<double>& wf) {
  static const GaussRule1d g = gauss_legendre01(kGauss);
  u.clear();
  wf.clear();
  double u0 = 0.0;
  while (u0 < kUMax) {
    double width = std::min(std::max(1.0, 0.5 * u0), 4.0);
    if (omega > 0.0) width = std::min(width, 2.0 * M_PI / omega);
    width *= panel_scale;
    const double u1 = std::min(u0 + width, kUMax);
    for (int i = 0; i < kGauss; ++i) {
      const double ui = u0 + (u1 - u0) * g.x[i];
      u.push_back(ui);
      wf.push_back((u1 - u0) * g.w[i] * compliance_minus_one(ui, kap));
    }
    u0 = u1;
  }
}

int nystrom_nodes(double lambda, double node_scale) {
  return static_cast<int>(std::ceil(node_scale * (24.0 + 4.5 * lambda)));
}

// One linear solve: the contact of radius a (derivation point 3).
std::shared_ptr<LayerHertzSolution> solve_radius(double a, double R, double h, double E, double nu,
                                                 const LayerHertzQuadrature& q) {
  auto s = std::make_shared<LayerHertzSolution>();
  s->a = a;
  s->h = h;
  s->R = R;
  s->Estar = E / (1.0 - nu * nu);
  s->kap = 3.0 - 4.0 * nu;
  s->lambda = a / h;
  s->panel_scale = q.panel_scale;
  const double lam = s->lambda;
  if (!(lam <= kMaxRatio))
    throw std::domain_error("layer_hertz: contact radius / thickness = " + show(lam) +
                            " exceeds the supported 100");
  const int n = nystrom_nodes(lam, q.node_scale);
  const GaussRule1d rule = gauss_legendre01(n);
  s->x = rule.x;
  s->w = rule.w;
  wavenumber_nodes(2.0 * lam, s->kap, q.panel_scale, s->u, s->wf);
  const int m = static_cast<int>(s->u.size());

  Eigen::MatrixXd C(n, m);  // C(i, j) = cos(λ u_j x_i)
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i) C(i, j) = std::cos(lam * s->u[j] * s->x[i]);
  const Eigen::Map<const Eigen::VectorXd> wf(s->wf.data(), m), w(s->w.data(), n), x(s->x.data(), n);
  const Eigen::MatrixXd k = C * wf.asDiagonal() * C.transpose();  // k(x_i, x_j)
  Eigen::MatrixXd A = lam * k * w.asDiagonal();
  A.diagonal().array() += 0.5 * M_PI;
  Eigen::MatrixXd rhs(n, 2);
  rhs.col(0).setOnes();
  rhs.col(1) = x.array().square().matrix();
  const Eigen::MatrixXd G = A.partialPivLu().solve(rhs);  // γ₁, γ₂ at the nodes

  // P_k(u) = Σ w_j γ_k(x_j) cos(λ u x_j); the Nyström interpolant at the edge is
  // γ_k(1) = (2/π)[rhs_k(1) − λ ∫ f(u) cos(λu) P_k(u) du].
  const Eigen::MatrixXd P = C.transpose() * (w.asDiagonal() * G);  // m × 2
  double kg1 = 0.0, kg2 = 0.0;
  for (int j = 0; j < m; ++j) {
    const double c = s->wf[j] * std::cos(lam * s->u[j]);
    kg1 += c * P(j, 0);
    kg2 += c * P(j, 1);
  }
  const double g1 = 2.0 / M_PI * (1.0 - lam * kg1), g2 = 2.0 / M_PI * (1.0 - lam * kg2);
  s->d = g2 / g1;
  const Eigen::VectorXd gamma = s->d * G.col(0) - G.col(1);
  s->gamma.assign(gamma.data(), gamma.data() + n);
  const Eigen::VectorXd Pc = s->d * P.col(0) - P.col(1);
  s->P.assign(Pc.data(), Pc.data() + m);
  const GaussRule1d rv = gauss_legendre01(n);
  s->v = rv.x;
  s->wv = rv.w;
  return s;
}

double pressure(const LayerHertzSolution& s, double r) {
  const double rho = std::fabs(r) / s.a;
  if (!(rho < 1.0)) return rho >= 1.0 ? 0.0 : std::numeric_limits<double>::quiet_NaN();
  const double Y2 = (1.0 - rho) * (1.0 + rho), Y = std::sqrt(Y2);
  const double lam = s.lambda;
  const std::size_t m = s.u.size();
  double sum = 0.0;
  for (std::size_t i = 0; i < s.v.size(); ++i) {
    const double xx = std::sqrt(rho * rho + Y2 * s.v[i] * s.v[i]);  // > 0: Gauss nodes avoid v = 0
    // γ'(x)/x = (2/π)[−2 + λ² ∫ f(u) u sin(λux)/x P(u) du]
    double acc = 0.0;
    for (std::size_t j = 0; j < m; ++j) acc += s.wf[j] * s.u[j] * std::sin(lam * s.u[j] * xx) * s.P[j];
    const double dg_over_x = 2.0 / M_PI * (-2.0 + lam * lam * acc / xx);
    sum -= s.wv[i] * dg_over_x;
  }
  return s.Estar * s.a / (2.0 * s.R) * Y * sum;
}

double deflection(const LayerHertzSolution& s, double r) {
  r = std::fabs(r);
  const double delta = s.d * s.a * s.a / s.R;
  if (r <= s.a) return delta - r * r / (2.0 * s.R);
  // Far field: w decays at least like e^{−0.739(r−a)/h} (nearest pole of M), below 1e-17 δ beyond 60h, where
  // the cancellation between the closed-form terms (roundoff ~1e-14 δ) would dominate the computed value.
  if (r - s.a > 60.0 * s.h) return 0.0;
  const double rho = r / s.a, lam = s.lambda;
  const double th_a = std::asin(1.0 / rho);
  double out = (s.d - 0.5 * rho * rho) * th_a + 0.5 * std::sqrt((rho - 1.0) * (rho + 1.0));
  // λ ∫ Ŵ(ρ sin θ) dθ: wavenumber nodes for the frequency λ(ρ + 1) of cos(λux)·P(u), P re-evaluated there.
  std::vector<double> u, wf;
  wavenumber_nodes(lam * (rho + 1.0), s.kap, s.panel_scale, u, wf);
  const std::size_t m = u.size(), n = s.x.size();
  std::vector<double> c(m);
  for (std::size_t j = 0; j < m; ++j) {
    double P = 0.0;
    for (std::size_t i = 0; i < n; ++i) P += s.w[i] * s.gamma[i] * std::cos(lam * u[j] * s.x[i]);
    c[j] = wf[j] * P;
  }
  // θ panels of width ≤ 1.5/(λρ) (Ŵ is analytic for |Im x| < 2/λ) and ≤ (π/2 − θ_a)/2.
  static const GaussRule1d g = gauss_legendre01(kGauss);
  const double span = 0.5 * M_PI - th_a;
  const int panels =
      static_cast<int>(std::ceil(std::max(2.0, span * lam * rho / 1.5) / std::min(1.0, s.panel_scale)));
  double integral = 0.0;
  for (int p = 0; p < panels; ++p) {
    const double t0 = th_a + span * p / panels, t1 = th_a + span * (p + 1) / panels;
    for (int i = 0; i < kGauss; ++i) {
      const double xx = rho * std::sin(t0 + (t1 - t0) * g.x[i]);
      double W = 0.0;
      for (std::size_t j = 0; j < m; ++j) W += c[j] * std::cos(lam * u[j] * xx);
      integral += (t1 - t0) * g.w[i] * W;
    }
  }
  out += lam * integral;
  return 2.0 / M_PI * s.a * s.a / s.R * out;
}

LayerHertzResult make_result(std::shared_ptr<const LayerHertzSolution> s) {
  LayerHertzResult r;
  r.a_mm = s->a;
  r.delta_mm = s->d * s->a * s->a / s->R;
  double I = 0.0;
  for (std::size_t i = 0; i < s->x.size(); ++i) I += s->w[i] * s->gamma[i];
  r.force_N = M_PI * s->Estar * s->a * s->a * s->a / s->R * I;
  r.nodes = static_cast<int>(s->x.size());
  r.p0_MPa = pressure(*s, 0.0);
  r.solution = std::move(s);
  return r;
}

// Solves quantity(a) = target for a, quantity = F or δ (both increasing in a), by a secant iteration on
// φ(ln a) = ln quantity − ln target, safeguarded by bisection once the root is bracketed. slope0 ≈ dφ/d ln a.
template <class Quantity>
LayerHertzResult solve_for(const char* who, double target, double a0, double slope0, double R, double h,
                           double E, double nu, const LayerHertzQuadrature& q, Quantity quantity) {
  struct Trial {
    double l = 0, phi = 0;
    std::shared_ptr<const LayerHertzSolution> s;
  };
  const double ln_target = std::log(target);
  const double l_max = std::log(kMaxRatio * h) - 1e-12;  // exp(l_max)/h ≤ 100 despite rounding
  double lo = -std::numeric_limits<double>::infinity(), hi = std::numeric_limits<double>::infinity();
  Trial best;
  best.phi = std::numeric_limits<double>::infinity();
  auto trial = [&](double l) {
    Trial t;
    t.l = l;
    t.s = solve_radius(std::exp(l), R, h, E, nu, q);
    t.phi = std::log(quantity(make_result(t.s))) - ln_target;
    if (t.phi < 0.0) lo = std::max(lo, l);
    if (t.phi > 0.0) hi = std::min(hi, l);
    if (std::fabs(t.phi) < std::fabs(best.phi)) best = t;
    return t;
  };
  Trial t0 = trial(std::min(std::log(a0), l_max));
  Trial t1 = trial(std::min(t0.l - t0.phi / slope0, l_max));
  for (int it = 0; it < 100 && best.phi != 0.0; ++it) {
    double slope = (t1.phi - t0.phi) / (t1.l - t0.l);
    if (!(std::isfinite(slope) && slope > 0.1)) slope = slope0;
    double l2 = t1.l - t1.phi / slope;
    l2 = std::clamp(l2, t1.l - 1.0, t1.l + 1.0);
    if (l2 <= lo || l2 >= hi) l2 = 0.5 * (std::max(lo, t1.l - 1.0) + std::min(hi, t1.l + 1.0));
    if (l2 > l_max) {
      if (t1.l >= l_max) break;  // the root lies beyond the supported a/h
      l2 = l_max;
    }
    if (std::fabs(l2 - t1.l) < 1e-15 || hi - lo < 1e-15) break;
    t0 = t1;
    t1 = trial(l2);
    if (std::fabs(t1.phi) < 1e-15) break;
  }
  if (!(std::fabs(best.phi) < 1e-12)) {
    if (best.l >= l_max - 1e-12)
      throw std::domain_error(std::string(who) +
                              ": the contact radius exceeds 100 h (outside the solver's range)");
    throw std::runtime_error(std::string(who) + ": contact radius iteration did not converge (residual " +
                             show(best.phi) + ")");
  }
  return make_result(best.s);
}

}  // namespace

double LayerHertzResult::pressure_MPa(double r_mm) const {
  if (!solution) throw std::logic_error("LayerHertzResult::pressure_MPa: empty result");
  return pressure(*solution, r_mm);
}

double LayerHertzResult::deflection_mm(double r_mm) const {
  if (!solution) throw std::logic_error("LayerHertzResult::deflection_mm: empty result");
  return deflection(*solution, r_mm);
}

HertzHalfspace hertz_halfspace(double force_N, double R_mm, double E_MPa, double nu) {
  check_positive("hertz_halfspace", "force_N", force_N);
  check_inputs("hertz_halfspace", R_mm, 1.0, E_MPa, nu);
  const double Estar = E_MPa / (1.0 - nu * nu);
  HertzHalfspace r;
  r.force_N = force_N;
  r.a_mm = std::cbrt(3.0 * force_N * R_mm / (4.0 * Estar));
  r.delta_mm = r.a_mm * r.a_mm / R_mm;
  r.p0_MPa = 3.0 * force_N / (2.0 * M_PI * r.a_mm * r.a_mm);
  return r;
}

double layer_surface_compliance(double t, double nu) {
  if (!(t >= 0.0) || !(nu >= 0.0 && nu <= 0.5))
    throw std::invalid_argument("layer_surface_compliance: need t >= 0 and nu in [0, 0.5]");
  const double kap = 3.0 - 4.0 * nu;
  if (t < 0.5) {
    // 2κ(sinh 2t − 2t) + 4(κ − 1)t: the series of sinh y − y keeps M ≈ 2t³/3 accurate at ν = 0.5.
    const double y = 2.0 * t, y2 = y * y;
    double term = y * y2 / 6.0, shm = 0.0;
    for (int k = 1; k < 30 && term > 1e-18 * shm; ++k) {
      shm += term;
      term *= y2 / ((2.0 * k + 2.0) * (2.0 * k + 3.0));
    }
    const double num = 2.0 * kap * shm + 4.0 * (kap - 1.0) * t;
    const double den = 2.0 * kap * std::cosh(y) + 1.0 + kap * kap + 4.0 * t * t;
    return num / den;
  }
  const double X = std::exp(-2.0 * t);
  return (kap * (1.0 - X * X) - 4.0 * t * X) / (kap * (1.0 + X * X) + (1.0 + kap * kap + 4.0 * t * t) * X);
}

LayerHertzResult layer_hertz_radius(double a_mm, double R_mm, double h_mm, double E_MPa, double nu,
                                    LayerHertzQuadrature quadrature) {
  check_positive("layer_hertz_radius", "a_mm", a_mm);
  check_inputs("layer_hertz_radius", R_mm, h_mm, E_MPa, nu);
  check_quadrature("layer_hertz_radius", quadrature);
  return make_result(solve_radius(a_mm, R_mm, h_mm, E_MPa, nu, quadrature));
}

LayerHertzResult layer_hertz_force(double force_N, double R_mm, double h_mm, double E_MPa, double nu,
                                   LayerHertzQuadrature quadrature) {
  check_positive("layer_hertz_force", "force_N", force_N);
  check_inputs("layer_hertz_force", R_mm, h_mm, E_MPa, nu);
  check_quadrature("layer_hertz_force", quadrature);
  // Start from the smaller of Hertz's radius and the incompressible lubrication one, F = πEa⁶/(96Rh³) (both
  // upper bounds at ν = 0.5: the base stiffens the layer, and the edge boundary layer stiffens it beyond the
  // lubrication limit); d ln F / d ln a is 3 (thick) to 6 (thin).
  const double a_hertz = hertz_halfspace(force_N, R_mm, E_MPa, nu).a_mm;
  const double a_lub = std::pow(96.0 * R_mm * h_mm * h_mm * h_mm * force_N / (M_PI * E_MPa), 1.0 / 6.0);
  return solve_for("layer_hertz_force", force_N, std::min(a_hertz, a_lub), a_hertz < a_lub ? 3.0 : 6.0, R_mm,
                   h_mm, E_MPa, nu, quadrature, [](const LayerHertzResult& r) { return r.force_N; });
}

LayerHertzResult layer_hertz_depth(double delta_mm, double R_mm, double h_mm, double E_MPa, double nu,
                                   LayerHertzQuadrature quadrature) {
  check_positive("layer_hertz_depth", "delta_mm", delta_mm);
  check_inputs("layer_hertz_depth", R_mm, h_mm, E_MPa, nu);
  check_quadrature("layer_hertz_depth", quadrature);
  // Hertz a = √(Rδ) is a lower bound (thin layers: up to 2√(Rδ)); d ln δ / d ln a ≈ 2.
  return solve_for("layer_hertz_depth", delta_mm, std::sqrt(R_mm * delta_mm), 2.0, R_mm, h_mm, E_MPa, nu,
                   quadrature, [](const LayerHertzResult& r) { return r.delta_mm; });
}

}  // namespace skinfem::contact
