// A small hole in a rigid plate pressed on the skin, resolved by the mesh, against the penny-shaped crack.
//
// Inside the contact the plate holds the skin's surface flat; a hole of radius ε removes the pressure p over
// the disc and lets the surface bulge into it. For ε much smaller than the layer's thickness and the contact
// radius this is the penny-shaped crack under internal pressure p (Sneddon 1946): frictionless contact
// leaves no shear on the plane, u_z is held outside the disc, and at ν = 1/2 normal and shear decouple
// anyway. One crack face opens by w(r) = 4(1 − ν²) p √(ε² − r²) / (πE), a bulge of volume
//   V = 8(1 − ν²) p ε³ / (3E)   ( = 2 p ε³ / (3G) at ν = 1/2).
// The perturbation carries no net force (u_z = 0 outside the hole, so no 1/r far field): a sensor at depth
// d ≫ ε sees the bulge as a point dilatation of volume V, so the signal scales as V ∝ ε³ ∝ S^{3/2}, with S
// the hole's area, and not as S (the paper's first-order formula ς ≈ −p S g, which ignores the pressure the
// hole pushes onto its rim). Next multipole: relative (ε/d)², below 1 % here.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>

#include "../layer_fixture.hpp"
#include "skinfem/contact/contact_solver.hpp"
#include "skinfem/contact/holes/dimple.hpp"
#include "skinfem/contact/holes/small_hole.hpp"

