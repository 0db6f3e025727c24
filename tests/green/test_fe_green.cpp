// FE Green tensors by reciprocity (green/fe_green.hpp): the adjoint route against direct solves, the
// shipped flat layer against the exact bonded-layer tensor (ladder rung 5, the k regression), and the
// force balance ∬ g_zz dA = 1 of the discrete Green map.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "fem/base_traction.hpp"
#include "fem/elastic_model.hpp"
#include "fem/face_index.hpp"
#include "green/calibration.hpp"
#include "green/fe_green.hpp"
#include "mesh/build.hpp"
#include "mesh/surface_quadrature.hpp"
#include "scene/load.hpp"

namespace skinfem::green {
namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// The small flat layer of the reciprocity tests: h = 1.5 mm, |x|, |y| ≤ 4 mm, two sensors.
struct SmallLayer {
  Scene scene;
  TetMesh mesh;
  ElasticModel model;
  FeGreen fe;
  static Scene make_scene() {
    Scene s;
    s.geometry.kind = GeometryKind::flat;
    s.geometry.flat = {1.5, 4.0};
    s.sensors.positions = {{0.0, 0.0}, {0.7, -0.4}};
    s.sensors.disc_diameter = 0.2;
    s.mesh.h_min = 0.25, s.mesh.h_max = 1.0, s.mesh.growth = 1.5;
    return s;
  }
  SmallLayer()
      : scene(make_scene()),
        mesh(build_mesh(scene)),
        model(mesh, scene.material, SideCondition::free, {}),
        fe(model, scene.sensors) {}
};
const SmallLayer& small_layer() {
  static const SmallLayer l;
  return l;
}

// The shipped flat-layer scene (h = 3.04 mm, half width 20 mm, one sensor at the origin), no punch.
struct ShippedLayer {
  Scene scene;
  TetMesh mesh;
  ElasticModel model;
  FeGreen fe;
  double build_seconds = 0;
  ShippedLayer(std::chrono::steady_clock::time_point t0 = std::chrono::steady_clock::now())
      : scene(load_scene(std::string(SKINFEM_SOURCE_DIR) + "/scenes/flat_layer.json")),
        mesh(build_mesh(scene)),
        model(mesh, scene.material, scene.geometry.side, {}),
        fe(model, scene.sensors),
        build_seconds(seconds_since(t0)) {}
};
const ShippedLayer& shipped_layer() {
  static const ShippedLayer l;
  return l;
}

const std::vector<Vec2> kOffsets = {{0.0, 0.0}, {1.0, 0.3}, {-2.0, 0.5}};

// Component-wise max |a_i − b_i| / max_i |b_i|.
std::array<double, 4> relative_gap(const std::vector<GreenSample>& a, const std::vector<GreenSample>& b) {
  std::array<double, 4> out{};
  for (size_t c = 0; c < 4; ++c) {
    double peak = 0, gap = 0;
    for (size_t i = 0; i < b.size(); ++i) {
      peak = std::max(peak, std::abs(component(b[i], kComponents[c])));
      gap = std::max(gap, std::abs(component(a[i], kComponents[c]) - component(b[i], kComponents[c])));
    }
    out[c] = gap / peak;
  }
  return out;
}

// The four readings of `sensor` from direct solves: a load built by `load(direction)` for a normal
// (0, 0, −1) and a tangential (1, 0, 0) force, read at the sensor's centre or over its disc.
template <class LoadFn>
GreenSample direct_sample(const SmallLayer& l, int sensor, bool disc, const LoadFn& load) {
  const auto& p = l.scene.sensors.positions[sensor];
  GreenSample g;
  for (bool tangential : {false, true}) {
    const Eigen::Vector3d dir = tangential ? Eigen::Vector3d(1, 0, 0) : Eigen::Vector3d(0, 0, -1);
    const BaseTraction base(l.mesh, l.model.solve(load(dir), {}).reactions);
    const SensorReading r =
        disc ? base.disc_mean(p[0], p[1], l.scene.sensors.disc_diameter) : base.reading_at(p[0], p[1]);
    (tangential ? g.xz : g.zz) = r.sigma_z;
    (tangential ? g.xx : g.zx) = r.sigma_x;
  }
  return g;
}

// The readings of `sensor` for a load spread by `rule` around (cx, cy), integrating the adjoint fields
// directly (top-surface P2 interpolation: an implementation independent of FeGreen::at).
GreenSample adjoint_quadrature(const SmallLayer& l, const PlanarFaceIndex& top, int sensor, bool disc, double cx,
                               double cy, const std::vector<std::array<double, 3>>& rule) {
  const Eigen::VectorXd& yz = l.fe.adjoint(sensor, 'z', disc);
  const Eigen::VectorXd& yx = l.fe.adjoint(sensor, 'x', disc);
  Eigen::Vector3d vz = Eigen::Vector3d::Zero(), vx = Eigen::Vector3d::Zero();
  for (const auto& q : rule) {
    double s, t;
    const int f = top.find(cx + q[0], cy + q[1], s, t);
    EXPECT_GE(f, 0);
    if (f < 0) continue;
    const auto N = triangle_shape(s, t);
    for (int k = 0; k < 6; ++k) {
      vz += q[2] * N[k] * yz.segment<3>(3 * l.mesh.faces(f, k));
      vx += q[2] * N[k] * yx.segment<3>(3 * l.mesh.faces(f, k));
    }
  }
  return {-vz.z(), -vx.z(), vz.x(), vx.x()};  // a normal force is −e_z, a tangential one +e_x
}

TEST(FeGreen, PointLoadsEqualDirectSolvesByReciprocity) {
  // Reference: Maxwell–Betti in the discrete system. A reading is J = w·R; the direct route solves
  // K x = f and forms R, the adjoint route solves for y with base displacement −w and forms y·f. Both
  // are the same bilinear form of K⁻¹, so they differ only by the two solves' errors. MUMPS LDLᵀ
  // solves to a relative residual far below the 1e-10 the solver enforces (both residuals are printed
  // and checked against 1e-10); a relative residual ε moves a functional by ≤ cond·ε, and the small
  // P2 system here (cond ~ 10⁴–10⁵ for h_max/h_min = 4, 1 mm elements) keeps the direct/adjoint gap
  // ≲ 1e-10 even at ε = 1e-15 · cond… so 1e-9 of each component's peak holds with margin and any
  // sign, index or quadrature mismatch between the routes (≥ 1e-3) fails it.
  const auto t0 = std::chrono::steady_clock::now();
  const SmallLayer& l = small_layer();
  std::printf("small layer: %d nodes, adjoint residual %.2e (%.1f s)\n", l.mesh.num_nodes(),
              l.fe.max_adjoint_residual(), seconds_since(t0));
  EXPECT_LT(l.fe.max_adjoint_residual(), 1e-10);
  EXPECT_EQ(l.fe.adjoint_solves(), 8);
  for (bool disc : {false, true}) {
    std::vector<GreenSample> adjoint, direct;
    for (int sensor = 0; sensor < 2; ++sensor)
      for (const Vec2& off : kOffsets) {
        const auto& p = l.scene.sensors.positions[sensor];
        adjoint.push_back(l.fe.at(sensor, disc, off[0], off[1], LayerLoad::point, 0));
        direct.push_back(direct_sample(l, sensor, disc, [&](const Eigen::Vector3d& F) {
          return l.model.point_load(p[0] + off[0], p[1] + off[1], F);
        }));
      }
    const auto gap = relative_gap(adjoint, direct);
    for (size_t c = 0; c < 4; ++c) {
      std::printf("point load, %s reading, g_%s: max |adjoint − direct| / peak = %.2e\n",
                  disc ? "disc" : "centre", component_name(kComponents[c]), gap[c]);
      EXPECT_LT(gap[c], 1e-9) << (disc ? "disc " : "centre ") << component_name(kComponents[c]);
    }
  }
  std::printf("total %.1f s\n", seconds_since(t0));
}

TEST(FeGreen, UniformPatchEqualsDirectPatchLoadToQuadratureAccuracy) {
  // Reference: reciprocity again, now for a uniform disc load (radius 0.25 mm, 1 N). ElasticModel::
  // patch_load spreads the force with a 16 × 48 polar Gauss rule, FeGreen::at integrates the adjoint
  // field with load_quadrature's 12 × 32 rule: the same integral by two rules. So
  //  (a) the adjoint field integrated with patch_load's own rule (load_quadrature(uniform, a, 16, 48),
  //      the same points and weights) equals the direct solve to round-off (1e-9, as for point loads);
  //  (b) FeGreen's 12 × 32 value reproduces the top-surface P2 interpolation done here to round-off;
  //  (c) direct − FeGreen = Q16×48 − Q12×32 is pure quadrature error. The integrand (the adjoint
  //      displacement on the top) is continuous and piecewise quadratic, with gradient jumps on the face
  //      edges crossing the disc, so the polar Gauss rule converges only algebraically and not
  //      monotonically. The bound used: with E_n the error of rule n, direct − FeGreen = E12 − E16 and
  //      Q24×64 − Q12×32 = E12 − E24; the finer rules are not worse than the 12 × 32 one (|E16|,
  //      |E24| ≤ |E12|, checked through the measured differences below), so |E12 − E16| ≤ 2|E12| ≤
  //      2(|Q24 − Q12| + |E24|) ≤ 4 max|Q24 − Q12| over the samples of the component. We assert the
  //      gap within 4× that measured refinement difference and, as a stated bound, within 2e-3 of the
  //      component's peak (a 0.25 mm disc over 0.25 mm faces: a few faces cut, kinks of O(h_face ×
  //      curvature of the field ~ 1e-3) relative).
  const auto t0 = std::chrono::steady_clock::now();
  const SmallLayer& l = small_layer();
  const PlanarFaceIndex top(l.mesh, kTop);
  const double a = 0.25;
  const auto q12 = load_quadrature(LayerLoad::uniform, a, 12, 32);
  const auto q16 = load_quadrature(LayerLoad::uniform, a, 16, 48);
  const auto q24 = load_quadrature(LayerLoad::uniform, a, 24, 64);
  for (bool disc : {false, true}) {
    std::vector<GreenSample> at, direct, own12, own16, own24;
    for (int sensor = 0; sensor < 2; ++sensor)
      for (const Vec2& off : kOffsets) {
        const auto& p = l.scene.sensors.positions[sensor];
        const double cx = p[0] + off[0], cy = p[1] + off[1];
        at.push_back(l.fe.at(sensor, disc, off[0], off[1], LayerLoad::uniform, a));
        direct.push_back(direct_sample(l, sensor, disc, [&](const Eigen::Vector3d& F) {
          return l.model.patch_load(TractionPatch{{cx, cy}, 2 * a, {F.x(), F.y(), F.z()}, 1.0});
        }));
        own12.push_back(adjoint_quadrature(l, top, sensor, disc, cx, cy, q12));
        own16.push_back(adjoint_quadrature(l, top, sensor, disc, cx, cy, q16));
        own24.push_back(adjoint_quadrature(l, top, sensor, disc, cx, cy, q24));
      }
    const auto exact_rule = relative_gap(own16, direct), same_rule = relative_gap(at, own12);
    const auto gap = relative_gap(at, direct), refine = relative_gap(own12, own24),
               fine = relative_gap(own16, own24);
    for (size_t c = 0; c < 4; ++c) {
      const char* name = component_name(kComponents[c]);
      std::printf(
          "uniform patch, %s reading, g_%s (relative to peak): direct vs adjoint 16x48 %.2e; FeGreen vs "
          "12x32 here %.2e; direct vs FeGreen %.2e; |Q24x64 − Q12x32| %.2e; |Q24x64 − Q16x48| %.2e\n",
          disc ? "disc" : "centre", name, exact_rule[c], same_rule[c], gap[c], refine[c], fine[c]);
      EXPECT_LT(exact_rule[c], 1e-9) << name;
      EXPECT_LT(same_rule[c], 1e-12) << name;
      EXPECT_LE(fine[c], refine[c]) << name;  // the finer rules are not worse (premise of the bound)
      EXPECT_LE(gap[c], 4 * refine[c] + 1e-9) << name;
      EXPECT_LT(gap[c], 2e-3) << name;
    }
  }
  std::printf("total %.1f s\n", seconds_since(t0));
}

TEST(FeGreen, ShippedFlatLayerMatchesTheExactLayer) {
  // Reference: the exact bonded-layer Green tensor (LayerGreen, Hankel transforms), converged to 1e-8
  // of the peak and better (test_layer_exact.cpp halves the panels and raises s_max), with the same load
  // model: the rigid-punch half-space pressure of radius 0.25 mm, scanned along |x| ≤ 4h at 0.05 mm.
  // Tolerances are the acceptance criteria of the k issue, not measured values: every disc-mean
  // component within 1 % of the exact peak, k_central and k_lsq_line (fit_profile on point values)
  // within 0.5 % of the exact ones.
  const auto t0 = std::chrono::steady_clock::now();
  const ShippedLayer& l = shipped_layer();
  const double h = l.scene.geometry.flat.h, a = 0.5 * l.scene.calibration.punch_diameter;
  ASSERT_EQ(l.scene.geometry.kind, GeometryKind::flat);
  ASSERT_DOUBLE_EQ(h, 3.04);
  ASSERT_DOUBLE_EQ(a, 0.25);
  std::printf("flat_layer: %d nodes, mesh + factor + 4 adjoint solves %.1f s, adjoint residual %.2e\n",
              l.mesh.num_nodes(), l.build_seconds, l.fe.max_adjoint_residual());
  const ScanProfile prof = scan_profile(l.fe, 0, LayerLoad::punch, a, 4 * h, 0.05);
  const LayerGreen layer(h, 0.5, LayerLoad::punch, a);
  const auto exact_point = exact_profile(layer, prof.offset_x);
  const auto exact_disc = exact_profile(layer, prof.offset_x, l.scene.sensors.disc_diameter);

  const auto err = max_error_over_peak(prof.disc, exact_disc);
  for (size_t c = 0; c < 4; ++c) {
    std::printf("disc mean g_%s: max |FE − exact| / exact peak = %.3e\n", component_name(kComponents[c]),
                err[c]);
    EXPECT_LT(err[c], 0.01) << component_name(kComponents[c]);
  }
  const KReport fe_k = fit_profile(prof.offset_x, prof.point, h);
  const KReport ex_k = fit_profile(prof.offset_x, exact_point, h);
  std::printf("k_central FE %.6f exact %.6f (%+.3f %%); k_lsq_line FE %.6f exact %.6f (%+.3f %%)\n",
              fe_k.k_central, ex_k.k_central, 100 * (fe_k.k_central / ex_k.k_central - 1), fe_k.k_lsq_line,
              ex_k.k_lsq_line, 100 * (fe_k.k_lsq_line / ex_k.k_lsq_line - 1));
  EXPECT_LT(std::abs(fe_k.k_central / ex_k.k_central - 1), 0.005);
  EXPECT_LT(std::abs(fe_k.k_lsq_line / ex_k.k_lsq_line - 1), 0.005);

  // The exact values pinned: the series is converged to 1e-8 relative (test_layer_exact.cpp), the fit
  // minimises to a 1e-12 bracket (kfit.hpp), so 1e-4 is pure rounding of the printed digits.
  EXPECT_NEAR(ex_k.k_central, 1.54996, 1e-4);
  EXPECT_NEAR(ex_k.k_lsq_line, 1.60856, 1e-4);
  // The paper's k = 1.48 (one FE run by its authors) is NOT reproduced for this load model by either
  // criterion: it lies outside k_central_exact ± 3 % (and further from k_lsq_line_exact), a margin
  // larger than every discretization error above.
  EXPECT_GT(std::abs(1.48 / ex_k.k_central - 1), 0.03);
  EXPECT_GT(std::abs(1.48 / ex_k.k_lsq_line - 1), 0.03);
  std::printf("paper k = 1.48: %+.2f %% from k_central_exact, %+.2f %% from k_lsq_line_exact\n",
              100 * (1.48 / ex_k.k_central - 1), 100 * (1.48 / ex_k.k_lsq_line - 1));
  std::printf("total %.1f s\n", seconds_since(t0));
}

TEST(FeGreen, GreenMapIntegratesToTheTotalForce) {
  // Reference: force balance (REFERENCES.md: ∬ g_zz dA = 1 at the base of any bonded layer), in its
  // exact discrete form. By reciprocity the disc reading of the direct solve for a uniform unit pressure
  // on the whole top, J = w·R with f = traction_load(top, (0, 0, −1)), equals y·f = ∫_top y·t dA =
  // −∫_top y_z dA for the adjoint y of the disc-mean σ_z reading: the same 7-point face rule builds f
  // and the integral here, so the two agree to solver tolerance (1e-9 relative; see the point-load test).
  // Both equal 1 up to the free side: under uniform pressure an infinite incompressible bonded layer
  // stays still with p = 1 (σ_zz = −1 everywhere, exactly representable by P2–P1), and the perturbation
  // of the free side decays into the layer like exp(−π r / 2h)·…, at r = 20 mm = 6.6 h below 1e-4. So
  // both must be within 1e-3 of 1.
  const auto t0 = std::chrono::steady_clock::now();
  const ShippedLayer& l = shipped_layer();
  const auto& pos = l.scene.sensors.positions.at(0);
  const Eigen::VectorXd& y = l.fe.adjoint(0, 'z', true);
  double map_integral = 0, top_area = 0;
  for (int f = 0; f < l.mesh.faces.rows(); ++f) {
    if (l.mesh.face_marker(f) != kTop) continue;
    for (const auto& q : face_quadrature(l.mesh, f)) {
      double yz = 0;
      for (int k = 0; k < 6; ++k) yz += q.N[k] * y[3 * l.mesh.faces(f, k) + 2];
      map_integral -= q.weight * yz;
      top_area += q.weight;
    }
  }
  const Eigen::VectorXd load = traction_load(
      l.mesh, kTop, [](const Eigen::Vector3d&, const Eigen::Vector3d&) { return Eigen::Vector3d(0, 0, -1); });
  const LoadCaseResult r = l.model.solve(load, {});
  const double direct =
      disc_reading_functional(l.mesh, pos[0], pos[1], l.scene.sensors.disc_diameter, 'z').dot(r.reactions);
  const double via_base = BaseTraction(l.mesh, r.reactions).disc_mean(pos[0], pos[1], 0.2).sigma_z;
  const double w = 2 * l.scene.geometry.flat.half_width;
  std::printf(
      "top area %.6f mm² (exact %.1f); ∬ g_zz dA = %.12f; direct disc reading %.12f (BaseTraction %.12f); "
      "|map − direct| = %.2e; |map − 1| = %.2e (%.1f s)\n",
      top_area, w * w, map_integral, direct, via_base, std::abs(map_integral - direct),
      std::abs(map_integral - 1), seconds_since(t0));
  EXPECT_NEAR(top_area, w * w, 1e-9 * w * w);  // flat top: the face rule is exact for the area
  EXPECT_NEAR(map_integral, direct, 1e-9);
  EXPECT_NEAR(via_base, direct, 1e-12);
  EXPECT_NEAR(map_integral, 1.0, 1e-3);
  EXPECT_NEAR(direct, 1.0, 1e-3);
}

}  // namespace
}  // namespace skinfem::green
