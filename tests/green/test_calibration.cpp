// The paper's calibration of a scan (green/calibration.hpp): thickness and scale fitted to the exact layer.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "skinfem/green/calibration.hpp"
#include "skinfem/green/layer_exact.hpp"

namespace {

using skinfem::green::effective_thickness;
using skinfem::green::GreenSample;
using skinfem::green::LayerGreen;
using skinfem::green::LayerLoad;
using skinfem::green::paper_calibration;

constexpr double kH0 = 3.04, kRadius = 0.25;

std::vector<double> offsets() {
  std::vector<double> x;
  for (int i = -60; i <= 60; ++i) x.push_back(0.15 * i);
  return x;
}

// A scan that is the exact layer of thickness h times (s_z, s_x) is its own calibration: the misfit is zero
// at h and grows on both sides (amplitude ∝ 1/h² is taken up by the scale, the width ∝ h is not), so golden
// section (bracket 1e-6 h0) returns h and the scales follow to the same relative order.
TEST(PaperCalibration, RecoversThicknessAndScalesOfAScaledLayer) {
  const std::vector<double> x = offsets();
  for (double h : {0.9, 1.5, 2.9, 4.5})
    for (double s : {1.0, 2.76}) {
      const LayerGreen layer(h, 0.5, LayerLoad::punch, kRadius);
      std::vector<GreenSample> g;
      for (double xi : x) {
        GreenSample v = layer.at(xi, 0.0);
        v.zz *= s;
        v.zx *= 11 * s;
        g.push_back(v);
      }
      const auto c = paper_calibration(x, g, kH0, 0.5, LayerLoad::punch, kRadius);
      EXPECT_NEAR(c.thickness_mm, h, 1e-5 * kH0) << "h " << h << " s " << s;
      EXPECT_NEAR(c.scale_z, s, 1e-4 * s) << "h " << h;
      EXPECT_NEAR(c.scale_x, 11 * s, 1e-4 * 11 * s) << "h " << h;
      EXPECT_LT(c.rms_z_over_peak, 1e-4);
      EXPECT_LT(c.rms_x_over_peak, 1e-4);
    }
}

// With the scale held at 1 the thickness search is [0.5 h0, 1.5 h0]: a layer outside it is an error naming
// the bound, not the bound returned as a thickness.
TEST(PaperCalibration, ThicknessAtTheSearchBoundIsAnError) {
  const std::vector<double> x = offsets();
  for (double h : {0.9, 5.0}) {
    const LayerGreen layer(h, 0.5, LayerLoad::punch, kRadius);
    std::vector<double> zz;
    for (double xi : x) zz.push_back(layer.at(xi, 0.0).zz);
    EXPECT_THROW(effective_thickness(x, zz, kH0, 0.5, LayerLoad::punch, kRadius), std::domain_error) << h;
  }
  const LayerGreen layer(2.5, 0.5, LayerLoad::punch, kRadius);
  std::vector<double> zz;
  for (double xi : x) zz.push_back(layer.at(xi, 0.0).zz);
  EXPECT_NEAR(effective_thickness(x, zz, kH0, 0.5, LayerLoad::punch, kRadius), 2.5, 1e-5 * kH0);
}

// effective_thickness stops a misfit's sum once it has answered the golden section's comparison
// (green/calibration.cpp). The search written out here with full sums, on a scan no layer fits exactly (a
// wavy FE-like profile), must return the same thickness to the last bit: the early stop changes no step.
TEST(EffectiveThickness, EqualsTheGoldenSectionOfFullSums) {
  const std::vector<double> x = offsets();
  for (double h : {2.2, 3.0, 3.7}) {
    const LayerGreen layer(h, 0.5, LayerLoad::punch, kRadius);
    std::vector<double> zz;
    for (double xi : x) zz.push_back(layer.at(xi, 0.0).zz * (1 + 0.03 * std::sin(2.1 * xi)));
    const auto misfit = [&](double t) {
      const LayerGreen l(t, 0.5, LayerLoad::punch, kRadius);
      double s = 0;
      for (size_t i = 0; i < x.size(); ++i) s += std::pow(l.zz_at(x[i], 0.0) - zz[i], 2);
      return s;
    };
    double a = 0.5 * kH0, b = 1.5 * kH0;
    const double phi = 0.5 * (std::sqrt(5.0) - 1);
    double c = b - phi * (b - a), d = a + phi * (b - a), fc = misfit(c), fd = misfit(d);
    while (b - a > 1e-6 * kH0) {
      if (fc < fd) {
        b = d, d = c, fd = fc;
        c = b - phi * (b - a), fc = misfit(c);
      } else {
        a = c, c = d, fc = fd;
        d = a + phi * (b - a), fd = misfit(d);
      }
    }
    EXPECT_EQ(effective_thickness(x, zz, kH0, 0.5, LayerLoad::punch, kRadius), 0.5 * (a + b)) << h;
  }
}

}  // namespace
