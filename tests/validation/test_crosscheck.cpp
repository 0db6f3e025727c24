// validation/crosscheck: which sensors are the paper's "front" ones. Reference: the geometry of the
// sliding direction itself (a sensor is ahead when its offset from the contact centre has a non-negative
// component along the direction), checked on the paper's line of ten sensors.
#include <gtest/gtest.h>

#include "skinfem/validation/crosscheck.hpp"

namespace skinfem::validation {
namespace {

Sensors paper_line() {
  Sensors s;
  for (int k = 0; k < 10; ++k) s.positions.push_back({-4.5 + k, 0.0});
  return s;
}

TEST(FrontSensors, AheadAlongPlusXAreTheRightHalf) {
  EXPECT_EQ(front_sensors(paper_line(), {0.5, 0}, {1, 0}), (std::vector<int>{5, 6, 7, 8, 9}));
}

TEST(FrontSensors, SlidingTowardMinusXTurnsThemAround) {
  // Sensor #6 (x = 0.5) lies on the centre's line across the sliding direction: it counts as front both ways.
  EXPECT_EQ(front_sensors(paper_line(), {0.5, 0}, {-1, 0}), (std::vector<int>{0, 1, 2, 3, 4, 5}));
}

TEST(FrontSensors, SlidingAlongYFollowsTheSensorsOffset) {
  Sensors s;
  s.positions = {{0, -2}, {3, -1}, {-3, 1}, {0, 2}};
  EXPECT_EQ(front_sensors(s, {0, 0}, {0, 1}), (std::vector<int>{2, 3}));
  EXPECT_EQ(front_sensors(s, {0, 0}, {0, -1}), (std::vector<int>{0, 1}));
  // A line of sensors along x, sliding along y through it: none is ahead, so there are no front sensors.
  EXPECT_TRUE(front_sensors(paper_line(), {0.5, 0}, {0, 1}).empty());
}

}  // namespace
}  // namespace skinfem::validation
