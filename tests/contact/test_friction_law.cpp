// Friction laws (contact/contact_solver.hpp, FrictionLaw): a shear strength τ where the skin touches, alone
// or with Coulomb's μp. The paper's layer (h = 3.04 mm, E = 3 MPa, ν = 0.5) under a sphere R = 129.7 mm at
// 0.8 N, a hole region of radius 0.25 mm at the centre meshed at kHoleH.
//
// Independent checks: under a shear strength the hole is a point force −τ S_d along the sliding direction
// (the plate puts the missing pressure back on the rim, not the missing shear), so its tangential signal is
// the sensor's own Green map (green/fe_green.hpp, FeGreen::at, a uniform load over the exact disc) times
// −τ S_d; a full FE solve with the solved load reproduces the condensed readings and force (reactions
// against adjoints); the laws superpose where the pressure does not see the traction (uncoupled).
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <cstdio>
#include <memory>

#include "layer_fixture.hpp"
#include "skinfem/contact/contact_solver.hpp"
#include "skinfem/contact/holes/cover.hpp"
#include "skinfem/fem/base_traction.hpp"
#include "skinfem/green/fe_green.hpp"

namespace skinfem::contact {
namespace {

constexpr double kHoleH = 0.05;  // mm, mesh size over the hole region
constexpr double kTau = 0.1;     // MPa
constexpr double kMu = 0.5;

struct Fixture : testing::CondensedLayer {
  std::unique_ptr<green::FeGreen> green;
};

Fixture& layer() {
  static Fixture f;
  static const bool ready = [] {
    ContactLoad c;
    c.force = 0.8;
    c.mu = kMu;
    c.static_ratio = 0.1;
    c.holes = {Hole{{0, 0}, 0.5, kHoleH}};  // meshing only: solves pass their own holes
    testing::condense_layer(f,
                            testing::layer_scene("test_friction_law", 0.6, {{0, 0}, {1, 0}, {2, 0}}, c, 3.2));
    f.green = std::make_unique<green::FeGreen>(*f.model, f.scene.sensors);
    return true;
  }();
  (void)ready;
  return f;
}

ContactLoad load(FrictionLaw law, std::optional<double> tau0 = kTau) {
  ContactLoad c = *layer().scene.contact;
  c.holes.clear();
  c.law = law;
  c.tau0 = tau0;
  return c;
}

struct Holed {
  std::vector<char> excluded;
  Eigen::VectorXd covered;
};
Holed hole_at(const Vec2& centre, double diameter) {
  Fixture& f = layer();
  const std::vector<Hole> h{Hole{centre, diameter}};
  return {excluded_by_holes(f.condensed->zone, f.mesh, h), hole_cover(f.condensed->zone, f.mesh, h)};
}

// Uncoupled, the pressure is the frictionless one, so the signal splits exactly into the frictionless
// (rim-reloaded) part and the shear's; the shear's is −τ S_d times the Green map of a uniform load over the
// disc. The hats carry the disc's shear lumped within one hat (kHoleH) of its edge: a displacement of at
// most kHoleH, so the difference is bounded by τ S_d kHoleH |∇g|, |∇g| from the map's differences.
TEST(FrictionLaw, UnderAShearStrengthAHoleIsAPointForceOnTheGreenMap) {
  Fixture& f = layer();
  const ContactSolver shear(*f.condensed, load(FrictionLaw::shear_strength)),
      none(*f.condensed, load(FrictionLaw::coulomb));
  for (double d : {0.5, 0.3}) {
    const Holed h = hole_at({0, 0}, d);
    const ContactResult r0 = shear.solve(FrictionMode::uncoupled),
                        r = shear.solve(FrictionMode::uncoupled, h.excluded, {}, h.covered),
                        n0 = none.solve(FrictionMode::none), n = none.solve(FrictionMode::none, h.excluded);
    const double eps = 0.5 * d, S = M_PI * eps * eps;
    EXPECT_NEAR(r0.tangential_force_N - r.tangential_force_N, kTau * S,
                1e-4 * kTau * S);  // polygon, curvature
    const Eigen::VectorXd signal = r.readings - r0.readings, rim = n.readings - n0.readings;
    for (int k = 0; k < 3; ++k) {
      const double ox = -f.scene.sensors.positions[k][0];
      const auto g = [&](double dx) {
        return f.green->at(k, true, ox + dx, 0, green::LayerLoad::uniform, eps);
      };
      const green::GreenSample G = g(0), gp = g(kHoleH), gm = g(-kHoleH);
      const double grad_xz = std::abs(gp.xz - gm.xz) / (2 * kHoleH),
                   grad_xx = std::abs(gp.xx - gm.xx) / (2 * kHoleH);
      const double expect_z = -kTau * S * G.xz, expect_x = -kTau * S * G.xx;
      const double tol_z = kTau * S * kHoleH * grad_xz + 1e-3 * std::abs(expect_z),
                   tol_x = kTau * S * kHoleH * grad_xx + 1e-3 * std::abs(expect_x);
      EXPECT_NEAR(signal[2 * k] - rim[2 * k], expect_z, tol_z) << "sensor " << k << ", hole " << d;
      EXPECT_NEAR(signal[2 * k + 1] - rim[2 * k + 1], expect_x, tol_x) << "sensor " << k << ", hole " << d;
      std::printf(
          "hole %.2f mm, sensor at x = %g: shear signal (z, x) = (%.4f, %.4f) kPa, point force "
          "(%.4f, %.4f) kPa, rim part (%.4f, %.4f) kPa\n",
          d, -ox, 1e3 * (signal[2 * k] - rim[2 * k]), 1e3 * (signal[2 * k + 1] - rim[2 * k + 1]),
          1e3 * expect_z, 1e3 * expect_x, 1e3 * rim[2 * k], 1e3 * rim[2 * k + 1]);
    }
  }
}

// Reactions of a full solve with the solved load (pressure and shear) against the condensed readings, and
// the base's tangential force against the shear's integral: two methods, equal to solver round-off.
TEST(FrictionLaw, CoupledShearReadingsEqualAFullSolve) {
  Fixture& f = layer();
  for (FrictionLaw law : {FrictionLaw::shear_strength, FrictionLaw::mixed}) {
    const ContactSolver solver(*f.condensed, load(law));
    const Holed h = hole_at({0.4, 0}, 0.5);
    for (const ContactResult& r : {solver.solve(FrictionMode::coupled),
                                   solver.solve(FrictionMode::coupled, h.excluded, {}, h.covered)}) {
      const Eigen::VectorXd F = f.condensed->zone.load(r.lambda, f.condensed->direction, r.ratio, r.shear);
      const MixedSolution x = f.model->solver().solve(F);
      const BaseTraction base(f.mesh, f.model->solver().reactions(x, F));
      const double scale = r.readings.cwiseAbs().maxCoeff();
      for (size_t k = 0; k < f.scene.sensors.positions.size(); ++k) {
        const auto& p = f.scene.sensors.positions[k];
        const SensorReading v = base.disc_mean(p[0], p[1], 0.2);
        EXPECT_NEAR(v.sigma_z, r.readings[2 * k], 1e-8 * scale);
        EXPECT_NEAR(v.sigma_x, r.readings[2 * k + 1], 1e-8 * scale);
      }
      EXPECT_NEAR(base.total_force().z(), r.force_N, 1e-9);
      EXPECT_NEAR(-base.total_force().x(), r.tangential_force_N, 1e-9);
      EXPECT_LT(r.complementarity, 1e-10);
    }
  }
}

// The shear acts exactly where the solved contact touches: τ on active multipliers, 0 elsewhere, except the
// edge multipliers that hold a fraction (they touch without their own shear and lift under it).
TEST(FrictionLaw, CoupledShearActsOnItsOwnContact) {
  Fixture& f = layer();
  const ContactSolver solver(*f.condensed, load(FrictionLaw::shear_strength));
  for (FrictionMode mode : {FrictionMode::coupled, FrictionMode::static_residual}) {
    const ContactResult r = solver.solve(mode);
    const double tau = mode == FrictionMode::coupled ? kTau : kTau * 0.1 / kMu;
    EXPECT_DOUBLE_EQ(r.tau, tau);
    std::vector<char> active(f.condensed->zone.size(), 0);
    for (int i : r.active) active[i] = 1;
    int fractional = 0;
    for (int i = 0; i < f.condensed->zone.size(); ++i) {
      if (r.shear[i] == tau * active[i]) continue;
      ++fractional;
      EXPECT_GT(r.shear[i], 0);
      EXPECT_LT(r.shear[i], tau);
    }
    EXPECT_EQ(fractional, r.partial_shear);
    std::printf("%s: %zu active multipliers, %d holding a fraction of tau\n", to_string(mode),
                r.active.size(), r.partial_shear);
  }
}

// Where the pressure does not see the traction the laws superpose: mixed = Coulomb + shear − frictionless,
// with and without a hole; a zero shear strength is Coulomb (mixed) or frictionless (shear_strength).
TEST(FrictionLaw, LawsSuperposeWhereThePressureIgnoresTheTraction) {
  Fixture& f = layer();
  const ContactSolver mixed(*f.condensed, load(FrictionLaw::mixed)),
      shear(*f.condensed, load(FrictionLaw::shear_strength)),
      coulomb(*f.condensed, load(FrictionLaw::coulomb, std::nullopt));
  const Holed h = hole_at({-0.6, 0}, 0.5);
  for (bool holed : {false, true}) {
    const auto solve = [&](const ContactSolver& s, FrictionMode m) {
      return holed ? s.solve(m, h.excluded, {}, h.covered) : s.solve(m);
    };
    const ContactResult a = solve(mixed, FrictionMode::uncoupled),
                        b = solve(coulomb, FrictionMode::uncoupled),
                        c = solve(shear, FrictionMode::uncoupled), d = solve(coulomb, FrictionMode::none);
    const Eigen::VectorXd sum = b.readings + c.readings - d.readings;
    EXPECT_LT((a.readings - sum).cwiseAbs().maxCoeff(), 1e-12 * a.readings.cwiseAbs().maxCoeff());
    EXPECT_NEAR(a.tangential_force_N, b.tangential_force_N + c.tangential_force_N, 1e-12);
  }
  const ContactSolver zero_mixed(*f.condensed, load(FrictionLaw::mixed, 0.0)),
      zero_shear(*f.condensed, load(FrictionLaw::shear_strength, 0.0));
  for (FrictionMode m : {FrictionMode::static_residual, FrictionMode::uncoupled, FrictionMode::coupled}) {
    EXPECT_EQ(zero_mixed.solve(m).readings, coulomb.solve(m).readings);
    EXPECT_EQ(zero_shear.solve(m).readings, coulomb.solve(FrictionMode::none).readings);
  }
}

// "from_force": τ0 = μF/A over the frictionless contact, so the uncoupled sliding shear totals μF.
// A shear strength far above the contact's pressure lifts, in the coupled linear model, the edge it acts on:
// no contact set is consistent. The solve says so naming the scene's field (issue 57: an internal line).
TEST(FrictionLaw, AShearStrengthThatLiftsItsOwnEdgeIsRefusedByName) {
  Fixture& f = layer();
  const ContactSolver solver(*f.condensed, load(FrictionLaw::shear_strength, 0.5));
  try {
    solver.solve(FrictionMode::coupled);
    FAIL() << "tau0 = 0.5 MPa solved";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("contact.friction.tau0 = 0.5: the coupled contact has no consistent "
                                         "contact set"),
              std::string::npos)
        << e.what();
  }
}

TEST(FrictionLaw, ShearStrengthFromTheForceTotalsMuF) {
  Fixture& f = layer();
  const ContactSolver solver(*f.condensed, load(FrictionLaw::shear_strength, std::nullopt));
  const ContactResult r = solver.solve(FrictionMode::uncoupled);
  EXPECT_NEAR(r.tangential_force_N, kMu * r.force_N, 1e-12);
  double area = 0;
  for (int i : r.active) area += f.condensed->zone.area[i];
  EXPECT_NEAR(solver.tau0(), kMu * 0.8 / area, 1e-12);
}

// The Coulomb ratio below which the coupled LCP matrix C_zz + r C_zt has a positive definite symmetric part
// (a P-matrix: one solution under force control, Cottle, Pang & Stone thm 3.3.7), from the generalized
// eigenproblem S v = μ C_zz v, against a second method: the smallest eigenvalue of the symmetric part itself
// just below and just above the bound. Below it the coupled contact solves at force balance.
TEST(FrictionLaw, CoupledRatioBoundIsWhereTheSymmetricPartStopsBeingPositiveDefinite) {
  Fixture& f = layer();
  const ContactSolver solver(*f.condensed, load(FrictionLaw::coulomb));
  const double bound = solver.unique_ratio_bound();
  ASSERT_TRUE(std::isfinite(bound) && bound > 0) << bound;
  const auto smallest = [&](double r) {
    const Eigen::MatrixXd M = f.condensed->C_zz + r * f.condensed->C_zt;
    return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(0.5 * (M + M.transpose()), Eigen::EigenvaluesOnly)
        .eigenvalues()
        .minCoeff();
  };
  EXPECT_GT(smallest(0.999 * bound), 0) << "bound " << bound;
  EXPECT_LT(smallest(1.001 * bound), 0) << "bound " << bound;
  ContactLoad c = load(FrictionLaw::coulomb);
  c.mu = 0.9 * bound;
  const ContactResult r = ContactSolver(*f.condensed, c).solve(FrictionMode::coupled);
  EXPECT_NEAR(r.force_N, 0.8, 1e-9);
  EXPECT_NEAR(r.tangential_force_N, c.mu * 0.8, 1e-9 * c.mu);
  std::printf("coupled ratio bound %.4g; solved at mu = %.4g, complementarity %.2e\n", bound, c.mu,
              r.complementarity);
}

}  // namespace
}  // namespace skinfem::contact
