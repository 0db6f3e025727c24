#include "pipeline/progress.hpp"

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

}  // namespace skinfem::pipeline
