// Richardson extrapolation (validation/richardson.hpp) on quantities with a known expansion.
#include <gtest/gtest.h>

#include <cmath>

#include "validation/richardson.hpp"

namespace skinfem::validation {
namespace {

// Q = 2 + 0.3 s^1.7 on scales 2, √2, 1: exact order and limit (equal ratios, so no higher term to leave).
TEST(Richardson, RecoversOrderAndLimitOfAPowerLaw) {
  const std::array<double, 3> s{2.0, std::sqrt(2.0), 1.0};
  std::array<double, 3> q;
  for (int i = 0; i < 3; ++i) q[i] = 2 + 0.3 * std::pow(s[i], 1.7);
  const Richardson r = richardson(q, s);
  ASSERT_TRUE(r.asymptotic);
  EXPECT_NEAR(r.order, 1.7, 1e-12);
  EXPECT_NEAR(r.limit, 2.0, 1e-12);
}

// Unequal ratios: the order uses the first pair, the limit the second; still exact for a pure power law.
TEST(Richardson, UnequalRatios) {
  const std::array<double, 3> s{3.0, 1.5, 1.0};
  std::array<double, 3> q;
  for (int i = 0; i < 3; ++i) q[i] = -1 + 0.05 * s[i] * s[i];
  const Richardson r = richardson(q, s);
  ASSERT_TRUE(r.asymptotic);
  EXPECT_NEAR(r.order, 2.0, 1e-12);
  EXPECT_NEAR(r.limit, -1.0, 1e-12);
}

// Differences of opposite sign or growing: no asymptotic regime, the finest value is the reference.
TEST(Richardson, RefusesANonAsymptoticSequence) {
  EXPECT_FALSE(richardson({1.0, 1.2, 1.1}, {2, 1.41, 1}).asymptotic);
  EXPECT_FALSE(richardson({1.0, 1.1, 1.3}, {2, 1.41, 1}).asymptotic);
  EXPECT_EQ(richardson({1.0, 1.2, 1.1}, {2, 1.41, 1}).limit, 1.1);
}

TEST(LogLogSlope, RecoversThePowerOfAPowerLawAndRefusesBadInput) {
  const std::vector<double> x{1e4, 3e4, 1e5, 2e5};
  std::vector<double> y;
  for (double v : x) y.push_back(2.5e-7 * std::pow(v, 1.7));
  EXPECT_NEAR(loglog_slope(x, y), 1.7, 1e-12);
  EXPECT_TRUE(std::isnan(loglog_slope({1e4}, {1.0})));
  EXPECT_TRUE(std::isnan(loglog_slope({1e4, 2e4}, {1.0, 0.0})));
  EXPECT_TRUE(std::isnan(loglog_slope({1e4, 1e4}, {1.0, 2.0})));
}

}  // namespace
}  // namespace skinfem::validation
