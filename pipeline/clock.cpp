#include "skinfem/pipeline/clock.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <cstdio>
#include <stdexcept>

#ifdef __GLIBC__
#include <malloc.h>
#endif

namespace skinfem::pipeline {

double peak_rss_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;  // ru_maxrss is in KiB on Linux
}

RssSampler::RssSampler(int every_ms) {
  sample();
  thread_ = std::thread([this, every_ms] {
    while (!stop_.load()) {
      std::this_thread::sleep_for(std::chrono::milliseconds(every_ms));
      sample();
    }
  });
}

RssSampler::~RssSampler() {
  stop_ = true;
  thread_.join();
}

void RssSampler::sample() {
  // /proc/self/statm: sizes in pages, the resident set second.
  long pages = 0, resident = 0;
  if (std::FILE* f = std::fopen("/proc/self/statm", "r")) {
    if (std::fscanf(f, "%ld %ld", &pages, &resident) != 2) resident = 0;
    std::fclose(f);
  }
  const long kb = resident * (sysconf(_SC_PAGESIZE) / 1024);
  long seen = peak_kb_.load();
  while (kb > seen && !peak_kb_.compare_exchange_weak(seen, kb)) {
  }
}

double RssSampler::peak_mb() {
  sample();
  return peak_kb_.load() / 1024.0;
}

void release_freed_memory() {
#ifdef __GLIBC__
  malloc_trim(0);
#endif
}

double Timings::at(const std::string& stage) const {
  const auto it = seconds_.find(stage);
  if (it == seconds_.end()) throw std::out_of_range("no stage '" + stage + "' was timed");
  return it->second;
}

double Timings::total() const {
  double t = 0;
  for (const auto& [stage, seconds] : seconds_) t += seconds;
  return t;
}

}  // namespace skinfem::pipeline
