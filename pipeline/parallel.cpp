#include "pipeline/parallel.hpp"

#include <sched.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <exception>
#include <thread>
#include <vector>

namespace skinfem::pipeline {

int worker_threads() {
  cpu_set_t set;
  int n = sched_getaffinity(0, sizeof set, &set) == 0 ? CPU_COUNT(&set) : 1;
  if (const char* omp = std::getenv("OMP_NUM_THREADS")) {
    char* end = nullptr;
    const long cap = std::strtol(omp, &end, 10);
    if (end != omp && *end == '\0' && cap >= 1) n = std::min<long>(n, cap);
  }
  return std::max(1, n);
}

void run_indexed(int n, bool parallel, const std::function<void(int)>& item,
                 const std::function<void(int)>& done) {
  std::vector<std::exception_ptr> failed(std::max(0, n));
  std::atomic<int> next{0}, finished{0};
  const auto work = [&](bool reports) {
    for (;;) {
      if (reports && done) done(finished.load());
      const int i = next++;
      if (i >= n) return;
      try {
        item(i);
      } catch (...) {
        failed[i] = std::current_exception();
      }
      ++finished;
    }
  };
  std::vector<std::thread> others;
  const int threads = parallel ? std::min(worker_threads(), n) : 1;
  for (int t = 1; t < threads; ++t) others.emplace_back(work, false);
  work(true);
  for (std::thread& t : others) t.join();
  if (done) done(finished.load());
  for (const std::exception_ptr& e : failed)
    if (e) std::rethrow_exception(e);
}

}  // namespace skinfem::pipeline
