// The bonded-layer Hertz contact of contact/layer_hertz.hpp with a linear rough interface in series
// (scene.hpp, InterfaceLaw::linear): inside the contact the layer's deflection plus the interface's closure
// p/K meet the sphere, w(r) + p(r)/K = δ − r²/(2R); outside p = 0. Units mm, N, MPa; K in MPa/mm.
//
// Method (layer_hertz_interface.cpp has the derivation). In Sneddon's representation p̃(s) = ∫₀ᵃ g cos(sτ) dτ
// the closure adds (1/2K) PV∫₋ₐᵃ g'(τ)/(t − τ) dτ to the layer's Fredholm operator (g even): a Prandtl-type
// singular integro-differential equation. With x = t/a = cos θ and g = (E*a²/2R) Σ c_n sin nθ (n odd: g
// even, g(a) = 0), that operator is diagonal, (πE*/(4aK)) Σ n c_n sin nθ / sin θ (Chebyshev's
// PV∫ T_n/((y − x)√(1−y²)) = π U_{n−1}(x)), the layer's part is the smooth kernel of layer_hertz.hpp, and
// the pressure at the edge is p(a⁻) ∝ Σ n c_n: it must vanish (the closure is continuous and zero outside),
// which fixes a. Collocation at N points + that condition solve for c and δ at a given a; load or depth
// control iterate on a. F = (π²/2) a (E*a²/2R) c_1 exactly.
//
// Accuracy: the edge is not analytic (log terms of the Prandtl operator), so the series converges
// algebraically: tests/contact/test_layer_hertz_interface.cpp measures the order in N and checks the hard
// limit (K → ∞: layer_hertz) and the Winkler limit (K → 0: F = πKRδ²).
#pragma once

namespace skinfem::contact {

struct LayerHertzInterfaceResult {
  double a_mm = 0;      ///< contact radius
  double p0_MPa = 0;    ///< central pressure
  double delta_mm = 0;  ///< rigid approach of the sphere from first touch
  double force_N = 0;   ///< total normal force
  int terms = 0;        ///< sine terms N
};

/// Contact radius given: one linear solve. K > 0 MPa/mm; terms ≥ 2; the rest as layer_hertz_radius.
/// Throws std::invalid_argument (one line) on bad input.
LayerHertzInterfaceResult layer_hertz_interface_radius(double a_mm, double R_mm, double h_mm, double E_MPa,
                                                       double nu, double K, int terms = 64);
/// Load control (F > 0 N) and depth control (δ > 0 mm): the radius iterated to 1e-12 relative.
LayerHertzInterfaceResult layer_hertz_interface_force(double force_N, double R_mm, double h_mm, double E_MPa,
                                                      double nu, double K, int terms = 64);
LayerHertzInterfaceResult layer_hertz_interface_depth(double delta_mm, double R_mm, double h_mm, double E_MPa,
                                                      double nu, double K, int terms = 64);

}  // namespace skinfem::contact
