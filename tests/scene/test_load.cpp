// Scene files: the shipped scenes load with the right values; every class of bad input is rejected
// with a one-line message naming the file, the JSON path, the offending value and what is allowed.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <string>
#include <utility>

#include "skinfem/scene/load.hpp"
#include "skinfem/scene/scene.hpp"

namespace fs = std::filesystem;
using namespace skinfem;

namespace {

const std::string kSource = "scenes/x.json";

// A valid scene assembled from parts; tests replace one part with bad JSON.
struct Doc {
  std::string geometry =
      R"({"type": "cap", "R": 129.7, "h": 3.04, "apex": [0.5, 0.0], "truncation_radius": 12.0})";
  std::string material = R"({"E": 3.0, "nu": 0.5})";
  std::string sensors = R"({"positions": [[0, 0]], "disc_diameter": 0.2})";
  std::string mesh = R"({"h_min": 0.25, "growth": 1.3, "h_max": 2.0})";
  std::string extra;  // further top-level members, each starting with ", "
  std::string str() const {
    return "{\"geometry\": " + geometry + ", \"material\": " + material + ", \"sensors\": " + sensors +
           ", \"mesh\": " + mesh + extra + "}";
  }
};

std::string with(std::string Doc::*part, const std::string& value) {
  Doc d;
  d.*part = value;
  return d.str();
}

std::string error_of(const std::string& text, const std::string& source = kSource) {
  try {
    parse_scene(text, source);
  } catch (const SceneError& e) {
    return e.what();
  }
  ADD_FAILURE() << "accepted: " << text;
  return "";
}

void expect_error(const std::string& text, std::initializer_list<std::string> parts) {
  const std::string msg = error_of(text);
  EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
  EXPECT_EQ(msg.rfind(kSource + ": ", 0), 0u) << msg;
  for (const std::string& p : parts)
    EXPECT_NE(msg.find(p), std::string::npos) << "no '" << p << "' in: " << msg;
}

#define EXPECT_SCENE_ERROR(text, ...)  \
  do {                                 \
    SCOPED_TRACE(text);                \
    expect_error(text, {__VA_ARGS__}); \
  } while (0)

fs::path tmp_dir() {
  const fs::path dir = fs::path(SKINFEM_TEST_TMP) / "scene_test_load";
  fs::create_directories(dir);
  return dir;
}

void write_file(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

}  // namespace

TEST(SceneLoad, Candelier2011) {
  const std::string path = std::string(SKINFEM_SOURCE_DIR) + "/scenes/candelier2011.json";
  const Scene s = load_scene(path);
  EXPECT_EQ(s.name, "candelier2011");
  EXPECT_EQ(s.source_path, path);
  ASSERT_EQ(s.geometry.kind, GeometryKind::cap);
  EXPECT_DOUBLE_EQ(s.geometry.cap.R, 129.7);
  EXPECT_DOUBLE_EQ(s.geometry.cap.h, 3.04);
  EXPECT_DOUBLE_EQ(s.geometry.cap.apex_x, 0.5);
  EXPECT_DOUBLE_EQ(s.geometry.cap.apex_y, 0.0);
  EXPECT_DOUBLE_EQ(s.geometry.cap.truncation_radius, 18.0);
  EXPECT_EQ(s.geometry.side, SideCondition::free);
  EXPECT_DOUBLE_EQ(nominal_thickness(s), 3.04);
  EXPECT_DOUBLE_EQ(s.material.E, 3.0);
  EXPECT_DOUBLE_EQ(s.material.nu, 0.5);
  ASSERT_EQ(s.sensors.positions.size(), 10u);
  for (int i = 0; i < 10; ++i) {
    EXPECT_NEAR(s.sensors.positions[i][0], -4.5 + i, 1e-12) << "sensor " << i + 1;
    EXPECT_EQ(s.sensors.positions[i][1], 0.0) << "sensor " << i + 1;
  }
  EXPECT_DOUBLE_EQ(s.sensors.disc_diameter, 0.2);
  EXPECT_TRUE(s.mesh.refine_sensors);
  EXPECT_DOUBLE_EQ(s.mesh.max_radius_edge, 1.5);
  EXPECT_DOUBLE_EQ(s.mesh.min_dihedral_deg, 10);
  // Mesh sizes are tuned for cost versus error (docs/scenes.md, docs/contact_results.md); the region along
  // the sensor line is physics.
  ASSERT_FALSE(s.mesh.regions.empty());
  EXPECT_EQ(s.mesh.regions[0].a, (Vec2{-4.5, 0.0}));
  EXPECT_EQ(s.mesh.regions[0].b, (Vec2{4.5, 0.0}));
  EXPECT_TRUE(s.loads.punches.empty());
  EXPECT_TRUE(s.loads.patches.empty());
  EXPECT_DOUBLE_EQ(s.calibration.punch_diameter, 0.5);
  EXPECT_DOUBLE_EQ(s.calibration.spacing, 0.05);
  EXPECT_EQ(s.calibration.scan_half_width, 0.0);
}

TEST(SceneLoad, FlatLayer) {
  const Scene s = load_scene(std::string(SKINFEM_SOURCE_DIR) + "/scenes/flat_layer.json");
  EXPECT_EQ(s.name, "flat_layer");
  ASSERT_EQ(s.geometry.kind, GeometryKind::flat);
  EXPECT_DOUBLE_EQ(s.geometry.flat.h, 3.04);
  EXPECT_DOUBLE_EQ(s.geometry.flat.half_width, 20.0);
  EXPECT_DOUBLE_EQ(nominal_thickness(s), 3.04);
  EXPECT_DOUBLE_EQ(s.material.E, 3.0);
  EXPECT_DOUBLE_EQ(s.material.nu, 0.5);
  ASSERT_EQ(s.sensors.positions.size(), 1u);
  EXPECT_EQ(s.sensors.positions[0], (Vec2{0.0, 0.0}));
  EXPECT_DOUBLE_EQ(s.sensors.disc_diameter, 0.2);
  ASSERT_FALSE(s.mesh.regions.empty());
  EXPECT_EQ(s.mesh.regions[0].a, (Vec2{0.0, 0.0}));
  EXPECT_EQ(s.mesh.regions[0].b, (Vec2{0.0, 0.0}));
  ASSERT_EQ(s.loads.punches.size(), 1u);
  const Punch& p = s.loads.punches[0];
  EXPECT_EQ(p.center, (Vec2{0.0, 0.0}));
  EXPECT_DOUBLE_EQ(p.diameter, 0.5);
  ASSERT_TRUE(p.force.has_value());
  EXPECT_DOUBLE_EQ(*p.force, 1.0);
  EXPECT_FALSE(p.displacement.has_value());
  EXPECT_DOUBLE_EQ(s.calibration.punch_diameter, 0.5);
}

TEST(SceneLoad, OptionalKeysTakeDefaults) {
  const Scene s = parse_scene(Doc{}.str(), "some/dir/my_scene.json");
  EXPECT_EQ(s.name, "my_scene");
  EXPECT_EQ(s.source_path, "some/dir/my_scene.json");
  EXPECT_EQ(s.geometry.side, SideCondition::free);
  EXPECT_TRUE(s.mesh.refine_sensors);
  EXPECT_TRUE(s.mesh.regions.empty());
  EXPECT_DOUBLE_EQ(s.mesh.max_radius_edge, MeshControls{}.max_radius_edge);
  EXPECT_DOUBLE_EQ(s.mesh.min_dihedral_deg, MeshControls{}.min_dihedral_deg);
  EXPECT_TRUE(s.loads.punches.empty());
  EXPECT_DOUBLE_EQ(s.calibration.punch_diameter, Calibration{}.punch_diameter);
  EXPECT_DOUBLE_EQ(s.calibration.spacing, Calibration{}.spacing);
}

TEST(SceneLoad, OptionalKeysAreRead) {
  Doc d;
  d.geometry = R"({"type": "flat", "h": 2, "half_width": 10, "side": "fixed"})";
  d.mesh = R"({"h_min": 0.1, "growth": 1.2, "h_max": 1, "refine_sensors": false, "min_dihedral_deg": 15,
               "max_radius_edge": 1.2, "regions": [{"from": [0, 0], "to": [1, 0], "radius": 0, "h": 0.05}]})";
  d.extra = R"(, "name": "x1", "calibration": {"punch_diameter": 0.3, "scan_half_width": 6, "spacing": 0.1},
             "loads": {"punches": [{"center": [1, 2], "diameter": 0.5, "displacement": 0.01}],
                       "patches": [{"center": [0, 0], "diameter": 0.5, "direction": [3, 0, -4], "force": 2}]})";
  const Scene s = parse_scene(d.str(), kSource);
  EXPECT_EQ(s.name, "x1");
  EXPECT_EQ(s.geometry.side, SideCondition::fixed);
  EXPECT_FALSE(s.mesh.refine_sensors);
  EXPECT_DOUBLE_EQ(s.mesh.min_dihedral_deg, 15);
  EXPECT_DOUBLE_EQ(s.mesh.max_radius_edge, 1.2);
  ASSERT_EQ(s.mesh.regions.size(), 1u);
  EXPECT_DOUBLE_EQ(s.mesh.regions[0].h, 0.05);
  EXPECT_DOUBLE_EQ(s.calibration.punch_diameter, 0.3);
  EXPECT_DOUBLE_EQ(s.calibration.scan_half_width, 6);
  EXPECT_DOUBLE_EQ(s.calibration.spacing, 0.1);
  ASSERT_EQ(s.loads.punches.size(), 1u);
  EXPECT_FALSE(s.loads.punches[0].force.has_value());
  EXPECT_DOUBLE_EQ(*s.loads.punches[0].displacement, 0.01);
  ASSERT_EQ(s.loads.patches.size(), 1u);
  EXPECT_NEAR(s.loads.patches[0].direction[0], 0.6, 1e-15);
  EXPECT_NEAR(s.loads.patches[0].direction[1], 0.0, 1e-15);
  EXPECT_NEAR(s.loads.patches[0].direction[2], -0.8, 1e-15);
  EXPECT_DOUBLE_EQ(s.loads.patches[0].force, 2);
}

