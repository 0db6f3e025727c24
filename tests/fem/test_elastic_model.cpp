// ElasticModel end to end: force balance of the base tractions, punches driven by force or by
// displacement, a flat rigid punch against Johnson's half-space stiffness, the docs/theory.md sign
// convention of sensor readings, and the adjoint reading functional.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include "skinfem/fem/base_traction.hpp"
#include "skinfem/fem/elastic_model.hpp"
#include "skinfem/mesh/build.hpp"
#include "skinfem/mesh/surface_quadrature.hpp"

namespace skinfem {
namespace {

constexpr double kE = 3.0;       // MPa
constexpr double kThick = 1.5;   // mm
constexpr double kDisc = 0.2;    // mm, sensor disc diameter
constexpr double kPunchD = 0.5;  // mm, punch / patch diameter

// A flat layer (h = 1.5 mm, |x|, |y| ≤ 3 mm) refined around a punch at the origin and two sensor
// discs, at (0, 0) and (−1, 0).
const TetMesh& layer() {
  static const TetMesh m = [] {
    Scene s;
    s.geometry.kind = GeometryKind::flat;
    s.geometry.flat = {kThick, 3.0};
    s.sensors.positions = {{0, 0}, {-1, 0}};
    s.sensors.disc_diameter = kDisc;
    s.loads.punches = {Punch{{0, 0}, kPunchD, 1.0, std::nullopt}};
    s.mesh.h_min = 0.2;
    s.mesh.h_max = 0.75;
    s.mesh.growth = 1.5;
    return build_mesh(s);
  }();
  return m;
}

const ElasticModel& model_without_punch() {
  static const ElasticModel model(layer(), Material{kE, 0.5}, SideCondition::free, {});
  return model;
}

Punch force_punch(double force) { return Punch{{0, 0}, kPunchD, force, std::nullopt}; }
Punch depth_punch(double depth) { return Punch{{0, 0}, kPunchD, std::nullopt, depth}; }

const ElasticModel& model_with_punch() {
  static const ElasticModel model(layer(), Material{kE, 0.5}, SideCondition::free, {force_punch(1.0)});
  return model;
}

Eigen::Vector3d column_sums(const Eigen::VectorXd& v) { return v.reshaped(3, v.size() / 3).rowwise().sum(); }

// ∫ t dA over the base, with the recovered traction field evaluated at every base face's degree-5
// points: t is P2 on flat faces, so this is exact, and independent of how total_force() is computed.
Eigen::Vector3d integrate_base_traction(const TetMesh& m, const BaseTraction& bt) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int f = 0; f < m.faces.rows(); ++f) {
    if (m.face_marker(f) != kBase) continue;
    for (const auto& q : face_quadrature(m, f)) {
      const auto t = bt.traction(q.x.x(), q.x.y());
      EXPECT_TRUE(t.has_value());
      if (t) sum += q.weight * *t;
    }
  }
  return sum;
}

TEST(ElasticModel, BaseTractionBalancesTheAppliedForce) {
  // Reference: statics. The translations e_c are in the kernel of A and B (no strain, no
  // divergence), so Σ_d (A u + Bᵀp)_d = 0 per component; at the free DOFs that sum equals the load
  // up to the solver residual, hence Σ reactions = −Σ loads to ~1e-15 relative (direct LDLᵀ). The
  // mass-matrix spreading keeps the integral: ∫ t = Σ_i t_i ∫ φ_i = 1ᵀ M T = 1ᵀ R, since Σ φ_i = 1.
  // The patch's density is its force over the sum of its quadrature weights and Σ N_k = 1 on each face, so
  // the load vector carries the requested force to round-off too.
  const ElasticModel& model = model_without_punch();
  const TetMesh& m = layer();
  const std::vector<Eigen::Vector3d> directions = {{1, 0, 0}, {0, 0, -1}, {1, 0.5, -1}};
  for (const auto& dir : directions) {
    const TractionPatch patch{{0.3, -0.2}, 0.6, {dir.x(), dir.y(), dir.z()}, 0.8};
    const Eigen::Vector3d F = 0.8 * dir.normalized();
    const Eigen::VectorXd f = model.patch_load(patch);
    EXPECT_LT((column_sums(f) - F).norm(), 1e-13 * F.norm()) << dir.transpose();
    const LoadCaseResult res = model.solve(f, {});
    EXPECT_LT((Eigen::Vector3d(res.applied_force_N) - F).norm(), 1e-13 * F.norm()) << dir.transpose();
    const BaseTraction bt(m, res.reactions);
    const Eigen::Vector3d total = bt.total_force(), integral = integrate_base_traction(m, bt);
    std::printf("direction (%g, %g, %g): |total + F|/|F| %.2e, |∫t dA + F|/|F| %.2e\n", dir.x(), dir.y(),
                dir.z(), (total + F).norm() / F.norm(), (integral + F).norm() / F.norm());
    EXPECT_LT((total + F).norm(), 1e-10 * F.norm()) << dir.transpose();
    EXPECT_LT((integral + F).norm(), 1e-10 * F.norm()) << dir.transpose();
  }
}

