#include "pipeline/clock.hpp"

#include <sys/resource.h>

#ifdef __GLIBC__
#include <malloc.h>
#endif

namespace skinfem::pipeline {

double peak_rss_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;  // ru_maxrss is in KiB on Linux
}

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
