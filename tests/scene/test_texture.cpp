// A textured plate's holes (scene/texture.hpp). References: the lattice's definition (origin + i·period,
// row by row); the random pattern's contract (the count round(density × area), inside the rectangle,
// diameters in range, no two overlapping, the same holes for the same seed and others for another); the
// scan's positions (from, from + step, …, to inclusive); and the tracks' geometry (a row's holes share one
// track, a hole that never comes near the zone has none).
#include <gtest/gtest.h>

#include <cmath>

#include "skinfem/scene/texture.hpp"

namespace skinfem {
namespace {

TEST(Texture, TheLatticeIsRowByRowFromItsOrigin) {
  Texture t;
  t.listed = {Hole{{9, 9}, 0.3, 0, 0.5}};
  t.lattice = HoleLattice{{-1, 0.5}, {0.9, 1.2}, 3, 2, 0.5, 0.4};
  const TextureHoles h = texture_holes(t);
  ASSERT_TRUE(h.error.empty());
  ASSERT_EQ(h.holes.size(), 7u);
  EXPECT_EQ(h.holes[0].center[0], 9);  // the listed ones first
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i) {
      const Hole& k = h.holes[1 + 3 * j + i];
      EXPECT_NEAR(k.center[0], -1 + 0.9 * i, 1e-12);
      EXPECT_NEAR(k.center[1], 0.5 + 1.2 * j, 1e-12);
      EXPECT_EQ(k.diameter, 0.5);
      EXPECT_EQ(k.depth, 0.4);
    }
}

TEST(Texture, RandomHolesKeepTheirContractAndTheirSeed) {
  Texture t;
  t.random = RandomHoles{{-2, -1}, {3, 1}, 2.0, 0.2, 0.4, 0.5, 7};
  const TextureHoles a = texture_holes(t), b = texture_holes(t);
  ASSERT_TRUE(a.error.empty()) << a.error;
  ASSERT_EQ(a.holes.size(), 20u);  // 2 per mm² on 5 × 2 mm
  for (size_t k = 0; k < a.holes.size(); ++k) {
    const Hole& h = a.holes[k];
    EXPECT_EQ(h.center[0], b.holes[k].center[0]);
    EXPECT_EQ(h.center[1], b.holes[k].center[1]);
    EXPECT_GE(h.center[0], -2);
    EXPECT_LE(h.center[0], 3);
    EXPECT_GE(h.center[1], -1);
    EXPECT_LE(h.center[1], 1);
    EXPECT_GE(h.diameter, 0.2);
    EXPECT_LE(h.diameter, 0.4);
    for (size_t l = 0; l < k; ++l) EXPECT_FALSE(holes_overlap(h, a.holes[l])) << k << " and " << l;
  }
  t.random->seed = 8;
  const TextureHoles c = texture_holes(t);
  EXPECT_NE(c.holes[0].center[0], a.holes[0].center[0]);
}

TEST(Texture, MirroredRandomHolesComeInPairsAboutTheAxis) {
  Texture t;
  t.random = RandomHoles{{-2, -1}, {3, 1}, 2.0, 0.2, 0.4, 0.5, 7};
  t.random->mirror = true;
  const TextureHoles a = texture_holes(t);
  ASSERT_TRUE(a.error.empty()) << a.error;
  ASSERT_EQ(a.holes.size(), 20u);  // 10 pairs: 2 per mm² on 5 × 2 mm
  for (size_t k = 0; k < a.holes.size(); k += 2) {
    const Hole &h = a.holes[k], &image = a.holes[k + 1];
    EXPECT_GE(h.center[1], 0.5 * h.diameter) << "a pair must not overlap itself";
    EXPECT_LE(h.center[1], 1);
    EXPECT_EQ(image.center[0], h.center[0]);
    EXPECT_EQ(image.center[1], -h.center[1]);
    EXPECT_EQ(image.diameter, h.diameter);
    for (size_t l = 0; l < a.holes.size(); ++l)
      if (l != k) {
        EXPECT_FALSE(holes_overlap(h, a.holes[l])) << k << " and " << l;
      }
  }
}

TEST(Texture, RandomHolesThatCannotFitSaySo) {
  Texture t;
  // 40 holes of 0.5 mm on 2 mm²: more than the plane can hold (at most about 2 mm² / 0.2 mm² each).
  t.random = RandomHoles{{-1, -0.5}, {1, 0.5}, 20.0, 0.5, 0.5, 0.5, 1};
  const TextureHoles h = texture_holes(t);
  EXPECT_LT(h.holes.size(), 40u);
  EXPECT_NE(h.error.find("of its 40 holes"), std::string::npos) << h.error;
}

TEST(Texture, TheScanRunsFromItsStartToItsEndByItsStep) {
  const Scan s{0, 10, 0.025};
  ASSERT_EQ(s.positions(), 401);
  EXPECT_NEAR(s.u(400), 10, 1e-12);
  EXPECT_EQ(Scan({-1, 1, 0.3}).positions(), 7);  // the last step short of `to` is not taken
}

TEST(Texture, ARowsHolesShareOneTrackAndAFarHoleHasNone) {
  std::vector<Hole> holes;
  for (int i = 0; i < 10; ++i) holes.push_back(Hole{{-19.0 + i, 0}, 0.5, 0, 0.5});
  holes.push_back(Hole{{0, 6}, 0.5, 0, 0.5});  // 6 mm off the row: never within the 2 mm zone
  const std::vector<HoleTrack> t = hole_tracks(holes, {1, 0}, Scan{0, 30, 0.1}, {0.5, 0}, 2.0);
  ASSERT_EQ(t.size(), 1u);
  // Each crosses the zone whole during the scan; the centre's segment where the hole reaches the zone: within
  // 2 + 0.25 mm of x = 0.5.
  EXPECT_NEAR(t[0].from[0], 0.5 - 2.25, 1e-12);
  EXPECT_NEAR(t[0].to[0], 0.5 + 2.25, 1e-12);
  EXPECT_EQ(t[0].radius, 0.25);
}

}  // namespace
}  // namespace skinfem
