// A rigid sphere on the finite-strain skin (contact/finite_contact.hpp: normal gaps on the displaced top,
// pressures along the sphere's turning normal) against: the small-strain contact of the same sphere on the
// linear skin (fem/elastic_model.hpp, contact/lcp.hpp) as the force vanishes, the global balance of forces
// under a follower load, complementarity, and Newton's quadratic convergence.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "../common/newton_rate.hpp"
#include "../common/plate_on_cap.hpp"
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

FiniteContactResult finite(double force) {
  Layer& l = layer();
  return solve_finite_contact(l.mesh, l.mu_shear, l.held.fixed, *l.zone, *l.indenter,
                              {force, 0, {1, 0}, {}, {}, 0});
}

double rel_norm(const Eigen::VectorXd& a, const Eigen::VectorXd& b) { return (a - b).norm() / b.norm(); }

TEST(FiniteSphere, SmallForcesTendToTheSmallStrainContactAtFirstOrder) {
  // The small-strain contact of the same sphere, built here on the linear skin from the geometry at rest:
  // normal gaps g⁰ and their derivative Dn⁰ (MortarZone::sphere_gaps at u = 0, the sphere at first touch),
  // compliance Dn⁰ K⁻¹ Dn⁰ᵀ by one linear solve per multiplier, u = K⁻¹ Dn⁰ᵀ λ. (The linear contact of
  // contact/condensed.hpp pushes vertically: it differs from both by the normals' tilt over the touched
  // hats, a relative 3e-3 at every force here.) At forces this small the sphere touches the same vertices in
  // both (asserted), so the problem is smooth in F and the finite solution is the small-strain one plus
  // O(F²): the relative gap between the two displacement fields halves with the force.
  Layer& l = layer();
  const MortarZone& z = *l.zone;
  const int n3 = 3 * l.mesh.num_nodes();
  const Eigen::Vector3d c0(0, 0, l.indenter->z_touch() + l.indenter->R());
  const MortarZone::SphereGaps rest = z.sphere_gaps(l.mesh, Eigen::VectorXd::Zero(n3), c0, l.indenter->R());
  Eigen::MatrixXd U(n3, z.size());
  for (int j = 0; j < z.size(); ++j)
    U.col(j) = l.linear->solve(Eigen::VectorXd(rest.Dn.row(j).transpose()), {}).solution.u;
  Eigen::MatrixXd M = rest.Dn * U;
  M = 0.5 * (M + M.transpose()).eval();
  const double forces[] = {4e-4, 2e-4, 1e-4, 5e-5};
  std::vector<double> gap;
  for (double F : forces) {
    const FiniteContactResult f = finite(F);
    const LcpSolution small = ContactLcp(M, rest.g, rest.m).solve_force(F);
    ASSERT_EQ(f.active, small.active) << "F " << F;
    gap.push_back(rel_norm(f.solution.u, U * small.lambda));
    std::printf("F %.1e N: %zu multipliers in contact, relative gap %.3e\n", F, f.active.size(), gap.back());
  }
  EXPECT_GT(gap.back(), 1e-7);  // far above the Newton floor (~1e-9 of u): the ratios below are the physics'
  for (size_t i = 1; i < gap.size(); ++i)
    EXPECT_NEAR(std::log2(gap[i - 1] / gap[i]), 1.0, 0.1) << "forces " << forces[i - 1] << ", " << forces[i];
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
  Eigen::Vector3d base = Eigen::Vector3d::Zero(), load = Eigen::Vector3d::Zero(), horizontal_abs = {0, 0, 0};
  for (int i = 0; i < l.mesh.num_nodes(); ++i) {
    if (l.held.fixed[3 * i + 2]) base += r.internal_force.segment<3>(3 * i);
    load += r.load.segment<3>(3 * i);
    horizontal_abs += r.load.segment<3>(3 * i).cwiseAbs();
  }
  // Σ λ_i m_i = F holds at the last iterate's normals; the load is the final state's, which moved by the
  // last Newton step: equal to the residual tolerance (1e-10).
  EXPECT_NEAR(load.z(), -F, 1e-9 * F);
  EXPECT_GT(horizontal_abs.x(), 1e-3 * F);  // the normals do turn
  EXPECT_LT((base + load).norm(), 1e-8 * F);
  EXPECT_GE(r.lambda.minCoeff(), 0.0);
  const double gap_scale = r.gap.cwiseAbs().maxCoeff();
  EXPECT_GE(r.gap.minCoeff(), -1e-10 * gap_scale);
  EXPECT_LT(r.lambda.cwiseProduct(r.gap).cwiseAbs().maxCoeff(), 1e-10 * r.lambda.maxCoeff() * gap_scale);
}

TEST(FiniteSphere, NewtonConvergesQuadraticallyOnceTheContactSetSettles) {
  // With the pressures' turning in the tangent, Newton on the settled set is quadratic: log r_{k+1} / log r_k
  // ≥ 1.8 over pairs of iterates both made with the settled set and r_{k+1} above round-off (as under a
  // plane, test_finite_contact.cpp). Without the turning term it was 1.39 here.
  EXPECT_GE(testing::check_newton_rate(pressed().steps, 1.8), 1);
}

}  // namespace
}  // namespace skinfem::contact