namespace skinfem::contact {
namespace {

constexpr double kHoleH = 0.05;  // mesh size over the hole's disc, mm
constexpr double kE = testing::kLayerE, kNu = testing::kLayerNu;

// The paper's layer (h = 3.04 mm) under a sphere R = 129.7 mm at 0.8 N (a ≈ 2.5 mm, p0 ≈ 64 kPa, which
// varies by 1 % over the largest hole); a hole disc of radius 0.25 at the contact centre meshed at kHoleH.
// Smaller holes reuse the same mesh (the multipliers strictly inside their disc are dropped).
struct Fixture : testing::CondensedLayer {
  std::unique_ptr<ContactSolver> solver;
  ContactResult intact;
};

Fixture& layer_with_hole() {
  static Fixture f;
  static const bool ready = [] {
    ContactLoad c;
    c.force = 0.8;
    c.holes = {Hole{{0, 0}, 0.5, kHoleH}};
    testing::condense_layer(f, testing::layer_scene("test_hole", 0.6, {{0, 0}, {1, 0}}, c, 3.2));
    f.solver = std::make_unique<ContactSolver>(*f.condensed, *f.scene.contact);
    f.intact = f.solver->solve(FrictionMode::none);
    return true;
  }();
  (void)ready;
  return f;
}

// One hole of radius ε at the centre, frictionless. The discrete hole is the set of dropped multipliers:
// its area S = Σ ∫ψ_i over them (the pressure it removes is p S), ε_h = √(S/π); p is the intact pressure
// averaged over it; V = −Σ g_i over them (their weighted gaps: the skin above the plate's plane).
struct HoleResponse {
  double eps_h = 0, S = 0, p = 0, V = 0;
  Eigen::VectorXd signal;  // readings with the hole − without, MPa
};

HoleResponse hole_response(double eps) {
  Fixture& f = layer_with_hole();
  const MortarZone& zone = f.condensed->zone;
  const auto excluded = excluded_by_holes(zone, f.mesh, {Hole{{0, 0}, 2 * eps}});
  const ContactResult r = f.solver->solve(FrictionMode::none, excluded);
  HoleResponse h;
  for (int i = 0; i < zone.size(); ++i)
    if (excluded[i]) {
      h.S += zone.area[i];
      h.p += f.intact.lambda[i] * zone.area[i];
      h.V -= r.gap[i];
    }
  h.p /= h.S;
  h.eps_h = std::sqrt(h.S / M_PI);
  h.signal = r.readings - f.intact.readings;
  return h;
}

double penny_volume(double p, double eps) { return 8 * (1 - kNu * kNu) * p * std::pow(eps, 3) / (3 * kE); }

const std::array<double, 3> kRadii{0.25, 0.19, 0.13};

// The bulge against the crack's volume. The mesh resolves the hole's edge to one element, so the error is
// first order in kHoleH/ε; a study at hole mesh sizes 0.07, 0.05, 0.035 and ε from 0.13 to 0.25 (15 cases)
// found V below the crack's volume by 0.20–0.33 kHoleH/ε (2.8 % at kHoleH/ε = 0.14, 18 % at 0.54), never
// above it: the tolerance is 0.4 kHoleH/ε.
TEST(Hole, BulgeMatchesThePennyShapedCrack) {
  for (double eps : kRadii) {
    const HoleResponse h = hole_response(eps);
    EXPECT_NEAR(h.eps_h / eps, 1.0, kHoleH / eps) << "the discrete hole is the disc to one element";
    const double ratio = h.V / penny_volume(h.p, h.eps_h);
    EXPECT_LT(ratio, 1.0 + 1e-3) << "ε " << eps;
    EXPECT_GT(ratio, 1.0 - 0.4 * kHoleH / eps) << "ε " << eps;
  }
}

// The signal follows the bulge: ς / V is the same for every radius (to the next multipole, (ε/d)² < 1 %,
// with d ≥ 3.04 mm the distance to the sensor; tolerance 2 %), and |ς| ∝ S^{3/2}: the exponent fitted over
// three radii is 1.5 within 0.1 (the bulge's first-order mesh error, 0.4 kHoleH/ε at most, tilts it by at
// most 0.4 · 0.05 · (1/0.13 − 1/0.25) / ln(S_max/S_min) < 0.06). The area law of the first-order model
// would give 1.
TEST(Hole, SignalScalesAsTheBulgeVolumeNotTheArea) {
  std::array<HoleResponse, 3> h;
  for (int i = 0; i < 3; ++i) h[i] = hole_response(kRadii[i]);
  for (int sensor = 0; sensor < 2; ++sensor) {
    const double per_volume = h[0].signal[2 * sensor] / h[0].V;
    ASSERT_LT(per_volume, 0.0) << "the bulge relieves the sensors under the contact";
    for (int i = 1; i < 3; ++i)
      EXPECT_NEAR(h[i].signal[2 * sensor] / h[i].V / per_volume, 1.0, 0.02) << "sensor " << sensor;
    // Least-squares slope of ln|ς_z| against ln S.
    double mx = 0, my = 0;
    for (const auto& r : h) {
      mx += std::log(r.S) / 3;
      my += std::log(std::abs(r.signal[2 * sensor])) / 3;
    }
    double sxy = 0, sxx = 0;
    for (const auto& r : h) {
      sxy += (std::log(r.S) - mx) * (std::log(std::abs(r.signal[2 * sensor])) - my);
      sxx += (std::log(r.S) - mx) * (std::log(r.S) - mx);
    }
    EXPECT_NEAR(sxy / sxx, 1.5, 0.1) << "sensor " << sensor;
  }
}

// The small-hole model (contact/holes/small_hole.hpp: the crack's volume as a dimple in the intact contact)
// against the resolved holes: the signal per unit bulge volume, and the full prediction. The model's V is
// the crack's, the FE's is 0.4 kHoleH/ε low at most (above), and the dimple stands for the bulge up to the
// next multipole ((ε/d)² < 1 %): tolerance 0.4 kHoleH/ε + 2 %, against the model evaluated at the hole's
// centre with the hole's diameter.
TEST(Hole, SmallHoleModelPredictsTheResolvedSignal) {
  Fixture& f = layer_with_hole();
  const PlanarFaceIndex top(f.mesh, kTop);
  for (double eps : kRadii) {
    const HoleResponse h = hole_response(eps);
    const Eigen::MatrixXd model =
        small_hole_signals(*f.solver, FrictionMode::none, f.mesh, top, {{0, 0}}, 2 * h.eps_h, kE, kNu);
    for (int sensor = 0; sensor < 2; ++sensor)
      EXPECT_NEAR(h.signal[2 * sensor] / model(0, 2 * sensor), 1.0, 0.4 * kHoleH / eps + 0.02)
          << "ε " << eps << ", sensor " << sensor;
  }
}

// The bulge model (contact/holes/dimple.hpp: the crack's bulge as a dimple of the indenter, the hole-free
// contact set kept) against the resolved holes, with the small-hole model's bound (0.4 kHoleH/ε + 2 %,
// above), and against the small-hole model (contact/holes/small_hole.hpp), which puts the same volume at the
// hole's centre: both are the first term in the hole's volume, so their difference is the next one, the
// bulge's spread (second moment 2ε²/5) seen through a kernel that varies over the sensor's distance d, of
// order (ε/d)²: its observed order in ε over the three radii must be 2 (within 0.3, the radii's discrete
// holes being the disc to one element). The dimple's volume under a uniform unit pressure is the crack's,
// 8(1 − ν²)ε³/(3E): the hats sum to 1, so only the rule over the disc is tested (to 1e-10).
TEST(Hole, BulgeModelPredictsTheResolvedSignal) {
  Fixture& f = layer_with_hole();
  const PlanarFaceIndex top(f.mesh, kTop);
  const HoleDimples dimples(*f.solver, f.mesh, top, kE, kNu);
  std::array<std::array<double, 2>, 3> spread{};  // per radius and sensor: bulge / small-hole − 1
  for (int k = 0; k < 3; ++k) {
    const double eps = kRadii[k];
    const HoleResponse h = hole_response(eps);
    const Hole hole{{0, 0}, 2 * h.eps_h};
    const Eigen::VectorXd unit = Eigen::VectorXd::Ones(f.condensed->zone.size());
    EXPECT_NEAR(dimples(hole, unit).opening.sum() / penny_volume(1.0, h.eps_h), 1.0, 1e-10);
    const Eigen::VectorXd bulge =
        f.solver->solve(FrictionMode::none, dimples(hole, f.intact.lambda)).readings - f.intact.readings;
    const Eigen::MatrixXd small =
        small_hole_signals(*f.solver, FrictionMode::none, f.mesh, top, {{0, 0}}, 2 * h.eps_h, kE, kNu);
    for (int sensor = 0; sensor < 2; ++sensor) {
      EXPECT_NEAR(h.signal[2 * sensor] / bulge[2 * sensor], 1.0, 0.4 * kHoleH / eps + 0.02)
          << "ε " << eps << ", sensor " << sensor;
      spread[k][sensor] = bulge[2 * sensor] / small(0, 2 * sensor) - 1;
    }
  }
  for (int sensor = 0; sensor < 2; ++sensor) {
    const double order = std::log(spread[0][sensor] / spread[2][sensor]) / std::log(kRadii[0] / kRadii[2]);
    EXPECT_NEAR(order, 2.0, 0.3) << "sensor " << sensor << ": bulge / small-hole − 1 = " << spread[0][sensor]
                                 << ", " << spread[1][sensor] << ", " << spread[2][sensor];
  }
}

}  // namespace
}  // namespace skinfem::contact
