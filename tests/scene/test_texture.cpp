// A textured plate's holes (scene/texture.hpp). References: the lattice's definition (origin + i·period,
// row by row); the random pattern's contract (the count round(density × area), inside the rectangle,
// diameters in range, no two overlapping, the same holes for the same seed and others for another); the
// scan's positions (from, from + step, …, to inclusive); the tracks' geometry (a row's holes share one
// track, a hole that never comes near the zone has none); a grating's grooves (origin + i·period along the
// sliding direction, their length across it) and the rectangles' distances in closed form.
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

TEST(Texture, AGratingsGroovesLieAcrossTheSlidingDirection) {
  Texture t;
  t.listed = {Hole{{9, 9}, 0.3, 0, 0.5}};
  Grooves g;
  g.origin = {-1, 0.5}, g.width = 0.4, g.length = 6, g.period = 1.5, g.depth = 0.3, g.count = 3;
  g.direction = {0.6, 0.8};
  t.grooves = g;
  const TextureHoles h = texture_holes(t);
  ASSERT_EQ(h.holes.size(), 4u);
  for (int i = 0; i < 3; ++i) {
    const Hole& k = h.holes[1 + i];
    EXPECT_NEAR(k.center[0], -1 + 1.5 * i * 0.6, 1e-12);
    EXPECT_NEAR(k.center[1], 0.5 + 1.5 * i * 0.8, 1e-12);
    EXPECT_TRUE(k.groove());
    EXPECT_EQ(k.diameter, 0.4);
    EXPECT_EQ(k.length, 6);
    EXPECT_EQ(k.depth, 0.3);
    EXPECT_NEAR(k.across[0], -0.8, 1e-15);
    EXPECT_NEAR(k.across[1], 0.6, 1e-15);
  }
  // Neighbours are a period apart: the plate between them is period − width wide.
  EXPECT_NEAR(rim_gap(h.holes[1], h.holes[2]), 1.1, 1e-12);
  // Inside: within half the width along (0.6, 0.8) and half the length across.
  const Hole& k = h.holes[1];
  EXPECT_TRUE(hole_contains(k, -1 + 0.19 * 0.6 - 2.9 * 0.8, 0.5 + 0.19 * 0.8 + 2.9 * 0.6));
  EXPECT_FALSE(hole_contains(k, -1 + 0.21 * 0.6, 0.5 + 0.21 * 0.8));
  EXPECT_FALSE(hole_contains(k, -1 - 3.01 * 0.8, 0.5 + 3.01 * 0.6));
}

TEST(Texture, RimGapsOfGroovesAndDiscs) {
  Hole g{{0, 0}, 0.5, 0, 0.5};
  g.length = 4;  // x in [-0.25, 0.25], y in [-2, 2]
  const auto disc = [](double x, double y, double d) { return Hole{{x, y}, d, 0, 0.5}; };
  EXPECT_NEAR(rim_gap(g, disc(1.0, 0.5, 0.4)), 0.55, 1e-12);                  // beside its long side
  EXPECT_NEAR(rim_gap(disc(1.0, 0.5, 0.4), g), 0.55, 1e-12);                  // either order
  EXPECT_NEAR(rim_gap(g, disc(0.25 + 0.3, 2 + 0.4, 0.2)), 0.5 - 0.1, 1e-12);  // off a corner: 3-4-5
  EXPECT_NEAR(rim_gap(g, disc(0.1, 1.0, 0.2)), -0.15 - 0.1, 1e-12);           // inside, 0.15 from a side
  EXPECT_TRUE(holes_overlap(g, disc(0.3, 0, 0.2)));
  Hole far = g;
  far.center = {0.7, 5};  // 0.2 apart along x, 1 along y
  EXPECT_NEAR(rim_gap(g, far), std::hypot(0.2, 1.0), 1e-12);
  far.center = {0.7, 3};  // side by side
  EXPECT_NEAR(rim_gap(g, far), 0.2, 1e-12);
  // Random holes are drawn clear of the grooves.
  Texture t;
  Grooves gr;
  gr.origin = {-1.5, 0}, gr.width = 0.3, gr.length = 3, gr.period = 1, gr.count = 4;
  t.grooves = gr;
  t.random = RandomHoles{{-2, -1}, {2, 1}, 1.0, 0.2, 0.3, 0.5, 3};
  const TextureHoles h = texture_holes(t);
  ASSERT_TRUE(h.error.empty()) << h.error;
  for (size_t a = 4; a < h.holes.size(); ++a)
    for (size_t b = 0; b < 4; ++b) EXPECT_GE(rim_gap(h.holes[a], h.holes[b]), 0) << a << " and " << b;
}

// A groove crossing a zone of radius 2 about (0.5, 0). Short (0.2 × 0.6 mm), it meets the zone while its
// centre line is within 2 + 0.1 mm of x = 0.5, and its part in the zone lies within hypot(0.1, 0.6) of its
// centre line's point nearest the zone's centre. Long (10 mm), it sweeps the whole zone: the zone is its
// track.
TEST(Texture, AGroovesTrackIsTheSmallerOfItsSweptStripAndTheZone) {
  Hole g{{-10, 0.3}, 0.2, 0, 0.5};
  g.length = 0.6;
  std::vector<HoleTrack> t = hole_tracks({g}, {1, 0}, Scan{0, 30, 0.1}, {0.5, 0}, 2.0);
  ASSERT_EQ(t.size(), 1u);
  EXPECT_NEAR(t[0].from[0], 0.5 - 2.1, 1e-12);
  EXPECT_NEAR(t[0].to[0], 0.5 + 2.1, 1e-12);
  EXPECT_NEAR(t[0].from[1], 0, 1e-12);
  EXPECT_NEAR(t[0].radius, std::hypot(0.1, 0.6), 1e-12);
  // Its end 1.2 mm from the zone's centre (y from 1.2 to 1.8): the chord there is 2·sqrt(4 − 1.44).
  g.center[1] = 1.5;
  t = hole_tracks({g}, {1, 0}, Scan{0, 30, 0.1}, {0.5, 0}, 2.0);
  ASSERT_EQ(t.size(), 1u);
  EXPECT_NEAR(t[0].from[0], 0.5 - 0.1 - 1.6, 1e-12);
  EXPECT_NEAR(t[0].from[1], 1.2, 1e-12);
  g.center[1] = 2.4;  // 2.1 mm away: never
  EXPECT_TRUE(hole_tracks({g}, {1, 0}, Scan{0, 30, 0.1}, {0.5, 0}, 2.0).empty());
  g.length = 10, g.center[1] = 0.3;
  t = hole_tracks({g}, {1, 0}, Scan{0, 30, 0.1}, {0.5, 0}, 2.0);
  ASSERT_EQ(t.size(), 1u);
  EXPECT_EQ(t[0].from, (Vec2{0.5, 0}));
  EXPECT_EQ(t[0].to, (Vec2{0.5, 0}));
  EXPECT_EQ(t[0].radius, 2.0);
  // Half the scan: the groove never gets past the zone's centre line, but still sweeps most of it.
  EXPECT_EQ(hole_tracks({g}, {1, 0}, Scan{0, 10.5, 0.1}, {0.5, 0}, 2.0).size(), 1u);
}

}  // namespace
}  // namespace skinfem
