// The command table (scene/commands.hpp): names unique, every choice option with its choices and its default
// among them, exclusions naming an option registered before, and every command a sweep may run naming the
// summary file its gather reads and plotting only keys of it the command writes. The friction choices are
// the scene's modes (scene/laws.hpp) plus "scene".
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <stdexcept>

#include "skinfem/scene/commands.hpp"
#include "skinfem/scene/laws.hpp"

namespace skinfem {
namespace {

TEST(Commands, NamesAndOptionsAreUniqueAndConsistent) {
  std::set<std::string> names;
  for (const CommandSpec& c : commands()) {
    EXPECT_TRUE(names.insert(c.name).second) << c.name;
    EXPECT_FALSE(c.help.empty()) << c.name;
    std::set<std::string> options;
    int positional = 0;
    for (const OptionSpec& o : c.options) {
      EXPECT_TRUE(options.insert(o.name).second) << c.name << " " << o.name;
      positional += o.kind == OptionKind::positional;
      if (o.kind == OptionKind::choice) {
        ASSERT_FALSE(o.choices.empty()) << c.name << " " << o.name;
        EXPECT_NE(std::find(o.choices.begin(), o.choices.end(), o.default_value), o.choices.end())
            << c.name << " " << o.name << " default " << o.default_value;
      }
      for (const std::string& other : o.excludes) EXPECT_TRUE(options.count(other)) << o.name << " " << other;
    }
    // One positional, the scene or the sweep spec; invert reads its signals file first.
    EXPECT_EQ(positional, c.name == "invert" ? 2 : 1) << c.name;
    if (c.in_sweeps) {
      EXPECT_FALSE(c.summary_file.empty()) << c.name;
      // Every command a sweep runs takes a scene and the size guard.
      EXPECT_TRUE(options.count("scene") && options.count("max_dofs")) << c.name;
    }
  }
  EXPECT_THROW(command_named("frobnicate"), std::out_of_range);
}

TEST(Commands, FrictionChoicesAreTheScenesModes) {
  for (const char* name : {"contact"}) {
    const CommandSpec& c = command_named(name);
    const auto o = std::find_if(c.options.begin(), c.options.end(),
                                [](const OptionSpec& s) { return s.name == "friction"; });
    ASSERT_NE(o, c.options.end());
    std::vector<std::string> expected{"scene"};
    for (const std::string& m : friction_mode_names()) expected.push_back(m);
    EXPECT_EQ(o->choices, expected);
  }
}

TEST(Commands, FlagNamesAreTheOptionsInKebabCase) {
  EXPECT_EQ(option_flag("error_scales"), "--error-scales");
  EXPECT_EQ(option_flag("no_error_bars"), "--no-error-bars");
  EXPECT_EQ(option_flag("path"), "--path");
}

}  // namespace
}  // namespace skinfem
