// Hard cases at coarse settings: each one is solved with finite fields that balance the applied force, or
// refused with an error that says why; never a crash, never NaN. References: statics (Σ reactions +
// applied force = 0, exact for the discrete system up to the solver residual, see test_elastic_model) and
// the sign of the work done (a pressing punch sinks: depth > 0).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "skinfem/fem/base_traction.hpp"
#include "skinfem/fem/elastic_model.hpp"
#include "skinfem/fem/sensor_reading.hpp"
#include "skinfem/mesh/build.hpp"

namespace skinfem {
namespace {

Scene flat(double h, double half_width, double punch_d, double h_min) {
  Scene s;
  s.geometry.kind = GeometryKind::flat;
  s.geometry.flat = {h, half_width};
  s.sensors.positions = {{0.0, 0.0}};
  s.sensors.disc_diameter = std::min(0.2, punch_d);
  s.loads.punches = {Punch{{0, 0}, punch_d, 1.0, std::nullopt}};
  s.mesh.h_min = h_min;
  s.mesh.h_max = std::max(h_min, std::min(3.0, half_width / 2));
  s.mesh.growth = 1.6;
  return s;
}

// Solves the scene's punch at 1 N and checks finiteness, statics and the sign of the depth.
void expect_sound(const Scene& s, const std::string& what, double nu = 0.5,
                  SideCondition side = SideCondition::free) {
  const TetMesh m = build_mesh(s);
  const ElasticModel model(m, Material{3.0, nu}, side, s.loads.punches);
  const LoadCaseResult r = model.solve(Eigen::VectorXd::Zero(3 * m.num_nodes()), s.loads.punches);
  EXPECT_TRUE(r.solution.u.allFinite()) << what;
  EXPECT_TRUE(r.solution.p.allFinite()) << what;
  const Eigen::Vector3d reactions = r.reactions.reshaped(3, r.reactions.size() / 3).rowwise().sum();
  const Eigen::Vector3d applied(r.applied_force_N[0], r.applied_force_N[1], r.applied_force_N[2]);
  EXPECT_LT((reactions + applied).norm(), 1e-8 * applied.norm()) << what;
  EXPECT_NEAR(r.punches.at(0).force_N, 1.0, 1e-9) << what;
  EXPECT_GT(r.punches[0].displacement_mm, 0) << what;
  // Every sensor, through the reading seam and through the traction field (two routes, equal in exact
  // arithmetic): finite and the same, whatever the case. The sensor under the pressing punch reads
  // compression, σ_z > 0.
  const SensorReadings readings(m, reading_sites(s.sensors));
  const BaseTraction field(m, r.reactions);
  for (int k = 0; k < readings.size(); ++k) {
    const SensorReading a = readings.read(k, r.reactions);
    const Vec2& p = s.sensors.positions[k];
    const SensorReading b = field.disc_mean(p[0], p[1], s.sensors.disc_diameter);
    EXPECT_TRUE(std::isfinite(a.sigma_z) && std::isfinite(a.sigma_x)) << what << ", sensor " << k;
    const double scale = std::max({std::abs(b.sigma_z), std::abs(b.sigma_x), 1e-300});
    EXPECT_NEAR(a.sigma_z, b.sigma_z, 1e-10 * scale) << what << ", sensor " << k;
    EXPECT_NEAR(a.sigma_x, b.sigma_x, 1e-10 * scale) << what << ", sensor " << k;
    if (p[0] == 0 && p[1] == 0) {
      EXPECT_GT(a.sigma_z, 0) << what;
    }
  }
}

TEST(HardCases, ThicknessOverPunchRadiusFrom0_1To100) {
  // a = punch radius, h = 1 mm: h/a = 0.1 (a plate pressed by a wide punch) to 100 (a needle). Elements
  // grow fast (×2 per element) so that the extreme ratios stay coarse.
  for (double h_over_a : {0.1, 1.0, 10.0, 100.0}) {
    const double a = 1.0 / h_over_a;
    Scene s = flat(1.0, a + 2.0, 2 * a, std::clamp(a, 0.02, 0.8));
    s.mesh.growth = 2.0;
    expect_sound(s, "h/a = " + std::to_string(h_over_a));
  }
}

TEST(HardCases, PoissonRatiosAndSideConditions) {
  for (double nu : {0.0, 0.3, 0.49999, 0.5})
    for (SideCondition side : {SideCondition::free, SideCondition::fixed})
      expect_sound(
          flat(2.0, 4.0, 0.5, 0.4),
          "nu = " + std::to_string(nu) + (side == SideCondition::free ? ", side free" : ", side fixed"), nu,
          side);
}

TEST(HardCases, PunchSmallerThanTheLocalElement) {
  // The punch region would ask for h_min = 0.5; the punch is 0.05 wide: the mesh follows its circle.
  expect_sound(flat(2.0, 4.0, 0.05, 0.5), "punch 0.05 mm in 0.5 mm elements");
}

TEST(HardCases, SensorNextToTheCutSide) {
  Scene s = flat(2.0, 4.0, 0.5, 0.4);
  s.sensors.positions.push_back({4.0 - 0.1 - 1e-6, 0.0});  // disc touching the side
  expect_sound(s, "sensor disc at the side");
}

TEST(HardCases, CapTruncatedCloseToItsRim) {
  // R = 20, h = 3: the top meets the base at r = 10.54 mm; cut at 10.4 the side wall is 0.06 mm high, a
  // sliver-prone ring of skin.
  Scene s = flat(3.0, 0, 0.5, 0.5);
  s.geometry.kind = GeometryKind::cap;
  s.geometry.cap = {20.0, 3.0, 0.0, 0.0, 10.4};
  s.mesh.h_max = 3.0;
  expect_sound(s, "cap cut 0.14 mm inside its rim");
}

}  // namespace
}  // namespace skinfem
