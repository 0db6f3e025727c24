// Sweep specs: members in the stated order with the stated values (grid, zip, ranges), names that follow the
// content only, imported surfaces kept findable, and each class of bad spec refused in one line.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "skinfem/scene/sweep.hpp"

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

TEST(Sweep, AStepRangeEndsAtItsEndNeverBeyond) {
  // from + i·step rounds (0.1 + 2 × 0.1 = 0.30000000000000004): the last value is `to` when that close to it.
  const struct {
    double from, to, step;
    std::vector<double> want;
  } ranges[] = {{0.1, 0.3, 0.1, {0.1, 0.2, 0.3}},
                {0.7, 1.0, 0.1, {0.7, 0.8, 0.9, 1.0}},
                {0.3, 0.9, 0.3, {0.3, 0.6, 0.9}},
                {1.0, 2.05, 0.5, {1.0, 1.5, 2.0}}};
  int k = 0;
  for (const auto& g : ranges) {
    char spec[256];
    std::snprintf(spec, sizeof spec, R"({"scene": "skins/base.json", "command": "green",
      "axes": [{"pointer": "/material/E", "range": {"from": %.17g, "to": %.17g, "step": %.17g}}]})",
                  g.from, g.to, g.step);
    const Sweep s = load_sweep(write_spec("step_" + std::to_string(k++), spec));
    ASSERT_EQ(s.members.size(), g.want.size()) << spec;
    for (std::size_t m = 0; m < g.want.size(); ++m) {
      EXPECT_LE(s.members[m].scene.material.E, g.to) << spec;
      EXPECT_NEAR(s.members[m].scene.material.E, g.want[m], 1e-12) << spec;
    }
    if (g.want.back() == g.to) {
      EXPECT_EQ(s.members.back().scene.material.E, g.to) << spec;
    }
  }
}

TEST(Sweep, AMembersNameFollowsTheSurfaceItImports) {
  const std::string spec = write_spec("surface_edit", R"({"scene": "skins/dome.json", "command": "kfit",
    "axes": [{"pointer": "/material/nu", "values": [0.5]}]})");
  const fs::path skins = fs::path(spec).parent_path() / "skins";
  fs::copy_file(fs::path(SKINFEM_SOURCE_DIR) / "scenes" / "dome.stl", skins / "dome.stl",
                fs::copy_options::overwrite_existing);
  std::ofstream(skins / "dome.json") << R"({"geometry": {"type": "surface", "path": "dome.stl"},
    "material": {"E": 3.0, "nu": 0.5}, "sensors": {"positions": [[0.0, 0.0]], "disc_diameter": 0.2},
    "mesh": {"h_min": 0.6, "growth": 1.5, "h_max": 3.0}})";
  const std::string before = load_sweep(spec).members[0].id;
  EXPECT_EQ(load_sweep(spec).members[0].id, before);
  std::ofstream(skins / "dome.stl", std::ios::app) << "\n";
  EXPECT_NE(load_sweep(spec).members[0].id, before) << "an edited surface kept its member's name";
}

TEST(Sweep, ARelativeSurfaceOnAnAxisIsFoundFromTheMembersFolder) {
  const std::string spec = write_spec("surface_axis", R"({"scene": "skins/dome.json", "command": "kfit",
    "axes": [{"pointer": "/geometry/path", "values": ["dome.stl", "dome2.stl"]}]})");
  const fs::path skins = fs::path(spec).parent_path() / "skins";
  for (const char* name : {"dome.stl", "dome2.stl"})
    fs::copy_file(fs::path(SKINFEM_SOURCE_DIR) / "scenes" / "dome.stl", skins / name,
                  fs::copy_options::overwrite_existing);
  std::ofstream(skins / "dome.json") << R"({"geometry": {"type": "surface", "path": "dome.stl"},
    "material": {"E": 3.0, "nu": 0.5}, "sensors": {"positions": [[0.0, 0.0]], "disc_diameter": 0.2},
    "mesh": {"h_min": 0.6, "growth": 1.5, "h_max": 3.0}})";
  const Sweep s = load_sweep(spec);
  ASSERT_EQ(s.members.size(), 2u);
  for (int m = 0; m < 2; ++m) {
    const std::string expected = (skins / (m == 0 ? "dome.stl" : "dome2.stl")).lexically_normal().string();
    EXPECT_NE(s.members[m].scene_json.find("\"" + expected + "\""), std::string::npos)
        << s.members[m].scene_json;
    EXPECT_EQ(s.members[m].scene.geometry.surface.path, expected);
  }
}

TEST(Sweep, OptionsAreCheckedAsTheCommandLineChecksThem) {
  const std::string head =
      R"({"scene": "skins/base.json", "command": "report", "axes": [{"pointer": "/material/nu", "values": [0.5]}], )";
  // --error-scales: two levels at least, each in (1, 4], coarse to fine, none twice.
  for (const char* bad : {"[2]", "[1.41, 2]", "[2, 2]", "[5, 2]", "[2, 1]"})
    EXPECT_NE(refused(std::string("scales") + std::to_string(std::string(bad).size()) + bad[1],
                      head + R"("options": {"error_scales": )" + bad + "}}")
                  .find("options.error_scales = [" + std::string(bad).substr(1, 1)),
              std::string::npos)
        << bad;
  EXPECT_EQ(
      load_sweep(write_spec("scales_ok", head + R"("options": {"error_scales": [3, 2, 1.41]}})")).options,
      (std::vector<std::string>{"--error-scales", "3,2,1.4099999999999999"}));
  // With no_error_bars the command line does not look at them.
  EXPECT_EQ(load_sweep(write_spec("scales_off",
                                  head + R"("options": {"error_scales": [0.5], "no_error_bars": true}})"))
                .options.size(),
            3u);
}

TEST(Sweep, ZipHasTheGridsMemberCap) {
  std::string values = "[";
  for (int i = 0; i <= 10000; ++i) values += (i ? ", " : "") + std::to_string(1 + i);
  EXPECT_NE(refused("zip_size", R"({"scene": "skins/base.json", "command": "green", "combine": "zip",
    "axes": [{"pointer": "/material/E", "values": )" +
                                    values + "]}]}")
                .find("axes = 10001: the zipped axes have this many members; allowed at most 10000"),
            std::string::npos);
}

TEST(Sweep, AnAxisInsideAnotherAxisIsRefused) {
  const std::string head = R"({"scene": "skins/base.json", "command": "green", "axes": )";
  EXPECT_NE(refused("nested", head + R"([{"pointer": "/sensors/positions", "values": [[[0, 0]], [[1, 0]]]},
    {"pointer": "/sensors/positions/0/0", "values": [0.5]}]})")
                .find("axes[1].pointer = \"/sensors/positions/0/0\": lies inside axes[0].pointer "
                      "/sensors/positions"),
            std::string::npos);
  EXPECT_NE(refused("nested_up", head + R"([{"pointer": "/material/nu", "values": [0.5]},
    {"pointer": "/sensors/positions/0", "values": [[0.5, 0]]},
    {"pointer": "/sensors", "values": [{"positions": [[0, 0]], "disc_diameter": 0.2}]}]})")
                .find("axes[2].pointer = \"/sensors\": contains axes[1].pointer /sensors/positions/0"),
            std::string::npos);
  // A key whose name merely starts like another's is no nesting.
  EXPECT_EQ(load_sweep(write_spec("not_nested", head + R"([{"pointer": "/geometry/h", "values": [3.0]},
    {"pointer": "/geometry/half_width", "values": [20.0]}]})"))
                .members.size(),
            1u);
}
