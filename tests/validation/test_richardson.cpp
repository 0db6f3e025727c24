// Richardson extrapolation (validation/richardson.hpp) on quantities with a known expansion.
#include <gtest/gtest.h>

#include <cmath>

#include "skinfem/validation/richardson.hpp"

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

// Q = 1 + s⁶ with a P2-like ceiling of 4: the order is found (6) but not taken, and the finest value stays
// the reference; with the default ceiling the same sequence is asymptotic.
TEST(Richardson, RefusesAnOrderAboveTheCeiling) {
  const std::array<double, 3> s{2.0, std::sqrt(2.0), 1.0};
  std::array<double, 3> q;
  for (int i = 0; i < 3; ++i) q[i] = 1 + std::pow(s[i], 6);
  const Richardson capped = richardson(q, s, 4);
  EXPECT_FALSE(capped.asymptotic);
  EXPECT_TRUE(capped.above_max_order);
  EXPECT_NEAR(capped.order, 6.0, 1e-10);
  EXPECT_EQ(capped.limit, q[2]);
  const Richardson free = richardson(q, s);
  EXPECT_TRUE(free.asymptotic);
  EXPECT_FALSE(free.above_max_order);
  EXPECT_NEAR(free.limit, 1.0, 1e-10);
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
