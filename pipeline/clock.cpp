#include "pipeline/clock.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <string>

#ifdef __GLIBC__
#include <malloc.h>
#endif

namespace skinfem::pipeline {

namespace {
// The process's peak before the last window started, MB.
double peak_before_window_mb = 0;

// The kernel's high-water mark (VmHWM, reset with the window), MB; getrusage's where /proc is not readable.
double high_water_mb() {
  if (std::ifstream status("/proc/self/status"); status) {
    std::string line;
    while (std::getline(status, line))
      if (line.rfind("VmHWM:", 0) == 0) return std::strtod(line.c_str() + 6, nullptr) / 1024.0;  // kB
  }
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;  // ru_maxrss is in KiB on Linux
}
}  // namespace

double peak_rss_mb() { return std::max(peak_before_window_mb, high_water_mb()); }

void start_peak_window() {
  peak_before_window_mb = peak_rss_mb();
  std::ofstream("/proc/self/clear_refs") << "5";
}

double window_peak_rss_mb() { return high_water_mb(); }

void release_freed_memory() {
#ifdef __GLIBC__
  malloc_trim(0);
#endif
}

double total_seconds(const nlohmann::json& wall) {
  double t = 0;
  for (const auto& [stage, seconds] : wall.items())
    if (seconds.is_number()) t += seconds.get<double>();
  return t;
}

}  // namespace skinfem::pipeline
