// `skinfem contact` on the meridian (pipeline/meridian_contact.hpp): a sphere pressed into a flat layer read
// as the unbounded layer. References: the header's rules, case by case (each scene field that breaks the
// symmetry or the exactness names itself; the frictionless and uncoupled modes are kept, static and coupled
// left out when their ratio is > 0); equilibrium (the multipliers' pressure, integrated here exactly over r
// from pressure_at, carries the scene's force); the problem's own structure (the axisymmetric field read by
// a sensor rotated by θ about the axis gives the same σ_z and cos θ times σ_x; a shift of the indenter and
// every sensor together changes nothing); and the JSON against the typed run (kPa = 1e3 MPa, µm = 1e3 mm).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "skinfem/pipeline/contact.hpp"
#include "skinfem/pipeline/meridian_contact.hpp"

namespace skinfem::pipeline {
namespace {

// The meridian's LCP is solved by pivoting on a direct factorization: readings and forces repeat to
// round-off amplified by the condensed compliance's condition number, well below 1e-9 relative.
constexpr double kRoundOff = 1e-9;
constexpr double kForce = 0.3, kMu = 0.5;

bool has(const std::string& text, const std::string& what) { return text.find(what) != std::string::npos; }

// Sensors on the x axis at radii 0, 1, 1.5 and one at radius 1.5 rotated by 45° (and one on the y axis),
// far enough from the side (2.5 h) for the unbounded layer.
Scene sphere_on_layer() {
  Scene s;
  s.name = "meridian_layer";
  s.source_path = "meridian_layer.json";
  s.geometry.kind = GeometryKind::flat;
  s.geometry.flat = {2.0, 12.0};
  s.sensors.positions = {{0, 0}, {1, 0}, {1.5, 0}, {0.75 * std::sqrt(2.0), 0.75 * std::sqrt(2.0)}, {0, 1}};
  ContactLoad c;
  c.indenter = IndenterKind::sphere;
  c.sphere_R = 20;
  c.force = kForce;
  c.zone_radius = 2;
  c.h = 0.35;
  c.mu = kMu;
  c.friction = FrictionMode::uncoupled;
  c.direction = {1, 0};
  s.contact = c;
  return s;
}

class MeridianContactStage : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    scene_ = new Scene(sphere_on_layer());
    run_ = new MeridianContactRun(meridian_contact_run(*scene_, FrictionMode::uncoupled));
  }
  static void TearDownTestSuite() {
    delete run_;
    delete scene_;
  }
  static Scene* scene_;
  static MeridianContactRun* run_;
};
Scene* MeridianContactStage::scene_ = nullptr;
MeridianContactRun* MeridianContactStage::run_ = nullptr;

TEST_F(MeridianContactStage, WhatBreaksTheSymmetryOrExactnessIsNamed) {
  const Scene ok = sphere_on_layer();
  EXPECT_EQ(meridian_contact_unavailable(ok, FrictionMode::none, false), "");
  EXPECT_EQ(meridian_contact_unavailable(ok, FrictionMode::uncoupled, false), "");
  // Coupled friction with μ > 0 tilts the pressure: the zone is no disc.
  EXPECT_TRUE(has(meridian_contact_unavailable(ok, FrictionMode::coupled, false), "contact.friction.mu"));
  // Reporting every mode needs coupled (and static) exact too.
  EXPECT_TRUE(has(meridian_contact_unavailable(ok, FrictionMode::none, true), "contact reports every mode"));
  Scene rest = ok;
  rest.contact->mu = 0;
  rest.contact->static_ratio = 0.1;
  EXPECT_TRUE(has(meridian_contact_unavailable(rest, FrictionMode::static_residual, false),
                  "contact.friction.static_ratio"));
  Scene frictionless = ok;
  frictionless.contact->mu = 0;
  EXPECT_EQ(meridian_contact_unavailable(frictionless, FrictionMode::coupled, true), "");

  Scene posts = ok;
  posts.sensors.model = SensorModel::post;
  EXPECT_TRUE(has(meridian_contact_unavailable(posts, FrictionMode::none, false), "posts"));
  Scene hole = ok;
  hole.contact->holes = {Hole{{0.5, 0}}};
  EXPECT_TRUE(has(meridian_contact_unavailable(hole, FrictionMode::none, false), "off the contact's axis"));
  hole.contact->holes = {Hole{{0, 0}}};
  EXPECT_TRUE(has(meridian_contact_unavailable(hole, FrictionMode::none, false), "holes are on the 3D path"));
  Scene law = ok;
  law.contact->law = FrictionLaw::shear_strength;
  EXPECT_TRUE(has(meridian_contact_unavailable(law, FrictionMode::none, false), "friction law"));
  Scene interface = ok;
  interface.contact->interface = {InterfaceLaw::exponential, 0, 0.005, 0.01};
  EXPECT_TRUE(has(meridian_contact_unavailable(interface, FrictionMode::none, false), "interface"));
  Scene linear = ok;
  linear.contact->interface = {InterfaceLaw::linear, 10, 0, 0};  // a linear interface keeps the meridian
  EXPECT_EQ(meridian_contact_unavailable(linear, FrictionMode::none, false), "");
  // The side within 2.5 h = 5 mm of the zone's edge (12 − 2 = 10 mm from the centre: fine; 6 − 2: not).
  Scene narrow = ok;
  narrow.geometry.flat.half_width = 6;
  narrow.sensors.positions = {{0, 0}};
  EXPECT_TRUE(has(meridian_contact_unavailable(narrow, FrictionMode::none, false), "contact zone ends"));
  Scene far_sensor = ok;
  far_sensor.sensors.positions.push_back({8, 0});
  EXPECT_TRUE(has(meridian_contact_unavailable(far_sensor, FrictionMode::none, false), "sensor 6"));
  // A sphere on a cap off its apex.
  Scene cap = ok;
  cap.geometry.kind = GeometryKind::cap;
  cap.sensors.positions = {{0, 0}};
  cap.contact->center = {0.5, 0};
  EXPECT_TRUE(has(meridian_contact_unavailable(cap, FrictionMode::none, false), "off the cap's axis"));
  cap.contact->center = {0, 0};
  EXPECT_EQ(meridian_contact_unavailable(cap, FrictionMode::none, false), "");
}