TEST(SceneLoad, SurfacePathIsResolvedAgainstTheSceneFile) {
  const fs::path dir = tmp_dir();
  write_file(dir / "dome.stl", "solid dome\nendsolid dome\n");
  Doc d;
  d.geometry = R"({"type": "surface", "path": "dome.stl"})";
  d.sensors = R"({"positions": [[1000, 0]], "disc_diameter": 0.2})";  // footprint not checked for surfaces
  write_file(dir / "surf_scene.json", d.str());
  const Scene s = load_scene((dir / "surf_scene.json").string());
  EXPECT_EQ(s.name, "surf_scene");  // file stem
  ASSERT_EQ(s.geometry.kind, GeometryKind::surface);
  EXPECT_TRUE(fs::equivalent(s.geometry.surface.path, dir / "dome.stl"));
  EXPECT_EQ(nominal_thickness(s), 0.0);  // unknown before the surface is read

  d.geometry = R"({"type": "surface", "path": "DOME.STL"})";
  write_file(dir / "DOME.STL", "solid dome\nendsolid dome\n");
  EXPECT_NO_THROW(parse_scene(d.str(), (dir / "x.json").string()));  // extension is case-insensitive
}

TEST(SceneLoad, SurfaceErrors) {
  const fs::path dir = tmp_dir();
  Doc d;
  d.geometry = R"({"type": "surface", "path": "dome.step"})";
  const std::string wrong_ext = error_of(d.str(), (dir / "x.json").string());
  EXPECT_NE(wrong_ext.find("geometry.path = \"dome.step\""), std::string::npos) << wrong_ext;
  EXPECT_NE(wrong_ext.find(".stl, .obj or .off"), std::string::npos) << wrong_ext;

  d.geometry = R"({"type": "surface", "path": "no_such_file.off"})";
  const std::string missing = error_of(d.str(), (dir / "x.json").string());
  EXPECT_NE(missing.find("geometry.path = \"no_such_file.off\""), std::string::npos) << missing;
  EXPECT_NE(missing.find("existing file"), std::string::npos) << missing;
  EXPECT_NE(missing.find((dir / "no_such_file.off").string()), std::string::npos) << missing;

  EXPECT_SCENE_ERROR(with(&Doc::geometry, R"({"type": "surface", "path": ""})"), "geometry.path = \"\"");
  EXPECT_SCENE_ERROR(with(&Doc::geometry, R"({"type": "surface", "path": "a.stl", "R": 3})"),
                     "geometry.R: unknown key; allowed: type, path, side");
}

TEST(SceneLoad, LoadSceneErrors) {
  const fs::path dir = tmp_dir();
  try {
    load_scene((dir / "missing.json").string());
    FAIL() << "no error";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find((dir / "missing.json").string() + ": cannot read"),
              std::string::npos)
        << e.what();
  }
  write_file(dir / "broken.json", "{\n  \"name\": \"b\",\n  \"geometry\": {,\n}\n");
  try {
    load_scene((dir / "broken.json").string());
    FAIL() << "no error";
  } catch (const SceneError& e) {
    const std::string msg = e.what();
    EXPECT_EQ(msg.rfind((dir / "broken.json").string() + ": ", 0), 0u) << msg;
    EXPECT_NE(msg.find("line 3"), std::string::npos) << msg;
    EXPECT_NE(msg.find("byte"), std::string::npos) << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
  }
}

TEST(SceneLoad, JsonSyntaxErrors) {
  EXPECT_SCENE_ERROR("{\"geometry\": 1,\n \"material\": }", "invalid JSON", "line 2", "byte");
  EXPECT_SCENE_ERROR("", "invalid JSON", "line 1");
  EXPECT_SCENE_ERROR(Doc{}.str() + " trailing", "invalid JSON");
  EXPECT_SCENE_ERROR("{\"material\": {\"E\": NaN}}", "invalid JSON");
  EXPECT_SCENE_ERROR(with(&Doc::extra, ", /* comment */ \"name\": \"a\""), "invalid JSON");
}

TEST(SceneLoad, DuplicateKeys) {
  EXPECT_SCENE_ERROR(with(&Doc::material, R"({"E": 3.0, "nu": 0.5, "E": 4.0})"), "material.E: duplicate key");
  EXPECT_SCENE_ERROR(
      with(&Doc::mesh,
           R"({"h_min": 0.25, "growth": 1.3, "h_max": 2.0, "regions": [{"from": [0, 0], "to": [0, 0],
          "radius": 1}, {"from": [0, 0], "to": [0, 0], "radius": 1, "radius": 2}]})"),
      "mesh.regions[1].radius: duplicate key");
  EXPECT_SCENE_ERROR(with(&Doc::extra, R"(, "material": {"E": 1, "nu": 0})"), "material: duplicate key");
}

TEST(SceneLoad, UnknownKeys) {
  EXPECT_SCENE_ERROR(
      with(&Doc::extra, R"(, "colour": "red")"),
      "colour: unknown key; allowed: name, geometry, material, sensors, mesh, loads, calibration");
  EXPECT_SCENE_ERROR(
      with(&Doc::geometry,
           R"({"type": "cap", "R": 129.7, "h": 3.04, "apex": [0, 0], "truncation_radius": 12, "foo": 1})"),
      "scenes/x.json: geometry.foo: unknown key; allowed: type, R, R_y, h, apex, truncation_radius, side");
  EXPECT_SCENE_ERROR(with(&Doc::geometry, R"({"type": "flat", "h": 3, "half_width": 15, "R": 1})"),
                     "geometry.R: unknown key; allowed: type, h, half_width, side");
  EXPECT_SCENE_ERROR(with(&Doc::material, R"({"E": 3.0, "nu": 0.5, "G": 1})"),
                     "material.G: unknown key; allowed: E, nu");
  EXPECT_SCENE_ERROR(with(&Doc::sensors, R"({"positions": [[0, 0]], "disc_diameter": 0.2, "n": 1})"),
                     "sensors.n: unknown key; allowed: positions, line, disc_diameter");
  EXPECT_SCENE_ERROR(
      with(&Doc::sensors,
           R"({"line": {"start": [0, 0], "step": [1, 0], "count": 1, "end": 3}, "disc_diameter": 0.2})"),
      "sensors.line.end: unknown key; allowed: start, step, count");
  EXPECT_SCENE_ERROR(
      with(&Doc::mesh, R"({"h_min": 0.25, "growth": 1.3, "h_max": 2.0, "min_radius_edge": 2})"),
      "mesh.min_radius_edge: unknown key; allowed:", "max_radius_edge");
  EXPECT_SCENE_ERROR(
      with(&Doc::mesh, R"({"h_min": 0.25, "growth": 1.3, "h_max": 2.0, "regions": [{"a": [0, 0]}]})"),
      "mesh.regions[0].a: unknown key; allowed: from, to, radius, h");
  EXPECT_SCENE_ERROR(with(&Doc::extra, R"(, "loads": {"contact": {}})"),
                     "loads.contact: unknown key; allowed: punches, patches");
  EXPECT_SCENE_ERROR(
      with(&Doc::extra,
           R"(, "loads": {"punches": [{"center": [0, 0], "diameter": 0.5, "force": 1, "f": 2}]})"),
      "loads.punches[0].f: unknown key; allowed: center, diameter, force, displacement");
  EXPECT_SCENE_ERROR(
      with(
          &Doc::extra,
          R"(, "loads": {"patches": [{"center": [0, 0], "diameter": 0.5, "direction": [1, 0, 0], "force": 1, "t": 0}]})"),
      "loads.patches[0].t: unknown key; allowed: center, diameter, direction, force");
  EXPECT_SCENE_ERROR(with(&Doc::extra, R"(, "calibration": {"punch": 0.5})"),
                     "calibration.punch: unknown key; allowed: punch_diameter, scan_half_width, spacing");
}

TEST(SceneLoad, MissingRequiredKeys) {
  EXPECT_SCENE_ERROR(R"({"material": {"E": 3, "nu": 0.5}})", "geometry: required key is missing");
  EXPECT_SCENE_ERROR(with(&Doc::material, R"({"nu": 0.5})"), "material.E: required key is missing",
                     "a Young's modulus in (0, 1e12] MPa");
  EXPECT_SCENE_ERROR(with(&Doc::geometry, R"({"R": 129.7, "h": 3.04})"),
                     "geometry.type: required key is missing", "\"cap\", \"flat\", \"surface\"");
  EXPECT_SCENE_ERROR(with(&Doc::geometry, R"({"type": "cap", "R": 129.7, "h": 3.04, "apex": [0, 0]})"),
                     "geometry.truncation_radius: required key is missing");
  EXPECT_SCENE_ERROR(with(&Doc::geometry, R"({"type": "flat", "h": 3.04})"),
                     "geometry.half_width: required key is missing");
  EXPECT_SCENE_ERROR(with(&Doc::geometry, R"({"type": "surface"})"),
                     "geometry.path: required key is missing");
  EXPECT_SCENE_ERROR(with(&Doc::sensors, R"({"positions": [[0, 0]]})"),
                     "sensors.disc_diameter: required key is missing");
  EXPECT_SCENE_ERROR(
      with(&Doc::sensors, R"({"line": {"start": [0, 0], "step": [1, 0]}, "disc_diameter": 0.2})"),
      "sensors.line.count: required key is missing");
  EXPECT_SCENE_ERROR(with(&Doc::mesh, R"({"h_min": 0.25, "h_max": 2.0})"),
                     "mesh.growth: required key is missing");
  EXPECT_SCENE_ERROR(
      with(&Doc::mesh, R"({"h_min": 0.25, "growth": 1.3, "h_max": 2.0, "regions": [{"from": [0, 0],
                                         "to": [0, 0]}]})"),
      "mesh.regions[0].radius: required key is missing");
  EXPECT_SCENE_ERROR(with(&Doc::extra, R"(, "loads": {"punches": [{"diameter": 0.5, "force": 1}]})"),
                     "loads.punches[0].center: required key is missing", "[x, y]");
  EXPECT_SCENE_ERROR(
      with(&Doc::extra, R"(, "loads": {"patches": [{"center": [0, 0], "diameter": 0.5, "force": 1}]})"),
      "loads.patches[0].direction: required key is missing");
}

