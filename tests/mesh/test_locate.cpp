// CGAL AABB point location with isoparametric reference coordinates.
#include <gtest/gtest.h>

#include <random>

#include "skinfem/mesh/build.hpp"
#include "skinfem/mesh/locate.hpp"
#include "skinfem/mesh/p2_tet.hpp"
#include "skinfem/mesh/shape.hpp"

namespace skinfem {
namespace {

TEST(PointLocator, FindsRandomInteriorPointsAndRejectsOutsideOnes) {
  Scene s;
  s.geometry.cap = {20.0, 3.0, 0.0, 0.0, 5.0};
  s.sensors.positions = {{0.0, 0.0}};
  s.mesh.h_min = 0.5;
  s.mesh.h_max = 1.5;
  const TetMesh m = build_mesh(s);
  const SkinShape shape(s.geometry);
  const PointLocator locator(m);
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(0, 1);
  for (int i = 0; i < 2000; ++i) {
    const double r = 5.0 * std::sqrt(u(rng)), th = 2 * M_PI * u(rng);
    const double x = r * std::cos(th), y = r * std::sin(th), z = shape.top_z(x, y) * u(rng);
    const Eigen::Vector3d p(x, y, z);
    const auto loc = locator.locate(p);
    ASSERT_TRUE(loc) << "point " << p.transpose() << " not found";
    // the isoparametric map sends the reference coordinates back to p
    const p2::Vec10 n = p2::shape(loc->xi);
    Eigen::Vector3d back = Eigen::Vector3d::Zero();
    for (int k = 0; k < 10; ++k) back += n[k] * m.nodes.row(m.tets(loc->tet, k)).transpose();
    EXPECT_LT((back - p).norm(), 1e-10);
    for (double L : loc->barycentric) EXPECT_GT(L, -1e-8);
  }
  EXPECT_FALSE(locator.locate({0, 0, 3.5}));    // above the apex
  EXPECT_FALSE(locator.locate({6.0, 0, 1.0}));  // beyond the truncation
  EXPECT_FALSE(locator.locate({0, 0, -0.1}));   // below the base
  // exactly on the curved top: found although it lies outside the straight-sided tets
  const auto top = locator.locate({1.234, -0.77, shape.top_z(1.234, -0.77)});
  ASSERT_TRUE(top);
}

}  // namespace
}  // namespace skinfem
