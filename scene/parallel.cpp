#include "skinfem/scene/parallel.hpp"

#include <sched.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace skinfem {

namespace {
thread_local int t_thread_cap = 0;  // 0: none
}  // namespace

ThreadCap::ThreadCap(int n) : before_(t_thread_cap) {
  t_thread_cap = before_ > 0 ? std::min(before_, std::max(1, n)) : std::max(1, n);
}
ThreadCap::~ThreadCap() { t_thread_cap = before_; }

int worker_threads() {
  if (t_thread_cap == 1) return 1;  // no system call for a thread that may use one core
  cpu_set_t set;
  int n = sched_getaffinity(0, sizeof set, &set) == 0 ? CPU_COUNT(&set) : 1;
  if (const char* omp = std::getenv("OMP_NUM_THREADS")) {
    char* end = nullptr;
    const long cap = std::strtol(omp, &end, 10);
    if (end != omp && *end == '\0' && cap >= 1) n = static_cast<int>(std::min<long>(n, cap));
  }
  if (t_thread_cap > 0) n = std::min(n, t_thread_cap);
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
  std::size_t reported = n + 1;  // the count last passed to done (on this thread only): no line twice
  const auto report = [&] {
    const std::size_t k = finished.load();
    if (k != reported) done(reported = k);
  };
  const auto work = [&](bool reports) {
    // An item's own loops run on its thread: one loop's threads are the machine's cores already.
    std::optional<ThreadCap> one_each;
    if (threads > 1) one_each.emplace(1);
    for (;;) {
      if (reports && done) report();
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
  if (done) report();
  if (error) std::rethrow_exception(error);
}

namespace {
// What the children share with this process: the next index to take, then per item its status, its message
// if it threw, and its doubles.
struct Shared {
  std::atomic<long> next;
};
constexpr std::size_t kMessage = 512;
enum : int { kPending = 0, kDone = 1, kThrew = 2 };

// Item i's doubles, checked for their number.
std::vector<double> item(const std::function<std::vector<double>(std::size_t)>& f, std::size_t i,
                         std::size_t width) {
  std::vector<double> v = f(i);
  if (v.size() != width) throw std::logic_error("map_in_processes: an item returned the wrong width");
  return v;
}

// Every item in order on this thread.
std::vector<std::vector<double>> map_here(std::size_t n, std::size_t width,
                                          const std::function<std::vector<double>(std::size_t)>& f) {
  std::vector<std::vector<double>> out(n);
  for (std::size_t i = 0; i < n; ++i) out[i] = item(f, i, width);
  return out;
}
}  // namespace

ProcessMap::ProcessMap(std::size_t n, std::size_t width, std::function<std::vector<double>(std::size_t)> f,
                       int workers, int nice)
    : n_(n), width_(width), f_(std::move(f)) {
  workers = static_cast<int>(std::min<std::size_t>(n, static_cast<std::size_t>(std::max(1, workers))));
  if (n == 0) return;
  static_assert(std::atomic<long>::is_always_lock_free && std::atomic<int>::is_always_lock_free,
                "a counter and flags shared between processes must be lock-free");
  status_at_ = sizeof(Shared), message_at_ = status_at_ + n * sizeof(int);
  values_at_ = (message_at_ + n * kMessage + 7) / 8 * 8, bytes_ = values_at_ + n * width * sizeof(double);
  void* map = mmap(nullptr, bytes_, PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
  if (map == MAP_FAILED) throw std::runtime_error("map_in_processes: cannot map shared memory");
  map_ = static_cast<char*>(map);
  auto* shared = new (map_) Shared{{0}};
  auto* status = reinterpret_cast<std::atomic<int>*>(map_ + status_at_);
  char* messages = map_ + message_at_;
  auto* values = reinterpret_cast<double*>(map_ + values_at_);
  const pid_t parent = getpid();
  help_ = nice > 0;
  for (int w = 0; w < workers; ++w) {
    const pid_t pid = fork();
    if (pid < 0) break;  // the children started take every item
    if (pid == 0) {
      // A child: never outlives this process, never returns into the caller's stack, no exit handlers.
      prctl(PR_SET_PDEATHSIG, SIGKILL);
      if (getppid() != parent) _exit(1);
      if (nice > 0) setpriority(PRIO_PROCESS, 0, nice);
      int rc = 0;
      try {
        for (long i; (i = shared->next.fetch_add(1)) < static_cast<long>(n);) {
          try {
            const std::vector<double> v = item(f_, static_cast<std::size_t>(i), width);
            std::memcpy(values + i * width, v.data(), width * sizeof(double));
            status[i].store(kDone, std::memory_order_release);
          } catch (const std::exception& e) {
            std::strncpy(messages + i * kMessage, e.what(), kMessage - 1);
            status[i].store(kThrew, std::memory_order_release);
          }
        }
      } catch (...) {
        rc = 1;
      }
      _exit(rc);
    }
    children_.push_back(pid);
  }
}

ProcessMap::~ProcessMap() {
  for (const pid_t pid : children_) kill(pid, SIGKILL);
  reap();
  if (map_) munmap(map_, bytes_);
}

std::string ProcessMap::reap() {
  std::string ended;
  for (const pid_t pid : children_) {
    int st = 0;
    while (waitpid(pid, &st, 0) < 0 && errno == EINTR) {
    }
    if (WIFSIGNALED(st) && ended.empty())
      ended = "a worker process ended by signal " + std::to_string(WTERMSIG(st)) + " (" +
              strsignal(WTERMSIG(st)) + ")";
  }
  children_.clear();
  return ended;
}

std::vector<std::vector<double>> ProcessMap::get() {
  if (children_.empty()) return map_here(n_, width_, f_);  // none could start (or no item): done here
  std::vector<std::vector<double>> out(n_);
  std::vector<std::string> failed_here(n_);
  auto* status = reinterpret_cast<std::atomic<int>*>(map_ + status_at_);
  std::string ended;
  if (help_) {
    // Low-priority children may wait long for a core on a busy machine: the items none has taken, then
    // those none has finished, are computed here too, and the children go. One item's numbers do not depend
    // on where it ran.
    const auto here = [&](std::size_t i) {
      try {
        out[i] = item(f_, i, width_);
      } catch (const std::exception& e) {
        out[i].clear();
        failed_here[i] = e.what();
      }
    };
    auto* shared = reinterpret_cast<Shared*>(map_);
    for (long i; (i = shared->next.fetch_add(1)) < static_cast<long>(n_);) here(static_cast<std::size_t>(i));
    for (std::size_t i = 0; i < n_; ++i)
      if (status[i].load(std::memory_order_acquire) == kPending) here(i);
    for (const pid_t pid : children_) kill(pid, SIGKILL);
    reap();  // killed by us: not an error
  } else {
    ended = reap();
  }
  const char* messages = map_ + message_at_;
  const auto* values = reinterpret_cast<const double*>(map_ + values_at_);
  std::string error;
  for (std::size_t i = 0; i < n_ && error.empty(); ++i) {
    const int st = status[i].load(std::memory_order_acquire);
    if (!failed_here[i].empty())
      error = failed_here[i];
    else if (!out[i].empty())
      continue;  // computed here
    else if (st == kThrew)
      error = std::string(messages + i * kMessage);
    else if (st != kDone)
      error = ended.empty() ? "a worker process ended before its item " + std::to_string(i) : ended;
    else
      out[i].assign(values + i * width_, values + (i + 1) * width_);
  }
  if (!error.empty()) throw std::runtime_error(error);
  return out;
}

std::vector<std::vector<double>> map_in_processes(std::size_t n, std::size_t width,
                                                  const std::function<std::vector<double>(std::size_t)>& f) {
  const std::size_t workers = std::min<std::size_t>(n, static_cast<std::size_t>(worker_threads()));
  if (workers <= 1) return map_here(n, width, f);
  return ProcessMap(n, width, f, static_cast<int>(workers)).get();
}

}  // namespace skinfem