TEST(SceneLoad, WrongTypes) {
  EXPECT_SCENE_ERROR("[1, 2]", "(top level) = [1,2]: must be an object");
  EXPECT_SCENE_ERROR(with(&Doc::material, R"({"E": "3", "nu": 0.5})"),
                     "material.E = \"3\": must be a Young's modulus in (0, 1e12] MPa");
  EXPECT_SCENE_ERROR(with(&Doc::material, R"({"E": true, "nu": 0.5})"),
                     "material.E = true: must be a Young's modulus in (0, 1e12] MPa");
  EXPECT_SCENE_ERROR(with(&Doc::material, "[3, 0.5]"),
                     "material = [3,0.5]: must be an object with keys E, nu");
  EXPECT_SCENE_ERROR(with(&Doc::geometry, R"({"type": 1})"), "geometry.type = 1: must be one of");
  EXPECT_SCENE_ERROR(with(&Doc::geometry, R"({"type": "cube"})"),
                     "geometry.type = \"cube\": must be one of \"cap\", \"flat\", \"surface\"");
  EXPECT_SCENE_ERROR(
      with(&Doc::geometry,
           R"({"type": "cap", "R": 129.7, "h": 3.04, "apex": [0.5], "truncation_radius": 12})"),
      "geometry.apex = [0.5]: must be a point [x, y]");
  EXPECT_SCENE_ERROR(
      with(&Doc::geometry,
           R"({"type": "cap", "R": 129.7, "h": 3.04, "apex": [0, "0"], "truncation_radius": 12})"),
      "geometry.apex = [0,\"0\"]: must be a point [x, y]");
  EXPECT_SCENE_ERROR(with(&Doc::geometry, R"({"type": "flat", "h": 3, "half_width": 15, "side": "glued"})"),
                     "geometry.side = \"glued\": must be \"free\" or \"fixed\"");
  EXPECT_SCENE_ERROR(with(&Doc::mesh, R"({"h_min": 0.25, "growth": 1.3, "h_max": 2.0, "refine_sensors": 1})"),
                     "mesh.refine_sensors = 1: must be true or false");
  EXPECT_SCENE_ERROR(with(&Doc::mesh, R"({"h_min": 0.25, "growth": 1.3, "h_max": 2.0, "regions": {}})"),
                     "mesh.regions = {}: must be an array of regions");
  EXPECT_SCENE_ERROR(with(&Doc::extra, R"(, "name": 5)"), "name = 5: must be a file name of 1 to 100");
  EXPECT_SCENE_ERROR(with(&Doc::extra, R"(, "name": "")"), "name = \"\": must be a file name of 1 to 100");
  EXPECT_SCENE_ERROR(with(&Doc::extra, R"(, "loads": {"punches": {"center": [0, 0]}})"),
                     "loads.punches = {\"center\":[0,0]}: must be an array of punches");
  EXPECT_SCENE_ERROR(with(&Doc::extra, R"(, "loads": [])"),
                     "loads = []: must be an object with keys punches, patches");
}

TEST(SceneLoad, NumbersMustBeFinite) {
  // JSON has no inf/nan literals; numbers that overflow a double are rejected by the parser.
  EXPECT_SCENE_ERROR(with(&Doc::material, R"({"E": 1e999, "nu": 0.5})"), "invalid JSON", "1e999", "finite");
  EXPECT_SCENE_ERROR(with(&Doc::sensors, R"({"positions": [[-1e400, 0]], "disc_diameter": 0.2})"),
                     "invalid JSON", "-1e400", "finite");
  EXPECT_SCENE_ERROR(with(&Doc::material, R"({"E": Infinity, "nu": 0.5})"), "invalid JSON");
}

TEST(SceneLoad, Material) {
  EXPECT_SCENE_ERROR(with(&Doc::material, R"({"E": 0, "nu": 0.5})"),
                     "material.E = 0: must be a Young's modulus in (0, 1e12] MPa");
  EXPECT_SCENE_ERROR(with(&Doc::material, R"({"E": -3, "nu": 0.5})"),
                     "material.E = -3: must be a Young's modulus in (0, 1e12] MPa");
  EXPECT_SCENE_ERROR(with(&Doc::material, R"({"E": 3, "nu": 0.7})"),
                     "scenes/x.json: material.nu = 0.7: must be a number in [0, 0.5]");
  EXPECT_SCENE_ERROR(with(&Doc::material, R"({"E": 3, "nu": -0.1})"),
                     "material.nu = -0.1: must be a number in [0, 0.5]");
  EXPECT_NO_THROW(parse_scene(with(&Doc::material, R"({"E": 3, "nu": 0})"), kSource));
  // The law: linear unless asked; the neo-Hookean skin is incompressible only.
  EXPECT_EQ(parse_scene(with(&Doc::material, R"({"E": 3, "nu": 0.4})"), kSource).material.model,
            MaterialModel::linear);
  EXPECT_EQ(parse_scene(with(&Doc::material, R"({"E": 3, "nu": 0.5, "model": "neo_hookean"})"), kSource)
                .material.model,
            MaterialModel::neo_hookean);
  EXPECT_SCENE_ERROR(with(&Doc::material, R"({"E": 3, "nu": 0.45, "model": "neo_hookean"})"),
                     "material.nu = 0.45: must be 0.5 with \"model\": \"neo_hookean\"");
  EXPECT_SCENE_ERROR(with(&Doc::material, R"({"E": 3, "nu": 0.5, "model": 1})"),
                     "material.model = 1: must be one of \"linear\", \"neo_hookean\"");
}

TEST(SceneLoad, CapGeometry) {
  const auto cap = [](const std::string& R, const std::string& h, const std::string& rt) {
    return with(&Doc::geometry, R"({"type": "cap", "R": )" + R + R"(, "h": )" + h +
                                    R"(, "apex": [0.5, 0], "truncation_radius": )" + rt + "}");
  };
  EXPECT_SCENE_ERROR(cap("0", "3.04", "12"), "geometry.R = 0: must be a length in (0, 10000] mm");
  EXPECT_SCENE_ERROR(cap("129.7", "0", "12"), "geometry.h = 0: must be a number in (0, R) = (0, 129.7)");
  EXPECT_SCENE_ERROR(cap("129.7", "129.7", "12"),
                     "geometry.h = 129.7: must be a number in (0, R) = (0, 129.7)");
  // sqrt(129.7² − 126.66²) = 27.9166...
  EXPECT_SCENE_ERROR(cap("129.7", "3.04", "30"),
                     "geometry.truncation_radius = 30: must be a number > 0 and < 27.91",
                     "sqrt(R^2 - (R - h)^2)", "thins to zero");
  EXPECT_SCENE_ERROR(cap("129.7", "3.04", "27.92"), "geometry.truncation_radius = 27.92", "< 27.91");
  EXPECT_SCENE_ERROR(cap("129.7", "3.04", "0"),
                     "geometry.truncation_radius = 0: must be a number > 0 and < 27.9");
  EXPECT_NO_THROW(parse_scene(cap("129.7", "3.04", "27.9"), kSource));
}

TEST(SceneLoad, EllipsoidalCapGeometry) {
  const auto cap = [](const std::string& Ry, const std::string& h, const std::string& rt) {
    return with(&Doc::geometry, R"({"type": "cap", "R": 15, "R_y": )" + Ry + R"(, "h": )" + h +
                                    R"(, "apex": [0, 0], "truncation_radius": )" + rt + "}");
  };
  // c = sqrt(R R_y) = sqrt(120) = 10.954; along y (the shorter axis, b = sqrt(R_y c) = 9.361) the top meets
  // the base at b sqrt(1 − (1 − h/c)²) = 6.4362 for h = 3.
  const Scene s = parse_scene(cap("8", "3", "6.4"), kSource);
  EXPECT_DOUBLE_EQ(s.geometry.cap.radius_y(), 8.0);
  EXPECT_FALSE(s.geometry.cap.spherical());
  EXPECT_SCENE_ERROR(cap("8", "11", "6"), "geometry.h = 11: must be a number in (0, sqrt(R R_y))", "10.95");
  EXPECT_SCENE_ERROR(cap("8", "3", "6.5"),
                     "geometry.truncation_radius = 6.5: must be a number > 0 and < 6.436",
                     "ellipsoidal cap first thins to zero");
  EXPECT_SCENE_ERROR(cap("-1", "3", "6"), "geometry.R_y = -1: must be a length in (0, 10000] mm");
  // R_y = R is the sphere, with the sphere's own rule.
  EXPECT_TRUE(parse_scene(cap("15", "3", "6"), kSource).geometry.cap.spherical());
}

