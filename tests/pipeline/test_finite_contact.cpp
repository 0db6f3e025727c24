// The finite-strain contact as `skinfem contact` runs it (pipeline/finite_contact.hpp) on the shipped
// scenes/hertz_layer.json (a sphere, R = 129.7 mm, on the bonded 3.04 mm layer), against the small-strain
// contact of the same sphere on the same mesh as the force falls from the scene's F = 0.8 N to F/8.
//
// Reference, a second method: the small-strain contact built here on the linear skin (fem/elastic_model.hpp)
// from the geometry at rest, the sphere's normal gaps g⁰ and their derivative Dn⁰ (MortarZone::sphere_gaps
// at u = 0), compliance Dn⁰ K⁻¹ Dn⁰ᵀ, u = K⁻¹ Dn⁰ᵀ λ (contact/lcp.hpp's force-controlled LCP). It is the
// finite problem's exact linearization at rest, so the two differ by the finite-strain terms alone. (`skinfem
// contact` on the linear skin pushes vertically and weights its gaps otherwise; tests/contact/
// test_finite_sphere.cpp says by how much.)
//
// Why the exponent: the first correction of finite over linear elasticity is quadratic in the displacement
// gradient (Green's strain E = ε + ½ ∇uᵀ∇u, the rotations), so in the H¹ seminorm it is, relative to the
// solution, of the order of the solution's strain weighted by its own gradient energy,
//   ε_q = (∫|∇u|⁴ / ∫|∇u|²)^½,
// and it falls with the force as ε_q does. Under a sphere the strain scales as a/R, not as F: a ∝ F^(1/3)
// on a half-space and F^(1/6) on a thin bonded incompressible layer, so the exponent is far below 1. The
// loads keep the same contact set in both solutions (asserted), so nothing jumps between them and the fit
// measures the physics, not the mesh.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "../common/convergence.hpp"
#include "skinfem/contact/lcp.hpp"
#include "skinfem/fem/elastic_model.hpp"
#include "skinfem/mesh/p2_tet.hpp"
#include "skinfem/pipeline/finite_contact.hpp"
#include "skinfem/scene/load.hpp"

namespace skinfem::pipeline {
namespace {

// ∫|∇v|² and ∫|∇v|⁴ over the skin (Frobenius norm of the displacement gradient, degree-5 points); v: 3N, mm.
struct GradientMoments {
  double second = 0, fourth = 0;
};
GradientMoments gradient_moments(const TetMesh& m, const Eigen::VectorXd& v) {
  GradientMoments g;
  Eigen::Matrix<double, 10, 3> X, V;
  for (int t = 0; t < m.num_tets(); ++t) {
    for (int a = 0; a < 10; ++a) {
      X.row(a) = m.nodes.row(m.tets(t, a));
      V.row(a) = v.segment<3>(3 * m.tets(t, a)).transpose();
    }
    for (const auto& q : p2::quadrature_degree5()) {
      const p2::Grad10 dref = p2::shape_gradient(q.xi);
      const Eigen::Matrix3d dX = X.transpose() * dref;
      const double w = q.weight * dX.determinant(), s = (V.transpose() * dref * dX.inverse()).squaredNorm();
      g.second += w * s;
      g.fourth += w * s * s;
    }
  }
  return g;
}

TEST(FiniteContactRun, OnTheHertzLayerTheFiniteSphereDiffersFromTheSmallStrainOneByItsStrain) {
  Scene scene = load_scene(std::string(SKINFEM_SOURCE_DIR) + "/scenes/hertz_layer.json");
  scene.material.model = MaterialModel::neo_hookean;
  const double F = *scene.contact->force;
  const std::vector<double> forces = {F, F / 2, F / 4, F / 8};
  std::unique_ptr<ElasticModel> linear;
  Eigen::MatrixXd U, M;  // K⁻¹ Dn⁰ᵀ (3N × n_c) and Dn⁰ K⁻¹ Dn⁰ᵀ
  contact::MortarZone::SphereGaps rest;
  std::vector<double> gap, strain, radius;
  for (double force : forces) {
    scene.contact->force = force;
    const FiniteContactRun run = finite_contact_run(scene, FrictionMode::none);
    const TetMesh& mesh = *run.solved;  // the half y ≥ 0, the same mesh at every force
    const contact::MortarZone& zone = run.solved_zone;
    if (!linear) {
      linear =
          std::make_unique<ElasticModel>(mesh, scene.material, scene.geometry.side, std::vector<Punch>{});
      const int n3 = 3 * mesh.num_nodes();
      const Eigen::Vector3d c0(0, 0, run.indenter->z_touch() + run.indenter->R());
      rest = zone.sphere_gaps(mesh, Eigen::VectorXd::Zero(n3), c0, run.indenter->R());
      U.resize(n3, zone.size());
      for (int j = 0; j < zone.size(); ++j)
        U.col(j) = linear->solve(Eigen::VectorXd(rest.Dn.row(j).transpose()), {}).solution.u;
      M = rest.Dn * U;
      M = 0.5 * (M + M.transpose()).eval();
    }
    ASSERT_EQ(U.rows(), 3 * mesh.num_nodes());
    const contact::LcpSolution small = contact::ContactLcp(M, rest.g, rest.m).solve_force(run.load.force);
    const Eigen::VectorXd u = U * small.lambda;
    ASSERT_EQ(run.solved_result.active, small.active) << "F " << force;
    EXPECT_EQ(run.tangential_force_N, 0.0);  // frictionless: no drag, whatever the mesh's asymmetry
    const GradientMoments of_u = gradient_moments(mesh, u);
    gap.push_back(std::sqrt(gradient_moments(mesh, run.solved_result.solution.u - u).second / of_u.second));
    strain.push_back(std::sqrt(of_u.fourth / of_u.second));
    radius.push_back(run.reference.moment_radius_mm);
    std::printf(
        "F %.3f N: %zu multipliers in contact, a = %.3f mm; relative H1 gap %.4e, strain %.4e (ratio %.3f)\n",
        force, small.active.size(), run.reference.moment_radius_mm, gap.back(), strain.back(),
        gap.back() / strain.back());
  }
  const double order = testing::observed_order(forces, gap),
               strain_order = testing::observed_order(forces, strain);
  std::printf("the gap falls as F^%.3f, the strain as F^%.3f, the contact radius as F^%.3f\n", order,
              strain_order, testing::observed_order(forces, radius));
  // The law: the gap falls as the strain does, to 0.1 (a drift of their ratio by 8^0.1 = 1.23 over the
  // loads, within "a factor of order one" below). Both are measured here, the strain from the small-strain
  // solution alone; a gap first order in the force (a linear error, a mismatched force) would give 1, a gap
  // that does not vanish (a discretization mismatch between the two problems) 0.
  EXPECT_NEAR(order, strain_order, 0.1);
  EXPECT_LT(order, 0.5);
  // The order: the correction is the strain times a factor of order one at every load.
  for (size_t i = 0; i < gap.size(); ++i) {
    EXPECT_GT(gap[i], strain[i] / 3) << "F " << forces[i];
    EXPECT_LT(gap[i], 3 * strain[i]) << "F " << forces[i];
  }
}

}  // namespace
}  // namespace skinfem::pipeline
