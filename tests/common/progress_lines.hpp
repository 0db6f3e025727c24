// The progress lines a test's code sends (pipeline/progress.hpp), collected for as long as the object lives;
// the sink that was installed before is put back after.
#pragma once

#include <string>
#include <vector>

#include "skinfem/pipeline/progress.hpp"

namespace skinfem::testing {

struct ProgressLines {
  ProgressLines()
      : previous(pipeline::set_progress_sink([this](const std::string& m) { lines.push_back(m); })) {}
  ~ProgressLines() { pipeline::set_progress_sink(previous); }
  ProgressLines(const ProgressLines&) = delete;
  ProgressLines& operator=(const ProgressLines&) = delete;
  std::vector<std::string> lines;
  pipeline::ProgressSink previous;
};

}  // namespace skinfem::testing
