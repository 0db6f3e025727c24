// The meridian contact path (contact/meridian_contact.hpp) against the exact bonded-layer Hertz contact
// (contact/layer_hertz.hpp, an independent Fredholm solution): a sphere pressed on a flat incompressible
// layer, scenes/hertz_layer.json's numbers.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "skinfem/contact/layer_hertz.hpp"
#include "skinfem/contact/layer_hertz_interface.hpp"
#include "skinfem/contact/meridian_contact.hpp"
#include "skinfem/green/layer_exact.hpp"
#include "skinfem/mesh/gauss_legendre.hpp"

namespace skinfem::contact {
namespace {

constexpr double kH = 3.04, kE = 3, kR = 129.7, kF = 0.8, kZone = 3.3;

MeridianContactSkin flat_layer() {
  // 20 h: the unbounded layer (pipeline/sensor_greens.hpp, kUnboundedRadiusOverH).
  return {[](double) { return kH; }, 20 * kH, kH, SideCondition::free, kE, 0.5};
}

double sphere_gap(double r) { return r * r / (kR + std::sqrt(kR * kR - r * r)); }

struct Errors {
  double a, p0, delta, pressure;  // relative; the pressure's largest nodal error over p0
  int dofs;
  double profile = 0;  // pressure_at's largest error over p0 on 4000 radii to 1.2 a (between the nodes too)
};

Errors against_exact(const MeridianContactResult& m, const LayerHertzResult& ex) {
  Errors e{m.contact_radius_mm / ex.a_mm - 1, m.p0_MPa / ex.p0_MPa - 1, m.depth_mm / ex.delta_mm - 1, 0,
           m.dofs};
  for (size_t i = 0; i < m.r.size(); ++i)
    e.pressure = std::max(e.pressure, std::abs(m.lambda[i] - ex.pressure_MPa(m.r[i])) / ex.p0_MPa);
  for (int j = 0; j <= 4000; ++j) {
    const double r = 1.2 * ex.a_mm * j / 4000;
    e.profile = std::max(e.profile, std::abs(m.pressure_at(r) - ex.pressure_MPa(r)) / ex.p0_MPa);
  }
  return e;
}

TEST(MeridianContact, HertzOnTheBondedLayerConvergesToTheExactSolution) {
  const LayerHertzResult ex = layer_hertz_force(kF, kR, kH, kE, 0.5);
  std::vector<Errors> levels;
  for (double scale : {2.0, 1.41, 1.0}) {
    const MeridianContactResult m = meridian_contact(flat_layer(), kZone, sphere_gap, MeridianContactLoad{kF},
                                                     {}, MeridianContactSizes::for_zone(kZone, kH, scale));
    const Errors e = against_exact(m, ex);
    std::printf(
        "scale %.2f: %d multipliers, %d DOFs; a %+.2e p0 %+.2e delta %+.2e, pressure %.2e of p0 (profile "
        "%.2e); "
        "%.3f s (mesh %.3f, assemble %.3f, factor %.3f, condense %.3f, LCP %.3f)\n",
        scale, m.multipliers, m.dofs, e.a, e.p0, e.delta, e.pressure, e.profile,
        m.cost.mesh_s + m.cost.assemble_s + m.cost.factor_s + m.cost.condense_s + m.cost.lcp_s, m.cost.mesh_s,
        m.cost.assemble_s, m.cost.factor_s, m.cost.condense_s, m.cost.lcp_s);
    EXPECT_NEAR(m.force_N, kF, 1e-12 * kF);
    EXPECT_LT(m.complementarity, 1e-10);
    levels.push_back(e);
  }
  // Issue 29's targets at the default sizes (scale 1): a, p0, δ within 0.05 %, the pressure within 1 % of p0
  // at every multiplier, the contact edge included.
  const Errors& fine = levels.back();
  EXPECT_LT(std::abs(fine.a), 5e-4);
  EXPECT_LT(std::abs(fine.p0), 5e-4);
  EXPECT_LT(std::abs(fine.delta), 5e-4);
  EXPECT_LT(fine.pressure, 1e-2);
  // The profile the report draws (pressure_at, between the nodes too) within issue 30's 2 % of p0 everywhere;
  // over scales 2, 1.41, 1 it measured 3.4 %, 0.80 %, 0.35 %.
  EXPECT_LT(fine.profile, 1e-2);
  // p0 converges at the P2 rate in the cell size (observed order fitted over the three levels); the edge's
  // pressure error depends on where the edge falls between multipliers, so it is bounded, not fitted.
  const double order = std::log(std::abs(levels[0].p0 / levels[2].p0)) / std::log(2.0);
  std::printf("observed order of p0's error: %.2f\n", order);
  EXPECT_GT(order, 1.5);
  EXPECT_LT(levels[1].pressure, 1e-2);
}

// Through a linear interface in series (K = 30 and 3 MPa/mm: closure at p0 of 2 and 16 µm against δ of 30
// and 38 µm) against the exact layer with the same interface (contact/layer_hertz_interface.hpp, a Chebyshev
// series converging algebraically: 64 terms).
TEST(MeridianContact, ThroughALinearInterfaceConvergesToTheExactSolution) {
  for (double K : {30.0, 3.0}) {
    const LayerHertzInterfaceResult ex = layer_hertz_interface_force(kF, kR, kH, kE, 0.5, K);
    MeridianContactSkin skin = flat_layer();
    skin.interface_K = K;
    std::vector<Errors> levels;
    for (double scale : {2.0, 1.41, 1.0}) {
      const double zone = K < 10 ? 4.5 : kZone;  // the compliant interface's contact is larger
      const MeridianContactResult m = meridian_contact(skin, zone, sphere_gap, MeridianContactLoad{kF}, {},
                                                       MeridianContactSizes::for_zone(zone, kH, scale));
      const Errors e{m.contact_radius_mm / ex.a_mm - 1, m.p0_MPa / ex.p0_MPa - 1,
                     m.depth_mm / ex.delta_mm - 1, 0, m.dofs};
      std::printf("K = %g, scale %.2f: a %+.2e p0 %+.2e delta %+.2e\n", K, scale, e.a, e.p0, e.delta);
      levels.push_back(e);
    }
    // The hard contact's targets at the default sizes; p0 converging (order fitted over the three levels).
    EXPECT_LT(std::abs(levels[2].a), 5e-4) << "K = " << K;
    EXPECT_LT(std::abs(levels[2].p0), 5e-4) << "K = " << K;
    EXPECT_LT(std::abs(levels[2].delta), 5e-4) << "K = " << K;
    EXPECT_GT(std::log(std::abs(levels[0].p0 / levels[2].p0)) / std::log(2.0), 1.2) << "K = " << K;
  }
}

// Sensor readings of the frictionless and the uncoupled contact against a second, independent route: the
// exact layer's Green tensor (green/layer_exact.hpp, Hankel transforms; disc means) integrated against the
// exact Hertz-layer pressure, σ_z = ∫ p g_zz dA, σ_x = ∫ p g_zx dA, and per unit Coulomb ratio along +x
// ∫ p g_xz dA and ∫ p g_xx dA. Sensors on y = 0 from the axis to 4.5 mm (the layer is symmetric in x).
TEST(MeridianContact, ReadingsAreTheExactLayersGreenTensorAgainstTheExactPressure) {
  const LayerHertzResult ex = layer_hertz_force(kF, kR, kH, kE, 0.5);
  const double b = 0.1;  // disc radius, mm
  const green::LayerGreen G(kH, 0.5, green::LayerLoad::point, 0, {}, b);
  std::vector<ReadingSite> sites;
  for (double x : {0.0, 1.5, 2.5, 3.5, 4.5}) sites.push_back(disc_site({x, 0}, 2 * b));
  // The exact readings: polar Gauss over the contact disc, r = a sin t (p ~ √(a − r) made smooth).
  const GaussRule1d gr = gauss_legendre01(48), ga = gauss_legendre01(96);
  Eigen::MatrixXd exact = Eigen::MatrixXd::Zero(4, sites.size());  // σ_z, σ_x; per ratio σ_z, σ_x
  for (size_t i = 0; i < gr.x.size(); ++i) {
    const double t = 0.5 * M_PI * gr.x[i], r = ex.a_mm * std::sin(t);
    const double w_r = gr.w[i] * 0.5 * M_PI * ex.a_mm * std::cos(t) * r * ex.pressure_MPa(r);
    for (size_t j = 0; j < ga.x.size(); ++j) {
      const double th = 2 * M_PI * ga.x[j], w = w_r * 2 * M_PI * ga.w[j];
      for (size_t k = 0; k < sites.size(); ++k) {
        const green::GreenSample g = G.at(r * std::cos(th) - sites[k].center[0], r * std::sin(th));
        exact.col(k) += w * Eigen::Vector4d(g.zz, g.zx, g.xz, g.xx);
      }
    }
  }
  const double peak = exact.row(0).cwiseAbs().maxCoeff();
  std::vector<double> errors;
  for (double scale : {2.0, 1.41, 1.0}) {
    const MeridianContactResult m =
        meridian_contact(flat_layer(), kZone, sphere_gap, MeridianContactLoad{kF, 0, {1, 0}}, sites,
                         MeridianContactSizes::for_zone(kZone, kH, scale));
    double e = 0;
    for (size_t k = 0; k < sites.size(); ++k) {
      const Eigen::Vector4d fe(m.readings[2 * k], m.readings[2 * k + 1], m.readings_per_ratio[2 * k],
                               m.readings_per_ratio[2 * k + 1]);
      e = std::max(e, (fe - exact.col(k)).cwiseAbs().maxCoeff() / peak);
    }
    std::printf("scale %.2f: largest reading error %.2e of the peak reading (%.4f kPa)\n", scale, e,
                1e3 * peak);
    errors.push_back(e);
  }
  // Within the 3D path's own error on this problem (0.1 % of the peak reading, README) at the default sizes,
  // converging: the order fitted over the three levels (cells × 2, × 1.41, × 1).
  const double order = std::log(errors[0] / errors[2]) / std::log(2.0);
  std::printf("observed order of the readings' error: %.2f\n", order);
  EXPECT_GT(order, 1.5);
  EXPECT_LT(errors[2], 1e-3);
}

}  // namespace
}  // namespace skinfem::contact
