// The k ≈ 1.48 regression (ladder rungs 5 and 7): FE Green tensors of the shipped flat-layer scene
// against the exact bonded-layer solution, and reciprocity against direct solves.
#include <gtest/gtest.h>

#include <cmath>

#include "skinfem/fem/face_index.hpp"
#include "skinfem/green/calibration.hpp"
#include "skinfem/mesh/build.hpp"
#include "skinfem/scene/load.hpp"

namespace skinfem::green {
namespace {

TEST(KRegression, FlatLayerGreenTensorMatchesTheExactLayerAndPinsK) {
  // Reference: the exact layer (Hankel transforms, layer_exact.cpp), converged to 1e-8 of the peak
  // (test_layer_exact.cpp), with the same load profile (rigid-punch half-space pressure, a = 0.25 mm).
  // Tolerances are the acceptance criteria of the k issue; the refinement study in the closing note
  // and README (55k → 142k DOFs: worst component 2.5 % → 0.17 %, k_central −0.55 % → −0.17 %) shows the
  // shipped 97k-DOF mesh sits inside them with margin (0.4 %, −0.12 %).
  const Scene scene = load_scene(std::string(SKINFEM_SOURCE_DIR) + "/tests/green/data/flat_layer.json");
  const TetMesh mesh = build_mesh(scene);
  const ElasticModel model(mesh, scene.material, scene.geometry.side, {});
  const FeGreen fe(model, scene.sensors);
  const double h = scene.geometry.flat.h, a = 0.5 * scene.calibration.punch_diameter;
  const ScanProfile prof = scan_profile(fe, 0, LayerLoad::punch, a, 4 * h, scene.calibration.spacing);
  const LayerGreen layer(h, scene.material.nu, LayerLoad::punch, a);
  const auto exact_point = exact_profile(layer, prof.offset_x);
  const auto exact_disc = exact_profile(layer, prof.offset_x, scene.sensors.disc_diameter);

  const auto err = max_error_over_peak(prof.disc, exact_disc);
  for (size_t c = 0; c < 4; ++c) {
    std::printf("g_%s: max |FE − exact| / peak = %.2e\n", component_name(kComponents[c]), err[c]);
    EXPECT_LT(err[c], 0.01) << component_name(kComponents[c]);
  }
  const KReport fe_k = fit_profile(prof.offset_x, prof.point, h);
  const KReport ex_k = fit_profile(prof.offset_x, exact_point, h);
  std::printf("k_central FE %.5f exact %.5f; k_lsq_line FE %.5f exact %.5f\n", fe_k.k_central, ex_k.k_central,
              fe_k.k_lsq_line, ex_k.k_lsq_line);
  EXPECT_NEAR(fe_k.k_central / ex_k.k_central, 1.0, 0.005);
  EXPECT_NEAR(fe_k.k_lsq_line / ex_k.k_lsq_line, 1.0, 0.005);
  // Pinned exact values (regenerate: skinfem kfit tests/green/data/flat_layer.json → k_central_exact,
  // k_lsq_line_exact); the series is converged far below this tolerance.
  EXPECT_NEAR(ex_k.k_central, 1.54996, 1e-4);
  EXPECT_NEAR(ex_k.k_lsq_line, 1.60856, 1e-4);
  // The paper's k = 1.48 lies outside both, by more than any discretization error seen here.
  EXPECT_GT(ex_k.k_central / 1.48 - 1, 0.03);
  EXPECT_GT(ex_k.k_lsq_line / 1.48 - 1, 0.03);
  // A base-traction reading is already in the paper's units: calibrated as the paper did (thickness and
  // scale free), its scan gives the layer's thickness and scales of 1, within the FE profile's error
  // (every component within 1 % of the peak, above).
  const PaperCalibration cal =
      paper_calibration(prof.offset_x, prof.point, h, scene.material.nu, LayerLoad::punch, a);
  std::printf("paper calibration: thickness %.5f mm (h %.3f), scale_z %.5f, scale_x %.5f\n", cal.thickness_mm,
              h, cal.scale_z, cal.scale_x);
  EXPECT_NEAR(cal.thickness_mm / h, 1.0, 0.01);
  EXPECT_NEAR(cal.scale_z, 1.0, 0.01);
  EXPECT_NEAR(cal.scale_x, 1.0, 0.01);
}

TEST(KRegression, AdjointGreenMapEqualsDirectSolves) {
  // Maxwell–Betti: the adjoint value and the direct solve are the same linear functional of the same
  // discrete system, so they agree to the solver tolerance (relative residual 1e-10).
  Scene s;
  s.geometry.kind = GeometryKind::flat;
  s.geometry.flat = {1.5, 4.0};
  s.sensors.positions = {{0.0, 0.0}, {0.7, -0.4}};
  s.mesh.h_min = 0.25, s.mesh.h_max = 1.0, s.mesh.growth = 1.5;
  const TetMesh mesh = build_mesh(s);
  const ElasticModel model(mesh, s.material, SideCondition::free, {});
  const FeGreen fe(model, s.sensors);
  for (int sensor = 0; sensor < 2; ++sensor)
    for (const auto& off : {Vec2{0.0, 0.0}, Vec2{1.0, 0.3}, Vec2{-2.0, 0.5}})
      for (bool tangential : {false, true}) {
        const auto& p = s.sensors.positions[sensor];
        const Eigen::Vector3d force = tangential ? Eigen::Vector3d(1, 0, 0) : Eigen::Vector3d(0, 0, -1);
        const LoadCaseResult r = model.solve(model.point_load(p[0] + off[0], p[1] + off[1], force), {});
        const BaseTraction base(mesh, r.reactions);
        for (bool disc : {false, true}) {
          const SensorReading direct = disc
                                           ? base.disc_mean(p[0], p[1], s.sensors.disc_diameter)
                                           : base.point_value(p[0], p[1], meshed_thickness(mesh, p[0], p[1]));
          const GreenSample g = fe.at(sensor, disc, off[0], off[1], LayerLoad::point, 0);
          const double scale = 3 / (2 * M_PI * 1.5 * 1.5);  // Boussinesq peak at this depth
          EXPECT_NEAR(tangential ? g.xz : g.zz, direct.sigma_z, 1e-9 * scale);
          EXPECT_NEAR(tangential ? g.xx : g.zx, direct.sigma_x, 1e-9 * scale);
        }
      }
}

}  // namespace
}  // namespace skinfem::green
