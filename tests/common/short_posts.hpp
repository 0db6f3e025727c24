// A post's reading as its height t → 0 (tests/green/test_post_sensor in 3D, test_meridian on the meridian):
// the post becomes the base under its outline and its reading the disc's of the same diameter. The wall's
// share of the force scales with its area 2πa·t, so the gap closes at first order in t for σ_x and at least
// as fast for σ_z, shrinking at every level.
#pragma once

#include <gtest/gtest.h>

#include <cstdio>
#include <vector>

#include "convergence.hpp"

namespace skinfem::testing {

inline void expect_gap_to_the_disc_closes(const std::vector<double>& heights,
                                          const std::vector<double>& gap_z,
                                          const std::vector<double>& gap_x) {
  const double order_z = observed_order(heights, gap_z), order_x = observed_order(heights, gap_x);
  std::printf("observed order of the gap to the disc: sigma_z %.2f, sigma_x %.2f\n", order_z, order_x);
  EXPECT_GT(order_x, 0.9);
  EXPECT_LT(order_x, 1.5);
  EXPECT_GT(order_z, 0.9);
  for (size_t i = 1; i < heights.size(); ++i) {
    EXPECT_LT(gap_z[i], gap_z[i - 1]);
    EXPECT_LT(gap_x[i], gap_x[i - 1]);
  }
}

}  // namespace skinfem::testing
