// The exact bonded-layer Hertz contact through a linear interface (contact/layer_hertz_interface.hpp) on the
// paper's layer (h = 3.04 mm, E = 3 MPa, ν = 0.5) under a sphere R = 129.7 mm at depth δ = 10 µm, against:
//   K → ∞: the hard layer solution (contact/layer_hertz.hpp, an independent Nyström method), the force
//          approaching it like 1/K;
//   K → 0: the Winkler foundation F = πKRδ², a = √(2Rδ) (the layer rigid next to the interface), approached
//          like K;
// and its own convergence in the number of sine terms.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "../common/convergence.hpp"
#include "skinfem/contact/layer_hertz.hpp"
#include "skinfem/contact/layer_hertz_interface.hpp"

namespace skinfem::contact {
namespace {

constexpr double kR = 129.7, kH = 3.04, kE = 3.0, kNu = 0.5, kDelta = 0.01;

using testing::order_from_differences;

TEST(LayerHertzInterface, TendsToTheHardLayerAsKGrows) {
  const LayerHertzResult hard = layer_hertz_depth(kDelta, kR, kH, kE, kNu);
  std::array<double, 3> e{};
  const std::array<double, 3> K{1e3, 1e4, 1e5};
  for (int l = 0; l < 3; ++l) {
    const LayerHertzInterfaceResult r = layer_hertz_interface_depth(kDelta, kR, kH, kE, kNu, K[l], 128);
    e[l] = r.force_N / hard.force_N - 1;
    std::printf("K = %g: F %.10f N (hard %.10f), a %.8f mm (%.8f), p0 %.8f kPa (%.8f)\n", K[l], r.force_N,
                hard.force_N, r.a_mm, hard.a_mm, 1e3 * r.p0_MPa, 1e3 * hard.p0_MPa);
  }
  // F = F_hard (1 − c/K): each tenfold K cuts the difference tenfold.
  EXPECT_NEAR(std::log(e[0] / e[1]) / std::log(10.0), 1.0, 0.05);
  EXPECT_NEAR(std::log(e[1] / e[2]) / std::log(10.0), 1.0, 0.1);
  const LayerHertzInterfaceResult stiff = layer_hertz_interface_depth(kDelta, kR, kH, kE, kNu, 1e7, 128);
  // The sine series converges slowly at the hard limit (the √ edge is not in its span): 128 terms give 1e-4.
  EXPECT_NEAR(stiff.force_N / hard.force_N, 1.0, 1e-5);
  EXPECT_NEAR(stiff.a_mm / hard.a_mm, 1.0, 1e-4);
  EXPECT_NEAR(stiff.p0_MPa / hard.p0_MPa, 1.0, 1e-3);
}

TEST(LayerHertzInterface, TendsToWinklerAsKVanishes) {
  std::array<double, 3> eF{}, ea{};
  const std::array<double, 3> K{0.04, 0.02, 0.01};
  const double a_w = std::sqrt(2 * kR * kDelta);
  for (int l = 0; l < 3; ++l) {
    const LayerHertzInterfaceResult r = layer_hertz_interface_depth(kDelta, kR, kH, kE, kNu, K[l]);
    const double winkler = M_PI * K[l] * kR * kDelta * kDelta;
    eF[l] = r.force_N / winkler - 1;
    ea[l] = r.a_mm / a_w - 1;
    std::printf("K = %g: F %.8e N (Winkler %.8e), a %.8f mm (%.8f)\n", K[l], r.force_N, winkler, r.a_mm, a_w);
  }
  // The layer's compliance in series: both differences fall like K, and the softest is the closest.
  EXPECT_NEAR(std::log(eF[0] / eF[1]) / std::log(2.0), 1.0, 0.05);
  EXPECT_NEAR(std::log(eF[1] / eF[2]) / std::log(2.0), 1.0, 0.05);
  EXPECT_NEAR(std::log(ea[0] / ea[1]) / std::log(2.0), 1.0, 0.05);
  EXPECT_LT(std::abs(eF[2]), 0.005);
}

TEST(LayerHertzInterface, ConvergesInTheNumberOfTerms) {
  // K = 30 MPa/mm: the closure at the centre is ~1 µm of the 10 µm approach.
  std::array<double, 4> a{}, F{};
  const std::array<int, 4> N{8, 16, 32, 64};
  for (int l = 0; l < 4; ++l) {
    const LayerHertzInterfaceResult r = layer_hertz_interface_depth(kDelta, kR, kH, kE, kNu, 30.0, N[l]);
    a[l] = r.a_mm;
    F[l] = r.force_N;
    std::printf("N = %d: a %.10f mm, F %.12f N, p0 %.10f kPa\n", N[l], r.a_mm, r.force_N, 1e3 * r.p0_MPa);
  }
  const double p = order_from_differences({a[1], a[2], a[3]}, 2.0);
  std::printf("observed order in N of a: %.2f\n", p);
  EXPECT_GT(p, 3.0);
  EXPECT_LT(std::abs(a[3] - a[2]) / a[3], 1e-6);
  EXPECT_LT(std::abs(F[3] - F[2]) / F[3], 1e-7);
}

TEST(LayerHertzInterface, RefusesBadInput) {
  EXPECT_THROW(layer_hertz_interface_depth(kDelta, kR, kH, kE, kNu, 0.0), std::invalid_argument);
  EXPECT_THROW(layer_hertz_interface_force(-1.0, kR, kH, kE, kNu, 30.0), std::invalid_argument);
  EXPECT_THROW(layer_hertz_interface_radius(1.0, kR, kH, kE, kNu, 30.0, 1), std::invalid_argument);
}

}  // namespace
}  // namespace skinfem::contact
