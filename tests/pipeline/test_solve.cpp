// `skinfem solve` as a stage (pipeline/solve.hpp) on a coarse flat layer. References: equilibrium (the base's
// total force equals minus the applied load, component by component, as the scene states it), linearity
// (the readings of two patches together are the sum of each alone, on the same deterministic mesh), the
// exact scaling with Young's modulus at ν = 0.5 under force control (stresses unchanged, displacements ∝
// 1/E), the punch's force and displacement controls as inverses of one linear map, the second solver (CG on
// the Schur complement against the direct factorization, to CG's tolerance), and the refusal of a scene
// without loads. The neo-Hookean skin (material.model): equilibrium to Newton's tolerance, and the small-load
// limit: the finite solution's readings tend to the linear ones with a difference of first order in the
// load (the expansion u = s u₁ + s² u₂ + … about rest, u₁ the linear solution), the observed order fitted
// over four loads.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "skinfem/pipeline/solve.hpp"

namespace skinfem::pipeline {
namespace {

// The direct solver's residual is at round-off; a sparse factorization of a few thousand unknowns loses a
// few digits to the saddle point's condition: 1e-9 relative to the largest reading is a loose round-off
// bound.
constexpr double kDirect = 1e-9;
// ModelOptions' CG tolerance is 1e-10 on the relative residual; the readings' error, amplified by the
// condition number of the Schur complement on this coarse mesh, stays below 1e-7 relative.
constexpr double kCg = 1e-7;

Scene layer() {
  Scene s;
  s.name = "solve_layer";
  s.source_path = "solve_layer.json";
  s.geometry.kind = GeometryKind::flat;
  s.geometry.flat = {1.5, 4.0};
  s.sensors.positions = {{0, 0}, {1, 0}, {0, 1.5}};
  s.mesh.h_min = 0.7;
  s.mesh.growth = 1.7;
  s.mesh.h_max = 1.5;
  s.mesh.sensor_h = 0.7;  // not finer than the loads' regions (h_min): a small mesh
  return s;
}

Punch punch(double force) {
  Punch p;
  p.center = {0.3, 0.2};
  p.diameter = 0.6;
  p.force = force;
  return p;
}

TractionPatch patch(Vec2 centre, Vec3 direction, double force) {
  return TractionPatch{centre, 0.8, direction, force};
}

double largest_reading(const SolveRun& r) {
  double m = 0;
  for (const SensorReading& s : r.readings) m = std::max({m, std::abs(s.sigma_z), std::abs(s.sigma_x)});
  return m;
}

TEST(Solve, TheBaseCarriesTheAppliedLoadInEveryComponent) {
  Scene s = layer();
  s.loads.punches = {punch(0.7)};
  s.loads.patches = {patch({-1, 0.5}, {1, 0, 0}, 0.3), patch({1, -1}, {0, 1, 0}, 0.2)};
  const SolveRun r = solve_run(s, SolverKind::direct_ldlt);
  // The punch presses 0.7 N down, the patches pull 0.3 N along x and 0.2 N along y: the base pushes back.
  const Eigen::Vector3d expected(-0.3, -0.2, 0.7);
  EXPECT_LT((r.base_force_N - expected).norm(), kDirect * expected.norm()) << r.base_force_N.transpose();
  EXPECT_NEAR(r.result.applied_force_N[0], 0.3, kDirect);
  EXPECT_NEAR(r.result.applied_force_N[1], 0.2, kDirect);
  EXPECT_NEAR(r.result.applied_force_N[2], -0.7, kDirect);
  EXPECT_LT(r.metrics.force_balance_rel, kDirect);
  ASSERT_EQ(r.result.punches.size(), 1u);
  EXPECT_NEAR(r.result.punches[0].force_N, 0.7, kDirect);
  EXPECT_GT(r.result.punches[0].displacement_mm, 0);
  EXPECT_EQ(r.readings.size(), s.sensors.positions.size());
  std::printf("%d nodes;", r.mesh->num_nodes());
  for (const auto& [k, v] : r.wall) std::printf(" %s %.3f s", k.c_str(), v);
  std::printf("\n");
  for (const char* stage : {"mesh", "assemble", "factor", "solve"})
    EXPECT_TRUE(r.wall.contains(stage)) << stage;
}

TEST(Solve, ReadingsOfTwoPatchesAreTheSumOfEachAlone) {
  // Every scene holds both patches (each patch refines the mesh under it), one at a time with no force.
  const TractionPatch pa = patch({0.5, 0}, {0, 0, -1}, 1.0), pb = patch({-0.5, 1}, {0.6, 0, -0.8}, 0.5);
  TractionPatch none_a = pa, none_b = pb;
  none_a.force = none_b.force = 0;
  Scene a = layer(), b = layer(), both = layer();
  a.loads.patches = {pa, none_b};
  b.loads.patches = {none_a, pb};
  both.loads.patches = {pa, pb};
  const SolveRun ra = solve_run(a, SolverKind::direct_ldlt), rb = solve_run(b, SolverKind::direct_ldlt),
                 rab = solve_run(both, SolverKind::direct_ldlt);
  ASSERT_EQ(rab.mesh->num_nodes(), ra.mesh->num_nodes());  // the same mesh: meshing is deterministic
  const double scale = largest_reading(rab);
  ASSERT_GT(scale, 0);
  for (size_t k = 0; k < rab.readings.size(); ++k) {
    EXPECT_NEAR(rab.readings[k].sigma_z, ra.readings[k].sigma_z + rb.readings[k].sigma_z, kDirect * scale);
    EXPECT_NEAR(rab.readings[k].sigma_x, ra.readings[k].sigma_x + rb.readings[k].sigma_x, kDirect * scale);
  }
  EXPECT_LT((rab.base_force_N - ra.base_force_N - rb.base_force_N).norm(), kDirect);
}

TEST(Solve, YoungsModulusScalesDisplacementsNotStresses) {
  Scene soft = layer();
  soft.loads.punches = {punch(0.5)};
  soft.loads.patches = {patch({-1, 0}, {1, 0, 0}, 0.2)};
  Scene stiff = soft;
  stiff.material.E = 2.5 * soft.material.E;
  const SolveRun rs = solve_run(soft, SolverKind::direct_ldlt),
                 rh = solve_run(stiff, SolverKind::direct_ldlt);
  const double scale = largest_reading(rs);
  for (size_t k = 0; k < rs.readings.size(); ++k) {
    EXPECT_NEAR(rh.readings[k].sigma_z, rs.readings[k].sigma_z, kDirect * scale);
    EXPECT_NEAR(rh.readings[k].sigma_x, rs.readings[k].sigma_x, kDirect * scale);
  }
  const double d = rs.result.punches.at(0).displacement_mm;
  EXPECT_NEAR(rh.result.punches.at(0).displacement_mm, d / 2.5, kDirect * d);
}

TEST(Solve, APunchsForceAndDisplacementControlsAreInverses) {
  Scene by_force = layer();
  by_force.loads.punches = {punch(0.9)};
  const SolveRun rf = solve_run(by_force, SolverKind::direct_ldlt);
  const double d = rf.result.punches.at(0).displacement_mm;
  Scene by_depth = layer();
  Punch p = punch(0);
  p.force.reset();
  p.displacement = d;
  by_depth.loads.punches = {p};
  const SolveRun rd = solve_run(by_depth, SolverKind::direct_ldlt);
  EXPECT_NEAR(rd.result.punches.at(0).force_N, 0.9, kDirect * 0.9);
  EXPECT_NEAR(rd.result.punches.at(0).displacement_mm, d, kDirect * d);
  const double scale = largest_reading(rf);
  for (size_t k = 0; k < rf.readings.size(); ++k)
    EXPECT_NEAR(rd.readings[k].sigma_z, rf.readings[k].sigma_z, kDirect * scale);
}

TEST(Solve, TheIterativeSolverAgreesWithTheDirectOneToItsTolerance) {
  Scene s = layer();
  s.loads.punches = {punch(0.6)};
  s.loads.patches = {patch({1, 1}, {0, 1, 0}, 0.25)};
  const SolveRun direct = solve_run(s, SolverKind::direct_ldlt), cg = solve_run(s, SolverKind::schur_cg);
  const double scale = largest_reading(direct);
  for (size_t k = 0; k < direct.readings.size(); ++k) {
    EXPECT_NEAR(cg.readings[k].sigma_z, direct.readings[k].sigma_z, kCg * scale);
    EXPECT_NEAR(cg.readings[k].sigma_x, direct.readings[k].sigma_x, kCg * scale);
  }
  const double d = direct.result.punches.at(0).displacement_mm;
  EXPECT_NEAR(cg.result.punches.at(0).displacement_mm, d, kCg * d);
}

TEST(Solve, ASceneWithoutLoadsIsRefusedNamingThem) {
  const Scene s = layer();
  try {
    solve_run(s, SolverKind::direct_ldlt);
    ADD_FAILURE() << "solved a scene without loads";
  } catch (const SceneError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("solve_layer.json"), std::string::npos) << what;
    EXPECT_NE(what.find("loads"), std::string::npos) << what;
  }
}

// Loads of every kind the finite-strain skin takes, scaled by s: two dead patches (normal and tangential) and
// a punch driven by its displacement.
Scene finite_layer(double s) {
  Scene sc = layer();
  sc.material.model = MaterialModel::neo_hookean;
  Punch p = punch(0);
  p.force.reset();
  p.displacement = 0.04 * s;
  sc.loads.punches = {p};
  sc.loads.patches = {patch({-1, 0.5}, {0, 0, -1}, 0.4 * s), patch({1, -1}, {1, 0, 0}, 0.3 * s)};
  return sc;
}

// Newton's tolerance is 1e-10 on the residual relative to the load: the base carries the dead patches and the
// punch's reaction to that bound, component by component.
void expect_finite_equilibrium(const SolveRun& r, double s) {
  ASSERT_FALSE(r.newton_steps.empty());
  EXPECT_LE(r.newton_steps.back().residuals.back(), 1e-10);
  const Eigen::Vector3d applied(r.result.applied_force_N[0], r.result.applied_force_N[1],
                                r.result.applied_force_N[2]);
  EXPECT_NEAR(applied[0], 0.3 * s, 1e-12);
  EXPECT_NEAR(applied[2], -0.4 * s - r.result.punches.at(0).force_N, 1e-12);
  EXPECT_GT(r.result.punches.at(0).force_N, 0);
  EXPECT_LT((r.base_force_N + applied).norm(), 1e-8 * applied.norm()) << s;
  EXPECT_EQ(r.readings.size(), 3u);
}

TEST(Solve, TheNeoHookeanSkinIsInEquilibrium) {
  const SolveRun r = solve_run(finite_layer(1), SolverKind::direct_ldlt);
  expect_finite_equilibrium(r, 1);
  EXPECT_EQ(r.model, nullptr);
  for (const char* stage : {"mesh", "assemble", "newton"}) EXPECT_TRUE(r.wall.contains(stage)) << stage;
}

TEST(Solve, TheNeoHookeanSkinTendsToTheLinearOneAtFirstOrderInTheLoad) {
  Scene linear_scene = finite_layer(1);
  linear_scene.material.model = MaterialModel::linear;
  const SolveRun linear = solve_run(linear_scene, SolverKind::direct_ldlt);
  std::vector<double> loads, differences;
  for (double s : {1.0, 0.5, 0.25, 0.125}) {
    const SolveRun r = solve_run(finite_layer(s), SolverKind::direct_ldlt);
    expect_finite_equilibrium(r, s);
    // The linear readings scale with s exactly.
    double diff = 0, scale = 0;
    for (size_t k = 0; k < r.readings.size(); ++k) {
      const SensorReading& a = r.readings[k];
      const SensorReading& b = linear.readings[k];
      diff = std::max({diff, std::abs(a.sigma_z - s * b.sigma_z), std::abs(a.sigma_x - s * b.sigma_x)});
      scale = std::max({scale, std::abs(s * b.sigma_z), std::abs(s * b.sigma_x)});
    }
    loads.push_back(s);
    differences.push_back(diff / scale);
    int iterations = 0;
    for (const NewtonStep& step : r.newton_steps) iterations += static_cast<int>(step.residuals.size()) - 1;
    std::printf("s %.3f: %d DOFs, %zu load steps, %d Newton iterations, %.2f s\n", s, r.dofs,
                r.newton_steps.size(), iterations, r.wall.at("newton"));
  }
  // The local order between consecutive loads is 1 + c s + O(s²) (the expansion's next term): its distance
  // from 1 halves with each halving of the load (at most 0.6× the previous one here, round-off aside), and at
  // the smallest loads it is within 0.1 of 1.
  std::vector<double> order;
  for (size_t i = 0; i + 1 < loads.size(); ++i)
    order.push_back(std::log(differences[i] / differences[i + 1]) / std::log(loads[i] / loads[i + 1]));
  std::printf(
      "relative difference finite − linear at s = 1, 1/2, 1/4, 1/8: %.3e %.3e %.3e %.3e; local orders "
      "%.3f %.3f %.3f\n",
      differences[0], differences[1], differences[2], differences[3], order[0], order[1], order[2]);
  EXPECT_LT(differences[0], 0.2);  // a moderate load: the expansion's regime
  for (size_t i = 0; i + 1 < order.size(); ++i)
    EXPECT_LT(std::abs(order[i + 1] - 1), 0.6 * std::abs(order[i] - 1));
  EXPECT_NEAR(order.back(), 1.0, 0.1);
}

}  // namespace
}  // namespace skinfem::pipeline
