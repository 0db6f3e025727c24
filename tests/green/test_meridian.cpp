// The meridian (axisymmetric, mode 0) Green map of the axis sensor (green/meridian.hpp) against two
// independent references: the exact bonded layer (green/layer_exact.hpp, Hankel transforms) and the 3D
// solver (green/fe_green.hpp) on a cap's apex sensor, each over three mesh levels with the observed order
// fitted.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "../common/convergence.hpp"
#include "fem/elastic_model.hpp"
#include "green/fe_green.hpp"
#include "green/layer_exact.hpp"
#include "green/meridian.hpp"
#include "mesh/build.hpp"

namespace skinfem {
namespace {

constexpr double kA = 0.25;  // the calibration punch radius, mm

// The rigid-punch load (green/fe_green.hpp's quadrature) centred at offset x on the axis sensor.
double punch_reading(const MeridianGreen& g, double x) {
  double v = 0;
  for (const auto& q : green::load_quadrature(green::LayerLoad::punch, kA))
    v += q[2] * g.zz(std::hypot(x + q[0], q[1]));
  return v;
}

TEST(MeridianGreen, FlatLayerConvergesToTheExactLayer) {
  // The exact layer is unbounded: the meridian reaches 60 mm (20 h), where the side's influence,
  // exp(−0.739 r/h) (README, Truncation), is below 1e-6. Cells grow geometrically from the axis (β = 3.6:
  // 0.1 mm to 3.7 mm at 60 radial cells) and cluster toward base and top.
  constexpr double h = 3.04;
  const green::LayerGreen point(h, 0.5, green::LayerLoad::point, 0),
      punch(h, 0.5, green::LayerLoad::punch, kA);
  std::vector<double> size, err_centre, err_map;
  double err_offsets = 0;
  for (int level : {2, 4, 8}) {
    const MeridianMesh m = meridian_mesh([](double) { return h; }, 60.0, 30 * level, 6 * level, 3.6, 0.5);
    const MeridianGreen g(m, 0.5);
    err_offsets = 0;
    for (double x : {1.0, 2.0, 4.0})
      err_offsets = std::max(err_offsets, std::abs(punch_reading(g, x) / punch.at(x, 0).zz - 1));
    double map_err = 0;
    for (double rho = 0; rho <= 12; rho += 0.05)
      map_err = std::max(map_err, std::abs(g.zz(rho) - point.at(rho, 0).zz) / point.at(0, 0).zz);
    size.push_back(1.0 / level);
    err_centre.push_back(std::abs(punch_reading(g, 0) / punch.at(0, 0).zz - 1));
    err_map.push_back(map_err);
    std::printf(
        "level %d: %d DOFs; punch reading at 0: error %.2e, at 1, 2, 4 mm: max %.2e; point map: %.2e "
        "of peak\n",
        level, g.dofs(), err_centre.back(), err_offsets, map_err);
  }
  const double order = testing::observed_order(size, err_map);
  std::printf("observed order of the point map %.2f\n", order);
  // Measured: point map 6.2e-3, 5.5e-4, 4.5e-5 of peak (order 3.6); the punch reading at 0, which gives
  // k_central, within 3e-5 at the finest level; at 1-4 mm, where g is smaller, within 3.2e-4. The issue's
  // target for k is 0.01 %.
  EXPECT_GT(order, 2.5);
  EXPECT_LT(err_centre.back(), 1e-4);
  EXPECT_LT(err_map.back(), 1e-4);
  EXPECT_LT(err_offsets, 1e-3);
}

TEST(MeridianGreen, CapApexAgreesWithThe3DSolver) {
  // A cap R = 20 mm, h = 3 mm, cut at 6 mm (side free), the sensor at its apex: the meridian solve against
  // the 3D reciprocity solve at three 3D mesh levels. The meridian at 4x its base resolution is converged
  // well below the 3D error (previous test: 3e-5), so |3D − meridian| is the 3D error and must fall with
  // the 3D mesh at an observed order. Measured: 2.6e-2, 1.6e-2, 4.0e-3 (13k, 29k, 57k DOFs; order 2.7).
  Scene s;
  s.geometry.kind = GeometryKind::cap;
  s.geometry.cap = {20.0, 3.0, 0.0, 0.0, 6.0};
  s.sensors.positions = {{0.0, 0.0}};
  s.sensors.disc_diameter = 0.2;
  s.mesh.growth = 1.5;
  const auto top = [](double r) { return 3.0 - 20.0 + std::sqrt(400.0 - r * r); };
  const MeridianGreen g2(meridian_mesh(top, 6.0, 120, 24, 2.0, 0.5), 0.5);
  std::vector<double> size, err;
  for (double scale : {2.0, 1.41, 1.0}) {
    s.mesh.h_min = 0.3 * scale, s.mesh.h_max = 1.2 * scale;
    const TetMesh mesh = build_mesh(s);
    const ElasticModel model(mesh, s.material, SideCondition::free, {});
    const green::FeGreen fe(model, s.sensors);
    double e = 0;
    for (double x : {0.0, 1.0, 2.0}) {
      const double g3 = fe.at(0, false, x, 0, green::LayerLoad::punch, kA).zz;
      e = std::max(e, std::abs(g3 / punch_reading(g2, x) - 1));
    }
    std::printf("3D h_min %.2f mm: %d DOFs, max |3D / meridian - 1| at 0, 1, 2 mm: %.2e\n", s.mesh.h_min,
                model.solver().free_dofs(), e);
    size.push_back(scale);
    err.push_back(e);
  }
  const double order = testing::observed_order(size, err);
  std::printf("observed order of the 3D error %.2f\n", order);
  EXPECT_GT(order, 1.0);
  EXPECT_LT(err.back(), 5e-3);
}

}  // namespace
}  // namespace skinfem
