// The paper's calibration of a scan (green/calibration.hpp): thickness and scale fitted to the exact layer.
#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "green/calibration.hpp"
#include "green/layer_exact.hpp"

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

}  // namespace