// The name is the report's folder: one path component that no shell or path can misread.
TEST(SceneLoad, NameIsOneSafeFileName) {
  EXPECT_EQ(parse_scene(with(&Doc::extra, R"j(, "name": "Candelier 2011 (run-2.b+)")j"), kSource).name,
            "Candelier 2011 (run-2.b+)");
  for (const char* bad : {R"(x'; touch SOMEFILE; echo ')", "../../escaped", "..", ".", "a/b", R"(a\\b)",
                          "-rf", " lead", ".hidden", "a\\u0000b", "tab\\there", "$(id)", "a`b`", "a\\\"b"})
    EXPECT_SCENE_ERROR(with(&Doc::extra, std::string(R"(, "name": ")") + bad + "\""),
                       "name = ", "must be a file name of 1 to 100 characters");
  EXPECT_SCENE_ERROR(with(&Doc::extra, R"(, "name": ")" + std::string(101, 'a') + "\""),
                     "must be a file name");
  // The default, the file's stem, follows the same rule and says so.
  EXPECT_EQ(parse_scene(with(&Doc::extra, ""), "dir/my scene.json").name, "my scene");
  const std::string msg = error_of(with(&Doc::extra, ""), "dir/x;y.json");
  EXPECT_NE(msg.find("name = \"x;y\": must be a file name"), std::string::npos) << msg;
  EXPECT_NE(msg.find("give a \"name\""), std::string::npos) << msg;
}

TEST(SceneLoad, Ridges) {
  const auto ridged = [](const std::string& ridges) {
    return with(&Doc::geometry, R"({"type": "flat", "h": 3, "half_width": 8, "ridges": )" + ridges + "}");
  };
  const Scene s = parse_scene(
      ridged(R"({"period": 0.22, "height": 0.05, "angle_deg": 30, "center": [1, 0], "radius": 1})"), kSource);
  EXPECT_TRUE(s.geometry.ridges.present());
  EXPECT_DOUBLE_EQ(s.geometry.ridges.mesh_size(), 0.22 / 6);
  EXPECT_SCENE_ERROR(ridged(R"({"period": 0.22, "height": 3, "center": [0, 0], "radius": 1})"),
                     "geometry.ridges.height = 3: must be a number in (0, 3)");
  EXPECT_SCENE_ERROR(ridged(R"({"period": 0.22, "height": 0.05, "center": [0, 0], "radius": 0.4})"),
                     "geometry.ridges.radius = 0.4: must be a number >= 2 x period = 0.44");
  EXPECT_SCENE_ERROR(ridged(R"({"period": 0.22, "height": 0.05, "center": [7.5, 0], "radius": 1})"),
                     "geometry.ridges.center = [7.5,0.0]: the patterned disc must lie on the skin",
                     "<= half_width - radius = 7");
  const Ridges rect = parse_scene(ridged(R"({"period": 0.2, "height": 0.05, "center": [0, 0], "radius": 1,
                                              "profile": "rectangular"})"),
                                  kSource)
                          .geometry.ridges;
  EXPECT_EQ(rect.profile, RidgeProfile::rectangular);
  EXPECT_DOUBLE_EQ(rect.edge_width, 0.05);
  EXPECT_DOUBLE_EQ(rect.mesh_size(), 0.025);
  EXPECT_SCENE_ERROR(
      ridged(R"({"period": 0.22, "height": 0.05, "center": [0, 0], "radius": 1, "profile": "square"})"),
      "geometry.ridges.profile = \"square\": must be \"sinusoidal\" or \"rectangular\"");
  EXPECT_SCENE_ERROR(ridged(R"({"period": 0.2, "height": 0.05, "center": [0, 0], "radius": 1,
                                "profile": "rectangular", "edge_width": 0.11})"),
                     "geometry.ridges.edge_width = 0.11: must be a number in (0, period/2 = 0.1]");
  // A ridge mesh coarser than a third of the period cannot hold the profile (the probe's 5 mm over 0.5 mm).
  EXPECT_SCENE_ERROR(ridged(R"({"period": 0.5, "height": 0.05, "center": [0, 0], "radius": 1, "h": 5})"),
                     "geometry.ridges.h = 5: must be a number in (0, period/3 = 0.166667 mm]");
  EXPECT_SCENE_ERROR(ridged(R"({"period": 1e-6, "height": 0.05, "center": [0, 0], "radius": 1, "h": 0.2})"),
                     "geometry.ridges.h = 0.2: must be a number in (0, period/3 = 3.33333e-07 mm]");
  EXPECT_SCENE_ERROR(ridged(R"({"period": 0.2, "height": 0.05, "center": [0, 0], "radius": 1,
                                "edge_width": 0.05})"),
                     "geometry.ridges.edge_width = 0.05: is only for \"profile\": \"rectangular\"");
  EXPECT_SCENE_ERROR(with(&Doc::geometry, R"({"type": "surface", "path": "x.stl", "ridges": {}})"),
                     "geometry.ridges: unknown key");
}

TEST(SceneLoad, FlatGeometry) {
  EXPECT_SCENE_ERROR(with(&Doc::geometry, R"({"type": "flat", "h": 0, "half_width": 15})"),
                     "geometry.h = 0: must be a length in (0, 10000] mm");
  EXPECT_SCENE_ERROR(with(&Doc::geometry, R"({"type": "flat", "h": 3, "half_width": -1})"),
                     "geometry.half_width = -1: must be a length in (0, 10000] mm");
}

TEST(SceneLoad, Sensors) {
  EXPECT_SCENE_ERROR(with(&Doc::sensors, R"({"disc_diameter": 0.2})"),
                     "sensors = {\"disc_diameter\":0.2}: must have exactly one of \"positions\"", "\"line\"");
  EXPECT_SCENE_ERROR(
      with(
          &Doc::sensors,
          R"({"positions": [[0, 0]], "line": {"start": [0, 0], "step": [1, 0], "count": 1}, "disc_diameter": 0.2})"),
      "sensors = ", "must have exactly one of \"positions\"");
  EXPECT_SCENE_ERROR(with(&Doc::sensors, R"({"positions": [], "disc_diameter": 0.2})"),
                     "sensors.positions = []: must be a non-empty array of points [x, y]");
  EXPECT_SCENE_ERROR(with(&Doc::sensors, R"({"positions": [[0, 0]], "disc_diameter": 0})"),
                     "sensors.disc_diameter = 0: must be a length in (0, 10000] mm");
  EXPECT_SCENE_ERROR(
      with(&Doc::sensors, R"({"positions": [[0, 0], [1, 0], [2, 0], [1, 2, 3]], "disc_diameter": 0.2})"),
      "sensors.positions[3] = [1,2,3]: must be a point [x, y]");
  EXPECT_SCENE_ERROR(
      with(&Doc::sensors, R"({"line": {"start": [0, 0], "step": [1, 0], "count": 0}, "disc_diameter": 0.2})"),
      "sensors.line.count = 0: must be an integer in [1, 100000]");
  EXPECT_SCENE_ERROR(
      with(&Doc::sensors,
           R"({"line": {"start": [0, 0], "step": [1, 0], "count": 2.5}, "disc_diameter": 0.2})"),
      "sensors.line.count = 2.5: must be an integer in [1, 100000]");
}

TEST(SceneLoad, SensorsInsideFootprint) {
  // Cap: apex at (0.5, 0), truncation_radius 12, disc radius 0.1 → centres within 11.9 of the apex.
  EXPECT_SCENE_ERROR(
      with(&Doc::sensors, R"({"positions": [[0, 0], [1, 0], [2, 0], [12.5, 0]], "disc_diameter": 0.2})"),
      "sensors.positions[3] = [12.5,0.0]: sensor disc (diameter 0.2) must lie inside the cap footprint",
      "11.9", "(0.5, 0)");
  EXPECT_NO_THROW(
      parse_scene(with(&Doc::sensors, R"({"positions": [[12.4, 0]], "disc_diameter": 0.2})"), kSource));
  EXPECT_SCENE_ERROR(
      with(&Doc::sensors,
           R"({"line": {"start": [-4.5, 0], "step": [2, 0], "count": 10}, "disc_diameter": 0.2})"),
      "sensors.line (sensor 10 of 10) = [13.5,0.0]: sensor disc", "11.9");
  // Flat: |x|, |y| + 0.1 <= 15.
  Doc d;
  d.geometry = R"({"type": "flat", "h": 3, "half_width": 15})";
  d.sensors = R"({"positions": [[0, 14.95]], "disc_diameter": 0.2})";
  EXPECT_SCENE_ERROR(
      d.str(),
      "sensors.positions[0] = [0.0,14.95]: sensor disc (diameter 0.2) must lie inside the flat layer",
      "|x|, |y| <= half_width - disc_diameter/2 = 14.9");
  d.sensors = R"({"positions": [[14.9, -14.9]], "disc_diameter": 0.2})";
  EXPECT_NO_THROW(parse_scene(d.str(), kSource));
}