TEST_F(MeridianContactStage, ThePathIsTakenWhenAskedOrWhenEveryModeIsExact) {
  const Scene s = sphere_on_layer();  // coupled with μ > 0: not every mode is exact
  std::string why;
  EXPECT_FALSE(contact_on_meridian(s, FrictionMode::uncoupled, GreenPath::automatic, &why));
  EXPECT_TRUE(has(why, "contact.friction.mu")) << why;
  EXPECT_TRUE(contact_on_meridian(s, FrictionMode::uncoupled, GreenPath::meridian, nullptr));
  EXPECT_FALSE(contact_on_meridian(s, FrictionMode::uncoupled, GreenPath::full3d, nullptr));
  Scene frictionless = s;
  frictionless.contact->mu = 0;
  why = "unset";
  EXPECT_TRUE(contact_on_meridian(frictionless, FrictionMode::none, GreenPath::automatic, &why));
  EXPECT_EQ(why, "");
}

TEST_F(MeridianContactStage, ThePressureCarriesTheForce) {
  const contact::MeridianContactResult& s = run_->solved;
  EXPECT_NEAR(s.force_N, kForce, kRoundOff * kForce);
  // p(r) is linear between the multipliers' radii and 0 beyond the last, so p·r is quadratic on each piece
  // and Simpson's rule integrates 2π ∫ p r dr exactly.
  ASSERT_GE(s.r.size(), 2u);
  EXPECT_EQ(s.r.front(), 0);
  double force = 0;
  for (size_t i = 0; i + 1 < s.r.size(); ++i) {
    const double a = s.r[i], b = s.r[i + 1], m = 0.5 * (a + b);
    force +=
        2 * M_PI * (b - a) / 6 * (s.pressure_at(a) * a + 4 * s.pressure_at(m) * m + s.pressure_at(b) * b);
  }
  EXPECT_NEAR(force, kForce, kRoundOff * kForce);
  EXPECT_EQ(s.pressure_at(s.r.back() + 1), 0);
  EXPECT_NEAR(s.p0_MPa, s.pressure_at(0), kRoundOff * s.p0_MPa);
  EXPECT_GT(s.contact_radius_mm, 0);
  EXPECT_LT(s.contact_radius_mm, run_->zone_radius);
}

TEST_F(MeridianContactStage, TheExactModesAreKeptAndTheOthersLeftOut) {
  ASSERT_EQ(run_->modes.size(), 3u);  // none, static (ratio 0: frictionless), uncoupled
  EXPECT_EQ(run_->left_out, std::vector<FrictionMode>{FrictionMode::coupled});
  const auto& none = run_->modes.at(FrictionMode::none);
  const auto& rest = run_->modes.at(FrictionMode::static_residual);
  const auto& un = run_->modes.at(FrictionMode::uncoupled);
  EXPECT_EQ(none.ratio, 0);
  EXPECT_EQ(rest.ratio, 0);
  EXPECT_EQ(un.ratio, kMu);
  EXPECT_EQ(rest.readings, none.readings);  // a static ratio of 0 is frictionless
  EXPECT_LT((un.readings - none.readings - kMu * run_->solved.readings_per_ratio).cwiseAbs().maxCoeff(),
            kRoundOff * un.readings.cwiseAbs().maxCoeff());
  EXPECT_EQ(run_->axis, (Vec2{0, 0}));
  EXPECT_EQ(run_->zone_radius, 2);
}

