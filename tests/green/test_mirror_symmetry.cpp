// The mirror-symmetric reduction (MeshPart::half_y): the half model, with u_y = 0 on its cut and a force
// standing for itself and its mirror image, against the full body solved on the half's mirrored mesh
// (mesh/mirror.hpp) — a second method on the same elements, so the two agree to round-off.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "skinfem/fem/elastic_model.hpp"
#include "skinfem/green/calibration.hpp"
#include "skinfem/green/fe_green.hpp"
#include "skinfem/mesh/build.hpp"
#include "skinfem/mesh/mirror.hpp"

namespace skinfem {
namespace {

Scene small_cap() {
  Scene s;
  s.geometry.kind = GeometryKind::cap;
  s.geometry.cap = {20.0, 3.0, 0.5, 0.0, 6.0};  // apex off the origin along x: the axis lies in y = 0
  s.sensors.positions = {{0.5, 0.0}, {-1.5, 0.0}, {2.0, 0.0}};
  s.sensors.disc_diameter = 0.2;
  s.mesh.h_min = 0.4, s.mesh.growth = 1.5, s.mesh.h_max = 1.5;
  return s;
}

TEST(MirrorSymmetry, HalfModelEqualsTheMirroredWholeForEveryReading) {
  const Scene s = small_cap();
  const TetMesh half = build_mesh(s, MeshPart::half_y);
  const TetMesh whole = mirror_half(half);
  ASSERT_TRUE(is_half_y(half));
  ASSERT_FALSE(is_half_y(whole));
  for (int i = 0; i < half.num_nodes(); ++i) {
    if (half.node_marker(i) & kSymmetry) {
      ASSERT_EQ(half.nodes(i, 1), 0.0) << "node " << i << " off the cut";
    }
  }
  for (auto side : {SideCondition::free, SideCondition::fixed}) {
    const ElasticModel reduced(half, s.material, side, {}), full(whole, s.material, side, {});
    const green::FeGreen gh(reduced, s.sensors), gw(full, s.sensors);
    std::printf("side %s: half %d DOFs, whole %d DOFs\n", side == SideCondition::free ? "free" : "fixed",
                reduced.solver().free_dofs(), full.solver().free_dofs());
    EXPECT_LT(reduced.solver().free_dofs(), 0.6 * full.solver().free_dofs());
    double worst = 0;
    for (int k = 0; k < 3; ++k)
      for (bool disc : {false, true})
        for (auto load : {green::LayerLoad::point, green::LayerLoad::punch}) {
          // Offsets on both sides of the cut and on it, every component against its peak over the set.
          std::vector<green::GreenSample> a, b;
          for (auto [ox, oy] :
               {std::pair{0.0, 0.0}, {0.7, 0.4}, {-1.1, -0.6}, {1.3, -1.2}, {0.3, 0.0}, {-0.4, 1.7}}) {
            a.push_back(gh.at(k, disc, ox, oy, load, 0.25));
            b.push_back(gw.at(k, disc, ox, oy, load, 0.25));
          }
          const auto err = green::max_error_over_peak(a, b);
          worst = std::max(worst, *std::max_element(err.begin(), err.end()));
        }
    // The kernel export's reading (disc reading, unit point force at an absolute top point), both sides.
    for (int k = 0; k < 3; ++k) {
      std::vector<green::GreenSample> a, b;
      for (auto [x, y] : {std::pair{0.2, 0.9}, {0.2, -0.9}, {-2.0, 0.0}, {3.1, -2.4}}) {
        green::GreenSample ga, gb;
        ASSERT_TRUE(gh.disc_map_at(k, x, y, ga) && gw.disc_map_at(k, x, y, gb));
        a.push_back(ga), b.push_back(gb);
      }
      const auto err = green::max_error_over_peak(a, b);
      worst = std::max(worst, *std::max_element(err.begin(), err.end()));
    }
    std::printf(
        "  max |half − whole| / peak over 3 sensors, point and disc, point and punch loads, kernel maps: "
        "%.2e\n",
        worst);
    // Round-off of two direct solves (MUMPS LDLᵀ, residual checked at 1e-10 relative).
    EXPECT_LT(worst, 1e-9);
  }
}

// Posts on the cut are cut in half (mesh/surface.cpp: the wall open at the cut, the top closed by its
// diameter, the cut meshed around them) and read over half their cross-section (fem/sensor_reading.cpp).
TEST(MirrorSymmetry, HalfPostsReadTheMirroredWholePosts) {
  Scene s = small_cap();
  s.sensors.model = SensorModel::post;
  s.sensors.post = {0.2, 0.3};
  const TetMesh half = build_mesh(s, MeshPart::half_y);
  const TetMesh whole = mirror_half(half);
  ASSERT_TRUE(is_half_y(half));
  ASSERT_FALSE(is_half_y(whole));
  EXPECT_EQ(half.straightened, 0);
  const ElasticModel reduced(half, s.material, SideCondition::free, {}),
      full(whole, s.material, SideCondition::free, {});
  const green::FeGreen gh(reduced, s.sensors), gw(full, s.sensors);
  std::printf("posts: half %d DOFs, whole %d DOFs\n", reduced.solver().free_dofs(),
              full.solver().free_dofs());
  double worst = 0;
  for (int k = 0; k < 3; ++k)
    for (auto load : {green::LayerLoad::point, green::LayerLoad::punch}) {
      std::vector<green::GreenSample> a, b;
      for (auto [ox, oy] : {std::pair{0.0, 0.0}, {0.7, 0.4}, {-1.1, -0.6}, {1.3, -1.2}, {0.3, 0.0}})
        a.push_back(gh.at(k, true, ox, oy, load, 0.25)), b.push_back(gw.at(k, true, ox, oy, load, 0.25));
      const auto err = green::max_error_over_peak(a, b);
      worst = std::max(worst, *std::max_element(err.begin(), err.end()));
    }
  std::printf("  max |half − whole| / peak over 3 posts, point and punch loads: %.2e\n", worst);
  EXPECT_LT(worst, 1e-9);  // round-off of two direct solves, as above
}

}  // namespace
}  // namespace skinfem