TEST(SceneLoad, Mesh) {
  const auto mesh = [](const std::string& body) { return with(&Doc::mesh, "{" + body + "}"); };
  EXPECT_SCENE_ERROR(mesh(R"("h_min": 0, "growth": 1.3, "h_max": 2)"),
                     "mesh.h_min = 0: must be a length in (0, 10000] mm");
  EXPECT_SCENE_ERROR(mesh(R"("h_min": 0.5, "growth": 1.3, "h_max": 0.4)"),
                     "mesh.h_max = 0.4: must be a number >= mesh.h_min = 0.5");
  EXPECT_SCENE_ERROR(mesh(R"("h_min": 0.5, "growth": 1, "h_max": 2)"),
                     "mesh.growth = 1: must be a number > 1");
  EXPECT_SCENE_ERROR(mesh(R"("h_min": 0.5, "growth": 1.3, "h_max": 2, "min_dihedral_deg": 0)"),
                     "mesh.min_dihedral_deg = 0: must be a number in (0, 30)");
  EXPECT_SCENE_ERROR(mesh(R"("h_min": 0.5, "growth": 1.3, "h_max": 2, "min_dihedral_deg": 30)"),
                     "mesh.min_dihedral_deg = 30: must be a number in (0, 30)");
  EXPECT_SCENE_ERROR(mesh(R"("h_min": 0.5, "growth": 1.3, "h_max": 2, "max_radius_edge": 1.05)"),
                     "mesh.max_radius_edge = 1.05: must be a number >= 1.1", "TetGen");
  EXPECT_SCENE_ERROR(
      mesh(
          R"("h_min": 0.5, "growth": 1.3, "h_max": 2, "regions": [{"from": [0, 0], "to": [1, 0], "radius": -1}])"),
      "mesh.regions[0].radius = -1: must be a number >= 0");
  EXPECT_SCENE_ERROR(
      mesh(
          R"("h_min": 0.5, "growth": 1.3, "h_max": 2, "regions": [{"from": [0, 0], "to": [1, 0], "radius": 1, "h": 0}])"),
      "mesh.regions[0].h = 0: must be a length in (0, 10000] mm");
  EXPECT_SCENE_ERROR(
      mesh(R"("h_min": 0.5, "growth": 1.3, "h_max": 2, "regions": [{"from": [0, 0], "to": 1, "radius": 1}])"),
      "mesh.regions[0].to = 1: must be a point [x, y]");
  EXPECT_SCENE_ERROR(mesh(R"("h_min": 0.5, "growth": 1.3, "h_max": 2, "regions": [3])"),
                     "mesh.regions[0] = 3: must be an object with keys from, to, radius, h");
}

TEST(SceneLoad, Punches) {
  const auto punch = [](const std::string& body) {
    return with(&Doc::extra, R"(, "loads": {"punches": [{"center": [0, 0], "diameter": 0.5, "force": 1}, {)" +
                                 body + "}]}");
  };
  EXPECT_SCENE_ERROR(punch(R"("center": [0, 0], "diameter": 0, "force": 1)"),
                     "loads.punches[1].diameter = 0: must be a length in (0, 10000] mm");
  EXPECT_SCENE_ERROR(punch(R"("center": [0, 0], "diameter": 0.5)"), "loads.punches[1] = {",
                     "must have exactly one of \"force\" (N) or \"displacement\" (mm)");
  EXPECT_SCENE_ERROR(punch(R"("center": [0, 0], "diameter": 0.5, "force": 1, "displacement": 0.01)"),
                     "loads.punches[1] = {", "must have exactly one of \"force\"");
  EXPECT_SCENE_ERROR(punch(R"("center": [0, 0], "diameter": 0.5, "force": 0)"),
                     "loads.punches[1].force = 0: must be a force in [1e-09, 1e+06] N");
  EXPECT_SCENE_ERROR(punch(R"("center": [0, 0], "diameter": 0.5, "displacement": -0.01)"),
                     "loads.punches[1].displacement = -0.01: must be a length in (0, 10000] mm");
}

TEST(SceneLoad, Patches) {
  const auto patch = [](const std::string& body) {
    return with(&Doc::extra, R"(, "loads": {"patches": [{)" + body + "}]}");
  };
  EXPECT_SCENE_ERROR(patch(R"("center": [0, 0], "diameter": 0, "direction": [1, 0, 0], "force": 1)"),
                     "loads.patches[0].diameter = 0: must be a length in (0, 10000] mm");
  EXPECT_SCENE_ERROR(patch(R"("center": [0, 0], "diameter": 0.5, "direction": [0, 0, 0], "force": 1)"),
                     "loads.patches[0].direction = [0,0,0]: must be a non-zero vector [x, y, z]");
  EXPECT_SCENE_ERROR(patch(R"("center": [0, 0], "diameter": 0.5, "direction": [1, 0], "force": 1)"),
                     "loads.patches[0].direction = [1,0]: must be a vector [x, y, z]");
  EXPECT_SCENE_ERROR(patch(R"("center": [0, 0], "diameter": 0.5, "direction": [1, 0, 0], "force": -1)"),
                     "loads.patches[0].force = -1: must be a force in [1e-09, 1e+06] N");
}

TEST(SceneLoad, Calibration) {
  EXPECT_SCENE_ERROR(with(&Doc::extra, R"(, "calibration": {"punch_diameter": 0})"),
                     "calibration.punch_diameter = 0: must be a length in (0, 10000] mm");
  EXPECT_SCENE_ERROR(with(&Doc::extra, R"(, "calibration": {"spacing": 0})"),
                     "calibration.spacing = 0: must be a length in (0, 10000] mm");
  EXPECT_SCENE_ERROR(with(&Doc::extra, R"(, "calibration": {"scan_half_width": -1})"),
                     "calibration.scan_half_width = -1: must be a number >= 0");
  EXPECT_NO_THROW(parse_scene(with(&Doc::extra, R"(, "calibration": {"scan_half_width": 0})"), kSource));
}

TEST(SceneLoad, EmptySourcePathIsNamedInMessages) {
  try {
    parse_scene("{}", "");
    FAIL() << "no error";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()), "<scene>: geometry: required key is missing; must be an object");
  }
}

// ---- The contact section ----------------------------------------------------------------------------

namespace {

// The default Doc (cap R = 129.7, h = 3.04, apex (0.5, 0), truncation_radius 12, E = 3, ν = 0.5) with a
// contact section of this body.
std::string contact(const std::string& body) { return with(&Doc::extra, R"(, "contact": {)" + body + "}"); }

// Flat layer h = 3, half_width 10, with a contact section of this body.
std::string flat_contact(const std::string& body) {
  Doc d;
  d.geometry = R"({"type": "flat", "h": 3, "half_width": 10})";
  d.extra = R"(, "contact": {)" + body + "}";
  return d.str();
}

// Half-space Hertz contact radius of a rigid body on an elastic one (Johnson 1985, eqs. 4.22–4.23), computed
// here independently of scene.cpp: a³ = 3 F R / (4 E*), or a² = R δ.
double hertz_force(double F, double R, double E, double nu) {
  return std::pow(3.0 * F * R * (1.0 - nu * nu) / (4.0 * E), 1.0 / 3.0);
}
double hertz_depth(double delta, double R) { return std::sqrt(R * delta); }

const std::string kPlane = R"("indenter": {"type": "plane"}, "force": 0.8)";

}  // namespace

TEST(SceneLoad, ShippedContactScenes) {
  const Scene c = load_scene(std::string(SKINFEM_SOURCE_DIR) + "/scenes/candelier2011.json");
  ASSERT_TRUE(c.contact);
  EXPECT_EQ(c.contact->indenter, IndenterKind::plane);  // the paper's plate on the cap
  EXPECT_EQ(contact_center(c), (Vec2{0.5, 0.0}));       // first touch at the apex
  EXPECT_TRUE(c.contact->sweep);
  const Scene h = load_scene(std::string(SKINFEM_SOURCE_DIR) + "/scenes/hertz_layer.json");
  ASSERT_TRUE(h.contact);
  EXPECT_EQ(h.contact->indenter, IndenterKind::sphere);
  EXPECT_EQ(h.contact->friction, FrictionMode::none);
}

TEST(SceneLoad, ContactEveryFieldIsRead) {
  const Scene s = parse_scene(contact(R"("indenter": {"type": "plane"}, "force": 0.8, "zone_radius": 3.0,
                 "h": 0.2, "holes": [{"center": [1, 0], "diameter": 0.5}, {"center": [-1, 2], "diameter": 0.3, "h": 0.05}],
                 "friction": {"mode": "coupled", "mu": 3, "static_ratio": 0.1, "direction": [3, -4]},
                 "sweep": {"from": [-2, 0], "to": [3, 0], "positions": 11, "hole_diameter": 0.4, "h": 0.1})"),
                              kSource);
  ASSERT_TRUE(s.contact);
  const ContactLoad& c = *s.contact;
  EXPECT_EQ(c.indenter, IndenterKind::plane);
  ASSERT_TRUE(c.force);
  EXPECT_EQ(*c.force, 0.8);
  EXPECT_FALSE(c.depth);
  EXPECT_EQ(c.zone_radius, 3.0);
  EXPECT_EQ(c.h, 0.2);
  ASSERT_EQ(c.holes.size(), 2u);
  EXPECT_EQ(c.holes[0].center, (Vec2{1, 0}));
  EXPECT_EQ(c.holes[0].diameter, 0.5);
  EXPECT_EQ(c.holes[1].center, (Vec2{-1, 2}));
  EXPECT_EQ(c.holes[1].diameter, 0.3);
  EXPECT_EQ(c.holes[0].h, 0.0);  // the zone's size
  EXPECT_EQ(c.holes[1].h, 0.05);
  EXPECT_EQ(c.friction, FrictionMode::coupled);
  EXPECT_EQ(c.mu, 3.0);
  EXPECT_EQ(c.static_ratio, 0.1);
  EXPECT_NEAR(c.direction[0], 0.6, 1e-15);  // normalised
  EXPECT_NEAR(c.direction[1], -0.8, 1e-15);
  ASSERT_TRUE(c.sweep);
  EXPECT_EQ(c.sweep->from, (Vec2{-2, 0}));
  EXPECT_EQ(c.sweep->to, (Vec2{3, 0}));
  EXPECT_EQ(c.sweep->positions, 11);
  EXPECT_EQ(c.sweep->hole_diameter, 0.4);
  EXPECT_EQ(c.sweep->h, 0.1);
  EXPECT_EQ(contact_center(s), (Vec2{0.5, 0.0}));  // a plane on a cap: the apex
  EXPECT_EQ(contact_zone_radius(s), 3.0);          // given
  EXPECT_EQ(contact_zone_h(s), 0.2);

  // A sphere on a flat layer, depth-controlled; every friction mode name.
  const Scene f = parse_scene(
      flat_contact(R"("indenter": {"type": "sphere", "R": 100, "center": [1.5, -2]}, "depth": 0.02,
                      "friction": {"mode": "static", "mu": 0.5, "static_ratio": 0.2})"),
      kSource);
  ASSERT_TRUE(f.contact);
  EXPECT_EQ(f.contact->indenter, IndenterKind::sphere);
  EXPECT_EQ(f.contact->sphere_R, 100.0);
  EXPECT_EQ(f.contact->center, (Vec2{1.5, -2}));
  EXPECT_EQ(contact_center(f), (Vec2{1.5, -2}));  // a sphere: its centre
  EXPECT_FALSE(f.contact->force);
  ASSERT_TRUE(f.contact->depth);
  EXPECT_EQ(*f.contact->depth, 0.02);
  EXPECT_EQ(f.contact->friction, FrictionMode::static_residual);
  EXPECT_EQ(f.contact->static_ratio, 0.2);
  for (const auto& [name, mode] :
       {std::make_pair("none", FrictionMode::none), std::make_pair("static", FrictionMode::static_residual),
        std::make_pair("uncoupled", FrictionMode::uncoupled),
        std::make_pair("coupled", FrictionMode::coupled)}) {
    // μ = 0 is allowed with every mode (coupled with μ = 0 must reproduce frictionless contact).
    const Scene m = parse_scene(
        contact(kPlane + R"(, "friction": {"mode": ")" + std::string(name) + R"(", "mu": 0})"), kSource);
    EXPECT_EQ(m.contact->friction, mode) << name;
    EXPECT_EQ(m.contact->mu, 0.0) << name;
  }
}

