// The paper's convolution model (validation/paper_model.hpp) against independent values: the exact layer's
// own disc-load tensor, and a full FE solve of a traction patch; its cached form against the plain one.
#include <gtest/gtest.h>

#include <cmath>

#include "skinfem/contact/mortar.hpp"
#include "skinfem/fem/base_traction.hpp"
#include "skinfem/mesh/build.hpp"
#include "skinfem/validation/paper_model.hpp"

namespace skinfem::validation {
namespace {

Sensors line_of_sensors() {
  Sensors s;
  s.positions = {{-2.0, 0.0}, {-0.7, 0.3}, {0.0, 0.0}, {1.1, 0.0}, {2.5, -0.4}};
  s.disc_diameter = 0.2;
  return s;
}

// A uniform disc load (radius 0.6 mm, 1 N, p_x = 0.4 p_z) convolved with the exact layer's point tensor
// equals the exact layer's tensor for that disc load (green/layer_exact.hpp, its own Hankel profile
// 2J1(sa)/(sa)): two independent evaluations of the same integral. Error budget: the polar rule is exact to
// ~1e-10 on this smooth integrand; the kernel's linear interpolation every 0.01 mm errs by (0.01/h)²/8 ≈ 1e-6
// of the peak (h = 3.04 mm); tolerance 1e-5 of each component's peak.
TEST(PaperModel, ExactLayerKernelConvolvesToTheExactDiscLoad) {
  const double h = 3.04, nu = 0.5, a = 0.6, ratio = 0.4;
  const Sensors sensors = line_of_sensors();
  const Tractions t =
      axisymmetric_tractions([a](double) { return 1.0 / (M_PI * a * a); }, {0.3, 0.1}, a, ratio);
  EXPECT_NEAR(t.force(), 1.0, 1e-12);
  const Eigen::VectorXd model = convolve(t, layer_exact_kernel(h, nu, 4.0), sensors);
  const green::LayerGreen disc(h, nu, green::LayerLoad::uniform, a);
  const green::LayerGreen point(h, nu);
  const double peak_z = point.at(1e-9, 0).zz, peak_x = point.at(0.5 * h, 0).zx;
  for (size_t k = 0; k < sensors.positions.size(); ++k) {
    const green::GreenSample g = disc.at(0.3 - sensors.positions[k][0], 0.1 - sensors.positions[k][1]);
    EXPECT_NEAR(model[2 * k], g.zz + ratio * g.xz, 1e-5 * peak_z) << "sensor " << k;
    EXPECT_NEAR(model[2 * k + 1], g.zx + ratio * g.xx, 1e-5 * std::abs(peak_x)) << "sensor " << k;
  }
}

// The rescaled half-space kernel with k = 1 is Boussinesq–Cerruti's tensor, and k rescales it as
// docs/theory.md §Conventions says: amplitude × k, width × k^−1/2.
TEST(PaperModel, RescaledKernelFollowsItsDefinition) {
  const GreenKernel g1 = rescaled_halfspace_kernel({3.0}, 1.0), gk = rescaled_halfspace_kernel({3.0}, 1.48);
  for (double x : {0.0, 0.7, 2.0}) {
    const green::GreenSample a = g1(0, x, 0.2), b = green::halfspace_green(x, 0.2, 3.0);
    EXPECT_DOUBLE_EQ(a.zz, b.zz);
    EXPECT_DOUBLE_EQ(a.xx, b.xx);
    const green::GreenSample c = gk(0, x / std::sqrt(1.48), 0.2 / std::sqrt(1.48));
    EXPECT_NEAR(c.zz, 1.48 * b.zz, 1e-15);
    EXPECT_NEAR(c.zx, 1.48 * b.zx, 1e-15);
  }
}

// A uniform traction patch on a flat layer: the FE readings of one full solve (base reactions) against the
// convolution of the same traction with the FE Green maps (reciprocity): two methods on one mesh. Both
// integrate the piecewise-quadratic adjoint trace over the disc with rules that ignore the element edges
// (16 × 48 points in the solve, 48 × 96 in the model): halving the model's rule moves it by 6e-7 of the
// peak reading, and the two agreed to 1.3e-6; tolerance 1e-5 of the peak.
TEST(PaperModel, FeKernelConvolutionEqualsAFullSolveForAPatch) {
  Scene s;
  s.geometry.kind = GeometryKind::flat;
  s.geometry.flat = {3.04, 7.0};
  s.material = {3.0, 0.5};
  s.sensors = line_of_sensors();
  s.mesh.h_min = 0.4;
  s.mesh.h_max = 2.0;
  s.mesh.growth = 1.7;
  s.mesh.refine_sensors = true;
  const TetMesh mesh = build_mesh(s);
  ElasticModel model(mesh, s.material, s.geometry.side, {});
  const green::FeGreen fe(model, s.sensors);
  const double ratio = 0.5, F = 0.8, a = 0.5;
  TractionPatch normal{{0.2, 0.1}, 2 * a, {0, 0, -1}, F}, shear{{0.2, 0.1}, 2 * a, {1, 0, 0}, ratio * F};
  const Eigen::VectorXd load = model.patch_load(normal) + model.patch_load(shear);
  const MixedSolution x = model.solver().solve(load);
  const BaseTraction base(mesh, model.solver().reactions(x, load));
  const Eigen::VectorXd conv =
      convolve(axisymmetric_tractions([&](double) { return F / (M_PI * a * a); }, {0.2, 0.1}, a, ratio),
               fe_kernel(fe), s.sensors);
  double peak = 0;
  for (size_t k = 0; k < s.sensors.positions.size(); ++k) {
    const SensorReading v = base.disc_mean(s.sensors.positions[k][0], s.sensors.positions[k][1], 0.2);
    peak = std::max(peak, std::abs(v.sigma_z));
  }
  for (size_t k = 0; k < s.sensors.positions.size(); ++k) {
    const SensorReading v = base.disc_mean(s.sensors.positions[k][0], s.sensors.positions[k][1], 0.2);
    EXPECT_NEAR(conv[2 * k], v.sigma_z, 1e-5 * peak) << "sensor " << k;
    EXPECT_NEAR(conv[2 * k + 1], v.sigma_x, 1e-5 * peak) << "sensor " << k;
  }
}

// A sweep's frames convolved through FeConvolution (the kernel evaluated once per quadrature point) are
// convolve(fe_tractions(...)) to the last bit: the same points, weights and sums in the same order, whether
// the pressure is zero on some faces, with or without a nodal shear.
TEST(PaperModel, FeConvolutionIsTheConvolutionOfFeTractionsToTheLastBit) {
  Scene s;
  s.geometry.kind = GeometryKind::flat;
  s.geometry.flat = {3.04, 7.0};
  s.sensors = line_of_sensors();
  s.mesh.h_min = 0.4;
  s.mesh.h_max = 2.0;
  s.mesh.growth = 1.7;
  const TetMesh mesh = build_mesh(s);
  const contact::MortarZone zone = contact::mortar_zone(mesh, {0.3, -0.2}, 2.2);
  ASSERT_GT(zone.size(), 10);
  const GreenKernel k = rescaled_halfspace_kernel(std::vector<double>(5, 3.04), 1.48);
  const FeConvolution on_zone(zone, mesh, k, s.sensors);
  Eigen::VectorXd lambda(zone.size()), shear(zone.size());
  for (int i = 0; i < zone.size(); ++i) {
    lambda[i] = i % 4 == 0 ? 0.0 : 0.01 * (1 + std::sin(1.7 * i));  // zeros: points fe_tractions skips
    shear[i] = 0.003 * std::cos(0.9 * i);
  }
  for (const Eigen::VectorXd& t : {Eigen::VectorXd(), shear}) {
    const Eigen::VectorXd a = on_zone(lambda, 0.4, t),
                          b = convolve(fe_tractions(zone, mesh, lambda, 0.4, t), k, s.sensors);
    ASSERT_EQ(a.size(), b.size());
    EXPECT_GT(b.cwiseAbs().maxCoeff(), 0.0);
    for (int j = 0; j < a.size(); ++j)
      EXPECT_EQ(a[j], b[j]) << "reading " << j << (t.size() ? " with shear" : "");
  }
}

// Eqs. (2)–(3) at one position, by hand: −(p_x g_x· + p_z g_z·) S.
TEST(PaperModel, FirstOrderHoleIsTheLocalTractionTimesTheKernel) {
  const Sensors sensors = line_of_sensors();
  const double a = 2.0, p0 = 0.05, ratio = 3.0, S = M_PI * 0.25 * 0.25;
  const Tractions t =
      axisymmetric_tractions([=](double r) { return p0 * std::sqrt(1 - r * r / (a * a)); }, {0, 0}, a, ratio);
  const GreenKernel g = rescaled_halfspace_kernel(std::vector<double>(sensors.positions.size(), 3.04), 1.48);
  const Eigen::MatrixXd hole = first_order_hole(t, g, sensors, {{0.5, 0.0}, {3.0, 0.0}}, S);
  const double p = p0 * std::sqrt(1 - 0.25 / (a * a));
  for (size_t k = 0; k < sensors.positions.size(); ++k) {
    const green::GreenSample G = g(k, 0.5 - sensors.positions[k][0], -sensors.positions[k][1]);
    EXPECT_NEAR(hole(0, 2 * k), -(ratio * p * G.xz + p * G.zz) * S, 1e-15);
    EXPECT_NEAR(hole(0, 2 * k + 1), -(ratio * p * G.xx + p * G.zx) * S, 1e-15);
    EXPECT_EQ(hole(1, 2 * k), 0.0);  // outside the contact: no pressure, no signal
  }
}

}  // namespace
}  // namespace skinfem::validation
