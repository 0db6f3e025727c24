#include "scene/parallel.hpp"

#include <sched.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace skinfem {

int worker_threads() {
  cpu_set_t set;
  int n = sched_getaffinity(0, sizeof set, &set) == 0 ? CPU_COUNT(&set) : 1;
  if (const char* omp = std::getenv("OMP_NUM_THREADS")) {
    char* end = nullptr;
    const long cap = std::strtol(omp, &end, 10);
    if (end != omp && *end == '\0' && cap >= 1) n = static_cast<int>(std::min<long>(n, cap));
  }
  return std::max(1, n);
}

void for_each_index(std::size_t n, const std::function<void(std::size_t)>& f, bool parallel,
                    const std::function<void(std::size_t)>& done) {
  const std::size_t threads =
      parallel ? std::min<std::size_t>(n, static_cast<std::size_t>(worker_threads())) : 1;
  std::atomic<std::size_t> next{0}, finished{0};
  std::mutex mutex;
  std::size_t failed = n;  // the lowest index that threw
  std::exception_ptr error;
  const auto work = [&](bool reports) {
    for (;;) {
      if (reports && done) done(finished.load());
      const std::size_t i = next++;
      {
        // Indices are taken in order, so every index below a failed one has been taken and finishes.
        const std::lock_guard<std::mutex> lock(mutex);
        if (i >= n || i > failed) return;
      }
      try {
        f(i);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(mutex);
        if (i < failed) failed = i, error = std::current_exception();
      }
      ++finished;
    }
  };
  std::vector<std::thread> pool;
  for (std::size_t t = 1; t < threads; ++t) pool.emplace_back(work, false);
  work(true);
  for (auto& t : pool) t.join();
  if (done) done(finished.load());
  if (error) std::rethrow_exception(error);
}

}  // namespace skinfem