TEST(SceneLoad, ContactDefaults) {
  EXPECT_FALSE(parse_scene(Doc{}.str(), kSource).contact);  // no section, no contact
  const Scene s = parse_scene(contact(kPlane), kSource);
  ASSERT_TRUE(s.contact);
  const ContactLoad& c = *s.contact;
  EXPECT_TRUE(c.holes.empty());
  EXPECT_EQ(c.zone_radius, 0.0);  // automatic
  EXPECT_EQ(c.h, 0.0);
  EXPECT_EQ(contact_zone_h(s), 0.25);  // mesh.h_min
  EXPECT_EQ(c.friction, FrictionMode::none);
  EXPECT_EQ(c.mu, 0.0);
  EXPECT_EQ(c.static_ratio, 0.0);
  EXPECT_EQ(c.direction, (Vec2{1, 0}));
  EXPECT_FALSE(c.sweep);

  // An empty friction object keeps every default; a sweep with only its path takes the rest.
  const Scene e =
      parse_scene(contact(kPlane + R"(, "friction": {}, "sweep": {"from": [-1, 0], "to": [1, 0]})"), kSource);
  EXPECT_EQ(e.contact->friction, FrictionMode::none);
  EXPECT_EQ(e.contact->direction, (Vec2{1, 0}));
  ASSERT_TRUE(e.contact->sweep);
  EXPECT_EQ(e.contact->sweep->positions, 201);
  EXPECT_EQ(e.contact->sweep->hole_diameter, 0.5);
  EXPECT_EQ(e.contact->sweep->h, 0.0);  // no refinement along the path
  EXPECT_EQ(e.contact->sweep->model, HoleModel::bulge);
}

// The automatic zone: 1.25 × Hertz under a force; 1.25 × 2 √(R δ), the thin incompressible layer's bound,
// at a depth (there the bonded layer's contact exceeds Hertz's). E* = 3 / (1 − 0.25) = 4 MPa.
TEST(SceneLoad, ContactZoneRadiusIsHertzWithMargin) {
  const double E = 3.0, nu = 0.5, Rcap = 129.7;
  // Plane on the cap: R_eff = the cap's radius.
  const Scene plane = parse_scene(contact(kPlane), kSource);
  EXPECT_NEAR(contact_zone_radius(plane), 1.25 * hertz_force(0.8, Rcap, E, nu), 1e-12);
  EXPECT_NEAR(contact_zone_radius(plane), 1.25 * std::cbrt(3 * 0.8 * 129.7 / (4 * 4.0)), 1e-12);
  const Scene plane_d = parse_scene(contact(R"("indenter": {"type": "plane"}, "depth": 0.03)"), kSource);
  EXPECT_NEAR(contact_zone_radius(plane_d), 1.25 * 2 * hertz_depth(0.03, Rcap), 1e-12);

  // Sphere on the cap: curvatures add, 1/R_eff = 1/R_s + 1/R_cap.
  const double Rsc = 1 / (1 / 50.0 + 1 / Rcap);
  const Scene sc = parse_scene(
      contact(R"("indenter": {"type": "sphere", "R": 50, "center": [0.5, 0]}, "force": 0.5)"), kSource);
  EXPECT_NEAR(contact_zone_radius(sc), 1.25 * hertz_force(0.5, Rsc, E, nu), 1e-12);
  const Scene sc_d = parse_scene(
      contact(R"("indenter": {"type": "sphere", "R": 50, "center": [0.5, 0]}, "depth": 0.02)"), kSource);
  EXPECT_NEAR(contact_zone_radius(sc_d), 1.25 * 2 * hertz_depth(0.02, Rsc), 1e-12);

  // Sphere on a flat layer, compressible material: R_eff = the sphere's radius, E* = E/(1 − ν²).
  Doc d;
  d.geometry = R"({"type": "flat", "h": 3, "half_width": 10})";
  d.material = R"({"E": 2.0, "nu": 0.3})";
  d.extra = R"(, "contact": {"indenter": {"type": "sphere", "R": 129.7, "center": [0, 0]}, "force": 0.8})";
  EXPECT_NEAR(contact_zone_radius(parse_scene(d.str(), kSource)), 1.25 * hertz_force(0.8, 129.7, 2.0, 0.3),
              1e-12);
  const Scene flat_d = parse_scene(
      flat_contact(R"("indenter": {"type": "sphere", "R": 129.7, "center": [0, 0]}, "depth": 0.0231)"),
      kSource);
  EXPECT_NEAR(contact_zone_radius(flat_d), 1.25 * 2 * hertz_depth(0.0231, 129.7), 1e-12);

  // Sphere on an imported surface: R_eff = the sphere's radius; no footprint check (unknown before meshing).
  const fs::path dir = tmp_dir();
  write_file(dir / "dome.stl", "solid dome\nendsolid dome\n");
  Doc s;
  s.geometry = R"({"type": "surface", "path": "dome.stl"})";
  s.extra = R"(, "contact": {"indenter": {"type": "sphere", "R": 40, "center": [100, 0]}, "force": 1})";
  const Scene surf = parse_scene(s.str(), (dir / "x.json").string());
  EXPECT_NEAR(contact_zone_radius(surf), 1.25 * hertz_force(1.0, 40, E, nu), 1e-12);

  // Built in code: a plane off a cap has no Hertz radius unless the zone is given.
  Scene coded = parse_scene(flat_contact(R"("indenter": {"type": "sphere", "R": 50, "center": [0, 0]},
                                           "force": 1)"),
                            kSource);
  coded.contact->indenter = IndenterKind::plane;
  EXPECT_THROW(contact_zone_radius(coded), SceneError);
  coded.contact->zone_radius = 2;
  EXPECT_EQ(contact_zone_radius(coded), 2.0);
}

TEST(SceneLoad, ContactPlaneNeedsACap) {
  EXPECT_SCENE_ERROR(flat_contact(kPlane), "contact.indenter.type = \"plane\"", "on a flat layer",
                     "touches it everywhere at once", "needs a cap");
  const fs::path dir = tmp_dir();
  write_file(dir / "dome.stl", "solid dome\nendsolid dome\n");
  Doc s;
  s.geometry = R"({"type": "surface", "path": "dome.stl"})";
  s.extra = ", \"contact\": {" + kPlane + "}";
  const std::string msg = error_of(s.str(), (dir / "x.json").string());
  EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
  EXPECT_NE(msg.find("contact.indenter.type = \"plane\""), std::string::npos) << msg;
  EXPECT_NE(msg.find("a plane needs a cap geometry"), std::string::npos) << msg;
  EXPECT_NE(msg.find("imported surface"), std::string::npos) << msg;
  // A sphere fits every geometry.
  EXPECT_NO_THROW(parse_scene(flat_contact(R"("indenter": {"type": "sphere", "R": 50, "center": [0, 0]},
                                              "force": 1)"),
                              kSource));
}

