// Exact frictionless contact of a rigid sphere with a flat elastic layer bonded to a rigid base (axisymmetric
// Hertz problem on a finite layer), and the half-space Hertz formulas.
//
// Units: mm, N, MPa throughout (lengths mm, forces N, pressures and moduli MPa).
//
// Problem. Layer 0 < z < h, u = 0 on the base z = 0; on the top z = h the shear traction is zero everywhere
// (frictionless sphere) and the normal pressure p(r) acts on the contact disc r < a. Linear isotropic
// elasticity, Young modulus E, 0 ≤ ν ≤ 0.5 (ν = 0.5 is the incompressible limit, no special case). The sphere
// of radius R is parabolic (Hertz): inside the contact the downward surface deflection is w(r) = δ − r²/(2R),
// δ the rigid approach of the sphere from first touch. Outside, the surface is free (w ≥ δ − r²/(2R)).
//
// Method (layer_hertz.cpp has the derivation). Per wavenumber s the surface deflection under a normal
// pressure is w̃(s) = [2/(E* s)] M(sh) p̃(s) (zeroth-order Hankel transforms, E* = E/(1 − ν²)), with
//   M(t) = (2κ sinh 2t − 4t) / (2κ cosh 2t + 1 + κ² + 4t²),   κ = 3 − 4ν,
// from the Papkovich–Neuber basis of green/layer_exact.cpp (M → 1 for a half-space; M ≈ 2t³/3 at ν = 0.5: the
// lubrication limit). Writing p̃(s) = ∫₀ᵃ g(τ) cos(sτ) dτ (Sneddon's representation: p(r) = g(a)/√(a² − r²) −
// ∫ᵣᵃ g'(τ) dτ/√(τ² − r²)), the contact condition becomes, after Abel's inversion, the Fredholm equation of
// the second kind (Lebedev & Ufliand, PMM 22 (1958); Vorovich et al., Nonclassical mixed problems, 1974)
//   (π/2) g(t) + ∫₀ᵃ K(t, τ) g(τ) dτ = (E*/2)(δ − t²/R),  0 ≤ t ≤ a,
//   K(t, τ) = ∫₀^∞ [M(sh) − 1] cos(st) cos(sτ) ds   (smooth: M − 1 decays like t² e^{−2t}),
// and F = 2π ∫₀ᵃ g dt. The edge condition g(a) = 0 (no edge singularity, p ~ √(a − r)) fixes δ for a given a.
// This representation was chosen over a direct discretization of p(r) because the kernel is smooth and the
// unknown analytic, so Gauss–Legendre Nyström converges exponentially (1e-12 with ~30 nodes for a ≈ h), and
// both the square-root edge and the contact radius come out exactly instead of from a fitted profile.
// Load or depth control: the contact radius is found by a safeguarded secant iteration on ln a.
//
// Accuracy: ≲ 1e-12 relative on a, p0, δ, F (tests/contact/test_layer_hertz.cpp halves/doubles both
// quadratures). Cost: one solve per trial radius, growing like (a/h)³: the paper's case (a/h ≈ 0.8, load
// control) takes ~1 ms; one radius takes 0.1 s at a/h = 40 and 0.7 s at a/h = 100, and load or depth control
// needs 5–10 of them. Contact radii beyond 100 h are refused (std::domain_error).
#pragma once

#include <memory>

namespace skinfem::contact {

/// Quadrature controls (defaults converge to ≲ 1e-12; tests scale them to show convergence).
struct LayerHertzQuadrature {
  double node_scale = 1.0;   ///< multiplies the number of Nyström nodes on [0, a] (2 doubles them)
  double panel_scale = 1.0;  ///< multiplies every wavenumber panel width (0.5 doubles the resolution)
};

/// Half-space Hertz contact (rigid sphere on an elastic half-space, Johnson 1985 §4.2).
struct HertzHalfspace {
  double a_mm = 0;      ///< contact radius, a³ = 3FR/(4E*)
  double p0_MPa = 0;    ///< central pressure 3F/(2πa²)
  double delta_mm = 0;  ///< indentation a²/R
  double force_N = 0;   ///< the total force F
};
HertzHalfspace hertz_halfspace(double force_N, double R_mm, double E_MPa, double nu);

/// Surface compliance factor M(t) of the bonded layer (t = s·h ≥ 0): ratio of the layer's surface deflection
/// to the half-space one under the normal harmonic pressure of wavenumber s, top shear-free. M(0) = 0, M → 1.
double layer_surface_compliance(double t, double nu);

struct LayerHertzSolution;  // internal state of a solved contact (layer_hertz.cpp)

/// A solved contact. Copies share the solution (cheap); pressure and deflection are thread-safe.
struct LayerHertzResult {
  double a_mm = 0;      ///< contact radius
  double p0_MPa = 0;    ///< central pressure p(0)
  double delta_mm = 0;  ///< indentation: rigid approach of the sphere from first touch (= w(0))
  double force_N = 0;   ///< total normal force 2π ∫ p r dr
  int nodes = 0;        ///< Nyström nodes used on [0, a]

  /// Contact pressure at radius r (MPa, ≥ 0, zero for r ≥ a, ~ √(a − r) at the edge).
  double pressure_MPa(double r_mm) const;
  /// Downward surface deflection at radius r (mm): δ − r²/(2R) inside the contact, the layer's free surface
  /// outside (may be negative: an incompressible layer bulges up around the contact); 0 beyond a + 60h, where
  /// |w| < 1e-17 δ. Cost outside the contact grows with r/h (paper's case: 0.2 ms at r − a = 2h, 1.5 ms at
  /// 10h, 11 ms at 30h); inside it is free, and pressure_MPa costs ~0.05 ms (a ≈ h) to 3 ms (a = 20h).
  double deflection_mm(double r_mm) const;

  std::shared_ptr<const LayerHertzSolution> solution;
};

/// Load control: total force F [N] > 0, sphere radius R [mm] > 0, thickness h [mm] > 0, E [MPa] > 0,
/// 0 ≤ nu ≤ 0.5. Throws std::invalid_argument (one line) on bad input.
LayerHertzResult layer_hertz_force(double force_N, double R_mm, double h_mm, double E_MPa, double nu,
                                   LayerHertzQuadrature quadrature = {});
/// Depth control: indentation δ [mm] > 0, otherwise as layer_hertz_force.
LayerHertzResult layer_hertz_depth(double delta_mm, double R_mm, double h_mm, double E_MPa, double nu,
                                   LayerHertzQuadrature quadrature = {});
/// The contact with a given contact radius a [mm] > 0 (one linear solve, no iteration).
LayerHertzResult layer_hertz_radius(double a_mm, double R_mm, double h_mm, double E_MPa, double nu,
                                    LayerHertzQuadrature quadrature = {});

}  // namespace skinfem::contact
