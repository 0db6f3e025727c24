// `skinfem green` as a stage (pipeline/green.hpp) on a coarse flat layer. References: Maxwell–Betti
// reciprocity against direct solves (the 3D maps at a top node, adjoint values, must equal the sensors'
// readings of a unit point force applied at that node and solved directly: σ_z and σ_x for a force along −z
// and along +x); mirror symmetry (on a half mesh written whole, every node and its mirror image carry the
// same values: the sensors lie on y = 0 and g is even in y); the footprint's box from the scene (and, for an
// imported STL written here, from its vertices); the kernel grid's limits as the header states them (1e6
// points, 2.5e7 values); each flat scan's difference from the exact layer recomputed here from the typed
// profiles; and green_json's numbers against the typed run.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <string>
#include <tuple>

#include "skinfem/fem/sensor_reading.hpp"
#include "skinfem/pipeline/green.hpp"

namespace skinfem::pipeline {
namespace {

// Reciprocity holds exactly for the discrete problem; the adjoint and the direct solve use one factorization,
// so they agree to round-off amplified by the system's condition: 1e-9 of the map's peak.
constexpr double kRoundOff = 1e-9;

Scene layer(SymmetryUse symmetry) {
  Scene s;
  s.name = "green_layer";
  s.geometry.kind = GeometryKind::flat;
  s.geometry.flat = {1.5, 5.0};
  s.sensors.positions = {{0, 0}, {1.5, 0}};
  s.mesh.h_min = 0.7;
  s.mesh.growth = 1.7;
  s.mesh.h_max = 1.5;
  s.mesh.sensor_h = 0.5;
  s.calibration.spacing = 0.25;
  s.symmetry = symmetry;
  return s;
}

struct Stage {
  Scene scene;
  std::unique_ptr<AdjointSetup> setup;
  std::unique_ptr<SensorGreens> greens;
  std::unique_ptr<GreenRun> run;
  explicit Stage(SymmetryUse symmetry, double grid_dx = 0) : scene(layer(symmetry)) {
    setup = adjoint_setup(scene);
    greens = std::make_unique<SensorGreens>(sensor_greens(scene, *setup));
    run = std::make_unique<GreenRun>(green_run(scene, *greens, setup.get(), grid_dx));
  }
};

class Green : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    whole_ = new Stage(SymmetryUse::none, 0.5);
    half_ = new Stage(SymmetryUse::automatic);
  }
  static void TearDownTestSuite() {
    delete whole_;
    delete half_;
  }
  static Stage* whole_;
  static Stage* half_;
};
Stage* Green::whole_ = nullptr;
Stage* Green::half_ = nullptr;

TEST_F(Green, TheMapsAreTheReadingsOfDirectSolvesAtTopNodes) {
  const Stage& s = *whole_;
  ASSERT_FALSE(is_half_y(s.setup->mesh));
  const TetMesh& top = *s.run->top;
  EXPECT_EQ(&top, &s.setup->mesh);  // the whole mesh's own nodes
  const ElasticModel& model = *s.setup->model;
  const SensorReadings readings(s.setup->mesh, reading_sites(s.scene.sensors), &model.solver());
  // Top nodes nearest a few points of the footprint.
  for (const Vec2 p : {Vec2{0.4, 0.3}, Vec2{-1, 1}, Vec2{2, -1.5}, Vec2{1.5, 0}}) {
    int j = -1;
    double best = 1e300;
    for (int n = 0; n < top.num_nodes(); ++n) {
      if (std::abs(top.nodes(n, 2) - 1.5) > 1e-12) continue;
      const double d = std::hypot(top.nodes(n, 0) - p[0], top.nodes(n, 1) - p[1]);
      if (d < best) best = d, j = n;
    }
    ASSERT_GE(j, 0);
    const double x = top.nodes(j, 0), y = top.nodes(j, 1);
    const LoadCaseResult down = model.solve(model.point_load(x, y, {0, 0, -1}), {});
    const LoadCaseResult along = model.solve(model.point_load(x, y, {1, 0, 0}), {});
    for (int k = 0; k < readings.size(); ++k) {
      const auto& map = s.run->maps[k];
      const double peak = std::max(*std::max_element(map[0].begin(), map[0].end()),
                                   -*std::min_element(map[0].begin(), map[0].end()));
      const SensorReading d = readings.read(k, down.reactions), a = readings.read(k, along.reactions);
      EXPECT_NEAR(map[0][j], d.sigma_z, kRoundOff * peak)
          << "zz, sensor " << k + 1 << " at " << x << ", " << y;
      EXPECT_NEAR(map[1][j], d.sigma_x, kRoundOff * peak) << "zx, sensor " << k + 1;
      EXPECT_NEAR(map[2][j], a.sigma_z, kRoundOff * peak) << "xz, sensor " << k + 1;
      EXPECT_NEAR(map[3][j], a.sigma_x, kRoundOff * peak) << "xx, sensor " << k + 1;
    }
  }
  ASSERT_TRUE(s.run->reciprocity_rel.has_value());
  EXPECT_LT(*s.run->reciprocity_rel, kRoundOff);
  EXPECT_EQ(s.run->mesh_part, "whole");
}

