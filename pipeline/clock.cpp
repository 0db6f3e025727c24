#include "pipeline/clock.hpp"

#include <sys/resource.h>

namespace skinfem::pipeline {

double peak_rss_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;  // ru_maxrss is in KiB on Linux
}

double total_seconds(const nlohmann::json& wall) {
  double t = 0;
  for (const auto& [stage, seconds] : wall.items())
    if (seconds.is_number()) t += seconds.get<double>();
  return t;
}

}  // namespace skinfem::pipeline
