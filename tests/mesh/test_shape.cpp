// The exact skin shapes: the ellipsoidal cap's apex curvatures, rim and volume quadrature, against closed
// forms (the sphere's volume, the curvature radii a²/c and b²/c of an ellipsoid at its pole); the ridges'
// profile and their volume (a Bessel integral) against brute-force quadrature in x and y.
#include <gtest/gtest.h>

#include <cmath>

#include "skinfem/mesh/shape.hpp"

namespace skinfem {
namespace {

Geometry ellipsoidal_cap(double R, double R_y, double h, double truncation) {
  Geometry g;
  g.kind = GeometryKind::cap;
  g.cap = {R, h, 0.7, -0.3, truncation, R_y};
  return g;
}

TEST(SkinShape, EllipsoidalCapHasApexCurvatureRadiiRAndRy) {
  // Central second differences, step 1e-3 mm: truncation error (step²/12)·|z''''| ~ 1e-9 of 1/R.
  const Geometry g = ellipsoidal_cap(15.0, 8.0, 4.0, 6.0);
  const SkinShape shape(g);
  const double x = 0.7, y = -0.3, d = 1e-3, z0 = shape.top_z(x, y);
  EXPECT_NEAR(z0, 4.0, 1e-14);
  const double zxx = (shape.top_z(x + d, y) - 2 * z0 + shape.top_z(x - d, y)) / (d * d);
  const double zyy = (shape.top_z(x, y + d) - 2 * z0 + shape.top_z(x, y - d)) / (d * d);
  EXPECT_NEAR(-1 / zxx, 15.0, 15.0 * 1e-6);
  EXPECT_NEAR(-1 / zyy, 8.0, 8.0 * 1e-6);
}

TEST(SkinShape, EllipsoidalCapMeetsTheBaseAtItsRimAlongTheShorterAxis) {
  const Geometry g = ellipsoidal_cap(15.0, 8.0, 4.0, 6.0);
  const SkinShape shape(g);
  const double rim = g.cap.rim_radius();
  EXPECT_NEAR(shape.top_z(0.7, -0.3 + rim), 0.0, 1e-12);
  EXPECT_GT(shape.top_z(0.7 + rim, -0.3), 0.5);  // the longer axis: still thick there
}

TEST(SkinShape, EllipsoidVolumeQuadratureMatchesTheSphereClosedForm) {
  // R_y = R(1 + 1e-10) takes the quadrature path; the shape differs from the sphere's by O(1e-10).
  for (double R : {20.0, 129.7}) {
    const Geometry sphere = ellipsoidal_cap(R, 0.0, 3.0, 6.0);
    const Geometry nearly = ellipsoidal_cap(R, R * (1 + 1e-10), 3.0, 6.0);
    ASSERT_TRUE(sphere.cap.spherical());
    ASSERT_FALSE(nearly.cap.spherical());
    const double v_closed = SkinShape(sphere).volume(), v_quad = SkinShape(nearly).volume();
    EXPECT_NEAR(v_quad, v_closed, 1e-9 * v_closed) << "R " << R;
  }
}

TEST(SkinShape, SphericalCapKeepsItsClosedForm) {
  const Geometry g = ellipsoidal_cap(129.7, 0.0, 3.04, 12.0);
  const SkinShape shape(g);
  const double r2 = 3.0 * 3.0 + 4.0 * 4.0;
  EXPECT_DOUBLE_EQ(shape.top_z(0.7 + 3.0, -0.3 + 4.0), 3.04 - 129.7 + std::sqrt(129.7 * 129.7 - r2));
  EXPECT_DOUBLE_EQ(g.cap.rim_radius(), std::sqrt(129.7 * 129.7 - (129.7 - 3.04) * (129.7 - 3.04)));
}

Geometry ridged_layer(double angle_deg) {
  Geometry g;
  g.kind = GeometryKind::flat;
  g.flat = {1.0, 3.0};
  g.ridges.period = 0.4;
  g.ridges.height = 0.1;
  g.ridges.angle_deg = angle_deg;
  g.ridges.center = {0.3, -0.2};
  g.ridges.radius = 1.5;
  return g;
}

TEST(SkinShape, RidgesHaveTheirPeriodHeightAndDirectionAndEndSmoothly) {
  const SkinShape s(ridged_layer(30.0));
  const double c = std::cos(M_PI / 6), sn = std::sin(M_PI / 6);
  // At the centre a crest (height/2 above the mean), half a period across the crests a trough, along them
  // the same crest.
  EXPECT_NEAR(s.top_z(0.3, -0.2), 1.05, 1e-15);
  EXPECT_NEAR(s.top_z(0.3 + 0.2 * c, -0.2 + 0.2 * sn), 0.95, 1e-14);
  EXPECT_NEAR(s.top_z(0.3 - 0.5 * sn, -0.2 + 0.5 * c), 1.05, 1e-14);
  EXPECT_NEAR(s.mean_top_z(0.3, -0.2), 1.0, 0);
  // Off the pattern the mean top; at its edge value and slope reach it continuously (the window is C¹).
  EXPECT_EQ(s.top_z(0.3 + 1.5, -0.2), 1.0);
  const double d = 1e-6, edge = 1.5 - 1e-9;
  const double slope_in = (s.top_z(0.3 + edge, -0.2) - s.top_z(0.3 + edge - d, -0.2)) / d;
  EXPECT_NEAR(s.top_z(0.3 + edge, -0.2), 1.0, 1e-12);
  EXPECT_NEAR(slope_in, 0.0, 1e-5);
}

Geometry rectangular_ridges(double angle_deg, double edge_width) {
  Geometry g = ridged_layer(angle_deg);
  g.ridges.profile = RidgeProfile::rectangular;
  g.ridges.edge_width = edge_width;
  return g;
}

TEST(SkinShape, RectangularRidgesHavePlateausAndC1Walls) {
  const SkinShape s(rectangular_ridges(0.0, 0.1));  // period 0.4: crests on |ξ| ≤ 0.05, walls to 0.15
  const auto z = [&](double xi) { return s.ridge_z(0.3 + xi, -0.2); };
  for (double xi : {0.0, 0.03, 0.05, -0.05, 0.4}) EXPECT_NEAR(z(xi), 0.05, 1e-15) << xi;
  for (double xi : {0.15, 0.2, -0.25, 0.6}) EXPECT_NEAR(z(xi), -0.05, 1e-15) << xi;
  EXPECT_NEAR(z(0.1), 0.0, 1e-15);  // the wall's middle, a quarter period from the crest
  // Steepest at the wall's middle: (height/2)·π/edge_width; flat where it meets each plateau.
  const double d = 1e-7;
  EXPECT_NEAR((z(0.1 + d) - z(0.1 - d)) / (2 * d), -0.05 * M_PI / 0.1, 1e-6);
  EXPECT_NEAR((z(0.05 + d) - z(0.05)) / d, 0.0, 1e-5);
  EXPECT_NEAR((z(0.15) - z(0.15 - d)) / d, 0.0, 1e-5);
  // A wall half a period wide leaves no plateau: the sinusoid, to round-off.
  const SkinShape wide(rectangular_ridges(30.0, 0.2)), sine(ridged_layer(30.0));
  for (double x = -1.2; x <= 1.8; x += 0.0137)
    EXPECT_NEAR(wide.ridge_z(x, 0.1 + 0.3 * x), sine.ridge_z(x, 0.1 + 0.3 * x), 1e-15) << x;
  EXPECT_NEAR(wide.volume(), sine.volume(), 1e-12);
}

TEST(SkinShape, RidgeVolumeMatchesBruteForceQuadrature) {
  // Reference: the midpoint rule on a 3000² grid over the pattern's bounding square (the ridges are C¹,
  // so its error is O(Δ²) ~ 1e-7 of the ridge volume's scale height/2 × area = 0.35 mm³). The rectangular
  // profile goes through its cosine series (shape.cpp); the midpoint rule sees it point by point.
  for (const Geometry& g : {ridged_layer(0.0), ridged_layer(30.0), rectangular_ridges(0.0, 0.1),
                            rectangular_ridges(30.0, 0.05)}) {
    const double angle = g.ridges.angle_deg;
    const SkinShape s(g);
    const int n = 3000;
    const double L = 3.0, dx = L / n;
    double v = 0;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) v += s.ridge_z(0.3 - 1.5 + (i + 0.5) * dx, -0.2 - 1.5 + (j + 0.5) * dx);
    v *= dx * dx;
    Geometry smooth = g;
    smooth.ridges = {};
    const double ridges = s.volume() - SkinShape(smooth).volume();
    EXPECT_NEAR(ridges, v, 1e-6) << "angle " << angle;
    EXPECT_GT(std::abs(ridges), 1e-4);  // the check is not vacuous
  }
}

}  // namespace
}  // namespace skinfem