TEST(SceneLoad, ContactHoleOffTheSkin) {
  // Cap: apex (0.5, 0), truncation_radius 12; a hole of diameter 0.5 needs its centre within 11.75.
  EXPECT_SCENE_ERROR(
      contact(kPlane +
              R"(, "holes": [{"center": [1, 0], "diameter": 0.5}, {"center": [12.4, 0], "diameter": 0.5}])"),
      "contact.holes[1] = {", "hole 2 of 2", "centre (12.4, 0)", "off the skin",
      "must lie on the skin's footprint", "truncation_radius - diameter/2 = 11.75", "got 11.9");
  EXPECT_NO_THROW(
      parse_scene(contact(kPlane + R"(, "holes": [{"center": [12.25, 0], "diameter": 0.5}])"), kSource));
  EXPECT_SCENE_ERROR(contact(kPlane + R"(, "holes": [{"center": [1, 0], "diameter": 0.5, "h": 0}])"),
                     "contact.holes[0].h = 0", "must be a length in (0, 10000] mm");
  // Flat: |x|, |y| <= half_width - diameter/2.
  EXPECT_SCENE_ERROR(flat_contact(R"("indenter": {"type": "sphere", "R": 50, "center": [0, 0]}, "force": 1,
                                     "holes": [{"center": [0, -9.9], "diameter": 0.4}])"),
                     "contact.holes[0] = {", "hole 1 of 1", "off the skin", "half_width - diameter/2 = 9.8",
                     "got 9.9");
  // The sphere's centre.
  EXPECT_SCENE_ERROR(
      flat_contact(R"("indenter": {"type": "sphere", "R": 100, "center": [10.5, 0]}, "force": 1)"),
      "contact.indenter.center = [10.5,0.0]", "the sphere's centre must lie on the skin's footprint",
      "half_width = 10", "got 10.5");
  EXPECT_SCENE_ERROR(
      contact(R"("indenter": {"type": "sphere", "R": 100, "center": [0.5, -12.5]}, "force": 1)"),
      "contact.indenter.center = [0.5,-12.5]", "the sphere's centre must lie on the skin's footprint",
      "truncation_radius = 12", "got 12.5");
  // The swept hole, at either end of its path.
  EXPECT_SCENE_ERROR(contact(kPlane + R"(, "sweep": {"from": [-11.3, 0], "to": [0, 0]})"),
                     "contact.sweep.from = [-11.3,0.0]", "the swept hole (diameter 0.5)",
                     "must stay on the skin's footprint", "hole_diameter/2 = 11.75", "got 11.8");
  EXPECT_NO_THROW(parse_scene(contact(kPlane + R"(, "sweep": {"from": [-11.2, 0], "to": [0, 0]})"), kSource));
  EXPECT_SCENE_ERROR(contact(kPlane + R"(, "sweep": {"from": [0, 0], "to": [0, 11], "hole_diameter": 2.5})"),
                     "contact.sweep.to = [0.0,11.0]", "the swept hole (diameter 2.5)");
  EXPECT_SCENE_ERROR(flat_contact(R"("indenter": {"type": "sphere", "R": 50, "center": [0, 0]}, "force": 1,
                                     "sweep": {"from": [-9.9, 0], "to": [9, 0]})"),
                     "contact.sweep.from = [-9.9,0.0]", "half_width - hole_diameter/2 = 9.75");
}

TEST(SceneLoad, ContactZoneMustStayOneThicknessInsideTheSide) {
  // Given zone on the cap: 10 + 3.04 > 12 from the apex.
  EXPECT_SCENE_ERROR(contact(kPlane + R"(, "zone_radius": 10)"), "contact.zone_radius = 10",
                     "must stay one skin thickness (h at the apex = 3.04)", "truncation_radius = 12",
                     "zone radius + h = 13.04 > 12", "would reach the truncated side");
  EXPECT_NO_THROW(parse_scene(contact(kPlane + R"(, "zone_radius": 8.9)"), kSource));
  // Sphere off-centre on a flat layer: 2.5 + 3 > 10 − 5.
  EXPECT_SCENE_ERROR(flat_contact(R"("indenter": {"type": "sphere", "R": 50, "center": [0, -5]}, "force": 1,
                                     "zone_radius": 2.5)"),
                     "contact.zone_radius = 2.5", "about (0, -5)", "half_width = 10",
                     "zone radius + h = 5.5 > 5", "would reach the truncated side");
  EXPECT_NO_THROW(parse_scene(flat_contact(R"("indenter": {"type": "sphere", "R": 50, "center": [0, -5]},
                                             "force": 1, "zone_radius": 1.9)"),
                              kSource));
  // The automatic zone names the load that sets it: 1.25 × Hertz at 100 N is 16.8 mm.
  EXPECT_SCENE_ERROR(contact(R"("indenter": {"type": "plane"}, "force": 100)"), "contact.force = 100",
                     "automatic candidate contact zone (1.25 x Hertz radius = 16.8",
                     "would reach the truncated side");
  EXPECT_SCENE_ERROR(contact(R"("indenter": {"type": "plane"}, "depth": 0.5)"), "contact.depth = 0.5",
                     "automatic candidate contact zone (1.25 x 2 sqrt(R_eff depth)",
                     "would reach the truncated side");
}

