// A sensor's point value as the limit of disc means (fem/base_traction.hpp, point_value_rule) against closed
// forms: the rule reads any cubic at the point exactly (odd terms vanish on a disc, the a² term is
// extrapolated away), and a quartic r⁴ with its stated remainder −a1²a2²/3 (the disc mean of r⁴ is a⁴/3).
#include <gtest/gtest.h>

#include <cmath>

#include "skinfem/fem/base_traction.hpp"

namespace skinfem {
namespace {

double rule_value(const std::vector<std::array<double, 3>>& rule, double (*f)(double, double)) {
  double v = 0;
  for (const auto& p : rule) v += p[2] * f(p[0], p[1]);
  return v;
}

TEST(PointValueRule, ReadsCubicsExactlyAndAQuarticWithItsRemainder) {
  constexpr double h = 3.04, a1 = h / 40, a2 = h / 20;
  const auto rule = point_value_rule(h);
  // Round-off over 768 weights summing |w| to 5/3: 1e-12.
  EXPECT_NEAR(rule_value(rule, [](double, double) { return 1.0; }), 1.0, 1e-12);
  const double cubic = rule_value(rule, [](double x, double y) {
    return 2.5 + 3 * x - 4 * y + 7 * x * x - 5 * x * y + 11 * y * y + x * x * x - 6 * x * y * y +
           2 * y * y * y;
  });
  EXPECT_NEAR(cubic, 2.5, 1e-12);
  const double quartic = rule_value(rule, [](double x, double y) { return std::pow(x * x + y * y, 2); });
  EXPECT_NEAR(quartic, -a1 * a1 * a2 * a2 / 3, 1e-12 * a2 * a2 * a2 * a2);
}

}  // namespace
}  // namespace skinfem