TEST(ElasticModel, PunchDrivenByForceOrByDepthAgree) {
  // Reference: linearity and an independent force recovery. The depth δ found for force F, imposed
  // as a displacement through MixedSolver directly, must give back F as −Σ of the z-reactions at the
  // punch nodes (only round-off separates the two routes: 1e-9); the punch is rigid (every punch node
  // moves by −δ); and 2F gives 2δ (exact linearity, round-off only).
  const ElasticModel& model = model_with_punch();
  const TetMesh& m = layer();
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(3 * m.num_nodes());
  const double F = 1.0;
  const LoadCaseResult by_force = model.solve(zero, {force_punch(F)});
  const double delta = by_force.punches.at(0).displacement_mm;
  EXPECT_GT(delta, 0);
  EXPECT_NEAR(by_force.punches[0].force_N, F, 1e-12 * F);
  for (int i : model.punch_groups().at(0)) EXPECT_NEAR(by_force.solution.u[3 * i + 2], -delta, 1e-14);

  const LoadCaseResult by_depth = model.solve(zero, {depth_punch(delta)});
  EXPECT_NEAR(by_depth.punches.at(0).force_N, F, 1e-9 * F);
  EXPECT_LT((by_depth.solution.u - by_force.solution.u).norm(), 1e-9 * by_force.solution.u.norm());

  Eigen::VectorXd g = zero;
  for (int i : model.punch_groups()[0]) g[3 * i + 2] = -delta;
  const MixedSolution direct = model.solver().solve(zero, g);
  const Eigen::VectorXd r = model.solver().reactions(direct, zero);
  double force = 0;
  for (int i : model.punch_groups()[0]) force -= r[3 * i + 2];
  EXPECT_NEAR(force, F, 1e-9 * F);

  const LoadCaseResult doubled = model.solve(zero, {force_punch(2 * F)});
  EXPECT_NEAR(doubled.punches.at(0).displacement_mm, 2 * delta, 1e-12 * delta);
  std::printf("punch F = %g N: depth %.6e mm; by depth: %.15f N; direct: %.15f N\n", F, delta,
              by_depth.punches[0].force_N, force);
}

