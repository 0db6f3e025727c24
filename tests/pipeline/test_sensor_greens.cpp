// pipeline/sensor_greens: the 3D path's Green maps over a sensor's whole footprint on the top, off its line
// as well as on it, against the exact bonded layer (green/layer_exact.hpp, Hankel transforms).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "../common/convergence.hpp"
#include "skinfem/green/layer_exact.hpp"
#include "skinfem/mesh/sizing.hpp"
#include "skinfem/pipeline/sensor_greens.hpp"
#include "skinfem/scene/load.hpp"

namespace skinfem::pipeline {
namespace {

using green::GreenSample;

std::array<double, 4> as_array(const GreenSample& g) { return {g.zz, g.zx, g.xz, g.xx}; }

TEST(SensorGreens, ThreeDMapsOffTheSensorLineConvergeToTheExactLayer) {
  // scenes/flat_layer.json (h = 3.04 mm, one 0.2 mm disc at the origin; its side 20 mm away, where it
  // moves the maps by < 1e-6 of their peak within 2h of the sensor: docs/scenes.md "Truncation"), solved in
  // 3D at mesh scales 2, 1.41 and 1. The disc readings for a unit point force anywhere within 2h of the
  // sensor (polar grid, every h/30 and 10°: on and off the sensor line) against the exact layer's disc means.
  // Bound: 0.5 % of each component's peak at the shipped sizes, where the top within one thickness of the
  // sensor is meshed at 0.2 thickness (the map footprint region of the scene); and the error must fall
  // with the mesh at an observed order ≥ 1.5 over the three levels (P2 maps of a smooth kernel: order 2–3).
  // The same for the sensor's point value (fem/base_traction.hpp point_value_rule, the limit of two disc
  // means) against the exact layer's value at a point, from the same solves.
  const Scene base = load_scene(std::string(SKINFEM_SOURCE_DIR) + "/scenes/flat_layer.json");
  const double h = base.geometry.flat.h;
  const green::LayerGreen exact(h, base.material.nu, green::LayerLoad::point, 0, {},
                                0.5 * base.sensors.disc_diameter),
      exact_point(h, base.material.nu, green::LayerLoad::point, 0);
  std::vector<std::array<double, 2>> points;
  for (int i = 0; i <= 60; ++i)
    for (int j = 0; j < (i == 0 ? 1 : 36); ++j) {
      const double r = i * h / 30, t = j * M_PI / 18;
      points.push_back({r * std::cos(t), r * std::sin(t)});
    }
  // [0]: disc readings, [1]: point values.
  std::array<std::vector<std::array<double, 4>>, 2> ref;
  std::array<std::array<double, 4>, 2> peak{};
  for (const auto& p : points)
    for (int kind = 0; kind < 2; ++kind) {
      ref[kind].push_back(as_array((kind == 0 ? exact : exact_point).at(p[0], p[1])));
      for (int c = 0; c < 4; ++c) peak[kind][c] = std::max(peak[kind][c], std::abs(ref[kind].back()[c]));
    }
  const std::vector<double> scales = {2.0, 1.41, 1.0};
  std::array<std::vector<std::array<double, 4>>, 2> err;
  const char* kinds[] = {"disc", "point"};
  for (double s : scales) {
    const SensorGreens greens = green_path(scaled_scene(base, s), GreenPath::full3d);
    ASSERT_EQ(greens.path, "3d");
    for (int kind = 0; kind < 2; ++kind) {
      std::array<double, 4> e{};
      for (size_t k = 0; k < points.size(); ++k) {
        GreenSample g;
        if (kind == 0)
          ASSERT_TRUE(greens.disc_map(0, points[k][0], points[k][1], g));
        else
          g = greens.at(0, false, points[k][0], points[k][1], green::LayerLoad::point, 0);
        const auto v = as_array(g);
        for (int c = 0; c < 4; ++c) e[c] = std::max(e[c], std::abs(v[c] - ref[kind][k][c]) / peak[kind][c]);
      }
      err[kind].push_back(e);
      std::printf("scale %.2f: %d DOFs; %s max |g - exact| / peak: zz %.2e, zx %.2e, xz %.2e, xx %.2e\n", s,
                  greens.dofs, kinds[kind], e[0], e[1], e[2], e[3]);
    }
  }
  const char* names[] = {"zz", "zx", "xz", "xx"};
  for (int kind = 0; kind < 2; ++kind)
    for (int c = 0; c < 4; ++c) {
      std::vector<double> e;
      for (const auto& level : err[kind]) e.push_back(level[c]);
      const double order = testing::observed_order(scales, e);
      std::printf("%s g_%s: observed order %.2f\n", kinds[kind], names[c], order);
      EXPECT_GE(order, 1.5) << kinds[kind] << " g_" << names[c];
      EXPECT_LE(err[kind].back()[c], 5e-3) << kinds[kind] << " g_" << names[c];
    }
}

}  // namespace
}  // namespace skinfem::pipeline
