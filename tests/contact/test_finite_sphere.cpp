// A rigid sphere on the finite-strain skin (contact/finite_contact.hpp: normal gaps on the displaced top,
// pressures along the sphere's turning normal) against: the small-strain contact of the same sphere on the
// linear skin (fem/elastic_model.hpp, contact/lcp.hpp) as the force vanishes, the global balance of forces
// under a follower load, complementarity, and Newton's quadratic convergence.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "../common/newton_rate.hpp"
#include "../common/plate_on_cap.hpp"
#include "skinfem/contact/contact_solver.hpp"
#include "skinfem/contact/finite_contact.hpp"
#include "skinfem/contact/lcp.hpp"
#include "skinfem/fem/elastic_model.hpp"
#include "skinfem/fem/supports.hpp"
#include "skinfem/mesh/build.hpp"

namespace skinfem::contact {
namespace {

// A sphere R = 20 mm on a flat layer 3 mm thick (E = 3 MPa, ν = 0.5), 8 mm wide, its zone 1.5 mm: at 0.3 N
// the contact reaches about 1.2 mm, a/R = 6 %, so the normals turn by up to 3.5°.
struct Layer {
  Scene scene;
  TetMesh mesh;
  Supports held;
  std::unique_ptr<Indenter> indenter;
  std::unique_ptr<MortarZone> zone;
  std::unique_ptr<ElasticModel> linear;
  double mu_shear = 1.0;  // E / 3
};

Layer& layer() {
  static Layer* l = [] {
    auto* x = new Layer;
    // The plate-on-cap test scene's mesh, load and zone (tests/common), the cap a flat layer, the plate a
    // sphere.
    Scene& s = x->scene;
    s = testing::plate_on_cap(4.0, 1.5);
    s.name = "sphere_on_layer";
    s.source_path = "sphere_on_layer.json";
    s.geometry.kind = GeometryKind::flat;
    s.geometry.flat = {3.0, 4.0};
    s.contact->indenter = IndenterKind::sphere;
    s.contact->sphere_R = 20.0;
    const ContactLoad& c = *s.contact;
    x->mesh = build_mesh(s);
    x->held = skin_supports(x->mesh, s.geometry.side, {});
    x->indenter = std::make_unique<Indenter>(s, x->mesh);
    x->zone = std::make_unique<MortarZone>(mortar_zone(x->mesh, {0, 0}, c.zone_radius));
    x->linear = std::make_unique<ElasticModel>(x->mesh, s.material, s.geometry.side, std::vector<Punch>{});
    return x;
  }();
  return *l;
}

FiniteContactResult finite(double force, double ratio = 0, double tau_mu = 0) {
  Layer& l = layer();
  return solve_finite_contact(l.mesh, l.mu_shear, l.held.fixed, *l.zone, *l.indenter,
                              {force, ratio, {1, 0}, {}, {}, tau_mu});
}

double rel_norm(const Eigen::VectorXd& a, const Eigen::VectorXd& b) { return (a - b).norm() / b.norm(); }

// The base's reaction and the sphere's load on the skin, each summed over the nodes, N.
struct Totals {
  Eigen::Vector3d base = Eigen::Vector3d::Zero(), load = Eigen::Vector3d::Zero();
};
Totals totals(const FiniteContactResult& r) {
  Layer& l = layer();
  Totals t;
  for (int i = 0; i < l.mesh.num_nodes(); ++i) {
    if (l.held.fixed[3 * i + 2]) t.base += r.internal_force.segment<3>(3 * i);
    t.load += r.load.segment<3>(3 * i);
  }
  return t;
}

// The small-strain contact of the same sphere, built on the linear skin from the geometry at rest: normal
// gaps g⁰ and their derivatives Dn⁰, Dt⁰ (MortarZone::sphere_gaps at u = 0, the sphere at first touch), the
// skin's answers Un = K⁻¹ Dn⁰ᵀ, Ut = K⁻¹ Dt⁰ᵀ by linear solves, compliances C_zz = Dn⁰ Un, C_zt = Dn⁰ Ut.
struct SmallStrainSphere {
  MortarZone::SphereGaps rest;
  Eigen::MatrixXd Un, Ut, C_zz, C_zt;
};
const SmallStrainSphere& small_strain() {
  static const SmallStrainSphere* s = [] {
    Layer& l = layer();
    const MortarZone& z = *l.zone;
    const int n3 = 3 * l.mesh.num_nodes();
    const Eigen::Vector3d c0(0, 0, l.indenter->z_touch() + l.indenter->R());
    const Eigen::Vector2d t(1, 0);
    auto* x = new SmallStrainSphere;
    x->rest = z.sphere_gaps(l.mesh, Eigen::VectorXd::Zero(n3), c0, l.indenter->R(), nullptr, &t);
    x->Un.resize(n3, z.size());
    x->Ut.resize(n3, z.size());
    for (int j = 0; j < z.size(); ++j) {
      x->Un.col(j) = l.linear->solve(Eigen::VectorXd(x->rest.Dn.row(j).transpose()), {}).solution.u;
      x->Ut.col(j) = l.linear->solve(Eigen::VectorXd(x->rest.Dt.row(j).transpose()), {}).solution.u;
    }
    x->C_zz = x->rest.Dn * x->Un;
    x->C_zz = 0.5 * (x->C_zz + x->C_zz.transpose()).eval();
    x->C_zt = x->rest.Dn * x->Ut;
    return x;
  }();
  return *s;
}

// Against the small-strain contact above, sliding under ratio·p and a shear strength τ = tau_mu F/A (the
// finite solve's τ, given: it is the same wherever both touch the same hats): u = Un λ + Ut (ratio λ +
// shear), the force the whole downward load (m⁰ + ratio mt⁰)ᵀ λ + mt⁰ᵀ shear (a fixed point on λ; the shear's
// touched set by contact_solver.hpp with the sphere's m⁰ for the areas). (The linear contact of
// contact/condensed.hpp pushes vertically and drags horizontally: it differs from both by the normals' tilt
// over the touched hats, a relative 3e-3 at every force here.) At forces this small the sphere touches the
// same vertices in both (asserted), so the problem is smooth in F and the finite solution is the
// small-strain one plus O(F²): the relative gap between the two displacement fields halves with the force.
void expect_first_order_in_the_force(double ratio, double tau_mu = 0) {
  const SmallStrainSphere& ss = small_strain();
  const MortarZone::SphereGaps& rest = ss.rest;
  // The same problem as a condensed contact (the sphere's m for the hats' areas) and as an LCP.
  CondensedContact c;
  c.zone = *layer().zone;
  c.zone.area = rest.m;
  c.C_zz = ss.C_zz;
  c.C_zt = ss.C_zt;
  c.gap0 = rest.g;
  c.S_p = c.S_t = Eigen::MatrixXd::Zero(0, rest.g.size());
  const ContactLcp lcp(ss.C_zz + ratio * ss.C_zt, rest.g, rest.m);
  const double forces[] = {4e-4, 2e-4, 1e-4, 5e-5};
  std::vector<double> gap;
  for (double F : forces) {
    const FiniteContactResult f = finite(F, ratio, tau_mu);
    Eigen::VectorXd lambda, shear = Eigen::VectorXd::Zero(rest.g.size());
    std::vector<int> active;
    double down = 0;  // the drag's downward part at the last λ and shear
    for (int k = 0; k < 20; ++k) {
      if (tau_mu > 0) {
        ContactLoad load;
        load.force = F - down;
        load.mu = ratio;
        load.law = ratio > 0 ? FrictionLaw::mixed : FrictionLaw::shear_strength;
        load.tau0 = f.tau;
        const ContactResult r = ContactSolver(c, load).solve(FrictionMode::coupled);
        lambda = r.lambda, shear = r.shear, active = r.active;
      } else {
        const LcpSolution r = lcp.solve_force(F - down);
        lambda = r.lambda, active = r.active;
      }
      down = rest.mt.dot(ratio * lambda + shear);
    }
    ASSERT_NEAR(rest.m.dot(lambda) + down, F, 1e-14);
    ASSERT_EQ(f.active, active) << "F " << F;
    gap.push_back(rel_norm(f.solution.u, ss.Un * lambda + ss.Ut * (ratio * lambda + shear)));
    std::printf("ratio %g, tau %.3g kPa, F %.1e N: %zu multipliers in contact, relative gap %.3e\n", ratio,
                1e3 * f.tau, F, f.active.size(), gap.back());
  }
  EXPECT_GT(gap.back(), 1e-7);  // far above the Newton floor (~1e-9 of u): the ratios below are the physics'
  for (size_t i = 1; i < gap.size(); ++i)
    EXPECT_NEAR(std::log2(gap[i - 1] / gap[i]), 1.0, 0.1) << "forces " << forces[i - 1] << ", " << forces[i];
}

TEST(FiniteSphere, SmallForcesTendToTheSmallStrainContactAtFirstOrder) { expect_first_order_in_the_force(0); }

TEST(FiniteSphere, SlidingSmallForcesTendToTheSmallStrainSlidingContactAtFirstOrder) {
  expect_first_order_in_the_force(1.0);
  expect_first_order_in_the_force(0.0, 1.0);  // a shear strength τ = F/A
}

const FiniteContactResult& pressed() {
  static const FiniteContactResult r = finite(0.3);
  return r;
}

TEST(FiniteSphere, TheBaseTakesBackTheTurningPressuresAndTheContactIsComplementary) {
  // The pressures push along the sphere's normals at the displaced surface, so their load has a horizontal
  // part where the surface tilts. Equilibrium: the base takes back the whole load (the internal force's test
  // functions sum to one), horizontal part included; its vertical part is the force, Σ λ_i m_i = F.
  Layer& l = layer();
  const FiniteContactResult& r = pressed();
  const double F = 0.3;
  const auto [base, load] = totals(r);
  double horizontal_abs = 0;  // Σ |load_x| over the nodes
  for (int i = 0; i < l.mesh.num_nodes(); ++i) horizontal_abs += std::abs(r.load[3 * i]);
  // Σ λ_i m_i = F holds at the last iterate's normals; the load is the final state's, which moved by the
  // last Newton step: equal to the residual tolerance (1e-10).
  EXPECT_NEAR(load.z(), -F, 1e-9 * F);
  EXPECT_GT(horizontal_abs, 1e-3 * F);  // the normals do turn
  EXPECT_LT((base + load).norm(), 1e-8 * F);
  EXPECT_GE(r.lambda.minCoeff(), 0.0);
  const double gap_scale = r.gap.cwiseAbs().maxCoeff();
  EXPECT_GE(r.gap.minCoeff(), -1e-10 * gap_scale);
  EXPECT_LT(r.lambda.cwiseProduct(r.gap).cwiseAbs().maxCoeff(), 1e-10 * r.lambda.maxCoeff() * gap_scale);
}

// A sliding sphere's Newton on the settled set: each iterate of a sliding step divides the residual by at
// least 1/rate (pairs above round-off); returns how many pairs it checked.
int expect_linear_newton(const std::vector<FiniteContactStep>& steps, double rate) {
  int pairs = 0;
  for (const FiniteContactStep& step : steps)
    for (size_t k = 1; k < step.residuals.size(); ++k)
      if ((step.ratio > 0 || step.tau > 0) && step.set_changes[k - 1] == 0 && step.set_changes[k] == 0 &&
          step.residuals[k] > 1e-13) {
        EXPECT_LT(step.residuals[k], rate * step.residuals[k - 1]) << "iteration " << k;
        ++pairs;
      }
  return pairs;
}

TEST(FiniteSphere, SlidingItsFrictionFollowsTheSurfaceAndTheBaseTakesBackTheWholeLoad) {
  // Coulomb friction in steady sliding along x, ratio 1: the traction ratio·p acts along the sphere's
  // tangent s ∝ t − (t·n) n at the displaced point, so it turns with the surface as the pressure does.
  // Equilibrium: the base takes back the whole load; the force is the sphere's whole downward load, the
  // friction's part included. Tangency: per multiplier ∫ψ_i s and ∫ψ_i n are orthogonal up to the normal's
  // turn across the hat, |cos| ≤ h/R (h = 0.35 mm, the zone's size). Newton: the tangent has the pressures'
  // turning but not the friction direction's (its derivative is not symmetric, and the tangent is factored
  // LDLᵀ), so Newton is linear on the settled set, each iterate dividing the residual by the omitted term's
  // size against the skin's stiffness, ratio·p_max h_layer / (μ R) = 0.022 here; asserted ≤ 0.1.
  Layer& l = layer();
  const double F = 0.3, ratio = 1.0;
  const FiniteContactResult r = finite(F, ratio);
  const auto [base, load] = totals(r);
  EXPECT_NEAR(load.z(), -F, 1e-9 * F);
  EXPECT_GT(load.x(), 0.9 * ratio * F);  // the drag along t, nearly horizontal under a wide sphere
  EXPECT_LT((base + load).norm(), 1e-8 * load.norm());
  EXPECT_GE(r.lambda.minCoeff(), 0.0);
  const double gap_scale = r.gap.cwiseAbs().maxCoeff();
  EXPECT_GE(r.gap.minCoeff(), -1e-10 * gap_scale);
  EXPECT_LT(r.lambda.cwiseProduct(r.gap).cwiseAbs().maxCoeff(), 1e-10 * r.lambda.maxCoeff() * gap_scale);

  const Eigen::Vector2d t(1, 0);
  const Eigen::Vector3d c(0, 0, l.indenter->z_touch() + l.indenter->R() - r.depth_mm);
  const MortarZone::SphereGaps at =
      l.zone->sphere_gaps(l.mesh, r.solution.u, c, l.indenter->R(), nullptr, &t);
  const double h_over_R = 0.35 / l.indenter->R();
  Eigen::MatrixXd normal(l.zone->size(), 3), tangent(l.zone->size(), 3);  // rows ∫ψ_i n, ∫ψ_i s
  for (int k = 0; k < 3; ++k) {
    Eigen::VectorXd e = Eigen::VectorXd::Zero(at.Dn.cols());
    for (int j = k; j < e.size(); j += 3) e[j] = 1;  // the φ sum to one
    normal.col(k) = at.Dn * e;
    tangent.col(k) = at.Dt * e;
  }
  for (int i : r.active)
    EXPECT_LT(std::abs(normal.row(i).dot(tangent.row(i))),
              h_over_R * normal.row(i).norm() * tangent.row(i).norm())
        << "multiplier " << i;

  const double contraction = ratio * r.lambda.maxCoeff() * 3.0 / (l.mu_shear * l.indenter->R());
  std::printf("omitted term / stiffness %.3f\n", contraction);
  EXPECT_GE(expect_linear_newton(r.steps, 0.1), 2);
}

TEST(FiniteSphere, UnderAShearStrengthTheDragActsOnTheTouchedHatsAlongTheSurface) {
  // τ = 3F/A (the paper's μ = 3 as a shear strength) at 0.3 N: the shear acts on the hats that touch, each
  // carrying τ or, at the edge, the fraction at which it just touches (contact_solver.hpp), none elsewhere;
  // along the sphere's tangent, so the base takes back the whole load and its vertical part is the force.
  Layer& l = layer();
  const double F = 0.3;
  const FiniteContactResult r = finite(F, 0.0, 3.0);
  EXPECT_NEAR(r.tau, 3.0 * F / r.frictionless_area_mm2, 1e-12 * r.tau);
  for (int i = 0; i < l.zone->size(); ++i) {
    if (!std::binary_search(r.active.begin(), r.active.end(), i))
      EXPECT_EQ(r.shear[i], 0.0) << "multiplier " << i;
    else
      EXPECT_TRUE(r.shear[i] > 0 && r.shear[i] <= r.tau * (1 + 1e-12)) << "multiplier " << i;
  }
  const auto [base, load] = totals(r);
  const double drag = l.zone->area.dot(r.shear), slope = l.scene.contact->zone_radius / l.indenter->R();
  std::printf("tau %.4g kPa, %d partial of %zu; drag %.5f N against area·tau %.5f N\n", 1e3 * r.tau,
              r.partial_shear, r.active.size(), load.x(), drag);
  EXPECT_NEAR(load.z(), -F, 1e-9 * F);
  EXPECT_LT((base + load).norm(), 1e-8 * load.norm());
  // Horizontal: the drag Σ area·τ_i, tilted by at most the slope at the zone's edge, plus the pressures'
  // horizontal parts, at most F times that slope.
  EXPECT_NEAR(load.x(), drag, (F + drag) * slope);
  // The omitted drag turning against the stiffness: τ h_layer / (μ R) = 0.046 here.
  EXPECT_GE(expect_linear_newton(r.steps, 0.1), 1);
}

TEST(FiniteSphere, NewtonConvergesQuadraticallyOnceTheContactSetSettles) {
  // With the pressures' turning in the tangent, Newton on the settled set is quadratic: log r_{k+1} / log r_k
  // ≥ 1.8 over pairs of iterates both made with the settled set and r_{k+1} above round-off (as under a
  // plane, test_finite_contact.cpp). Without the turning term it was 1.39 here.
  EXPECT_GE(testing::check_newton_rate(pressed().steps, 1.8), 1);
}

}  // namespace
}  // namespace skinfem::contact
