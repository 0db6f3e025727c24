// k fitting of the rescaled half-space Green tensor (green/kfit.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "skinfem/green/calibration.hpp"
#include "skinfem/green/halfspace.hpp"
#include "skinfem/green/kfit.hpp"
#include "skinfem/green/layer_exact.hpp"

namespace {

using skinfem::green::component;
using skinfem::green::fit_k_line;
using skinfem::green::GreenComponent;
using skinfem::green::k_central;
using skinfem::green::KFit;
using skinfem::green::LayerGreen;
using skinfem::green::LayerLoad;
using skinfem::green::rescaled_green;

constexpr double kPi = 3.14159265358979323846;
constexpr double kH = 3.04;
constexpr auto kAll = skinfem::green::kComponents;
const char* name(GreenComponent c) { return skinfem::green::component_name(c); }

std::vector<double> line(double half_width, int n) {
  std::vector<double> x(n);
  for (int i = 0; i < n; ++i) x[i] = -half_width + 2.0 * half_width * i / (n - 1);
  return x;
}

// Synthetic data from the model itself: the cost is exactly zero at k0 and quadratic around it, and golden
// section stops at a relative bracket of 1e-12, so k0 must be recovered far below the required 1e-6 and the
// residual is roundoff.
TEST(KFit, RecoversKnownK) {
  const std::vector<double> x = line(3.0 * kH, 121);
  for (double k0 : {0.62, 1.0, 1.48, 3.3})
    for (GreenComponent c : kAll) {
      std::vector<double> g;
      for (double xi : x) g.push_back(component(rescaled_green(xi, 0.0, kH, k0), c));
      const KFit f = fit_k_line(x, g, kH, c);
      EXPECT_NEAR(f.k, k0, 1e-6 * k0) << name(c);
      EXPECT_LT(f.rms_residual_over_peak, 1e-6) << name(c);
    }
}

// A post's σ_x reading has a gain c ≠ 1 (green/calibration.hpp's ChannelGains): samples c·k·g_half(√k x)
// fitted at that gain give back k, and with the gain fitted too (posts on springs, whose gain is not
// computed) both c and k: the amplitude ck and the width k^−1/2 are independent features. Held at gain 1 the
// same samples fit a wrong k (amplitude and width disagree) with a residual far above round-off.
TEST(KFit, TheModelAtTheSensorsGainRecoversK) {
  const std::vector<double> x = line(3.0 * kH, 121);
  for (double c0 : {1.3, 2.76, 30.0})
    for (double k0 : {1.0, 2.4})
      for (GreenComponent c : kAll) {
        std::vector<double> g;
        for (double xi : x) g.push_back(c0 * component(rescaled_green(xi, 0.0, kH, k0), c));
        const KFit f = fit_k_line(x, g, kH, c, c0);
        EXPECT_NEAR(f.k, k0, 1e-6 * k0) << name(c) << " c0 " << c0;
        EXPECT_EQ(f.gain, c0);
        EXPECT_LT(f.rms_residual_over_peak, 1e-6) << name(c);
        const KFit fitted = fit_k_line(x, g, kH, c, std::nullopt);
        EXPECT_NEAR(fitted.k, k0, 1e-6 * k0) << name(c) << " c0 " << c0;
        EXPECT_NEAR(fitted.gain, c0, 1e-6 * c0) << name(c) << " c0 " << c0;
        if (c0 == 1.3) {  // larger gains put the held fit's minimum beyond the search range
          const KFit held = fit_k_line(x, g, kH, c);
          EXPECT_GT(held.rms_residual_over_peak, 1e-3) << name(c) << " c0 " << c0;
        }
      }
}

TEST(KFit, AMinimumBeyondTheSearchRangeIsAnErrorNotTheBound) {
  // Samples of the rescaled model itself with k = 0.2 and 20: the least-squares minimum lies outside [kMinK,
  // kMaxK].
  const std::vector<double> x = line(3.0 * kH, 121);
  for (double k0 : {0.2, 20.0}) {
    std::vector<double> g;
    for (double xi : x) g.push_back(rescaled_green(xi, 0.0, kH, k0).zz);
    EXPECT_THROW(fit_k_line(x, g, kH, GreenComponent::zz), std::domain_error) << "k0 " << k0;
  }
}

TEST(KFit, CentralAmplitudeRatio) {
  for (double k0 : {0.8, 1.48, 2.5})
    EXPECT_NEAR(k_central(rescaled_green(0.0, 0.0, kH, k0).zz, kH), k0, 1e-14 * k0);
  EXPECT_NEAR(k_central(3.0 / (2.0 * kPi * kH * kH), kH), 1.0, 1e-15);
}

TEST(KFit, RejectsBadInput) {
  EXPECT_THROW(fit_k_line({}, {}, kH, GreenComponent::zz), std::invalid_argument);
  EXPECT_THROW(fit_k_line({0.0, 1.0}, {1.0}, kH, GreenComponent::zz), std::invalid_argument);
  EXPECT_THROW(fit_k_line({0.0, 1.0}, {1.0, 2.0}, 0.0, GreenComponent::zz), std::invalid_argument);
  EXPECT_THROW(k_central(1.0, -1.0), std::invalid_argument);
}

// The exact layer's readings under loads spread over radius a ≪ h follow the load's second moment:
// g(x) = g_point(x) + β(x)⟨r²⟩ + O(a⁴), with ⟨r²⟩ = 2a²/3 for the rigid-punch profile 1/(2πa√(a² − r²)) and
// a²/2 for the uniform disc. So k_point > k_uniform > k_punch for the centre value and for every component's
// line fit (a smooth functional of g), and (k_point − k_punch)/(k_point − k_uniform) = 4/3 up to a relative
// O((a/h)²), taken as (a/h)² (0.68 % at a = 0.25 mm, h = 3.04 mm).
TEST(KFit, ExactLayerKFollowsTheLoadsSecondMoment) {
  const std::vector<double> x = line(3.0 * kH, 241);
  constexpr double a = 0.25, tol = 4.0 / 3.0 * (a / kH) * (a / kH);
  double kc[3], kl[3][4];
  const LayerLoad loads[3] = {LayerLoad::point, LayerLoad::uniform, LayerLoad::punch};
  for (int i = 0; i < 3; ++i) {
    const LayerGreen layer(kH, 0.5, loads[i], loads[i] == LayerLoad::point ? 0.0 : a);
    std::vector<skinfem::green::GreenSample> s;
    for (double xi : x) s.push_back(layer.at(xi, 0.0));
    kc[i] = k_central(layer.at(0.0, 0.0).zz, kH);
    for (GreenComponent comp : kAll) {
      std::vector<double> g;
      for (const auto& si : s) g.push_back(component(si, comp));
      kl[i][static_cast<int>(comp)] = fit_k_line(x, g, kH, comp).k;
    }
  }
  EXPECT_GT(kc[0], kc[1]);
  EXPECT_GT(kc[1], kc[2]);
  EXPECT_NEAR((kc[0] - kc[2]) / (kc[0] - kc[1]), 4.0 / 3.0, tol);
  for (GreenComponent comp : kAll) {
    const double* k[3] = {&kl[0][static_cast<int>(comp)], &kl[1][static_cast<int>(comp)],
                          &kl[2][static_cast<int>(comp)]};
    EXPECT_GT(*k[0], *k[1]) << name(comp);
    EXPECT_GT(*k[1], *k[2]) << name(comp);
    EXPECT_NEAR((*k[0] - *k[2]) / (*k[0] - *k[1]), 4.0 / 3.0, tol) << name(comp);
  }
}

}  // namespace
