// Progress lines (pipeline/progress.hpp): an installed sink receives every message as given, replacing it
// returns the previous one, and without a sink nothing reaches the terminal (stdout and stderr captured);
// progress_step's line against the header's format "stage: done/total (P %, S s)" written out by hand.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "../common/progress_lines.hpp"
#include "skinfem/pipeline/progress.hpp"

namespace skinfem::pipeline {
namespace {

using Collect = testing::ProgressLines;

TEST(Progress, ASinkReceivesEveryLineAsGiven) {
  Collect c;
  progress("meshing flat_layer");
  progress("");
  progress("factor: 1/2");
  EXPECT_EQ(c.lines, (std::vector<std::string>{"meshing flat_layer", "", "factor: 1/2"}));
}

TEST(Progress, SettingASinkReturnsThePreviousOne) {
  std::vector<std::string> first, second;
  const ProgressSink outer = set_progress_sink([&](const std::string& m) { first.push_back("1 " + m); });
  const ProgressSink returned = set_progress_sink([&](const std::string& m) { second.push_back("2 " + m); });
  progress("a");  // only the current sink
  ASSERT_TRUE(returned);
  returned("b");  // the first sink, handed back
  const ProgressSink last = set_progress_sink(outer);
  ASSERT_TRUE(last);
  last("c");
  EXPECT_EQ(first, (std::vector<std::string>{"1 b"}));
  EXPECT_EQ(second, (std::vector<std::string>{"2 a", "2 c"}));
}

TEST(Progress, WithoutASinkNothingIsWritten) {
  const ProgressSink previous = set_progress_sink(nullptr);
  ::testing::internal::CaptureStdout();
  ::testing::internal::CaptureStderr();
  progress("meshing flat_layer");
  progress_step("factor", 1, 2, 0.5);
  const std::string out = ::testing::internal::GetCapturedStdout();
  const std::string err = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(out, "");
  EXPECT_EQ(err, "");
  // A null sink is silent too, and setting it hands back the one it replaces (here: none).
  std::vector<std::string> lines;
  set_progress_sink([&](const std::string& m) { lines.push_back(m); });
  EXPECT_TRUE(set_progress_sink(nullptr));
  progress("dropped");
  EXPECT_TRUE(lines.empty());
  EXPECT_FALSE(set_progress_sink(previous));
}

TEST(Progress, StepLineHasTheHeadersFormat) {
  Collect c;
  progress_step("sweep", 3, 4, 2.5);  // 3/4 = 75 %
  progress_step("condense", 0, 8, 0.0);
  progress_step("factor", 10, 10, 12.25);  // 12.25 s shown to 0.1 s
  ASSERT_EQ(c.lines.size(), 3u);
  EXPECT_EQ(c.lines[0], "sweep: 3/4 (75 %, 2.5 s)");
  EXPECT_EQ(c.lines[1], "condense: 0/8 (0 %, 0.0 s)");
  EXPECT_TRUE(c.lines[2] == "factor: 10/10 (100 %, 12.2 s)" || c.lines[2] == "factor: 10/10 (100 %, 12.3 s)")
      << c.lines[2];
}

}  // namespace
}  // namespace skinfem::pipeline