TEST(ElasticModel, FlatPunchStiffnessApproachesJohnsonFromAbove) {
  // Reference: Johnson, Contact Mechanics (1985) §3.8: a rigid flat punch of radius a on a half-space
  // has F = 2 a E* δ, E* = E/(1 − ν²) = 4E/3 at ν = 0.5. A layer of thickness h bonded to a rigid base
  // is stiffer. For a/h ≪ 1 the base adds a smooth, nearly constant part c/(E* h) to the surface
  // kernel; a constant shift changes the punch law to F = 2aE*δ / (1 − c' a/h), c' = −2α₀/π ≈ 1.13
  // for a bonded incompressible layer (α₀ of Dimitriadis et al., Biophys. J. 82 (2002) 2798, whose
  // spherical series 1 + 1.133χ + 1.283χ² has the same origin; Hayes et al., J. Biomech. 5 (1972) 541
  // tabulate ≈ 1.2 at a/h = 0.2). At a/h = 1/8 that is ≈ 1.16; the free sides at w = 8a = h soften it
  // by a few %. Discretization moves it both ways: the punch-edge singularity (p ~ (a − r)^−½) makes
  // the FE stiffer by O(h_min/a), the polygonal punch edge (straight chords, ≥ 2πa/h_min of them)
  // softer by O((h_min/a)²), ~1–3 % each here. Hence every level must lie in [1, 1.25]·2aE* (loose:
  // 1.16 ± a few %, the layer constant being only asymptotic), and the levels must agree within 5 %
  // of 2aE*. A monotone-convergence check (finer pair closer than the coarser pair) needs the
  // asymptotic regime h_min ≲ a/4, i.e. > 10⁵ nodes for h = 8a: beyond this suite's time budget;
  // the two competing errors above make the coarse levels converge non-monotonically.
  const double a = 0.25, h = 8 * a, w = 8 * a;
  const double johnson = 2 * a * (4.0 * kE / 3.0);
  const auto start = std::chrono::steady_clock::now();
  std::vector<double> ratio;
  for (double per_radius : {1.5, 2.0, 2.5}) {
    Scene s;
    s.geometry.kind = GeometryKind::flat;
    s.geometry.flat = {h, w};
    s.mesh.refine_sensors = false;
    s.loads.punches = {Punch{{0, 0}, 2 * a, 1.0, std::nullopt}};
    s.mesh.h_min = a / per_radius;
    s.mesh.h_max = 0.5 * h;
    s.mesh.growth = 2.0;  // coarse far field: the fine column through the thickness dominates the cost
    const TetMesh m = build_mesh(s);
    // One load per mesh: the Schur-CG road (CHOLMOD on A only) is the cheaper one here.
    const ElasticModel model(m, Material{kE, 0.5}, SideCondition::free, s.loads.punches,
                             ModelOptions{SolverKind::schur_cg, 1e-10, {}});
    const double delta = 0.01;
    const LoadCaseResult res = model.solve(Eigen::VectorXd::Zero(3 * m.num_nodes()), {depth_punch(delta)});
    ratio.push_back(res.punches[0].force_N / delta / johnson);
    // Diagnostic: top faces with corners strictly inside and strictly outside the punch circle cut
    // across its edge (the edge should be a mesh curve).
    int crossing = 0;
    for (int f = 0; f < m.faces.rows(); ++f) {
      if (m.face_marker(f) != kTop) continue;
      bool in = false, out = false;
      for (int k = 0; k < 3; ++k) {
        const double r = std::hypot(m.nodes(m.faces(f, k), 0), m.nodes(m.faces(f, k), 1)) / a;
        in |= r<1 - 1e-6, out |= r> 1 + 1e-6;
      }
      crossing += in && out;
    }
    std::printf(
        "h_min = a/%g: %d nodes, %zu punch nodes, %d top faces cut the punch edge; stiffness %.5f N/mm "
        "= %.5f x 2aE* (%.1f s so far)\n",
        per_radius, m.num_nodes(), model.punch_groups()[0].size(), crossing, ratio.back() * johnson,
        ratio.back(), std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  for (double r : ratio) {
    EXPECT_GT(r, 1.0);
    EXPECT_LT(r, 1.25);
  }
  const auto [lo, hi] = std::minmax_element(ratio.begin(), ratio.end());
  EXPECT_LT(*hi - *lo, 0.05);
}

// Half-space (Boussinesq/Cerruti, ν = 0.5) readings per unit force at depth h, offset (x, y) of the
// load from the sensor: σ_z from a normal load 3h³/(2πρ⁵); σ_x from a normal load −3xh²/(2πρ⁵) (the
// skin is pushed away from the load); σ_x from a +x load 3x²h/(2πρ⁵).
double g_zz(double x, double y, double h) {
  return 3 * h * h * h / (2 * M_PI * std::pow(x * x + y * y + h * h, 2.5));
}
double g_zx(double x, double y, double h) {
  return -3 * x * h * h / (2 * M_PI * std::pow(x * x + y * y + h * h, 2.5));
}
double g_xx(double x, double y, double h) {
  return 3 * x * x * h / (2 * M_PI * std::pow(x * x + y * y + h * h, 2.5));
}

TEST(ElasticModel, SensorReadingsFollowTheDesignSignConvention) {
  // Reference: docs/theory.md §Conventions (σ_z > 0 when the skin presses on the sensor, σ_x > 0 when it
  // drags it toward +x) and the half-space tensors above for the sign. The bonded layer only
  // concentrates the near field (k ≈ 1.48 in the paper), so each reading must have the half-space sign
  // and at least a quarter of its size (a guard against a vanishing field, not an accuracy claim).
  const TetMesh& m = layer();
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(3 * m.num_nodes());
  {  // normal punch, 1 N down at the origin
    const BaseTraction bt(m, model_with_punch().solve(zero, {force_punch(1.0)}).reactions);
    const SensorReading centre = bt.reading_at(0, 0), left = bt.disc_mean(-1, 0, kDisc);
    std::printf(
        "punch: sigma_z(0,0) %.4f MPa (half-space %.4f); disc at x=-1: sigma_z %.4f (%.4f), sigma_x %.4f "
        "(%.4f)\n",
        centre.sigma_z, g_zz(0, 0, kThick), left.sigma_z, g_zz(1, 0, kThick), left.sigma_x,
        g_zx(1, 0, kThick));
    EXPECT_GT(centre.sigma_z, 0.25 * g_zz(0, 0, kThick));
    EXPECT_GT(left.sigma_z, 0.25 * g_zz(1, 0, kThick));
    EXPECT_LT(left.sigma_x, 0.25 * g_zx(1, 0, kThick));  // the load is to the sensor's right: offset x = +1
  }
  {  // tangential patch, 1 N toward +x at the origin
    const ElasticModel& model = model_without_punch();
    const TractionPatch patch{{0, 0}, kPunchD, {1, 0, 0}, 1.0};
    const BaseTraction bt(m, model.solve(model.patch_load(patch), {}).reactions);
    const SensorReading centre = bt.disc_mean(0, 0, kDisc), left = bt.disc_mean(-1, 0, kDisc);
    std::printf("+x patch: disc at 0: sigma_x %.4f MPa; disc at x=-1: sigma_x %.4f (half-space %.4f)\n",
                centre.sigma_x, left.sigma_x, g_xx(1, 0, kThick));
    // Directly below, Cerruti's point-load g_xx vanishes (∝ x²), but the bonded base must carry the whole
    // tangential force within ~h of the load: the skin drags the sensor under the patch toward +x.
    EXPECT_GT(centre.sigma_x, 0);
    EXPECT_GT(left.sigma_x, 0.25 * g_xx(1, 0, kThick));
  }
}

TEST(ElasticModel, DiscReadingFunctionalReproducesDiscMean) {
  // Reference: disc_mean is the disc quadrature of t = M⁻¹R interpolated on the base; the functional
  // is the same quadrature moved onto R, w = M⁻¹ Σ_q w_q N(x_q). Equal in exact arithmetic; the base
  // mass matrix is well conditioned (graded mesh, cond ~ 10²–10³), so they agree to ~1e-14 relative.
  const TetMesh& m = layer();
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(3 * m.num_nodes());
  const TractionPatch slanted{{0.2, 0.1}, kPunchD, {1, 0.5, -1}, 1.0};
  const std::vector<Eigen::VectorXd> reactions = {
      model_with_punch().solve(zero, {force_punch(1.0)}).reactions,
      model_without_punch().solve(model_without_punch().patch_load(slanted), {}).reactions};
  for (const auto& R : reactions) {
    const BaseTraction bt(m, R);
    for (const auto& [x, y] : std::vector<std::pair<double, double>>{{-1, 0}, {0.4, -0.3}}) {
      const SensorReading mean = bt.disc_mean(x, y, kDisc);
      const double wz = disc_reading_functional(m, x, y, kDisc, 'z').dot(R);
      const double wx = disc_reading_functional(m, x, y, kDisc, 'x').dot(R);
      EXPECT_NEAR(wz, mean.sigma_z, 1e-12 * std::abs(mean.sigma_z)) << x << ", " << y;
      EXPECT_NEAR(wx, mean.sigma_x, 1e-12 * std::abs(mean.sigma_x)) << x << ", " << y;
    }
  }
}

}  // namespace
}  // namespace skinfem
