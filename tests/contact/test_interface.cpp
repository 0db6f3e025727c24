// A compliant interface (contact.interface, linear: the interface closes by p/K before the surfaces meet)
// on the paper's layer (h = 3.04 mm, E = 3 MPa, ν = 0.5) under a sphere R = 129.7 mm, against its two limits:
//   K → ∞: the hard contact, the difference falling like 1/K;
//   K → 0: the Winkler foundation p = K (δ − r²/2R), a² = 2Rδ, F = πKRδ² (the skin, in series, is rigid
//          next to the interface), the difference falling like K (the skin's compliance in series).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include "contact/contact_solver.hpp"
#include "layer_fixture.hpp"

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

double observed_order(const std::array<double, 3>& e, double ratio) {
  return std::log(std::abs(e[0] - e[1]) / std::abs(e[1] - e[2])) / std::log(ratio);
}

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
  EXPECT_NEAR(observed_order(e, 2.0), 1.0, 0.1);
  EXPECT_LT(e[0], e[2]);  // a softer interface is closer to Winkler from below
}

}  // namespace
}  // namespace skinfem::contact
