// What a stage costs: wall time and the process's peak resident memory.
#pragma once

#include <chrono>
#include <nlohmann/json.hpp>

namespace skinfem::pipeline {

class Stopwatch {
 public:
  Stopwatch() : start_(std::chrono::steady_clock::now()) {}
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  std::chrono::steady_clock::time_point start_;
};

// Peak resident set size of this process so far, MB.
double peak_rss_mb();
// A window for window_peak_rss_mb(): from here on, the peak of what follows alone (a refinement level after
// a larger one). Linux resets the kernel's high-water mark on request (/proc/self/clear_refs, 5); where it
// cannot, the window stays the whole process's and the figure is an upper bound.
void start_peak_window();
// Peak resident set size since the last start_peak_window() (since the start without one), MB.
double window_peak_rss_mb();
// Hands the heap's free pages back to the system. After a stage's solver is released its memory stays
// resident otherwise (glibc keeps freed heap pages), and the next stage's peak sits on top of it: the
// report's error-bar levels peaked 350 MB above its own chain on the paper's skin with posts.
void release_freed_memory();
// Sum of the numbers in a {"stage": seconds} object.
double total_seconds(const nlohmann::json& wall);

}  // namespace skinfem::pipeline
