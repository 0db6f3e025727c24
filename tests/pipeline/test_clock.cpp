// What a stage costs (pipeline/clock.hpp): Timings keeps seconds per named stage in name order, at() throws
// naming a stage never timed, total() is the sum of what was added and to_json writes {"stage": seconds};
// the memory figures against the process's own resident size, read independently from /proc/self/statm
// (a block of known size, touched page by page, must show in the peak and stay there once freed; freed
// heap pages pinned below a live allocation must leave the resident set on release_freed_memory). No
// assertion on wall time.
#include <gtest/gtest.h>
#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "skinfem/pipeline/clock.hpp"

namespace skinfem::pipeline {
namespace {

constexpr double kBlockMb = 64;

// The resident set size now, MB (the second field of /proc/self/statm, in pages).
double resident_mb() {
  long pages = 0, resident = 0;
  std::FILE* f = std::fopen("/proc/self/statm", "r");
  if (!f) return -1;
  const int read = std::fscanf(f, "%ld %ld", &pages, &resident);
  std::fclose(f);
  return read == 2 ? resident * (sysconf(_SC_PAGESIZE) / 1024.0) / 1024.0 : -1;
}

// An anonymous mapping of `mb` MB, every page written, so all of it is resident until unmapped.
struct TouchedBlock {
  explicit TouchedBlock(double mb) : size(static_cast<size_t>(mb * 1024 * 1024)) {
    data = mmap(nullptr, size, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (data == MAP_FAILED) throw std::runtime_error("mmap failed");
    std::memset(data, 1, size);
  }
  ~TouchedBlock() { munmap(data, size); }
  TouchedBlock(const TouchedBlock&) = delete;
  TouchedBlock& operator=(const TouchedBlock&) = delete;
  size_t size;
  void* data;
};

TEST(Timings, AtNamesAStageNeverTimed) {
  Timings t;
  t["mesh"] = 1.5;
  EXPECT_EQ(t.at("mesh"), 1.5);
  EXPECT_TRUE(t.contains("mesh"));
  EXPECT_FALSE(t.contains("factor"));
  try {
    t.at("factor");
    FAIL() << "at() of a stage never timed returned";
  } catch (const std::out_of_range& e) {
    EXPECT_NE(std::string(e.what()).find("factor"), std::string::npos) << e.what();
  }
  // at() is a look-up: it does not create the stage it was asked for.
  EXPECT_FALSE(t.contains("factor"));
}

TEST(Timings, TotalIsTheSumOfWhatWasAdded) {
  EXPECT_EQ(Timings().total(), 0.0);
  Timings t;
  t["assemble"] += 0.25;
  t["factor"] += 2.0;
  t["assemble"] += 0.5;  // a stage timed twice accumulates
  t["sweep"] = 4.0;
  EXPECT_EQ(t.at("assemble"), 0.75);
  EXPECT_EQ(t.total(), 0.75 + 2.0 + 4.0);
}

TEST(Timings, KeepsStagesInNameOrderAndWritesThemAsJson) {
  const Timings t{{"mesh", 1.0}, {"factor", 3.0}, {"assemble", 2.0}};
  std::vector<std::string> names;
  for (const auto& [stage, seconds] : t) names.push_back(stage);
  EXPECT_EQ(names, (std::vector<std::string>{"assemble", "factor", "mesh"}));

  const nlohmann::json j = t;  // through to_json, as summary.json's "wall_s"
  ASSERT_TRUE(j.is_object());
  EXPECT_EQ(j.size(), 3u);
  EXPECT_EQ(j.at("mesh").get<double>(), 1.0);
  EXPECT_EQ(j.at("factor").get<double>(), 3.0);
  EXPECT_EQ(j.at("assemble").get<double>(), 2.0);
  EXPECT_EQ(j, t.json());
  EXPECT_EQ(nlohmann::json(Timings{}), nlohmann::json::object());
}

TEST(Stopwatch, NeverRunsBackwards) {
  const Stopwatch w;
  const double a = w.seconds();
  const double b = w.seconds();
  EXPECT_GE(a, 0.0);
  EXPECT_GE(b, a);
}

// Freed memory leaves the resident set under glibc's allocator; AddressSanitizer's keeps freed blocks in
// quarantine, so there only the peaks are checked.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kOwnAllocator = false;  // AddressSanitizer's allocator keeps freed blocks in quarantine
#else
constexpr bool kOwnAllocator = true;
#endif

TEST(PeakRss, SeesATouchedBlockAndKeepsItAfterItIsFreed) {
  // The kernel's peak can only be at least every resident size seen, this one with the block included.
  double with_block = 0;
  {
    TouchedBlock block(kBlockMb);
    with_block = resident_mb();
  }
  ASSERT_GT(with_block, kBlockMb);
  if (kOwnAllocator) {
    EXPECT_LT(resident_mb(), with_block - 0.5 * kBlockMb);  // gone from the resident set
  }
  EXPECT_GE(peak_rss_mb(), with_block - 1);  // ... but not from the peak (1 MB: page counting)
}

TEST(RssSampler, KeepsTheLargestSample) {
  RssSampler sampler;
  const double before = sampler.peak_mb();
  EXPECT_GT(before, 0.0);
  double during = 0;
  {
    TouchedBlock block(kBlockMb);
    during = sampler.peak_mb();  // this moment's sample: the block is resident
    EXPECT_GE(during, before + 0.9 * kBlockMb);
    EXPECT_NEAR(during, resident_mb(), 1.0);
  }
  if (kOwnAllocator) {
    EXPECT_LT(resident_mb(), during - 0.5 * kBlockMb);
  }
  EXPECT_GE(sampler.peak_mb(), during);  // the block is gone, its sample stays
}

TEST(ReleaseFreedMemory, HandsFreedHeapPagesBack) {
  if (!kOwnAllocator)
    GTEST_SKIP() << "AddressSanitizer's allocator holds freed blocks; glibc's is tested in Release";
  // Small blocks come from the heap, not their own mappings: freed below a block still in use (the highest
  // of them, kept) they cannot be trimmed off the heap's top and stay resident until handed back.
  constexpr size_t kChunk = 1000, kCount = static_cast<size_t>(kBlockMb * 1024 * 1024 / kChunk);
  std::vector<char*> chunks(kCount);
  for (char*& c : chunks) {
    c = static_cast<char*>(std::malloc(kChunk));
    ASSERT_NE(c, nullptr);
    std::memset(c, 1, kChunk);
  }
  std::swap(*std::max_element(chunks.begin(), chunks.end(), std::less<char*>()), chunks.back());
  char* const pin = chunks.back();
  chunks.pop_back();
  const double allocated = resident_mb();
  for (char* c : chunks) std::free(c);
  const double freed = resident_mb();
  release_freed_memory();
  const double released = resident_mb();
  EXPECT_GT(freed, allocated - 0.25 * kBlockMb);  // free alone kept them (the premise of the function)
  EXPECT_LT(released, freed - 0.5 * kBlockMb);
  std::free(pin);
}

}  // namespace
}  // namespace skinfem::pipeline
