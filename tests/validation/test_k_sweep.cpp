// The k sensitivity sweep (validation/k_sweep.hpp) against what must hold independently of it.
#include <gtest/gtest.h>

#include <cmath>

#include "../common/convergence.hpp"
#include "validation/k_sweep.hpp"

namespace skinfem::validation {
namespace {

// Dimensional analysis: under a point load the layer's g_zz(0) is c(ν)/h², so k_central does not depend on
// the thickness (the exact layer is accurate to 1e-12); a punch of fixed size does (a/h changes).
TEST(KSweep, PointLoadKIsScaleFree) {
  KProtocol p;
  p.load = green::LayerLoad::point;
  p.h = 2.5;
  const double thin = k_of(p).k_central;
  p.h = 3.5;
  EXPECT_NEAR(k_of(p).k_central, thin, 1e-9);
  p.load = green::LayerLoad::punch;
  const double punch_thick = k_of(p).k_central;
  p.h = 2.5;
  EXPECT_GT(std::abs(k_of(p).k_central - punch_thick), 1e-3);
}

// A punch of radius a loads the layer like a point load up to O((a/h)²) (the kernel is even in the offset):
// the observed order of k_central(punch) − k_central(point) over diameters 0.5, 0.25, 0.1 is 2 within 0.2.
TEST(KSweep, SmallPunchTendsToThePointLoadAtSecondOrder) {
  KProtocol p;
  p.load = green::LayerLoad::point;
  const double point = k_of(p).k_central;
  p.load = green::LayerLoad::punch;
  std::vector<double> d{0.5, 0.25, 0.1}, e;
  for (double di : d) {
    p.punch_diameter = di;
    e.push_back(std::abs(k_of(p).k_central - point));
  }
  EXPECT_NEAR(testing::observed_order(d, e), 2.0, 0.2);
}

TEST(KSweep, CrossingsInterpolateBetweenNeighbours) {
  const std::vector<KSweepPoint> pts{
      {"a", 0, 1.0, 2.0}, {"a", 1, 2.0, 1.0}, {"b", 0, 5, 5}, {"a", 3, 0.0, 1.5}};
  EXPECT_EQ(crossings(pts, "a", "k_central", 1.5), (std::vector<double>{0.5, 1.5}));
  EXPECT_EQ(crossings(pts, "a", "k_lsq_line", 1.25), (std::vector<double>{0.75, 2.0}));
  EXPECT_TRUE(crossings(pts, "a", "k_central", 3.0).empty());
}

// The sweep varies one parameter at a time: every group holds the base case, with the same k.
TEST(KSweep, EveryGroupPassesThroughTheBaseCase) {
  const KProtocol base;
  const KSweepPoint k0 = k_of(base);
  const auto pts = k_sweep(base);
  for (const char* group : {"nu", "punch_diameter_mm", "disc_diameter_mm", "h_mm", "load"}) {
    int hits = 0;
    for (const auto& p : pts)
      if (p.parameter == group && std::abs(p.k_central - k0.k_central) < 1e-12 &&
          std::abs(p.k_lsq_line - k0.k_lsq_line) < 1e-12)
        ++hits;
    EXPECT_EQ(hits, 1) << group;
  }
}

}  // namespace
}  // namespace skinfem::validation
