// A compliant interface (contact.interface, linear: the interface closes by p/K before the surfaces meet)
// on the paper's layer (h = 3.04 mm, E = 3 MPa, ν = 0.5) under a sphere R = 129.7 mm, against its two limits:
//   K → ∞: the hard contact, the difference falling like 1/K;
//   K → 0: the Winkler foundation p = K (δ − r²/2R), a² = 2Rδ, F = πKRδ² (the skin, in series, is rigid
//          next to the interface), the difference falling like K (the skin's compliance in series).
// and an exponential interface (p = p_ref exp(−gap/u0)) against its limits and its one exact symmetry:
//   p_ref → 0: the skin is rigid next to the interface, p = p_ref exp((δ − r²/2R)/u0), F = 2πR u0 p_ref
//   e^{δ/u0}; u0 → 0: the hard contact; under force control p_ref only shifts the depth, by u0
//   ln(p_ref'/p_ref), and leaves the pressure.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include "../common/convergence.hpp"
#include "layer_fixture.hpp"
#include "skinfem/contact/contact_solver.hpp"

namespace skinfem::contact {
namespace {

constexpr double kR = testing::kSphereR;

testing::CondensedLayer& layer() {
  static testing::CondensedLayer f;
  static const bool ready = [] {
    ContactLoad c;
    c.depth = 0.01;
    testing::condense_layer(f, testing::layer_scene("test_interface", 0.4, {{0, 0}, {1.5, 0}}, c, 2.6));
    return true;
  }();
  (void)ready;
  return f;
}

ContactResult solve_with(std::optional<double> K) {
  ContactLoad c = *layer().scene.contact;
  if (K) c.interface = {InterfaceLaw::linear, *K};
  return ContactSolver(*layer().condensed, c).solve(FrictionMode::none);
}

ContactResult solve_exponential(double u0, double p_ref, ContactLoad c = *layer().scene.contact,
                                FrictionMode mode = FrictionMode::none) {
  c.interface = {InterfaceLaw::exponential, 0.0, u0, p_ref};
  return ContactSolver(*layer().condensed, c).solve(mode);
}

using testing::order_from_differences;

TEST(Interface, StiffInterfaceTendsToTheHardContact) {
  const ContactResult hard = solve_with(std::nullopt);
  std::array<double, 3> e{};
  const std::array<double, 3> K{1e3, 1e4, 1e5};
  for (int l = 0; l < 3; ++l) {
    const ContactResult r = solve_with(K[l]);
    e[l] = std::abs(r.force_N / hard.force_N - 1);
    std::printf("K = %g MPa/mm: F = %.9f N (hard %.9f N)\n", K[l], r.force_N, hard.force_N);
  }
  // The interface adds δ_i = p/K in series: F(K) = F_hard (1 − c/K + O(1/K²)), an error of order 1 in 1/K.
  EXPECT_NEAR(std::log(e[0] / e[1]) / std::log(10.0), 1.0, 0.05);
  EXPECT_NEAR(std::log(e[1] / e[2]) / std::log(10.0), 1.0, 0.05);
  EXPECT_LT(e[2], 1e-3);
}

TEST(Interface, SoftInterfaceTendsToWinkler) {
  const double delta = *layer().scene.contact->depth;
  std::array<double, 3> e{};
  const std::array<double, 3> K{0.04, 0.02, 0.01};
  for (int l = 0; l < 3; ++l) {
    const ContactResult r = solve_with(K[l]);
    const double winkler = M_PI * K[l] * kR * delta * delta;
    e[l] = r.force_N / winkler - 1;
    std::printf("K = %g MPa/mm: F = %.6e N, Winkler %.6e N, relative difference %.3e\n", K[l], r.force_N,
                winkler, e[l]);
  }
  // e(K) = −cK + e_h: the skin's compliance in series (first order in K) and the mortar's P1 quadrature of
  // the Winkler pressure e_h (independent of K). Differences remove e_h: their ratio is 2^1.
  EXPECT_NEAR(order_from_differences(e, 2.0), 1.0, 0.1);
  EXPECT_LT(e[0], e[2]);  // a softer interface is closer to Winkler from below
}

TEST(Interface, ExponentialWithARigidSkinIsGaussian) {
  // Width √(2R u0) = 0.72 mm: e^{−13} of the peak at the zone's edge (2.6 mm). The peak pressure
  // p_ref e^{δ/u0} = 12 p_ref deflects the skin by w ≈ 0.1–0.4 % of u0 here, so e(p_ref) = −c p_ref + e_h:
  // the skin in series (first order in p_ref) and the mortar's lumping of the law on the hat means e_h
  // (Jensen: e^{−ḡ} ≤ mean of e^{−g}, so e_h < 0, of order var(gap over a hat)/(2u0²) ≈ 3 %), independent of
  // p_ref.
  const double u0 = 0.002, delta = 0.005;
  ContactLoad c = *layer().scene.contact;
  c.depth = delta;
  std::array<double, 3> e{};
  const std::array<double, 3> p_ref{2e-5, 1e-5, 5e-6};
  for (int l = 0; l < 3; ++l) {
    const ContactResult r = solve_exponential(u0, p_ref[l], c);
    const double rigid = 2 * M_PI * kR * u0 * p_ref[l] * std::exp(delta / u0);
    e[l] = r.force_N / rigid - 1;
    std::printf("p_ref = %g MPa: F = %.6e N, rigid skin %.6e N, relative difference %.3e, %d Newton steps\n",
                p_ref[l], r.force_N, rigid, e[l], r.pivots);
    EXPECT_LT(r.complementarity, 1e-10);
  }
  const double e_h = 2 * e[2] - e[1];
  std::printf("observed order %.3f, lumping error e_h = %.3e\n", order_from_differences(e, 2.0), e_h);
  EXPECT_NEAR(order_from_differences(e, 2.0), 1.0, 0.1);
  EXPECT_LT(e_h, 0.0);
  EXPECT_GT(e_h, -0.06);
}

TEST(Interface, ExponentialTendsToTheHardContact) {
  // p_ref = the hard contact's mean pressure. The gap held is −u0 ln(p/p_ref) instead of 0: O(u0) inside,
  // spread over the O(u0)-wide tail at the edge, so F(u0) − F_hard is first order in u0 (to log factors).
  const ContactResult hard = solve_with(std::nullopt);
  const double p_mean = hard.force_N / [&] {
    double a = 0;
    for (int i : hard.active) a += layer().condensed->zone.area[i];
    return a;
  }();
  std::array<double, 3> e{};
  const std::array<double, 3> u0{4e-4, 2e-4, 1e-4};
  for (int l = 0; l < 3; ++l) {
    const ContactResult r = solve_exponential(u0[l], p_mean);
    e[l] = r.force_N / hard.force_N - 1;
    std::printf("u0 = %g mm: F = %.9f N (hard %.9f N), relative %.3e, %d Newton steps, residual %.1e\n",
                u0[l], r.force_N, hard.force_N, e[l], r.pivots, r.complementarity);
    EXPECT_LT(r.complementarity, 1e-10);
  }
  const double order = std::log(e[0] / e[1]) / std::log(2.0), order2 = std::log(e[1] / e[2]) / std::log(2.0);
  std::printf("observed orders %.3f, %.3f\n", order, order2);
  EXPECT_NEAR(order, 1.0, 0.15);
  EXPECT_NEAR(order2, 1.0, 0.15);
  EXPECT_LT(std::abs(e[2]), 0.02);
}

TEST(Interface, ExponentialReferencePressureOnlyShiftsTheDepth) {
  // g = −u0 ln(p/p_ref) where it touches: p_ref' = 4 p_ref adds u0 ln 4 to every held separation, which
  // the depth takes up exactly under force control.
  ContactLoad c = *layer().scene.contact;
  c.depth.reset();
  c.force = 0.8;
  const double u0 = 0.001;
  const ContactResult a = solve_exponential(u0, 0.01, c), b = solve_exponential(u0, 0.04, c);
  const double scale = a.lambda.cwiseAbs().maxCoeff();
  const double change = (a.lambda - b.lambda).cwiseAbs().maxCoeff() / scale;
  std::printf("max |dlambda| / max lambda = %.2e, depth shift %.9e mm (-u0 ln 4 = %.9e mm)\n", change,
              b.depth_mm - a.depth_mm, -u0 * std::log(4.0));
  EXPECT_LT(change, 1e-10);
  EXPECT_NEAR(b.depth_mm - a.depth_mm, -u0 * std::log(4.0), 1e-12);
  EXPECT_NEAR(a.force_N, 0.8, 1e-12);
}

}  // namespace
}  // namespace skinfem::contact
