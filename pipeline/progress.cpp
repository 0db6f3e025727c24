#include "skinfem/pipeline/progress.hpp"

#include <algorithm>
#include <cstdio>
#include <mutex>
#include <utility>

namespace skinfem::pipeline {

namespace {
std::mutex sink_mutex;
ProgressSink& sink() {
  static ProgressSink s;
  return s;
}
}  // namespace

ProgressSink set_progress_sink(ProgressSink s) {
  std::lock_guard<std::mutex> lock(sink_mutex);
  return std::exchange(sink(), std::move(s));
}

void progress(const std::string& message) {
  ProgressSink s;
  {
    std::lock_guard<std::mutex> lock(sink_mutex);
    s = sink();
  }
  if (s) s(message);
}

void progress_step(const std::string& stage, int done, int total, double elapsed_s) {
  char buf[64];
  std::snprintf(buf, sizeof buf, ": %d/%d (%.0f %%, %.1f s)", done, total, 100.0 * done / std::max(total, 1),
                elapsed_s);
  progress(stage + buf);
}

}  // namespace skinfem::pipeline