TEST_F(Green, AHalfsMapsAreEvenInY) {
  const Stage& s = *half_;
  ASSERT_TRUE(is_half_y(s.setup->mesh));
  const TetMesh& top = *s.run->top;
  EXPECT_FALSE(is_half_y(top));  // written whole
  EXPECT_GT(top.num_nodes(), s.setup->mesh.num_nodes());
  // Pair each node with its mirror image (x, −y) by coordinates.
  std::map<std::tuple<double, double, double>, int> at;
  for (int n = 0; n < top.num_nodes(); ++n) at[{top.nodes(n, 0), top.nodes(n, 1), top.nodes(n, 2)}] = n;
  int pairs = 0;
  for (int n = 0; n < top.num_nodes(); ++n) {
    if (!(top.nodes(n, 1) > 0)) continue;
    const auto it = at.find({top.nodes(n, 0), -top.nodes(n, 1), top.nodes(n, 2)});
    ASSERT_NE(it, at.end()) << "node " << n << " has no mirror image";
    for (size_t k = 0; k < s.run->maps.size(); ++k)
      for (int c = 0; c < 4; ++c) EXPECT_EQ(s.run->maps[k][c][n], s.run->maps[k][c][it->second]);
    ++pairs;
  }
  EXPECT_GT(pairs, 0);
  ASSERT_TRUE(s.run->reciprocity_rel.has_value());
  EXPECT_LT(*s.run->reciprocity_rel, kRoundOff);  // the point force on the cut, half of it on the half
  EXPECT_NE(s.run->mesh_part.find("half"), std::string::npos) << s.run->mesh_part;
}

TEST_F(Green, EachFlatScanIsComparedWithTheExactLayerOnItsOffsets) {
  const Stage& s = *whole_;
  EXPECT_TRUE(s.run->flat);
  ASSERT_EQ(s.run->scans.size(), 2u);
  for (const GreenScan& scan : s.run->scans) {
    const std::vector<double>& x = scan.profile.offset_x;
    ASSERT_GE(x.size(), 3u);
    // Symmetric offsets at the calibration spacing, 0 included (green/calibration.hpp).
    for (size_t i = 0; i < x.size(); ++i) {
      EXPECT_NEAR(x[i], -x[x.size() - 1 - i], 1e-12);
      if (i > 0) {
        EXPECT_NEAR(x[i] - x[i - 1], 0.25, 1e-12);
      }
    }
    EXPECT_EQ(scan.h_mm, s.greens->thickness[scan.sensor - 1]);
    ASSERT_EQ(scan.exact_disc.size(), x.size());
    ASSERT_EQ(scan.exact_point.size(), x.size());
    ASSERT_TRUE(scan.disc_max_diff_over_peak.has_value());
    for (int c = 0; c < 4; ++c) {
      double peak = 0, diff = 0;
      for (size_t i = 0; i < x.size(); ++i) {
        const double e = green::component(scan.exact_disc[i], green::kComponents[c]);
        peak = std::max(peak, std::abs(e));
        diff = std::max(diff, std::abs(green::component(scan.profile.disc[i], green::kComponents[c]) - e));
      }
      EXPECT_NEAR((*scan.disc_max_diff_over_peak)[c], diff / peak, 1e-12) << c;
    }
  }
}

TEST_F(Green, TheSummarySaysTheTypedRun) {
  const Stage& s = *whole_;
  const nlohmann::json j = green_json(s.scene, *s.greens, *s.run, 0.5);
  EXPECT_EQ(j.at("path"), s.greens->path);
  EXPECT_EQ(j.at("dofs").get<int>(), s.greens->dofs);
  EXPECT_EQ(j.at("adjoint_solves").get<int>(), s.greens->adjoint_solves);
  EXPECT_EQ(j.at("mesh_part"), "whole");
  EXPECT_EQ(j.at("reciprocity_check_rel").get<double>(), *s.run->reciprocity_rel);
  EXPECT_EQ(j.at("punch_diameter_mm").get<double>(), s.scene.calibration.punch_diameter);
  ASSERT_EQ(j.at("sensors").size(), s.run->scans.size());
  for (size_t k = 0; k < s.run->scans.size(); ++k) {
    const GreenScan& scan = s.run->scans[k];
    const nlohmann::json& js = j.at("sensors")[k];
    EXPECT_EQ(js.at("sensor").get<int>(), scan.sensor);
    EXPECT_EQ(js.at("h_mm").get<double>(), scan.h_mm);
    EXPECT_EQ(js.at("scan_half_width_mm").get<double>(), scan.profile.offset_x.back());
    const nlohmann::json& e = js.at("fe_vs_exact_max_err_over_peak");
    for (int c = 0; c < 4; ++c)
      EXPECT_EQ(e.at(green::component_name(green::kComponents[c])).get<double>(),
                (*scan.disc_max_diff_over_peak)[c]);
  }
  // The grid over the 10 mm square footprint at 0.5 mm: 21 × 21 points, all on the flat layer's top.
  ASSERT_TRUE(s.run->grid.has_value());
  const nlohmann::json& g = j.at("kernel_grid");
  EXPECT_EQ(g.at("nx").get<int>(), 21);
  EXPECT_EQ(g.at("ny").get<int>(), 21);
  EXPECT_EQ(g.at("points_on_skin").get<int>(), 21 * 21);
  EXPECT_EQ(g.at("x_range_mm"), nlohmann::json::array({-5.0, 5.0}));
  EXPECT_FALSE(green_json(s.scene, *s.greens, *s.run, 0).contains("meridian_check"));  // a flat layer
}

