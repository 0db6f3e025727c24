// The mesh-size estimate (mesh/size_estimate.hpp) against TetGen's actual element counts. Its constants were
// fitted on the three shipped scenes (estimate/actual 0.98–1.06 after the fit) and on flat layers 0.1–1 mm
// thick (0.83–1.05); with the column graded from the top, ridged layers (ridge sizes period/4 to period/8)
// come to 0.81–1.04. Measured again (2026-11): the shipped scenes at their own sizes 0.52 (fingertip)–1.04,
// at every size × 2 0.25–0.92 (TetGen grades more slowly than a growth of 2.4 asks; the built mesh is checked
// again before assembly). The guard only needs a factor of 2, so the tests allow [0.6, 1.6].
// Measured 2026-12 (whole skins, scaled_scene at 1, 1.41, 2), actual / estimate: candelier2011 1.30, 1.61,
// 2.17; fingertip 1.93, 2.55, 4.13; flat_layer 0.91, 0.95, 0.99; hertz_layer 1.26, 1.49, 1.88; texture_row
// 1.31, 1.50, 2.26. Neither a growth capped at what TetGen achieves nor a surface term (1/h² over top and
// base) brought all of them within 25 %; the progress line prints the range these span
// (pipeline/resources.cpp).
#include <gtest/gtest.h>

#include <cstdio>

#include "skinfem/mesh/build.hpp"
#include "skinfem/mesh/size_estimate.hpp"
#include "skinfem/mesh/sizing.hpp"
#include "skinfem/scene/load.hpp"

namespace skinfem {
namespace {

Scene layer(double h, double h_min) {
  Scene s;
  s.geometry.kind = GeometryKind::flat;
  s.geometry.flat = {h, 6.0};
  s.sensors.positions = {{0.0, 0.0}};
  s.sensors.disc_diameter = 0.2;
  s.mesh.h_min = h_min;
  s.mesh.h_max = 3.0;
  s.mesh.growth = 1.5;
  return s;
}

void expect_close(const Scene& s, const char* what) {
  const MeshEstimate e = estimate_mesh(s);
  ASSERT_TRUE(e.known);
  const double actual = build_mesh(s).num_tets();
  EXPECT_GT(e.tets / actual, 0.6) << what << ": estimate " << e.tets << ", actual " << actual;
  EXPECT_LT(e.tets / actual, 1.6) << what << ": estimate " << e.tets << ", actual " << actual;
}

// The estimate samples sizes a column at a time (SizingField::in_column, which skips regions that cannot
// win): the same values as in_volume point by point, bit for bit, on a scene with regions through the skin,
// at its top (the contact zone) and at its base (the sensor discs, refine_sensors).
TEST(SizeEstimate, AColumnsSizesAreThePointSizes) {
  const Scene scene = load_scene(std::string(SKINFEM_SOURCE_DIR) + "/scenes/candelier2011.json");
  const SizingField size(scene);
  const double z[] = {0.0, 0.01, 0.3, 1.0, 2.5, 4.0, 10.0};
  double column[7];
  for (double x = -9.5; x <= 9.5; x += 0.73)
    for (double y = -9.5; y <= 9.5; y += 0.61) {
      size.in_column(x, y, z, 7, column);
      for (int k = 0; k < 7; ++k)
        ASSERT_EQ(column[k], size.in_volume(x, y, z[k])) << x << ", " << y << ", " << z[k];
    }
}

TEST(SizeEstimate, ThickFlatLayer) { expect_close(layer(3.0, 0.3), "3 mm layer"); }
TEST(SizeEstimate, ThinFlatLayerIsCappedByItsThickness) { expect_close(layer(0.2, 0.2), "0.2 mm layer"); }

TEST(SizeEstimate, Cap) {
  Scene s = layer(3.0, 0.3);
  s.geometry.kind = GeometryKind::cap;
  s.geometry.cap = {20.0, 3.0, 0.5, 0.0, 6.0};
  expect_close(s, "cap R 20");
}

TEST(SizeEstimate, RidgedLayerCountsItsFineTop) {
  // Ridges meshed at 27.5 µm on a 3 mm layer: the fine elements fill a layer a few ridge sizes thick, which
  // evenly spaced depth samples missed (estimate/actual was 0.38).
  Scene s = layer(3.04, 0.2);
  s.mesh.growth = 1.7;
  s.geometry.ridges.period = 0.22;
  s.geometry.ridges.height = 0.05;
  s.geometry.ridges.radius = 0.6;
  s.geometry.ridges.h = 0.22 / 8;
  expect_close(s, "ridged layer");
}

TEST(SizeEstimate, PostsAreCavities) {
  // Three posts meshed at 0.05 mm up to their tops: their columns are fine, their insides no skin (counted
  // as skin at the post's size they made the paper's skin with posts look 1.5× its size, and `mesh` refused
  // it for memory).
  Scene s = layer(3.0, 0.3);
  s.sensors.positions = {{0.0, 0.0}, {1.0, 0.0}, {-1.0, 0.5}};
  s.sensors.model = SensorModel::post;
  expect_close(s, "posts");
}

TEST(SizeEstimate, HalfCountsTheRegionsOnItsSide) {
  // A refinement region wholly in y > 0 is wholly in the half: counted as 0.55 of the whole, such a cap was
  // estimated at 8.2 GB and ran past 300 s at 11.3 GB.
  Scene s = layer(3.0, 0.4);
  s.mesh.regions.push_back({{-3, 3}, {3, 3}, 1.0, 0.2});
  const MeshEstimate e = estimate_mesh(s, 1e12, MeshPart::half_y);
  const double actual = build_mesh(s, MeshPart::half_y).num_tets();
  const double whole = estimate_mesh(s).tets;
  std::printf("half: estimate %.0f, actual %.0f; whole estimate %.0f\n", e.tets, actual, whole);
  EXPECT_GT(e.tets / actual, 0.6);
  EXPECT_LT(e.tets / actual, 1.6);
  // The region holds most of the elements, and all of it is on the half's side.
  EXPECT_GT(e.tets, 0.8 * whole);
}

TEST(SizeEstimate, StopsEarlyAboveItsLimitAndSaysSo) {
  // h_min 1 µm over a 0.1 mm column through the layer: ~1e9 elements; the integration stops at the limit.
  Scene s = layer(3.0, 0.001);
  s.mesh.regions.push_back({{0, 0}, {0, 0}, 0.1, 0.0});
  const MeshEstimate e = estimate_mesh(s, 1e6);
  EXPECT_GT(e.tets, 1e6);
  EXPECT_LT(e.tets, 1e8);
}

TEST(SizeEstimate, ImportedSurfacesAreNotEstimated) {
  Scene s = layer(3.0, 0.3);
  s.geometry.kind = GeometryKind::surface;
  EXPECT_FALSE(estimate_mesh(s).known);
}

}  // namespace
}  // namespace skinfem
