// Work spread over threads and processes (scene/parallel.hpp): results in index order whoever computed them,
// an item's failure reported as a loop in one thread would report it, and a worker process that dies named;
// work started in low-priority processes beside the caller's (ProcessMap), and its children gone with it.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "skinfem/scene/parallel.hpp"

namespace skinfem {
namespace {

TEST(ForEachIndex, EveryIndexOnceAndTheLowestFailureRethrown) {
  std::vector<std::atomic<int>> seen(100);
  for_each_index(seen.size(), [&](std::size_t i) { ++seen[i]; });
  for (const auto& s : seen) EXPECT_EQ(s.load(), 1);
  try {
    for_each_index(50, [](std::size_t i) {
      if (i == 17 || i == 31) throw std::runtime_error("item " + std::to_string(i));
    });
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "item 17");
  }
}

// A ThreadCap holds on its own thread only, nests (the smaller cap wins), and ends with its scope.
TEST(ThreadCap, CapsThisThreadOnlyWhileItLives) {
  const int all = worker_threads();
  {
    const ThreadCap one(1);
    EXPECT_EQ(worker_threads(), 1);
    int other = 0;
    std::thread([&] { other = worker_threads(); }).join();
    EXPECT_EQ(other, all);
    {
      const ThreadCap many(1000);
      EXPECT_EQ(worker_threads(), 1);
    }
    EXPECT_EQ(worker_threads(), 1);
  }
  EXPECT_EQ(worker_threads(), all);
}

TEST(MapInProcesses, ResultsInIndexOrderFromTheChildren) {
  const pid_t here = getpid();
  const auto out = map_in_processes(40, 3, [](std::size_t i) {
    return std::vector<double>{static_cast<double>(i), 0.5 * static_cast<double>(i),
                               static_cast<double>(getpid())};
  });
  ASSERT_EQ(out.size(), 40u);
  std::set<double> pids;
  for (std::size_t i = 0; i < out.size(); ++i) {
    ASSERT_EQ(out[i].size(), 3u);
    EXPECT_EQ(out[i][0], static_cast<double>(i));
    EXPECT_EQ(out[i][1], 0.5 * static_cast<double>(i));
    pids.insert(out[i][2]);
  }
  // With more than one worker the items ran in children, never here; with one, here.
  if (worker_threads() > 1)
    EXPECT_EQ(pids.count(static_cast<double>(here)), 0u);
  else
    EXPECT_EQ(pids, std::set<double>{static_cast<double>(here)});
}

TEST(MapInProcesses, TheLowestFailingItemsMessage) {
  try {
    map_in_processes(30, 1, [](std::size_t i) -> std::vector<double> {
      if (i == 11 || i == 23) throw std::invalid_argument("design " + std::to_string(i) + " is not meshable");
      return {1.0};
    });
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "design 11 is not meshable");
  }
  try {
    map_in_processes(4, 2, [](std::size_t) { return std::vector<double>{1.0}; });
    FAIL() << "no exception";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("wrong width"), std::string::npos) << e.what();
  }
}

TEST(MapInProcesses, AWorkerKilledIsNamed) {
  if (worker_threads() < 2)
    GTEST_SKIP() << "one CPU: the items run in this process, which must not be killed";
  const pid_t here = getpid();
  try {
    map_in_processes(6, 1, [here](std::size_t i) {
      if (i == 2 && getpid() != here) raise(SIGKILL);
      return std::vector<double>{1.0};
    });
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("signal 9"), std::string::npos) << e.what();
  }
}

// A ProcessMap's items run in children at the priority asked while the caller goes on, or (with a nice) in
// the caller at get(), at its own priority; the results come back in index order.
TEST(ProcessMap, ItemsInLowPriorityChildrenWhileTheCallerGoesOn) {
  const pid_t here = getpid();
  errno = 0;
  const int callers = getpriority(PRIO_PROCESS, 0);
  ASSERT_EQ(errno, 0);
  ProcessMap map(
      5, 3,
      [here](std::size_t i) {
        errno = 0;
        const int nice = getpriority(PRIO_PROCESS, 0);
        return std::vector<double>{static_cast<double>(i), getpid() != here ? 1.0 : 0.0,
                                   errno == 0 ? nice : -100.0};
      },
      1, 19);
  double caller = 0;
  for (int i = 1; i <= 1000; ++i) caller += 1.0 / i;  // the caller's own work, meanwhile
  const auto out = map.get();
  EXPECT_GT(caller, 7.0);
  ASSERT_EQ(out.size(), 5u);
  for (std::size_t i = 0; i < 5; ++i) {
    EXPECT_EQ(out[i][0], static_cast<double>(i));
    EXPECT_EQ(out[i][2], out[i][1] == 1.0 ? 19.0 : callers) << "item " << i << " in a child: " << out[i][1];
  }
}

// Low-priority children that never finish (a machine too busy to give them a core) keep get() waiting no
// longer than the items take here: every item comes back, computed by the caller.
TEST(ProcessMap, ALowPriorityMapDoesNotWaitForItsChildren) {
  const pid_t here = getpid();
  ProcessMap map(
      4, 1,
      [here](std::size_t i) {
        if (getpid() != here) pause();  // until killed
        return std::vector<double>{10.0 + static_cast<double>(i)};
      },
      2, 19);
  const auto out = map.get();
  ASSERT_EQ(out.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(out[i][0], 10.0 + static_cast<double>(i));
}

// A map dropped before get() kills and reaps its children: none outlives it.
TEST(ProcessMap, DroppedUnwaitedItKillsItsChildren) {
  auto* pid = static_cast<std::atomic<int>*>(
      mmap(nullptr, sizeof(std::atomic<int>), PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0));
  ASSERT_NE(pid, MAP_FAILED);
  new (pid) std::atomic<int>(0);
  {
    ProcessMap map(
        1, 1,
        [pid](std::size_t) {
          pid->store(getpid());
          pause();  // until killed
          return std::vector<double>{0.0};
        },
        1);
    while (pid->load() == 0) usleep(1000);
  }
  EXPECT_EQ(kill(pid->load(), 0), -1);
  EXPECT_EQ(errno, ESRCH);
  munmap(pid, sizeof(std::atomic<int>));
}

}  // namespace
}  // namespace skinfem