TEST_F(Green, TheFootprintBoxIsTheScenesOrTheSurfacesExtent) {
  Scene flat = layer(SymmetryUse::automatic);
  EXPECT_EQ(footprint_box(flat), (std::array<double, 4>{-5, 5, -5, 5}));
  Scene cap;
  cap.geometry.kind = GeometryKind::cap;
  cap.geometry.cap.apex_x = 0.5;
  cap.geometry.cap.apex_y = -1;
  cap.geometry.cap.truncation_radius = 7;
  EXPECT_EQ(footprint_box(cap), (std::array<double, 4>{-6.5, 7.5, -8, 6}));
  // A box 3 × 2 × 1 mm from (−1, 0.5, 0), as ASCII STL: 12 triangles.
  const std::filesystem::path dir = std::filesystem::path(SKINFEM_TEST_TMP) / "pipeline_green";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "box.stl").string();
  {
    const double x[2] = {-1, 2}, y[2] = {0.5, 2.5}, z[2] = {0, 1};
    const auto v = [&](int i, int j, int k) { return std::array<double, 3>{x[i], y[j], z[k]}; };
    std::ofstream out(path);
    out << "solid box\n";
    const auto tri = [&](std::array<double, 3> a, std::array<double, 3> b, std::array<double, 3> c) {
      out << " facet normal 0 0 0\n  outer loop\n";
      for (const auto& p : {a, b, c}) out << "   vertex " << p[0] << " " << p[1] << " " << p[2] << "\n";
      out << "  endloop\n endfacet\n";
    };
    const auto quad = [&](std::array<double, 3> a, std::array<double, 3> b, std::array<double, 3> c,
                          std::array<double, 3> d) {
      tri(a, b, c);
      tri(a, c, d);
    };
    quad(v(0, 0, 0), v(0, 1, 0), v(1, 1, 0), v(1, 0, 0));  // base, outward −z
    quad(v(0, 0, 1), v(1, 0, 1), v(1, 1, 1), v(0, 1, 1));  // top
    quad(v(0, 0, 0), v(1, 0, 0), v(1, 0, 1), v(0, 0, 1));  // y = 0.5
    quad(v(0, 1, 0), v(0, 1, 1), v(1, 1, 1), v(1, 1, 0));  // y = 2.5
    quad(v(0, 0, 0), v(0, 0, 1), v(0, 1, 1), v(0, 1, 0));  // x = −1
    quad(v(1, 0, 0), v(1, 1, 0), v(1, 1, 1), v(1, 0, 1));  // x = 2
    out << "endsolid box\n";
  }
  Scene surface;
  surface.geometry.kind = GeometryKind::surface;
  surface.geometry.surface.path = path;
  EXPECT_EQ(footprint_box(surface), (std::array<double, 4>{-1, 2, 0.5, 2.5}));
}

TEST_F(Green, TheKernelGridIsBoundedAsTheHeaderSays) {
  Scene s = layer(SymmetryUse::automatic);
  s.geometry.flat.half_width = 10;                       // a 20 mm square: (⌊20/dx⌋ + 1)² points
  EXPECT_THROW(check_kernel_grid(s, 0.02), SceneError);  // 1001² > 1e6 points
  EXPECT_NO_THROW(check_kernel_grid(s, 0.0201));         // 996² = 992016 points, 2 sensors: 7.9e6 values
  s.sensors.positions.assign(7, Vec2{0, 0});             // 4 · 992016 · 7 = 2.78e7 values > 2.5e7
  EXPECT_THROW(check_kernel_grid(s, 0.0201), SceneError);
  s.sensors.positions.assign(6, Vec2{0, 0});  // 2.38e7 values
  EXPECT_NO_THROW(check_kernel_grid(s, 0.0201));
  try {
    check_kernel_grid(s, 0.01);
    ADD_FAILURE() << "a 4e6-point grid was accepted";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("--grid"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace skinfem::pipeline
