// The share of each multiplier's hat under a hole (contact/holes/cover.hpp), on a flat top where the hats'
// integrals are exact: the covered shares add up to the disc's area (a groove's: its rectangle's), hats
// inside the disc are covered whole, and the shares move continuously with the disc.
#include <gtest/gtest.h>

#include <cmath>

#include "skinfem/contact/holes/cover.hpp"
#include "skinfem/mesh/build.hpp"

namespace skinfem::contact {
namespace {

struct Fixture {
  TetMesh mesh;
  MortarZone zone;
};

const Fixture& flat() {
  static const Fixture f = [] {
    Scene s;
    s.name = "test_hole_cover";
    s.geometry.kind = GeometryKind::flat;
    s.geometry.flat = {1.0, 3.0};
    s.material = {3.0, 0.5};
    s.sensors.positions = {{0, 0}};
    s.sensors.disc_diameter = 0.2;
    s.mesh.h_min = 0.2;
    s.mesh.h_max = 1.0;
    s.mesh.growth = 1.7;
    s.mesh.refine_sensors = false;
    Fixture x;
    x.mesh = build_mesh(s);
    x.zone = mortar_zone(x.mesh, {0, 0}, 2.0);
    return x;
  }();
  return f;
}

double covered_area(const Eigen::VectorXd& covered) { return covered.dot(flat().zone.area); }

TEST(HoleCover, SharesAddUpToTheDiscsArea) {
  for (const Hole& h : {Hole{{0, 0}, 0.5}, Hole{{0.37, -0.21}, 0.8}, Hole{{-1.1, 0.4}, 0.13}}) {
    const double area = M_PI * 0.25 * h.diameter * h.diameter;
    EXPECT_NEAR(covered_area(hole_cover(flat().zone, flat().mesh, {h})), area, 1e-12 * area);
  }
  const Hole a{{-0.5, 0}, 0.4}, b{{0.6, 0.3}, 0.3};
  EXPECT_NEAR(covered_area(hole_cover(flat().zone, flat().mesh, {a, b})), M_PI * 0.25 * (0.16 + 0.09), 1e-12);
}

TEST(HoleCover, HatsInsideTheDiscAreCoveredWholeAndFarOnesNot) {
  const Fixture& f = flat();
  const double cx = 0.1, cy = 0.05, R = 1.0;
  const Eigen::VectorXd c = hole_cover(f.zone, f.mesh, {Hole{{cx, cy}, 2 * R}});
  // Each hat's reach: the farthest corner of the faces around its vertex.
  std::vector<double> reach(f.mesh.num_vertices, 0.0);
  for (int face : f.zone.faces)
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        const int u = f.mesh.faces(face, a), v = f.mesh.faces(face, b);
        reach[u] = std::max(reach[u], std::hypot(f.mesh.nodes(u, 0) - f.mesh.nodes(v, 0),
                                                 f.mesh.nodes(u, 1) - f.mesh.nodes(v, 1)));
      }
  // The 512-gon's in- and circumradius differ from R by less than 1e-4 R.
  int inside = 0, outside = 0;
  for (int i = 0; i < f.zone.size(); ++i) {
    const int v = f.zone.vertices[i];
    const double r = std::hypot(f.mesh.nodes(v, 0) - cx, f.mesh.nodes(v, 1) - cy);
    if (r + reach[v] < R * (1 - 1e-4)) {
      EXPECT_NEAR(c[i], 1.0, 1e-12);
      ++inside;
    } else if (r - reach[v] > R * (1 + 1e-4)) {
      EXPECT_EQ(c[i], 0.0);
      ++outside;
    } else {
      EXPECT_GE(c[i], 0.0);
      EXPECT_LE(c[i], 1.0);
    }
  }
  EXPECT_GT(inside, 0);
  EXPECT_GT(outside, 0);
}

// A groove's rectangle is clipped exactly (no polygon): its shares add up to width × length, at any angle.
TEST(HoleCover, AGroovesSharesAddUpToItsRectangle) {
  for (const Vec2& across : {Vec2{0, 1}, Vec2{0.6, 0.8}}) {
    Hole g{{0.1, 0.2}, 0.3, 0, 0.5};
    g.length = 2.0;
    g.across = across;
    EXPECT_NEAR(covered_area(hole_cover(flat().zone, flat().mesh, {g})), 0.6, 1e-12);
    // With a disc beside it: the two add.
    EXPECT_NEAR(covered_area(hole_cover(flat().zone, flat().mesh, {g, Hole{{-0.9, -0.6}, 0.4}})),
                0.6 + M_PI * 0.04, 1e-12);
  }
}

// A disc moved by δ changes each share by at most its boundary's length × δ over the hat's integral.
TEST(HoleCover, SharesMoveContinuouslyWithTheDisc) {
  const Fixture& f = flat();
  const double delta = 1e-7, d = 0.5;
  const Eigen::VectorXd a = hole_cover(f.zone, f.mesh, {Hole{{0.2, 0.1}, d}}),
                        b = hole_cover(f.zone, f.mesh, {Hole{{0.2 + delta, 0.1}, d}});
  for (int i = 0; i < f.zone.size(); ++i) EXPECT_LE(std::abs(a[i] - b[i]), M_PI * d * delta / f.zone.area[i]);
  EXPECT_GT((a - b).cwiseAbs().maxCoeff(), 0.0);
}

}  // namespace
}  // namespace skinfem::contact
