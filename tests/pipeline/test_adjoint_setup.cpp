// The first half of `green` and `kfit` (pipeline/adjoint_setup.hpp). References: closed forms of the shapes
// (a flat layer's thickness h; a spherical cap's h − R + √(R² − r²) about its apex; an imported 3 × 2 × 1 mm
// box, written here as STL, 1 mm thick over its footprint and nothing beyond it); the calibration scan's
// half-width as the header defines it (4h or the scene's, shortened so that the loaded disc of radius a stays
// on the footprint: room = edge − a − |x|, less half a step), computed here from the scene's numbers; the
// sensors' footprints against the base's extent (a disc's radius, a post's 5 % more); and the set-up's
// sharing (a skin given is used, not meshed again; a symmetric scene is meshed on its half).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <tuple>

#include "skinfem/mesh/build.hpp"
#include "skinfem/pipeline/adjoint_setup.hpp"

namespace skinfem::pipeline {
namespace {

constexpr double kRoundOff = 1e-12;  // relative: a closed form evaluated twice, or sums of exact steps

bool has(const std::string& text, const std::string& what) { return text.find(what) != std::string::npos; }

Scene layer() {
  Scene s;
  s.name = "adjoint_layer";
  s.source_path = "adjoint_layer.json";
  s.geometry.kind = GeometryKind::flat;
  s.geometry.flat = {1.5, 4.0};
  s.sensors.positions = {{0, 0}, {1.5, 0}};
  s.mesh.h_min = 0.7;
  s.mesh.growth = 1.7;
  s.mesh.h_max = 1.5;
  s.mesh.sensor_h = 0.5;
  return s;
}

Scene cap() {
  Scene s;
  s.name = "adjoint_cap";
  s.geometry.kind = GeometryKind::cap;
  s.geometry.cap.R = 40;
  s.geometry.cap.h = 2;
  s.geometry.cap.apex_x = 0.5;
  s.geometry.cap.truncation_radius = 5;
  s.sensors.positions = {{0.5, 0}, {2, 1}};
  s.mesh.h_min = 0.7;
  s.mesh.growth = 1.7;
  s.mesh.h_max = 1.5;
  return s;
}

// The box [−1, 2] × [0.5, 2.5] × [0, 1] mm as ASCII STL, outward facets; one file per test (`name`), as ctest
// may run two tests of this suite at once.
std::string box_stl(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path(SKINFEM_TEST_TMP) / "pipeline_adjoint_setup";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / (name + ".stl")).string();
  const double x[2] = {-1, 2}, y[2] = {0.5, 2.5}, z[2] = {0, 1};
  using P = std::array<double, 3>;
  const auto v = [&](int i, int j, int k) { return P{x[i], y[j], z[k]}; };
  std::ofstream out(path);
  out << "solid box\n";
  const auto quad = [&](P a, P b, P c, P d) {
    for (const auto& t : {std::array<P, 3>{a, b, c}, std::array<P, 3>{a, c, d}}) {
      out << " facet normal 0 0 0\n  outer loop\n";
      for (const P& p : t) out << "   vertex " << p[0] << " " << p[1] << " " << p[2] << "\n";
      out << "  endloop\n endfacet\n";
    }
  };
  quad(v(0, 0, 0), v(0, 1, 0), v(1, 1, 0), v(1, 0, 0));
  quad(v(0, 0, 1), v(1, 0, 1), v(1, 1, 1), v(0, 1, 1));
  quad(v(0, 0, 0), v(1, 0, 0), v(1, 0, 1), v(0, 0, 1));
  quad(v(0, 1, 0), v(0, 1, 1), v(1, 1, 1), v(1, 1, 0));
  quad(v(0, 0, 0), v(0, 0, 1), v(0, 1, 1), v(0, 1, 0));
  quad(v(1, 0, 0), v(1, 1, 0), v(1, 1, 1), v(1, 0, 1));
  out << "endsolid box\n";
  return path;
}

Scene box_scene(const std::string& name) {
  Scene s;
  s.name = "adjoint_box";
  s.geometry.kind = GeometryKind::surface;
  s.geometry.surface.path = box_stl(name);
  s.sensors.positions = {{0.5, 1.5}};
  s.mesh.h_min = 0.4;
  s.mesh.growth = 1.7;
  s.mesh.h_max = 0.8;
  s.calibration.punch_diameter = 0.4;
  s.calibration.spacing = 0.1;
  return s;
}

TEST(AdjointSetup, ThicknessIsTheShapesOwnHeight) {
  const Scene flat = layer();
  const TetMesh flat_mesh = build_mesh(flat);
  EXPECT_EQ(thickness_at(flat, flat_mesh, {0.3, -2}), 1.5);
  const Scene c = cap();
  const TetMesh cap_mesh = build_mesh(c);
  for (const Vec2 p : {Vec2{0.5, 0}, Vec2{2, 1}, Vec2{-3, 2.5}}) {
    const double r2 = (p[0] - 0.5) * (p[0] - 0.5) + p[1] * p[1];
    const double exact = 2 - 40 + std::sqrt(40 * 40 - r2);
    EXPECT_NEAR(thickness_at(c, cap_mesh, p), exact, kRoundOff * exact);
  }
  // Off the exact shapes' footprints (the flat layer's half-width 4; the cap's truncation radius around its
  // apex, where beyond its rim the sphere's formula has no real value) there is no skin: a scene error.
  for (const auto& [scene, mesh, p] :
       {std::tuple{&flat, &flat_mesh, Vec2{100, 0}}, std::tuple{&flat, &flat_mesh, Vec2{0, -4.5}},
        std::tuple{&c, &cap_mesh, Vec2{0.5 + c.geometry.cap.truncation_radius + 1, 0}},
        std::tuple{&c, &cap_mesh, Vec2{50, 0}}})
    try {
      thickness_at(*scene, *mesh, p);
      ADD_FAILURE() << "a point off the footprint has a thickness: (" << p[0] << ", " << p[1] << ")";
    } catch (const SceneError& e) {
      EXPECT_TRUE(has(e.what(), "footprint")) << e.what();
    }
  // An imported box: its meshed top, 1 mm above the base (planar faces: exact), and no skin beyond it.
  const Scene box = box_scene("thickness");
  const TetMesh box_mesh = build_mesh(box);
  EXPECT_NEAR(thickness_at(box, box_mesh, {0.3, 1.2}), 1.0, kRoundOff);
  try {
    thickness_at(box, box_mesh, {3, 1.5});
    ADD_FAILURE() << "a point beyond the box has a thickness";
  } catch (const SceneError& e) {
    EXPECT_TRUE(has(e.what(), "sensors")) << e.what();
  }
}

TEST(AdjointSetup, TheScanHalfWidthKeepsTheLoadedDiscOnTheFootprint) {
  Scene s = layer();  // half-width 4, punch radius a = 0.25, spacing 0.05, wanted 4h = 6
  const double a = 0.25, step = s.calibration.spacing;
  // Room on the flat layer: 4 − a − |x|, less half a step (the grid's last offset strictly inside).
  EXPECT_NEAR(scan_half_width(s, nullptr, 1.5, {0, 0}), 4 - a - 0.5 * step, kRoundOff);
  EXPECT_NEAR(scan_half_width(s, nullptr, 1.5, {1.5, 0}), 4 - a - 1.5 - 0.5 * step, kRoundOff);
  EXPECT_NEAR(scan_half_width(s, nullptr, 0.5, {0, 0}), 4 * 0.5, kRoundOff);  // 4h fits: as wanted
  s.calibration.scan_half_width = 1.2;                                        // the scene's, when it fits
  EXPECT_NEAR(scan_half_width(s, nullptr, 1.5, {0, 0}), 1.2, kRoundOff);
  // On a cap: the chord of the footprint shrunk by a, at the sensor's distance from the apex's line.
  const Scene c = cap();
  const double reach = 5 - a, dy = 1;
  EXPECT_NEAR(scan_half_width(c, nullptr, 1.8, {2, 1}),
              std::sqrt(reach * reach - dy * dy) - 1.5 - 0.5 * c.calibration.spacing, kRoundOff);
  // The imported box: walked along its meshed top in steps of 0.1 mm from x = 0.5; the disc (a = 0.2) fits
  // while 0.5 ± (w + 0.2) stays within [−1, 2]: w ≤ 1.3, the last whole step (less than 4h = 4 mm).
  const Scene box = box_scene("scan");
  const TetMesh box_mesh = build_mesh(box);
  EXPECT_NEAR(scan_half_width(box, &box_mesh, 1.0, {0.5, 1.5}), 1.3, 1e-9);
  EXPECT_THROW(scan_half_width(box, nullptr, 1.0, {0.5, 1.5}), std::logic_error);
  // A punch wider than the room: refused, naming the calibration.
  Scene wide = layer();
  wide.calibration.punch_diameter = 8.2;  // a = 4.1: past the 4 mm edge at once
  try {
    scan_half_width(wide, nullptr, 1.5, {0, 0});
    ADD_FAILURE() << "a scan off the footprint was accepted";
  } catch (const SceneError& e) {
    EXPECT_TRUE(has(e.what(), "calibration")) << e.what();
  }
}

TEST(AdjointSetup, EverySensorsFootprintMustLieOnTheBase) {
  Scene s = layer();
  const TetMesh mesh = build_mesh(s);
  EXPECT_NO_THROW(check_sensors_on_skin(s, mesh));
  s.sensors.positions = {{0, 0}, {0, 3.85}};  // the disc (radius 0.1) ends at 3.95 < 4
  EXPECT_NO_THROW(check_sensors_on_skin(s, mesh));
  s.sensors.positions = {{0, 0}, {0, 3.95}};  // its rim at 4.05: off the base
  try {
    check_sensors_on_skin(s, mesh);
    ADD_FAILURE() << "a disc off the base was accepted";
  } catch (const SceneError& e) {
    EXPECT_TRUE(has(e.what(), "sensor 2")) << e.what();
    EXPECT_TRUE(has(e.what(), "disc")) << e.what();
  }
}

TEST(AdjointSetup, AGivenSkinIsSharedAndASymmetricSceneMeshedOnItsHalf) {
  const Scene s = layer();
  const auto own = adjoint_setup(s);
  EXPECT_TRUE(is_half_y(own->mesh));  // sensors on y = 0, a flat layer: the half
  EXPECT_EQ(&own->mesh, &own->skin->mesh);
  EXPECT_EQ(own->model, own->skin->model.get());
  for (const char* stage : {"mesh", "assemble", "factor", "adjoint_solves"})
    EXPECT_TRUE(own->wall.contains(stage)) << stage;
  const auto shared = adjoint_setup(s, own->skin);
  EXPECT_EQ(shared->skin.get(), own->skin.get());
  EXPECT_EQ(shared->model, own->model);
  // The same factorization gives the same adjoints: the centre value of sensor 1 under a unit point load.
  const green::GreenSample a = own->fe->at(0, true, 0.3, 0, green::LayerLoad::point, 0);
  const green::GreenSample b = shared->fe->at(0, true, 0.3, 0, green::LayerLoad::point, 0);
  EXPECT_EQ(a.zz, b.zz);
  EXPECT_EQ(a.xx, b.xx);
}

}  // namespace
}  // namespace skinfem::pipeline