TEST_F(MeridianContactStage, ASensorRotatedAboutTheAxisReadsTheRotatedField) {
  // Frictionless, the base traction is radial and axisymmetric: a disc at radius 1.5 and angle 45° reads the
  // σ_z of the one on the x axis and cos 45° of its σ_x; on the y axis σ_x vanishes. Exact to round-off: the
  // disc's quadrature (polar, 32 equal angles) maps onto itself under rotations by multiples of 45°.
  const Eigen::VectorXd& f = run_->modes.at(FrictionMode::none).readings;
  const double scale = f.cwiseAbs().maxCoeff();
  ASSERT_GT(std::abs(f[2 * 2 + 1]), 1e-3 * scale);  // a shear to rotate
  EXPECT_NEAR(f[2 * 3], f[2 * 2], kRoundOff * scale);
  EXPECT_NEAR(f[2 * 3 + 1], std::sqrt(0.5) * f[2 * 2 + 1], kRoundOff * scale);
  EXPECT_NEAR(f[2 * 4 + 1], 0, kRoundOff * scale);
  EXPECT_NEAR(f[2 * 4], f[2 * 1], kRoundOff * scale);  // radius 1 on both axes
  EXPECT_NEAR(f[1], 0, kRoundOff * scale);             // at the centre
}

TEST_F(MeridianContactStage, ShiftingTheIndenterAndSensorsTogetherChangesNothing) {
  Scene shifted = *scene_;
  shifted.contact->center = {0.7, -0.4};
  for (Vec2& p : shifted.sensors.positions) p = {p[0] + 0.7, p[1] - 0.4};
  const MeridianContactRun m = meridian_contact_run(shifted, FrictionMode::uncoupled);
  EXPECT_EQ(m.axis, (Vec2{0.7, -0.4}));
  EXPECT_NEAR(m.solved.depth_mm, run_->solved.depth_mm, kRoundOff * run_->solved.depth_mm);
  const Eigen::VectorXd& a = m.modes.at(FrictionMode::uncoupled).readings;
  const Eigen::VectorXd& b = run_->modes.at(FrictionMode::uncoupled).readings;
  // Only the sensors' offsets from the axis, rounded once, differ.
  EXPECT_LT((a - b).cwiseAbs().maxCoeff(), kRoundOff * b.cwiseAbs().maxCoeff());
}

TEST_F(MeridianContactStage, TheJsonSaysTheTypedRun) {
  const nlohmann::json j = meridian_contact_json(*scene_, *run_);
  const contact::MeridianContactResult& s = run_->solved;
  EXPECT_EQ(j.at("path"), "meridian");
  EXPECT_EQ(j.at("friction"), "uncoupled");
  EXPECT_EQ(j.at("ratio").get<double>(), kMu);
  EXPECT_EQ(j.at("force_N").get<double>(), s.force_N);
  EXPECT_NEAR(j.at("tangential_force_N").get<double>(), kMu * s.force_N, 1e-15);
  EXPECT_NEAR(j.at("indentation_um").get<double>(), 1e3 * s.depth_mm, 1e-12 * 1e3 * s.depth_mm);
  EXPECT_NEAR(j.at("p0_kPa").get<double>(), 1e3 * s.p0_MPa, 1e-12 * 1e3 * s.p0_MPa);
  EXPECT_EQ(j.at("contact_radius_mm").get<double>(), s.contact_radius_mm);
  EXPECT_EQ(j.at("left_out"), nlohmann::json::array({"coupled"}));
  EXPECT_EQ(j.at("zone").at("multipliers").get<int>(), s.multipliers);
  EXPECT_EQ(j.at("dofs").get<int>(), s.dofs);
  for (const auto& [mode, v] : run_->modes) {
    const nlohmann::json& sensors = j.at("modes").at(to_string(mode)).at("sensors");
    ASSERT_EQ(sensors.size(), scene_->sensors.positions.size());
    for (size_t k = 0; k < sensors.size(); ++k) {
      EXPECT_EQ(sensors[k].at("sensor").get<size_t>(), k + 1);
      EXPECT_EQ(sensors[k].at("y_mm").get<double>(), scene_->sensors.positions[k][1]);
      EXPECT_NEAR(sensors[k].at("sigma_z_kPa").get<double>(), 1e3 * v.readings[2 * k], 1e-12);
      EXPECT_NEAR(sensors[k].at("sigma_x_kPa").get<double>(), 1e3 * v.readings[2 * k + 1], 1e-12);
    }
  }
  EXPECT_NEAR(j.at("wall_total_s").get<double>(), run_->wall.total(), 1e-12);
}

TEST_F(MeridianContactStage, WhereThePathDoesNotApplyOrTheZoneIsTooSmallTheRunIsRefused) {
  try {
    meridian_contact_run(*scene_, FrictionMode::coupled);
    ADD_FAILURE() << "coupled friction with mu > 0 solved on the meridian";
  } catch (const SceneError& e) {
    EXPECT_TRUE(has(e.what(), "meridian_layer.json")) << e.what();
    EXPECT_TRUE(has(e.what(), "contact.friction.mu")) << e.what();
    EXPECT_TRUE(has(e.what(), "--path 3d")) << e.what();
  }
  Scene small = *scene_;
  small.contact->zone_radius = 0.5 * run_->solved.contact_radius_mm;
  try {
    meridian_contact_run(small, FrictionMode::none);
    ADD_FAILURE() << "a contact larger than its zone was accepted";
  } catch (const SceneError& e) {
    EXPECT_TRUE(has(e.what(), "contact.zone_radius")) << e.what();
  }
}

}  // namespace
}  // namespace skinfem::pipeline
