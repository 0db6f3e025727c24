#include "app/common.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>

namespace skinfem::app {

void prepare_output_dir(const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir))
    throw std::runtime_error("--out " + dir + ": cannot create output directory (" + ec.message() + ")");
}

void check_output_dir(const std::string& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::path p = fs::absolute(dir, ec);
  if (fs::exists(p, ec) && !fs::is_directory(p, ec))
    throw SceneError("--out " + dir + ": exists and is not a directory; must be a directory or a new path");
  while (!p.empty() && !fs::exists(p, ec)) p = p.parent_path();
  if (p.empty() || !fs::is_directory(p, ec) || access(p.c_str(), W_OK) != 0)
    throw SceneError("--out " + dir + ": cannot create or write the output directory (" + p.string() +
                     " is not a writable directory)");
}

void write_text_atomic(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp);
    out << text;
    if (!out) throw std::runtime_error("cannot write " + path);
  }
  std::filesystem::rename(tmp, path);
}

void write_json(const std::string& path, const nlohmann::json& j) {
  write_text_atomic(path, j.dump(2) + "\n");
}

double peak_rss_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;  // ru_maxrss is in KiB on Linux
}

void progress(const std::string& message) { std::cerr << "[skinfem] " << message << std::endl; }

void progress_step(const std::string& stage, int done, int total, double elapsed_s) {
  char buf[64];
  std::snprintf(buf, sizeof buf, ": %d/%d (%.0f %%, %.1f s)", done, total, 100.0 * done / std::max(total, 1),
                elapsed_s);
  progress(stage + buf);
}

nlohmann::json scene_json(const Scene& scene) {
  return {{"name", scene.name},
          {"source", scene.source_path},
          {"E_MPa", scene.material.E},
          {"nu", scene.material.nu},
          {"sensors", scene.sensors.positions.size()}};
}

double total_seconds(const nlohmann::json& wall) {
  double t = 0;
  for (const auto& [stage, seconds] : wall.items())
    if (seconds.is_number()) t += seconds.get<double>();
  return t;
}

}  // namespace skinfem::app
