// Contact of a plate with the finite-strain skin (contact/finite_contact.hpp) against: the linear contact
// (contact/condensed.hpp and lcp.hpp, an independent small-strain path; contact_solver.hpp under a shear
// strength) as the force vanishes, the global balance of forces, complementarity, and Newton's quadratic
// convergence once the contact set settles.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <iterator>
#include <memory>
#include <string>

#include "../common/newton_rate.hpp"
#include "../common/plate_on_cap.hpp"
#include "skinfem/contact/condensed.hpp"
#include "skinfem/contact/contact_solver.hpp"
#include "skinfem/contact/finite_contact.hpp"
#include "skinfem/contact/lcp.hpp"
#include "skinfem/fem/sensor_reading.hpp"
#include "skinfem/fem/supports.hpp"
#include "skinfem/mesh/build.hpp"

namespace skinfem::contact {
namespace {

// The shared cap, within 4 mm of its apex (the library has no side check), its zone 1.5 mm: at 0.3 N the
// contact radius is about 1.2 mm.
Scene plate_on_cap() { return testing::plate_on_cap(4.0, 1.5); }

struct Cap {
  Scene scene = plate_on_cap();
  TetMesh mesh;
  Supports held;
  std::unique_ptr<Indenter> indenter;
  std::unique_ptr<MortarZone> zone;
  std::unique_ptr<ElasticModel> linear;
  std::unique_ptr<CondensedContact> condensed;  // the linear skin's
  double mu_shear = 1.0;                        // E / 3
};

Cap& cap() {
  static Cap* c = [] {
    auto* x = new Cap;
    x->mesh = build_mesh(x->scene);
    x->held = skin_supports(x->mesh, x->scene.geometry.side, {});
    x->indenter = std::make_unique<Indenter>(x->scene, x->mesh);
    x->zone = std::make_unique<MortarZone>(mortar_zone(x->mesh, {0, 0}, x->scene.contact->zone_radius));
    x->linear = std::make_unique<ElasticModel>(x->mesh, x->scene.material, x->scene.geometry.side,
                                               std::vector<Punch>{});
    x->condensed = std::make_unique<CondensedContact>(
        condense(*x->linear, *x->zone, *x->indenter,
                 SensorReadings(x->mesh, reading_sites(x->scene.sensors), &x->linear->solver()), {1, 0}));
    return x;
  }();
  return *c;
}

FiniteContactResult finite(double force, double ratio) {
  Cap& c = cap();
  return solve_finite_contact(c.mesh, c.mu_shear, c.held.fixed, *c.zone, *c.indenter,
                              {force, ratio, {1, 0}, {}, {}, 0});
}

LcpSolution linear(double force, double ratio) {
  const CondensedContact& k = *cap().condensed;
  return ContactLcp(k.C_zz + ratio * k.C_zt, k.gap0, k.zone.area).solve_force(force);
}

double rel_norm(const Eigen::VectorXd& a, const Eigen::VectorXd& b) { return (a - b).norm() / b.norm(); }

// The small forces at which the finite contact is compared with the linear one.
constexpr double kSmallForces[] = {4e-4, 2e-4, 1e-4, 5e-5};

// gap: the finite and linear displacements' relative gap at each of kSmallForces, which must halve with the
// force (local order 1 ± 0.1) far above the Newton floor (~1e-9 of u), so that the ratios are the physics'.
void expect_first_order_in_the_force(const std::vector<double>& gap) {
  ASSERT_EQ(gap.size(), std::size(kSmallForces));
  EXPECT_GT(gap.back(), 1e-7);
  for (size_t k = 1; k < gap.size(); ++k)
    EXPECT_NEAR(std::log2(gap[k - 1] / gap[k]), 1.0, 0.1)
        << "forces " << kSmallForces[k - 1] << ", " << kSmallForces[k];
}

TEST(FiniteContact, SmallForcesTendToTheLinearContactAtFirstOrder) {
  // At forces this small the plate touches the same few vertices in both laws (asserted), so the problem is
  // smooth in F and the finite solution is the linear one plus O(F²): the relative gap between the two
  // displacement fields halves with the force. (With the contact set free to grow the gap would scale as the
  // strain a/R ∝ F^(1/3), but on a fixed mesh that regime is masked by the set's jumps, vertex by vertex.)
  // Sliding (ratio 0.5) so that the coupled friction's first-order consistency is checked too.
  Cap& c = cap();
  const double ratio = 0.5;
  std::vector<double> gap;
  for (double F : kSmallForces) {
    const FiniteContactResult f = finite(F, ratio);
    const LcpSolution l = linear(F, ratio);
    ASSERT_EQ(f.active, l.active) << "F " << F;
    const Eigen::VectorXd u_lin = c.linear->solve(c.zone->load(l.lambda, {1, 0}, ratio), {}).solution.u;
    gap.push_back(rel_norm(f.solution.u, u_lin));
  }
  expect_first_order_in_the_force(gap);
}

// The paper's friction (μ = 3) at 0.3 N on the small cap: the contact reaches about 1.2 mm, a/R = 6 %.
const FiniteContactResult& sliding() {
  static const FiniteContactResult r = finite(0.3, 3.0);
  return r;
}

// Its frictionless start at the same force, where the static, sliding and shear-strength paths resume.
const FiniteContactResult& resting() {
  static const FiniteContactResult r = finite(0.3, 0.0);
  return r;
}

TEST(FiniteContact, TheSkinCarriesThePlatesForceAndTheContactIsComplementary) {
  Cap& c = cap();
  const FiniteContactResult& r = sliding();
  const double F = 0.3, ratio = 3.0;
  EXPECT_NEAR(r.lambda.dot(c.zone->area), F, 1e-12 * F);
  // Global balance: the internal force sums to zero over all nodes (its test functions sum to one), so at
  // equilibrium the base takes back the plate's whole force, friction included.
  Eigen::Vector3d base = Eigen::Vector3d::Zero();
  for (int i = 0; i < c.mesh.num_nodes(); ++i)
    if (c.held.fixed[3 * i + 2]) base += r.internal_force.segment<3>(3 * i);
  EXPECT_NEAR(base.x(), -ratio * F, 1e-8 * F);
  EXPECT_NEAR(base.y(), 0.0, 1e-8 * F);
  EXPECT_NEAR(base.z(), F, 1e-8 * F);
  EXPECT_GE(r.lambda.minCoeff(), 0.0);
  const double gap_scale = r.gap.cwiseAbs().maxCoeff();
  EXPECT_GE(r.gap.minCoeff(), -1e-10 * gap_scale);
  EXPECT_LT(r.lambda.cwiseProduct(r.gap).cwiseAbs().maxCoeff(), 1e-10 * r.lambda.maxCoeff() * gap_scale);
}

// A static and a sliding case share their path's first part, the frictionless contact at the full force:
// resumed from it, the ratio's part is the whole path's, to the last bit (the same steps on the same states).
TEST(FiniteContact, ThePathResumedFromTheFrictionlessStateIsTheWholePath) {
  Cap& c = cap();
  const FiniteContactResult &rest = resting(), &whole = sliding();
  const FiniteContactResult resumed = solve_finite_contact(
      c.mesh, c.mu_shear, c.held.fixed, *c.zone, *c.indenter, {0.3, 3.0, {1, 0}, {}, {}, 0}, {}, {}, &rest);
  EXPECT_EQ(resumed.solution.u, whole.solution.u);
  EXPECT_EQ(resumed.lambda, whole.lambda);
  EXPECT_EQ(resumed.depth_mm, whole.depth_mm);
  EXPECT_EQ(resumed.steps.size() + rest.steps.size(), whole.steps.size());
  EXPECT_EQ(resumed.factorizations + rest.factorizations, whole.factorizations);
  // Friction does not go back along the path.
  EXPECT_THROW(solve_finite_contact(c.mesh, c.mu_shear, c.held.fixed, *c.zone, *c.indenter,
                                    {0.3, 1.0, {1, 0}, {}, {}, 0}, {}, {}, &whole),
               std::invalid_argument);
}

// The zone's moment radius √(5/2 ⟨r²⟩_p) is a for a Hertzian pressure p0 √(1 − r²/a²) (∫p r² dA / ∫p dA =
// 2a²/5), and the moment anisotropy 1 for any axisymmetric one; sampled at the hats, the sums are a
// quadrature of error O((h/a)²) (h = 0.5 mm inside the zone, a = 1.2 mm: 0.17 times a constant well below
// 1/3, so within 5 %).
TEST(FiniteContact, TheZonesMomentsGiveAHertzianContactsRadius) {
  Cap& c = cap();
  const double a = 1.2;
  Eigen::VectorXd p = Eigen::VectorXd::Zero(c.zone->size());
  std::vector<int> active;
  for (int i = 0; i < c.zone->size(); ++i) {
    const double r = c.mesh.nodes.row(c.zone->vertices[i]).head<2>().norm();
    if (r < a) p[i] = std::sqrt(1 - r * r / (a * a)), active.push_back(i);
  }
  const ContactZoneFrame z = zone_frame(c.mesh, *c.zone, active, p, nullptr, {0, 0}, {1, 0});
  std::printf("moment radius %.4f mm for a = %.4f mm, anisotropy %.4f\n", z.moment_radius_mm, a,
              z.moment_anisotropy);
  EXPECT_NEAR(z.moment_radius_mm, a, 0.05 * a);
  EXPECT_NEAR(z.moment_anisotropy, 1.0, 0.1);
}

TEST(FiniteContact, NewtonConvergesQuadraticallyOnceTheContactSetSettles) {
  // Josephy–Newton: with the set fixed it is Newton on a smooth system, so near the solution each residual is
  // about the square of the last: log r_{k+1} / log r_k ≥ 1.8 (a constant C in r_{k+1} = C r_k² of up to
  // r_k^-0.2 allowed), over pairs of iterates both made with the settled set (no multiplier entered or left)
  // and r_{k+1} above round-off.
  EXPECT_GE(testing::check_newton_rate(sliding().steps, 1.8), 2);
}

// The skin's answer to a small change of the gaps, two ways: the tangent's condensed problem
// (tangent_contact) and the full finite-strain solve.
struct Tangent {
  SensorReadings readings;
  CondensedContact condensed;
};
const Tangent& tangent() {
  static const Tangent* t = [] {
    Cap& c = cap();
    SensorReadings readings(c.mesh, reading_sites(c.scene.sensors));
    CondensedContact k = tangent_contact(c.mesh, c.mu_shear, c.held.fixed, *c.zone, *c.indenter, readings,
                                         {0.3, 3.0, {1, 0}, {}, {}, 0}, sliding());
    return new Tangent{std::move(readings), std::move(k)};
  }();
  return *t;
}

TEST(FiniteContact, TheTangentContactHasTheFiniteSolutionAsItsOwn) {
  // tangent_contact's gaps are the finite contact's to first order about its state, so the complementarity
  // problem on them is solved by the finite contact's own multipliers and approach (up to the LCP's pivoting
  // round-off on the tangent's compliances).
  const FiniteContactResult& r = sliding();
  const CondensedContact& k = tangent().condensed;
  const LcpSolution l = ContactLcp(k.C_zz + 3.0 * k.C_zt, k.gap0, k.zone.area).solve_force(0.3);
  EXPECT_EQ(l.active, r.active);
  EXPECT_LT(rel_norm(l.lambda, r.lambda), 1e-8);
  EXPECT_NEAR(l.delta, r.depth_mm, 1e-8 * r.depth_mm);
}

// Weighted gaps opened by a smooth dent of depth `depth` mm and radius 0.4 mm in the plate at (0.3, 0),
// inside the contact (it reaches about 1.2 mm): ∫ψ_i of the dent's depth, lumped at each vertex.
Eigen::VectorXd dent(double depth) {
  const Cap& c = cap();
  Eigen::VectorXd o(c.zone->size());
  for (int i = 0; i < c.zone->size(); ++i) {
    const int v = c.zone->vertices[i];
    const double r2 = std::pow(c.mesh.nodes(v, 0) - 0.3, 2) + std::pow(c.mesh.nodes(v, 1), 2);
    o[i] = depth * c.zone->area[i] * std::max(0.0, 1 - r2 / 0.16);
  }
  return o;
}

TEST(FiniteContact, ADentsSignalIsTheTangentsAnswerToFirstOrder) {
  // A dent of depth s in the plate opens the gaps by s·o. The finite solve's change in the readings and the
  // multipliers, divided by s, tends to the tangent problem's (the derivative about the sliding state) with
  // an error O(s): halving s halves it, local order 1 ± 0.2 over three depths (1, 0.5 and 0.25 µm, a few % of
  // the pressure under the dent, so no multiplier enters or leaves the set: asserted).
  // Measured: 5.3e-2, 2.7e-2, 1.3e-2 (the multipliers; the readings 4.4e-2, 2.2e-2, 1.1e-2), orders 0.98 and
  // 0.99. This is what the linearized hole signal about the deformed state rests on (issue 54, item 4).
  Cap& c = cap();
  const FiniteContactResult& r = sliding();
  const Tangent& t = tangent();
  const CondensedContact& k = t.condensed;
  const auto read = [&](const FiniteContactResult& f) {
    const Eigen::VectorXd reactions = support_reactions(c.held, f.internal_force - f.load);
    Eigen::VectorXd v(2 * t.readings.size());
    for (int s = 0; s < t.readings.size(); ++s) {
      const SensorReading x = t.readings.read(s, reactions);
      v[2 * s] = x.sigma_z, v[2 * s + 1] = x.sigma_x;
    }
    return v;
  };
  const Eigen::VectorXd base = read(r);
  std::vector<double> err;
  for (double s : {1e-3, 5e-4, 2.5e-4}) {
    FiniteContactLoad load{0.3, 3.0, {1, 0}, dent(s), {}, 0};
    const FiniteContactResult f =
        solve_finite_contact(c.mesh, c.mu_shear, c.held.fixed, *c.zone, *c.indenter, load, {}, {}, &r);
    const LcpSolution l =
        ContactLcp(k.C_zz + 3.0 * k.C_zt, k.gap0 + load.opening, k.zone.area).solve_force(0.3);
    ASSERT_EQ(f.active, r.active) << "depth " << s;
    ASSERT_EQ(l.active, r.active) << "depth " << s;
    const Eigen::VectorXd tangent_signal = (k.S_p + 3.0 * k.S_t) * (l.lambda - r.lambda);
    const Eigen::VectorXd finite_signal = read(f) - base;
    ASSERT_GT(tangent_signal.norm(), 0.0);
    err.push_back(std::max(rel_norm(finite_signal, tangent_signal),
                           rel_norm(f.lambda - r.lambda, l.lambda - r.lambda)));
  }
  EXPECT_LT(err.back(), 0.05);  // the derivative is the tangent's: the first-order term dominates
  for (size_t i = 1; i < err.size(); ++i) EXPECT_NEAR(std::log2(err[i - 1] / err[i]), 1.0, 0.2) << err[i];
}

TEST(FiniteContact, ALoadNewtonCannotCarryIsAOneLineErrorNamingWhereItStopped) {
  // Two iterations per step and no halving: the first step (the force, from rest) needs three, so the solve
  // stops at the start of its path and says so and why, instead of returning an unconverged state.
  Cap& c = cap();
  NewtonOptions o;
  o.max_iterations = 2;
  o.max_halvings = 0;
  try {
    solve_finite_contact(c.mesh, c.mu_shear, c.held.fixed, *c.zone, *c.indenter,
                         {0.3, 3.0, {1, 0}, {}, {}, 0}, o);
    FAIL() << "no error";
  } catch (const SolverError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.find('\n'), std::string::npos);
    EXPECT_NE(what.find("Newton failed beyond 0 N and friction ratio 0"), std::string::npos) << what;
    EXPECT_NE(what.find("the last: no convergence in 2 iterations"), std::string::npos) << what;
  }
}

// A shear strength τ = tau_mu·F/A wherever the skin touches (A: the frictionless contact's area), sliding.
FiniteContactResult shearing(double force, double tau_mu, const FiniteContactResult* from = nullptr) {
  Cap& c = cap();
  FiniteContactLoad load{force, 0.0, {1, 0}, {}, {}, tau_mu};
  return solve_finite_contact(c.mesh, c.mu_shear, c.held.fixed, *c.zone, *c.indenter, load, {}, {}, from);
}

// The linear skin's sliding contact under the same law (ContactSolver's touched-set iteration).
ContactResult linear_shear(double force, double tau_mu) {
  ContactLoad load;
  load.force = force;
  load.mu = tau_mu;
  load.law = FrictionLaw::shear_strength;
  return ContactSolver(*cap().condensed, load).solve(FrictionMode::coupled);
}

TEST(FiniteContact, AShearStrengthsSmallForcesTendToTheLinearContactAtFirstOrder) {
  // As SmallForcesTendToTheLinearContactAtFirstOrder, under a shear strength τ = 0.5 F/A in place of
  // Coulomb's 0.5 p: the same few vertices touch in both laws (asserted), so τ is the same (the same A) and
  // the finite solution is the linear one plus O(F²): the relative gap between the displacements halves with
  // the force.
  Cap& c = cap();
  const double tau_mu = 0.5;
  std::vector<double> gap;
  for (double F : kSmallForces) {
    const FiniteContactResult f = shearing(F, tau_mu);
    const ContactResult l = linear_shear(F, tau_mu);
    ASSERT_EQ(f.active, l.active) << "F " << F;
    EXPECT_NEAR(f.tau, l.tau, 1e-12 * l.tau) << "F " << F;
    const Eigen::VectorXd u_lin =
        c.linear->solve(c.zone->load(l.lambda, {1, 0}, 0.0, l.shear), {}).solution.u;
    gap.push_back(rel_norm(f.solution.u, u_lin));
  }
  expect_first_order_in_the_force(gap);
}

// The paper's sliding force (3F) as a shear strength at 0.3 N on the small cap, its path resumed from the
// frictionless state of `sliding()`'s.
const FiniteContactResult& sheared() {
  static const FiniteContactResult r = shearing(0.3, 3.0, &resting());
  return r;
}

TEST(FiniteContact, AShearStrengthActsOnTheTouchedZoneAndTheSkinCarriesIt) {
  // τ = 3F/A with A the frictionless contact's area at F; the shear acts on the hats that touch (an edge hat
  // that lifts under its own shear holds a fraction), so the base's tangential reaction is −Σ area·shear, and
  // the skin carries the plate's normal force. Newton stays quadratic with the touched set iterated inside
  // each iterate.
  Cap& c = cap();
  const FiniteContactResult& r = sheared();
  const double F = 0.3;
  EXPECT_NEAR(r.tau, 3.0 * F / r.frictionless_area_mm2, 1e-12 * r.tau);
  EXPECT_NEAR(r.lambda.dot(c.zone->area), F, 1e-12 * F);
  Eigen::Vector3d base = Eigen::Vector3d::Zero();
  for (int i = 0; i < c.mesh.num_nodes(); ++i)
    if (c.held.fixed[3 * i + 2]) base += r.internal_force.segment<3>(3 * i);
  const double tangential = c.zone->area.dot(r.shear);
  int full = 0;
  for (int i = 0; i < c.zone->size(); ++i) {
    const bool touches = std::binary_search(r.active.begin(), r.active.end(), i);
    if (!touches) {
      EXPECT_EQ(r.shear[i], 0.0) << "multiplier " << i;
    }
    if (touches && r.shear[i] == r.tau) ++full;
  }
  EXPECT_EQ(full + r.partial_shear, static_cast<int>(r.active.size()));
  EXPECT_NEAR(base.x(), -tangential, 1e-8 * F);
  EXPECT_NEAR(base.z(), F, 1e-8 * F);
  // The sliding force is about 3F (A changes little as the shear tilts the contact).
  EXPECT_NEAR(tangential, 3.0 * F, 0.1 * 3.0 * F);
  EXPECT_GE(r.lambda.minCoeff(), 0.0);
  EXPECT_GE(r.gap.minCoeff(), -1e-10 * r.gap.cwiseAbs().maxCoeff());
  EXPECT_GE(testing::check_newton_rate(r.steps, 1.8), 1);
}

TEST(FiniteContact, UnderAShearStrengthTheTangentContactHasTheFiniteSolutionAsItsOwn) {
  // tangent_contact's gaps hold the finite state's shear too: the linear coupled contact on them, with the
  // finite τ, finds the finite multipliers, set and shear.
  Cap& c = cap();
  const FiniteContactResult& r = sheared();
  SensorReadings readings(c.mesh, reading_sites(c.scene.sensors));
  const CondensedContact k = tangent_contact(c.mesh, c.mu_shear, c.held.fixed, *c.zone, *c.indenter, readings,
                                             {0.3, 0.0, {1, 0}, {}, {}, 3.0}, r);
  ContactLoad load;
  load.force = 0.3;
  load.law = FrictionLaw::shear_strength;
  load.tau0 = r.tau;
  const ContactResult l = ContactSolver(k, load).solve(FrictionMode::coupled);
  EXPECT_EQ(l.active, r.active);
  EXPECT_LT(rel_norm(l.lambda, r.lambda), 1e-8);
  EXPECT_LT(rel_norm(l.shear, r.shear), 1e-8);
  EXPECT_NEAR(l.depth_mm, r.depth_mm, 1e-8 * r.depth_mm);
}

}  // namespace
}  // namespace skinfem::contact
