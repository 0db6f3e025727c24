// Independent work items on the machine's cores: a sweep's members, a calibration's sensors. The items must
// share only read-only data and write their own slots, so that results do not depend on the threads.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace skinfem {

// Threads such work may use: the CPUs this process may run on, at most OMP_NUM_THREADS when that is set (a
// sweep's member declares its threads that way).
int worker_threads();
// Caps worker_threads() on the calling thread while it lives (a cap inside another keeps the smaller): work
// run on a thread beside others (the report's k sweep) takes no more cores than it was given.
class ThreadCap {
 public:
  explicit ThreadCap(int n);
  ~ThreadCap();
  ThreadCap(const ThreadCap&) = delete;
  ThreadCap& operator=(const ThreadCap&) = delete;

 private:
  int before_;
};

// f(0), ..., f(n - 1) on up to worker_threads() threads when `parallel`, else in order on this one; with
// more than one thread, each item runs under ThreadCap(1) (a loop inside an item runs on the item's thread).
// After an item throws, no item above it starts; the exception of the lowest index that threw is rethrown
// once every thread has ended, as a loop in one thread would. done(k), if given, is called on this thread
// only, with k items finished, before each item it takes and once at the end, whenever k has changed since
// its last call (progress lines, none twice).
void for_each_index(std::size_t n, const std::function<void(std::size_t)>& f, bool parallel = true,
                    const std::function<void(std::size_t)>& done = {});

// f(0), ..., f(n - 1), each returning `width` doubles, in up to worker_threads() forked child processes:
// for work that is not safe side by side in one process (MUMPS instances share Fortran state; OpenBLAS's
// thread pool). Results come back in index order, whichever child computed them; a child inherits this
// process's settings (fix the BLAS's threads before the call). With one worker or one item, f runs here, in
// order. Throws std::runtime_error with the message of the lowest index that threw, or naming the signal
// that ended a child; a child dies with this process.
std::vector<std::vector<double>> map_in_processes(std::size_t n, std::size_t width,
                                                  const std::function<std::vector<double>(std::size_t)>& f);

// The same work started now in `workers` child processes (at least one, even for one item) and waited for
// by get(), while the caller goes on: for work beside this process's own (the report's post design beside
// its chain). A `nice` above 0 lowers the children's priority by it (19: they take what the caller's threads
// leave idle), and get() then computes here, at the caller's priority, every item no child has finished (a
// busy machine's low-priority children may wait long for a core; an item's numbers must not depend on where
// it runs). The children are forked here: make this call where no other thread of ours is inside the BLAS or
// MUMPS, and set what an item needs (its BLAS's threads) inside f. f runs here only in get(): when no process
// could start, or with a nice. A map not waited for kills its children when it goes.
class ProcessMap {
 public:
  ProcessMap(std::size_t n, std::size_t width, std::function<std::vector<double>(std::size_t)> f, int workers,
             int nice = 0);
  ~ProcessMap();
  ProcessMap(const ProcessMap&) = delete;
  ProcessMap& operator=(const ProcessMap&) = delete;
  // Every item's doubles, in index order; throws as map_in_processes. Once.
  std::vector<std::vector<double>> get();

 private:
  std::string reap();  // waits for every child; the first signal that ended one, as a sentence

  std::size_t n_, width_;
  std::function<std::vector<double>(std::size_t)> f_;
  char* map_ = nullptr;  // the shared memory: a Shared, then statuses, messages and values
  std::size_t status_at_ = 0, message_at_ = 0, values_at_ = 0, bytes_ = 0;
  std::vector<int> children_;  // pids
  bool help_ = false;          // get() computes what the children have not
};

}  // namespace skinfem