TEST(SceneLoad, ContactErrors) {
  EXPECT_SCENE_ERROR(with(&Doc::extra, R"(, "contact": 1)"),
                     "contact = 1: must be an object with keys indenter");
  EXPECT_SCENE_ERROR(contact(R"("force": 0.8)"), "contact.indenter: required key is missing");
  EXPECT_SCENE_ERROR(contact(R"("indenter": "plane", "force": 0.8)"),
                     "contact.indenter = \"plane\": must be");
  EXPECT_SCENE_ERROR(contact(R"("indenter": {}, "force": 0.8)"),
                     "contact.indenter.type: required key is missing");
  EXPECT_SCENE_ERROR(contact(R"("indenter": {"type": "cone"}, "force": 1)"),
                     "contact.indenter.type = \"cone\": must be \"plane\" or \"sphere\"");
  EXPECT_SCENE_ERROR(contact(R"("indenter": {"type": "plane", "R": 3}, "force": 1)"),
                     "contact.indenter.R: unknown key; allowed: type");
  EXPECT_SCENE_ERROR(contact(R"("indenter": {"type": "sphere", "center": [0, 0]}, "force": 1)"),
                     "contact.indenter.R: required key is missing");
  EXPECT_SCENE_ERROR(contact(R"("indenter": {"type": "sphere", "R": 0, "center": [0, 0]}, "force": 1)"),
                     "contact.indenter.R = 0: must be a radius in [0.001, 10000] mm");
  EXPECT_SCENE_ERROR(contact(R"("indenter": {"type": "sphere", "R": 5}, "force": 1)"),
                     "contact.indenter.center: required key is missing");
  EXPECT_SCENE_ERROR(contact(R"("indenter": {"type": "plane"})"), "contact = {",
                     "must have exactly one of \"force\" (N) or \"depth\" (mm)");
  EXPECT_SCENE_ERROR(contact(kPlane + R"(, "depth": 0.01)"), "contact = {", "exactly one of");
  EXPECT_SCENE_ERROR(contact(R"("indenter": {"type": "plane"}, "force": 0)"),
                     "contact.force = 0: must be a force in [1e-09, 1e+06] N");
  EXPECT_SCENE_ERROR(contact(R"("indenter": {"type": "plane"}, "depth": -0.1)"),
                     "contact.depth = -0.1: must be a length in (0, 10000] mm");
  EXPECT_SCENE_ERROR(contact(kPlane + R"(, "holes": {"center": [0, 0]})"), "contact.holes = {",
                     "must be an array of holes");
  EXPECT_SCENE_ERROR(contact(kPlane + R"(, "holes": [{"center": [0, 0]}])"),
                     "contact.holes[0].diameter: required key is missing");
  EXPECT_SCENE_ERROR(contact(kPlane + R"(, "holes": [{"center": [0, 0], "diameter": 0}])"),
                     "contact.holes[0].diameter = 0: must be a length in (0, 10000] mm");
  EXPECT_SCENE_ERROR(contact(kPlane + R"(, "holes": [{"center": [0], "diameter": 1}])"),
                     "contact.holes[0].center = [0]: must be a point [x, y]");
  EXPECT_SCENE_ERROR(contact(kPlane + R"(, "zone_radius": 0)"),
                     "contact.zone_radius = 0: must be a length in (0, 10000] mm");
  EXPECT_SCENE_ERROR(contact(kPlane + R"(, "h": -1)"), "contact.h = -1: must be a length in (0, 10000] mm");
  EXPECT_SCENE_ERROR(
      contact(kPlane + R"(, "friction": {"mode": "kinetic"})"),
      "contact.friction.mode = \"kinetic\": must be one of \"none\", \"static\", \"uncoupled\", "
      "\"coupled\"");
  EXPECT_SCENE_ERROR(contact(kPlane + R"(, "friction": {"mu": -1})"),
                     "contact.friction.mu = -1: must be a number >= 0");
  EXPECT_SCENE_ERROR(contact(kPlane + R"(, "friction": {"static_ratio": -0.1})"),
                     "contact.friction.static_ratio = -0.1: must be a number in [0, mu = 0]");
  // At rest the plate cannot hold more than Coulomb's cone: static_ratio 5 with mu 1 was 1.5 N on 0.3 N.
  EXPECT_SCENE_ERROR(contact(kPlane + R"(, "friction": {"mu": 1, "static_ratio": 5})"),
                     "contact.friction.static_ratio = 5: must be a number in [0, mu = 1]");
  EXPECT_SCENE_ERROR(contact(kPlane + R"(, "friction": {"mode": "static", "static_ratio": 0.1})"),
                     "contact.friction.static_ratio = 0.1: must be a number in [0, mu = 0]",
                     "give contact.friction.mu");
  // A hole coarser than its mesh can fall between contact vertices and read zero (contact.h 0.8 here).
  EXPECT_SCENE_ERROR(
      contact(kPlane + R"(, "h": 0.8, "holes": [{"center": [0.5, 0], "diameter": 0.5}])"),
      "contact.holes[0].diameter = 0.5: must be >= the mesh size over the hole (contact.h = 0.8 mm)",
      "give contact.holes[0].h <= 0.5");
  EXPECT_SCENE_ERROR(
      contact(kPlane + R"(, "h": 0.8, "sweep": {"from": [-1, 0], "to": [1, 0], "hole_model": "resolved"})"),
      "contact.sweep.hole_diameter = 0.5: must be >= the mesh size over the hole (contact.h = 0.8",
      "give contact.sweep.h <= 0.5");
  // A swept hole modelled as its bulge is not resolved by the mesh: no such rule.
  EXPECT_NO_THROW(
      parse_scene(contact(kPlane + R"(, "h": 0.8, "sweep": {"from": [-1, 0], "to": [1, 0]})"), kSource));
  // The bulge is a hard interface's; through a compliant one the hole is resolved, unless told otherwise.
  EXPECT_EQ(parse_scene(contact(kPlane + R"(, "interface": {"law": "linear", "K": 5}, "h": 0.4,
                                "sweep": {"from": [-1, 0], "to": [1, 0]})"),
                        kSource)
                .contact->sweep->model,
            HoleModel::resolved);
  EXPECT_SCENE_ERROR(contact(kPlane + R"(, "interface": {"law": "linear", "K": 5}, "h": 0.4,
                                "sweep": {"from": [-1, 0], "to": [1, 0], "hole_model": "bulge"})"),
                     "contact.sweep.hole_model = \"bulge\": is the hole's solution under a hard interface");
  EXPECT_SCENE_ERROR(contact(kPlane + R"(, "sweep": {"from": [-1, 0], "to": [1, 0], "hole_model": "crack"})"),
                     "contact.sweep.hole_model = \"crack\": must be one of \"bulge\", \"resolved\"");
  // Refined over the hole, it is accepted: the hole's own h (or the sweep's path h) is the size there.
  EXPECT_NO_THROW(
      parse_scene(contact(kPlane + R"(, "h": 0.8, "holes": [{"center": [0.5, 0], "diameter": 0.5, "h": 0.25}],
                          "sweep": {"from": [-1, 0], "to": [1, 0], "h": 0.4})"),
                  kSource));
  EXPECT_SCENE_ERROR(contact(kPlane + R"(, "friction": {"direction": [0, 0]})"),
                     "contact.friction.direction = [0,0]: must be a non-zero vector");
  EXPECT_SCENE_ERROR(contact(kPlane + R"(, "friction": {"direction": [1, 0, 0]})"),
                     "contact.friction.direction = [1,0,0]: must be a point [x, y]");
  EXPECT_SCENE_ERROR(
      contact(kPlane + R"(, "friction": {"mu": 1, "speed": 2})"),
      "contact.friction.speed: unknown key; allowed: mode, law, mu, tau0, static_ratio, direction");
  // Friction laws: a shear strength is a stress >= 0 or "from_force", and only a shear-strength law has one.
  EXPECT_SCENE_ERROR(
      contact(kPlane + R"(, "friction": {"law": "tresca"})"),
      R"(contact.friction.law = "tresca": must be one of "coulomb", "shear_strength", "mixed")");
  EXPECT_SCENE_ERROR(contact(kPlane + R"(, "friction": {"law": "shear_strength", "tau0": -0.1})"),
                     "contact.friction.tau0 = -0.1: must be a shear strength in [0, 1e6] MPa");
  EXPECT_SCENE_ERROR(
      contact(kPlane + R"(, "friction": {"law": "shear_strength", "tau0": 2})"),
      "contact.friction.tau0 = 2: must be at most the skin's shear modulus G = E / (2 (1 + nu)) "
      "= 1 MPa");
  EXPECT_SCENE_ERROR(
      contact(kPlane + R"(, "friction": {"law": "mixed", "tau0": "auto"})"),
      R"(contact.friction.tau0 = "auto": must be a shear strength in [0, 1e6] MPa, or "from_force")");
  EXPECT_SCENE_ERROR(
      contact(kPlane + R"(, "friction": {"mu": 1, "tau0": 0.1})"),
      R"(contact.friction.tau0 = 0.1: is the shear strength of "law": "shear_strength" or "mixed")");
  // Interfaces: hard, linear with a stiffness > 0, exponential with u0 and p_ref > 0; each parameter only
  // where its law has it; exponential touches everywhere, so only under Coulomb friction.
  EXPECT_SCENE_ERROR(contact(kPlane + R"(, "interface": {"law": "linear"})"),
                     "contact.interface.K: required key is missing");
  EXPECT_SCENE_ERROR(contact(kPlane + R"(, "interface": {"law": "linear", "K": -1})"),
                     "contact.interface.K = -1: must be an interface stiffness in (0, 1e12] MPa/mm");
  EXPECT_SCENE_ERROR(
      contact(kPlane + R"(, "interface": {"law": "hard", "K": 5})"),
      R"(contact.interface.K = 5: is the stiffness of "law": "linear"; this interface has none)");
  EXPECT_SCENE_ERROR(contact(kPlane + R"(, "interface": {"law": "softened"})"),
                     R"(contact.interface.law = "softened": must be one of "hard", "linear", "exponential")");
  EXPECT_SCENE_ERROR(contact(kPlane + R"(, "interface": {"law": "exponential", "p_ref": 0.01})"),
                     "contact.interface.u0: required key is missing");
  EXPECT_SCENE_ERROR(contact(kPlane + R"(, "interface": {"law": "exponential", "u0": 0, "p_ref": 0.01})"),
                     "contact.interface.u0 = 0: must be a decay length in (0, 1] mm");
  EXPECT_SCENE_ERROR(contact(kPlane + R"(, "interface": {"law": "exponential", "u0": 0.001, "p_ref": -1})"),
                     "contact.interface.p_ref = -1: must be a pressure in (0, 1e6] MPa");
  EXPECT_SCENE_ERROR(
      contact(kPlane + R"(, "interface": {"law": "linear", "K": 5, "u0": 0.001})"),
      R"(contact.interface.u0 = 0.001: is the decay length of "law": "exponential"; this interface has none)");
  EXPECT_SCENE_ERROR(
      contact(
          kPlane +
          R"(, "friction": {"law": "shear_strength", "mu": 1}, "interface": {"law": "exponential", "u0": 0.001, "p_ref": 0.01})"),
      R"(contact.interface.law = "exponential": touches everywhere, and a shear strength acts where the skin touches)");
  EXPECT_SCENE_ERROR(contact(kPlane + R"(, "interface": {"K": 5})"),
                     "contact.interface.law: required key is missing");
  {
    const Interface i =
        parse_scene(contact(kPlane + R"(, "interface": {"law": "exponential", "u0": 0.002, "p_ref": 0.03})"),
                    kSource)
            .contact->interface;
    EXPECT_EQ(i.law, InterfaceLaw::exponential);
    EXPECT_EQ(i.u0, 0.002);
    EXPECT_EQ(i.p_ref, 0.03);
  }
  EXPECT_EQ(parse_scene(contact(kPlane + R"(, "interface": {"law": "linear", "K": 40})"), kSource)
                .contact->interface.K,
            40.0);
  {
    const Scene s =
        parse_scene(contact(kPlane + R"(, "friction": {"law": "mixed", "mu": 0.5, "tau0": 0.12})"), kSource);
    EXPECT_EQ(s.contact->law, FrictionLaw::mixed);
    EXPECT_EQ(s.contact->tau0, 0.12);
    const Scene f = parse_scene(
        contact(kPlane + R"(, "friction": {"law": "shear_strength", "mu": 3, "tau0": "from_force"})"),
        kSource);
    EXPECT_EQ(f.contact->law, FrictionLaw::shear_strength);
    EXPECT_FALSE(f.contact->tau0.has_value());
  }
  EXPECT_SCENE_ERROR(contact(kPlane + R"(, "sweep": {"to": [1, 0]})"),
                     "contact.sweep.from: required key is missing");
  for (const char* n : {"1", "2.5", "100001", "\"5\""})
    EXPECT_SCENE_ERROR(
        contact(kPlane + R"(, "sweep": {"from": [0, 0], "to": [1, 0], "positions": )" + n + "}"),
        "contact.sweep.positions = " + std::string(n) + ": must be an integer in [2, 100000]");
  EXPECT_SCENE_ERROR(contact(kPlane + R"(, "sweep": {"from": [0, 0], "to": [1, 0], "hole_diameter": 0})"),
                     "contact.sweep.hole_diameter = 0: must be a length in (0, 10000] mm");
  // The bulge model's range (issue 57): (ε/d)² ≤ 0.065 on the 3.04 mm cap, 1.5 mm holes (0.061) pass, a 2 mm
  // hole (0.108) is refused unless resolved.
  EXPECT_NO_THROW(parse_scene(
      contact(kPlane + R"(, "sweep": {"from": [0, 0], "to": [1, 0], "hole_diameter": 1.5})"), kSource));
  EXPECT_SCENE_ERROR(contact(kPlane + R"(, "sweep": {"from": [0, 0], "to": [1, 0], "hole_diameter": 2})"),
                     "contact.sweep.hole_diameter = 2.0: the bulge hole model", "<= 0.065", "here 0.108",
                     R"(give "hole_model": "resolved")");
  EXPECT_NO_THROW(parse_scene(
      contact(kPlane +
              R"(, "sweep": {"from": [0, 0], "to": [1, 0], "hole_diameter": 2, "hole_model": "resolved"})"),
      kSource));
  EXPECT_SCENE_ERROR(contact(kPlane + R"(, "sweep": {"from": [0, 0], "to": [1, 0], "h": 0})"),
                     "contact.sweep.h = 0: must be a length in (0, 10000] mm");
  EXPECT_SCENE_ERROR(contact(kPlane + R"(, "sweep": {"from": [0, 0], "to": [1, 0], "step": 1})"),
                     "contact.sweep.step: unknown key; allowed: from, to, positions, hole_diameter, h");
  EXPECT_SCENE_ERROR(contact(kPlane + R"(, "colour": 1)"), "contact.colour: unknown key; allowed: indenter");
  EXPECT_SCENE_ERROR(contact(kPlane + R"(, "force": 1)"), "contact.force: duplicate key");
  EXPECT_SCENE_ERROR(contact(kPlane + R"(, "friction": {"mu": 1, "mu": 2})"),
                     "contact.friction.mu: duplicate key");
  EXPECT_SCENE_ERROR(with(&Doc::extra, ", \"contact\": {" + kPlane + R"(}, "contact": {})"),
                     "contact: duplicate key");
}
