#include "skinfem/contact/layer_hertz_interface.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "skinfem/contact/layer_hertz.hpp"
#include "skinfem/mesh/gauss_legendre.hpp"

// Derivation. Notation of layer_hertz.cpp: g(ax) = G γ(x), G = E*a²/(2R), δ = d a²/R, λ = a/h, the layer's
// Fredholm operator (π/2)γ + λ∫₀¹ k(x, ξ)γ(ξ) dξ with k(x, ξ) = ∫₀^∞ (M(u) − 1) cos(λux) cos(λuξ) du.
//
// 1. The closure. w(r) = (2/π)∫₀ʳ W(t)/√(r² − t²) dt inverts to W(t) = d/dt ∫₀ᵗ r w(r)/√(t² − r²) dr. For
//    w = p/K with p(r) = −∫ᵣᵃ g'(τ)/√(τ² − r²) dτ (g(a) = 0), exchanging the integrals and
//    ∫₀^min(t,τ) r dr/√((t² − r²)(τ² − r²)) = ½ ln|(t + τ)/(t − τ)| give
//      W_K(t) = (1/K) PV∫₀ᵃ g'(τ) τ/(t² − τ²) dτ = (1/2K) PV∫₋ₐᵃ g'(τ)/(t − τ) dτ   (g even).
//    Check: g = √(a² − τ²) is the uniform pressure π/2; the formula gives W_K = π/(2K) and w = π/(2K) = p/K.
// 2. The basis. x = cos θ, γ = Σ c_n sin nθ = Σ c_n √(1 − x²) U_{n−1}(x), n odd (γ even in x, γ(1) = 0:
//    no edge singularity). dγ/dx = −Σ n c_n T_n/√(1 − x²) and PV∫₋₁¹ T_n(y)/((y − x)√(1 − y²)) dy =
//    π U_{n−1}(x), so PV∫₋₁¹ γ'(y)/(x − y) dy = π Σ n c_n U_{n−1}(x). Divided by a²/R = 2G/E*:
//      Σ c_n [(π/2) sin nθ + λ L_n(x) + β π n sin nθ / sin θ] = d − x²,   β = E*/(4aK),
//    L_n(x) = ∫₀^∞ (M − 1) cos(λux) Q_n(u) du, Q_n(u) = ∫₀^{π/2} cos(λu cos φ) sin nφ sin φ dφ.
// 3. The edge. p(aρ) = −(G/a) ∫ᵨ¹ γ'(x)/√(x² − ρ²) dx → (π/2)(G/a) Σ n c_n as ρ → 1: zero, since the closure
//    p/K is continuous and p = 0 outside. Centre: p(0) = (π/2)(G/a) Σ (−1)^((n−1)/2) n c_n. Force:
//    F = 2πaG ∫₀¹ γ = (π²/2) a G c_1 (only sin θ has a non-zero mean against sin θ dθ).
// 4. Numerics. Collocation at θ_j = (j − ½)π/(2N); Q_n by Gauss–Legendre in φ (entire integrand, nodes
//    2(2N + 24λ) + 32); the u-integral on 16-point panels over [0, 24] of width ≤ min(1, π/λ) (f(24) ~ 1e-18,
//    as in layer_hertz.cpp).

