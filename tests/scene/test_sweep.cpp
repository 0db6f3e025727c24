// Sweep specs: members in the stated order with the stated values (grid, zip, ranges), names that follow the
// content only, imported surfaces kept findable, and each class of bad spec refused in one line.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "scene/sweep.hpp"

namespace fs = std::filesystem;
using namespace skinfem;

namespace {

// A spec beside its base scene in a fresh folder; returns the spec's path.
std::string write_spec(const std::string& name, const std::string& spec) {
  const fs::path dir = fs::path(SKINFEM_TEST_TMP) / ("sweep_" + name);
  fs::create_directories(dir / "skins");
  std::ofstream(dir / "skins" / "base.json")
      << R"({"geometry": {"type": "flat", "h": 3.0, "half_width": 20.0},
    "material": {"E": 3.0, "nu": 0.5}, "sensors": {"positions": [[0.0, 0.0]], "disc_diameter": 0.2},
    "mesh": {"h_min": 0.4, "growth": 1.5, "h_max": 3.0}, "calibration": {"punch_diameter": 0.5}})";
  std::ofstream(dir / "spec.json") << spec;
  return (dir / "spec.json").string();
}

std::string refused(const std::string& name, const std::string& spec) {
  try {
    load_sweep(write_spec(name, spec));
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
    return e.what();
  }
  ADD_FAILURE() << name << ": accepted";
  return "";
}

}  // namespace

TEST(Sweep, GridHasEveryCombinationLastAxisFastest) {
  const Sweep s = load_sweep(write_spec("grid", R"({"scene": "skins/base.json", "command": "kfit",
    "options": {"path": "meridian", "load": "point"},
    "axes": [{"pointer": "/material/nu", "values": [0.4, 0.5]},
             {"pointer": "/calibration/punch_diameter", "range": {"from": 0.25, "to": 1.0, "count": 4}}]})"));
  ASSERT_EQ(s.members.size(), 8u);
  EXPECT_EQ(s.options, (std::vector<std::string>{"--load", "point", "--path", "meridian"}));
  EXPECT_EQ(s.axes[1].column, "calibration.punch_diameter");
  const double d[] = {0.25, 0.5, 0.75, 1.0};
  std::set<std::string> ids;
  for (std::size_t m = 0; m < 8; ++m) {
    const Scene& scene = s.members[m].scene;
    EXPECT_DOUBLE_EQ(scene.material.nu, m < 4 ? 0.4 : 0.5) << m;
    EXPECT_DOUBLE_EQ(scene.calibration.punch_diameter, d[m % 4]) << m;
    EXPECT_EQ(s.members[m].id.size(), 12u);
    ids.insert(s.members[m].id);
  }
  EXPECT_EQ(ids.size(), 8u);
  EXPECT_EQ(s.name, "spec");
}

TEST(Sweep, ZipPairsTheAxesAndAStepRangeEndsAtItsLastStep) {
  const Sweep s = load_sweep(write_spec("zip", R"({"scene": "skins/base.json", "command": "green",
    "combine": "zip", "axes": [{"pointer": "/material/E", "range": {"from": 1, "to": 2.05, "step": 0.5}},
                               {"pointer": "/geometry/h", "values": [2.0, 3.0, 4.0]}]})"));
  ASSERT_EQ(s.members.size(), 3u);
  for (std::size_t m = 0; m < 3; ++m) {
    EXPECT_DOUBLE_EQ(s.members[m].scene.material.E, 1 + 0.5 * m);
    EXPECT_DOUBLE_EQ(s.members[m].scene.geometry.flat.h, 2.0 + m);
  }
}

TEST(Sweep, AMembersNameFollowsItsContentOnly) {
  // The same member in two sweeps of different shape has the same name; a different option renames it.
  const auto one = load_sweep(write_spec("name_a", R"({"scene": "skins/base.json", "command": "kfit",
    "axes": [{"pointer": "/material/nu", "values": [0.45]}]})"));
  const auto two = load_sweep(write_spec("name_b", R"({"scene": "skins/base.json", "command": "kfit",
    "mem_mb": 300, "axes": [{"pointer": "/material/nu", "values": [0.4, 0.45]}]})"));
  const auto other = load_sweep(write_spec("name_c", R"({"scene": "skins/base.json", "command": "kfit",
    "options": {"path": "3d"}, "axes": [{"pointer": "/material/nu", "values": [0.45]}]})"));
  EXPECT_EQ(one.members[0].id, two.members[1].id);
  EXPECT_NE(one.members[0].id, two.members[0].id);
  EXPECT_NE(one.members[0].id, other.members[0].id);
  EXPECT_EQ(two.mem_mb, 300);
}

