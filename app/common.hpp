// Shared plumbing of the skinfem subcommands: output files, timing, memory, progress.
#pragma once

#include <chrono>
#include <nlohmann/json.hpp>
#include <string>

#include "scene/scene.hpp"

namespace skinfem::app {

// Fails early (before any computation) when DIR could not be created or written; creates nothing.
void check_output_dir(const std::string& dir);
// Creates DIR if needed; throws with a one-line message when it cannot.
void prepare_output_dir(const std::string& dir);
// Writes text to path through a temporary file and a rename: never a half-written file.
void write_text_atomic(const std::string& path, const std::string& text);
void write_json(const std::string& path, const nlohmann::json& j);

double peak_rss_mb();
// Sum of the numbers in a {"stage": seconds} object.
double total_seconds(const nlohmann::json& wall);

class Stopwatch {
 public:
  Stopwatch() : start_(std::chrono::steady_clock::now()) {}
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  std::chrono::steady_clock::time_point start_;
};

// "[skinfem] stage…" on stderr, so stdout stays the human summary.
void progress(const std::string& message);
// "[skinfem] stage: done/total (P %, S s)".
void progress_step(const std::string& stage, int done, int total, double elapsed_s);

nlohmann::json scene_json(const Scene& scene);

}  // namespace skinfem::app