namespace skinfem::contact {

namespace {

struct Radius {
  double d = 0, force = 0, p0 = 0;
};

std::string show_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

void check(const char* who, const char* name, double v) {
  if (!(std::isfinite(v) && v > 0))
    throw std::invalid_argument(std::string(who) + ": " + name + " must be finite and > 0 (got " +
                                show_number(v) + ")");
}

void check_all(const char* who, double R, double h, double E, double nu, double K, int terms) {
  check(who, "R_mm", R);
  check(who, "h_mm", h);
  check(who, "E_MPa", E);
  check(who, "K", K);
  if (!(nu >= 0 && nu <= 0.5))
    throw std::invalid_argument(std::string(who) + ": nu must be in [0, 0.5] (got " + show_number(nu) + ")");
  if (terms < 2 || terms > 2000)
    throw std::invalid_argument(std::string(who) + ": terms must be in [2, 2000] (got " +
                                std::to_string(terms) + ")");
}

Radius solve_radius(double a, double R, double h, double E, double nu, double K, int N) {
  const double Estar = E / (1 - nu * nu), lam = a / h, beta = Estar / (4 * a * K);
  if (lam > 100) throw std::domain_error("layer_hertz_interface: contact radius / thickness exceeds 100");
  // Wavenumber nodes and weights·(M − 1).
  static const GaussRule1d g16 = gauss_legendre01(16);
  std::vector<double> u, wf;
  for (double u0 = 0; u0 < 24.0;) {
    const double u1 = std::min(24.0, u0 + std::min(1.0, M_PI / std::max(lam, 1e-12)));
    for (int i = 0; i < 16; ++i) {
      const double ui = u0 + (u1 - u0) * g16.x[i];
      u.push_back(ui);
      wf.push_back((u1 - u0) * g16.w[i] * (layer_surface_compliance(ui, nu) - 1.0));
    }
    u0 = u1;
  }
  const int m = static_cast<int>(u.size());
  const int P = 2 * (2 * N + static_cast<int>(std::ceil(24 * lam))) + 32;
  const GaussRule1d gp = gauss_legendre01(P);
  Eigen::MatrixXd C(m, P),
      S(N, P);  // Q_n(u_j) = (π/2) Σ_i w_i cos(λu_j cos φ_i) sin nφ_i sin φ_i, n = 2k + 1
  for (int i = 0; i < P; ++i) {
    const double phi = 0.5 * M_PI * gp.x[i];
    for (int j = 0; j < m; ++j) C(j, i) = 0.5 * M_PI * gp.w[i] * std::cos(lam * u[j] * std::cos(phi));
    for (int k = 0; k < N; ++k) S(k, i) = std::sin((2 * k + 1) * phi) * std::sin(phi);
  }
  const Eigen::MatrixXd Q = C * S.transpose();
  Eigen::MatrixXd X(N, m);  // wf_i cos(λ u_i x_j) at the collocation points
  for (int j = 0; j < N; ++j)
    for (int i = 0; i < m; ++i) X(j, i) = wf[i] * std::cos(lam * u[i] * std::cos((j + 0.5) * 0.5 * M_PI / N));
  const Eigen::MatrixXd L = X * Q;  // L_n(x_j)
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(N + 1, N + 1);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(N + 1);
  for (int j = 0; j < N; ++j) {
    const double th = (j + 0.5) * 0.5 * M_PI / N, x = std::cos(th);
    for (int k = 0; k < N; ++k) {
      const int n = 2 * k + 1;
      const double s = std::sin(n * th);
      A(j, k) = 0.5 * M_PI * s + lam * L(j, k) + beta * M_PI * n * s / std::sin(th);
    }
    A(j, N) = -1.0;
    b[j] = -x * x;
  }
  for (int k = 0; k < N; ++k) A(N, k) = 2 * k + 1;  // p(a⁻) = 0
  const Eigen::VectorXd c = A.partialPivLu().solve(b);
  Radius out;
  out.d = c[N];
  const double G = Estar * a * a / (2 * R);
  out.force = 0.5 * M_PI * M_PI * a * G * c[0];
  double s = 0;
  for (int k = 0; k < N; ++k) s += (k % 2 ? -1.0 : 1.0) * (2 * k + 1) * c[k];
  out.p0 = 0.5 * M_PI * G / a * s;
  return out;
}

LayerHertzInterfaceResult result(double a, double R, const Radius& x, int N) {
  return {a, x.p0, x.d * a * a / R, x.force, N};
}

// The radius at which quantity(a) (increasing in a) equals target: bracket by factors of 1.5 from a0, then
// Illinois false position on ln a to 1e-13 in ln quantity.
LayerHertzInterfaceResult solve_for(const char* who, double target, double a0,
                                    const std::function<double(double, const Radius&)>& quantity, double R,
                                    double h, double E, double nu, double K, int N) {
  const auto phi = [&](double l, Radius& r) {
    r = solve_radius(std::exp(l), R, h, E, nu, K, N);
    return std::log(quantity(std::exp(l), r)) - std::log(target);
  };
  Radius rl, rh;
  double lo = std::log(a0), hi = lo, flo = phi(lo, rl), fhi = flo;
  rh = rl;
  for (int i = 0; i < 60 && flo > 0; ++i) hi = lo, fhi = flo, rh = rl, lo -= std::log(1.5), flo = phi(lo, rl);
  for (int i = 0; i < 60 && fhi < 0; ++i) lo = hi, flo = fhi, rl = rh, hi += std::log(1.5), fhi = phi(hi, rh);
  if (!(flo <= 0 && fhi >= 0))
    throw std::runtime_error(std::string(who) + ": could not bracket the contact radius");
  int side = 0;
  for (int it = 0; it < 200; ++it) {
    if (std::abs(flo) < 1e-13) return result(std::exp(lo), R, rl, N);
    if (std::abs(fhi) < 1e-13) return result(std::exp(hi), R, rh, N);
    const double l = (lo * fhi - hi * flo) / (fhi - flo);
    Radius r;
    const double f = phi(l, r);
    if (f < 0) {
      lo = l, flo = f, rl = r;
      if (side == -1) fhi *= 0.5;
      side = -1;
    } else {
      hi = l, fhi = f, rh = r;
      if (side == 1) flo *= 0.5;
      side = 1;
    }
  }
  throw std::runtime_error(std::string(who) + ": the contact radius iteration did not converge");
}

}  // namespace

LayerHertzInterfaceResult layer_hertz_interface_radius(double a_mm, double R_mm, double h_mm, double E_MPa,
                                                       double nu, double K, int terms) {
  check("layer_hertz_interface_radius", "a_mm", a_mm);
  check_all("layer_hertz_interface_radius", R_mm, h_mm, E_MPa, nu, K, terms);
  return result(a_mm, R_mm, solve_radius(a_mm, R_mm, h_mm, E_MPa, nu, K, terms), terms);
}

LayerHertzInterfaceResult layer_hertz_interface_force(double force_N, double R_mm, double h_mm, double E_MPa,
                                                      double nu, double K, int terms) {
  check("layer_hertz_interface_force", "force_N", force_N);
  check_all("layer_hertz_interface_force", R_mm, h_mm, E_MPa, nu, K, terms);
  const double a0 = layer_hertz_force(force_N, R_mm, h_mm, E_MPa, nu).a_mm;
  return solve_for(
      "layer_hertz_interface_force", force_N, a0, [](double, const Radius& r) { return r.force; }, R_mm, h_mm,
      E_MPa, nu, K, terms);
}

LayerHertzInterfaceResult layer_hertz_interface_depth(double delta_mm, double R_mm, double h_mm, double E_MPa,
                                                      double nu, double K, int terms) {
  check("layer_hertz_interface_depth", "delta_mm", delta_mm);
  check_all("layer_hertz_interface_depth", R_mm, h_mm, E_MPa, nu, K, terms);
  const double a0 = layer_hertz_depth(delta_mm, R_mm, h_mm, E_MPa, nu).a_mm;
  return solve_for(
      "layer_hertz_interface_depth", delta_mm, a0,
      [R_mm](double a, const Radius& r) { return r.d * a * a / R_mm; }, R_mm, h_mm, E_MPa, nu, K, terms);
}

}  // namespace skinfem::contact
