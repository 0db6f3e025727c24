// The post design sweep (pipeline/post_design.hpp) gives the same numbers however its designs are spread:
// in worker processes, in this one (OMP_NUM_THREADS=1), or in one low-priority process started beside this
// thread (the report's way), bit for bit, in the order asked.
#include <gtest/gtest.h>

#include <cstdlib>

#include "skinfem/pipeline/post_design.hpp"
#include "skinfem/scene/load.hpp"

namespace skinfem::pipeline {
namespace {

Scene post_scene() {
  Scene s = load_scene(std::string(SKINFEM_SOURCE_DIR) + "/scenes/flat_layer.json");
  s.sensors.model = SensorModel::post;
  s.sensors.post.diameter = 0.2, s.sensors.post.height = 0.4;
  return s;
}

void expect_same(const SensorDesign& a, const SensorDesign& b) {
  EXPECT_EQ(a.diameter, b.diameter);
  EXPECT_EQ(a.height, b.height);
  for (const auto& [x, y] : {std::pair{a.zz, b.zz}, std::pair{a.xx, b.xx}}) {
    EXPECT_EQ(x.peak, y.peak);
    EXPECT_EQ(x.peak_at, y.peak_at);
    EXPECT_EQ(x.half_width, y.half_width);
    EXPECT_EQ(x.integral, y.integral);
  }
  EXPECT_EQ(a.peak_change, b.peak_change);
  EXPECT_EQ(a.half_width_change, b.half_width_change);
  EXPECT_EQ(a.integral_change, b.integral_change);
}

TEST(PostDesign, TheSameNumbersInWorkerProcessesAndInOne) {
  const Scene scene = post_scene();
  const PostDesign spread = post_design(scene, {0.2, 0.3}, {0.0, 0.4}, 2.0);
  setenv("OMP_NUM_THREADS", "1", 1);
  const PostDesign here = post_design(scene, {0.2, 0.3}, {0.0, 0.4}, 2.0);
  unsetenv("OMP_NUM_THREADS");
  // As the report runs it: one low-priority process from the start, beside this thread's own work.
  PostDesignRun beside(scene, {0.2, 0.3}, {0.0, 0.4}, 2.0, 1);
  const PostDesign started = beside.finish();
  EXPECT_EQ(spread.dofs, here.dofs);
  EXPECT_GT(spread.dofs, 0);
  expect_same(spread.disc, here.disc);
  expect_same(spread.post, here.post);
  ASSERT_EQ(spread.sweep.size(), 4u);
  ASSERT_EQ(here.sweep.size(), 4u);
  for (int i = 0; i < 4; ++i) expect_same(spread.sweep[i], here.sweep[i]);
  EXPECT_EQ(started.dofs, here.dofs);
  expect_same(started.disc, here.disc);
  expect_same(started.post, here.post);
  ASSERT_EQ(started.sweep.size(), 4u);
  for (int i = 0; i < 4; ++i) expect_same(started.sweep[i], here.sweep[i]);
  // Diameters outer, heights inner, as asked.
  EXPECT_EQ(spread.sweep[1].diameter, 0.2);
  EXPECT_EQ(spread.sweep[1].height, 0.4);
  EXPECT_EQ(spread.sweep[2].diameter, 0.3);
  EXPECT_EQ(spread.sweep[2].height, 0.0);
}

}  // namespace
}  // namespace skinfem::pipeline
