// validation/load_metrics: center_ratio reads the base below the load's centre, which a post's foot takes
// away (issue 57: a punch centred on a post solved, then exited with "point … is off the base").
#include <gtest/gtest.h>

#include "skinfem/validation/load_metrics.hpp"

namespace skinfem {
namespace {

Scene posts_under(const Vec2& centre, Vec3 direction = {0, 0, -1}) {
  Scene s;
  s.geometry.kind = GeometryKind::flat;
  s.sensors.positions = {{0, 0}, {1.0, 0.5}};
  s.sensors.model = SensorModel::post;
  s.sensors.post = {0.2, 0.4};
  s.loads.patches.push_back({centre, 0.5, direction, 1.0});
  return s;
}

TEST(LoadMetrics, NoCenterRatioOverAPostsFoot) {
  EXPECT_NE(center_ratio_unavailable(posts_under({0, 0})).find("over a post's foot"), std::string::npos);
  EXPECT_NE(center_ratio_unavailable(posts_under({1.05, 0.45})).find("over a post's foot"),
            std::string::npos);
  EXPECT_EQ(center_ratio_unavailable(posts_under({0.11, 0})), "");  // beside the post: base below
  EXPECT_NE(center_ratio_unavailable(posts_under({0.5, 0}, {1, 0, 0})).find("not a punch or a normal patch"),
            std::string::npos);
  Scene discs = posts_under({0, 0});
  discs.sensors.model = SensorModel::disc;  // a disc is the base itself
  EXPECT_EQ(center_ratio_unavailable(discs), "");
}

}  // namespace
}  // namespace skinfem
