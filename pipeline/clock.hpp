// What a stage costs: wall time and the process's peak resident memory.
#pragma once

#include <atomic>
#include <chrono>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>

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
// The peak resident memory of a stretch of work that follows a larger one (a coarse refinement level after
// the scene's own): the kernel keeps only the process's peak (resetting it would hide the true peak from
// whoever measures the process from outside), so a thread samples the resident size every `every_ms` while
// this lives. A peak shorter than the interval can be missed; a factorization's lasts seconds.
class RssSampler {
 public:
  explicit RssSampler(int every_ms = 5);
  ~RssSampler();
  RssSampler(const RssSampler&) = delete;
  RssSampler& operator=(const RssSampler&) = delete;
  double peak_mb();  // the largest sample so far, this moment's included

 private:
  void sample();
  std::atomic<bool> stop_{false};
  std::atomic<long> peak_kb_{0};
  std::thread thread_;
};
// Hands the heap's free pages back to the system. After a stage's solver is released its memory stays
// resident otherwise (glibc keeps freed heap pages), and the next stage's peak sits on top of it: the
// report's error-bar levels peaked 350 MB above its own chain on the paper's skin with posts.
void release_freed_memory();
// Wall-clock seconds per named stage of a run (mesh, assemble, factor, ...), kept in name order, the order
// summary.json writes them in ("wall_s").
class Timings {
 public:
  Timings() = default;
  Timings(std::initializer_list<std::pair<const std::string, double>> stages) : seconds_(stages) {}
  double& operator[](const std::string& stage) { return seconds_[stage]; }
  double at(const std::string& stage) const;  // throws std::out_of_range naming a stage never timed
  bool contains(const std::string& stage) const { return seconds_.count(stage) > 0; }
  double total() const;
  auto begin() const { return seconds_.begin(); }
  auto end() const { return seconds_.end(); }
  nlohmann::json json() const { return seconds_; }

 private:
  std::map<std::string, double> seconds_;
};
// As summary.json's "wall_s": {"stage": seconds}.
inline void to_json(nlohmann::json& j, const Timings& t) { j = t.json(); }

}  // namespace skinfem::pipeline
