// The Green tensor of the neo-Hookean skin about a preload (pipeline/preloaded_skin.hpp) against: the linear
// skin at rest (the tangent there is the linear incompressible system exactly, an independent assembly), and
// full finite-strain solves of the preload plus a small point force, whose readings' change over the force
// must tend to the tangent's adjoint value at first order (a wrong state, a wrong share of the patch on the
// half mesh or a wrong reading would leave an error that does not vanish with the force).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "skinfem/fem/finite_strain.hpp"
#include "skinfem/fem/newton.hpp"
#include "skinfem/fem/sensor_reading.hpp"
#include "skinfem/fem/supports.hpp"
#include "skinfem/green/fe_green.hpp"
#include "skinfem/mesh/build.hpp"
#include "skinfem/pipeline/preloaded_skin.hpp"

namespace skinfem::pipeline {
namespace {

// A 3 mm neo-Hookean layer, two sensors on the x axis, pressed by a 1 N patch of 3 mm at the origin
// (its mean pressure 0.14 MPa, a twentieth of E: the largest displacement 0.06 mm).
Scene preloaded_layer() {
  Scene s;
  s.name = "preloaded_layer";
  s.geometry.kind = GeometryKind::flat;
  s.geometry.flat.h = 3.0;
  s.geometry.flat.half_width = 8.0;
  s.material = {3.0, 0.5, MaterialModel::neo_hookean};
  s.sensors.positions = {{0.0, 0.0}, {1.0, 0.0}};
  s.sensors.disc_diameter = 0.2;
  s.mesh.h_min = 0.8;
  s.mesh.growth = 1.8;
  s.mesh.h_max = 2.5;
  s.mesh.refine_sensors = false;
  s.loads.patches = {TractionPatch{{0.0, 0.0}, 3.0, {0, 0, -1}, 1.0}};
  return s;
}

TEST(PreloadedSkin, APatchOnTheCutLoadsTheHalfWithHalfItsForce) {
  Scene s = preloaded_layer();
  const TractionPatch& patch = s.loads.patches[0];
  for (MeshPart part : {MeshPart::whole, MeshPart::half_y}) {
    const TetMesh mesh = build_mesh(s, part);
    const Eigen::VectorXd f = patch_load(mesh, patch);
    double fz = 0;
    for (int i = 0; i < mesh.num_nodes(); ++i) fz += f[3 * i + 2];
    const double share = part == MeshPart::half_y ? 0.5 : 1.0;
    EXPECT_NEAR(fz, -share * patch.force, 1e-12 * patch.force);
  }
}

TEST(PreloadedSkin, AtRestItsGreenTensorIsTheLinearSkins) {
  Scene s = preloaded_layer();
  s.loads.patches.clear();
  Preload preload;
  const std::shared_ptr<Skin> tangent = preloaded_skin(s, MeshPart::half_y, &preload);
  EXPECT_TRUE(preload.steps.empty());
  Scene linear = s;
  linear.material.model = MaterialModel::linear;
  const std::shared_ptr<Skin> skin = skin_setup(linear, MeshPart::half_y);
  const green::FeGreen a(*tangent->model, s.sensors), b(*skin->model, s.sensors);
  for (double ox : {-1.5, 0.0, 0.7, 2.0}) {
    const green::GreenSample ga = a.at(0, true, ox, 0.0, green::LayerLoad::point, 0);
    const green::GreenSample gb = b.at(0, true, ox, 0.0, green::LayerLoad::point, 0);
    const double scale = std::abs(b.at(0, true, 0, 0, green::LayerLoad::point, 0).zz);
    EXPECT_NEAR(ga.zz, gb.zz, 1e-12 * scale) << ox;
    EXPECT_NEAR(ga.zx, gb.zx, 1e-12 * scale) << ox;
    EXPECT_NEAR(ga.xz, gb.xz, 1e-12 * scale) << ox;
    EXPECT_NEAR(ga.xx, gb.xx, 1e-12 * scale) << ox;
  }
}

TEST(PreloadedSkin, TheTangentsGreenTensorIsTheFullSolvesDerivative) {
  // A downward point force ε at (0.7, 0) on top of the preload, on the half mesh (the half carries ε/2 of a
  // force on its cut, as it carries half the patch): sensor 1's readings change by
  // ε (g_zz, g_zx) + O(ε²), so the finite difference of two full solves over ε differs from the adjoint
  // value by O(ε): halving ε halves it (local order 1 ± 0.2 over ε = 0.04, 0.02, 0.01 N, 4 to 1 % of the
  // preload; Newton's 1e-10 residual is far below).
  const Scene s = preloaded_layer();
  Preload preload;
  const std::shared_ptr<Skin> skin = preloaded_skin(s, MeshPart::half_y, &preload);
  ASSERT_FALSE(preload.steps.empty());
  const green::FeGreen fe(*skin->model, s.sensors);
  const double x = 0.7, y = 0.0;
  const green::GreenSample g = fe.at(0, true, x, y, green::LayerLoad::point, 0);

  const TetMesh& mesh = skin->mesh;
  const double mu = Lame::from(s.material.E, s.material.nu).mu;
  const Supports held = skin_supports(mesh, s.geometry.side, {});
  const SensorReadings readings(mesh, reading_sites(s.sensors));
  const Eigen::VectorXd f0 = patch_load(mesh, s.loads.patches[0]);
  const auto read = [&](const Eigen::VectorXd& f) {
    const FiniteStrainResult r = solve_finite_strain(mesh, mu, held.fixed, f);
    return readings.read(0, support_reactions(held, r.internal_force - f));
  };
  const SensorReading base = read(f0);
  std::vector<double> err;
  for (double eps : {0.04, 0.02, 0.01}) {
    const SensorReading r = read(f0 + skin->model->point_load(x, y, {0, 0, -0.5 * eps}));
    const double dz = (r.sigma_z - base.sigma_z) / eps, dx = (r.sigma_x - base.sigma_x) / eps;
    err.push_back(std::hypot(dz - g.zz, dx - g.zx) / std::hypot(g.zz, g.zx));
    std::printf("eps %.3g N: finite difference (%.6e, %.6e), tangent (%.6e, %.6e) per N, relative gap %.3e\n",
                eps, dz, dx, g.zz, g.zx, err.back());
  }
  EXPECT_LT(err.back(), 0.05);
  for (size_t i = 1; i < err.size(); ++i) EXPECT_NEAR(std::log2(err[i - 1] / err[i]), 1.0, 0.2) << err[i];
}

}  // namespace
}  // namespace skinfem::pipeline