TEST(Sweep, ARelativeSurfaceIsFoundFromTheMembersFolder) {
  // The base scene names its surface relative to its own folder; the members live elsewhere.
  const std::string base_surface =
      write_spec("surface_base", R"({"scene": "skins/dome.json", "command": "kfit",
    "axes": [{"pointer": "/material/nu", "values": [0.5]}]})");
  const fs::path dir = fs::path(base_surface).parent_path();
  fs::copy_file(fs::path(SKINFEM_SOURCE_DIR) / "scenes" / "dome.stl", dir / "skins" / "dome.stl",
                fs::copy_options::overwrite_existing);
  std::ofstream(dir / "skins" / "dome.json") << R"({"geometry": {"type": "surface", "path": "dome.stl"},
    "material": {"E": 3.0, "nu": 0.5}, "sensors": {"positions": [[0.0, 0.0]], "disc_diameter": 0.2},
    "mesh": {"h_min": 0.6, "growth": 1.5, "h_max": 3.0}})";
  const Sweep s = load_sweep(base_surface);
  const std::string expected = (dir / "skins" / "dome.stl").lexically_normal().string();
  EXPECT_NE(s.members[0].scene_json.find(expected), std::string::npos) << s.members[0].scene_json;
  EXPECT_EQ(s.members[0].scene.geometry.surface.path, expected);
}

TEST(Sweep, BadSpecsAreRefusedInOneLine) {
  const std::string head = R"({"scene": "skins/base.json", "command": "kfit", )";
  EXPECT_NE(refused("pointer", head + R"("axes": [{"pointer": "/materail/nu", "values": [1]}]})")
                .find("axes[0].pointer = \"/materail/nu\": names nothing in the base scene"),
            std::string::npos);
  EXPECT_NE(refused("syntax", head + R"("axes": [{"pointer": "material/nu", "values": [1]}]})")
                .find("must be a JSON pointer"),
            std::string::npos);
  EXPECT_NE(refused("empty", head + R"("axes": [{"pointer": "/material/nu", "values": []}]})")
                .find("axes[0].values = []: must be a non-empty array"),
            std::string::npos);
  EXPECT_NE(refused("zip", head + R"("combine": "zip", "axes": [{"pointer": "/material/nu", "values": [0.4]},
              {"pointer": "/geometry/h", "values": [2, 3]}]})")
                .find("has 2 values, axes[0] has 1: zipped axes need equal lengths"),
            std::string::npos);
  EXPECT_NE(refused("member", head + R"("axes": [{"pointer": "/geometry/h", "values": [3, -1]}]})")
                .find("member 2 (/geometry/h = -1): "),
            std::string::npos);
  EXPECT_NE(refused("twice", head + R"("axes": [{"pointer": "/material/nu", "values": [0.4]},
              {"pointer": "/material/nu", "values": [0.5]}]})")
                .find("is already an axis"),
            std::string::npos);
  EXPECT_NE(refused("same", head + R"("axes": [{"pointer": "/material/nu", "values": [0.5, 0.5]}]})")
                .find("the same scene as an earlier member"),
            std::string::npos);
  EXPECT_NE(
      refused("option",
              head + R"("options": {"path": "2d"}, "axes": [{"pointer": "/material/nu", "values": [0.5]}]})")
          .find("options.path = \"2d\": must be one of 3d, auto, meridian"),
      std::string::npos);
  EXPECT_NE(
      refused("grid_size",
              head + R"("axes": [{"pointer": "/material/nu", "range": {"from": 0, "to": 0.5, "count": 200}},
              {"pointer": "/material/E", "range": {"from": 1, "to": 2, "count": 200}}]})")
          .find("allowed at most 10000"),
      std::string::npos);
  EXPECT_NE(refused("name", R"({"name": "../up", "scene": "skins/base.json", "command": "kfit",
              "axes": [{"pointer": "/material/nu", "values": [0.5]}]})")
                .find("name = \"../up\": must be a file name"),
            std::string::npos);
  // Read as a scene file is: a duplicate key in the spec or in its base scene is refused, not resolved.
  EXPECT_NE(refused("dup_spec",
                    head + R"("command": "green", "axes": [{"pointer": "/material/nu", "values": [0.5]}]})")
                .find("command: duplicate key"),
            std::string::npos);
  const std::string dup = write_spec("dup_base", R"({"scene": "skins/dup.json", "command": "kfit",
    "axes": [{"pointer": "/material/nu", "values": [0.5]}]})");
  std::ofstream(fs::path(dup).parent_path() / "skins" / "dup.json")
      << R"({"geometry": {"type": "flat", "h": 3.0, "h": 2.0, "half_width": 20.0}})";
  try {
    load_sweep(dup);
    ADD_FAILURE() << "a base scene with a duplicate key was accepted";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("dup.json: geometry.h: duplicate key"), std::string::npos)
        << e.what();
  }
  EXPECT_NE(refused("no_scene", R"({"command": "kfit", "axes": []})").find("scene"), std::string::npos);
}
