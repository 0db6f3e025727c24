// What users wait on: the main job and the commands it chains, run as a user runs them. Each benchmark runs
// the `skinfem` executable once into a fresh folder and reports, from the JSON it writes, the seconds of
// every stage (counters s_<stage>, from wall_s), the whole run's seconds, its DOFs and its peak memory (MB):
// the per-stage table of issue 52, kept where the next change will see it move.
//
//   $ build/bench/skinfem_bench --benchmark_filter=Command --benchmark_counters_tabular=true
//   Command/0  report --fast, candelier2011     s_factor 5.2  s_defect 4.3 ... dofs 95898  peak_mb 1213
#include <benchmark/benchmark.h>
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

extern char** environ;

namespace skinfem {
namespace {

struct Case {
  const char* label;
  const char* scene;
  std::vector<std::string> options;
  const char* summary;  // the JSON it writes, in its output folder
};

const Case kCases[] = {
    {"report --fast, candelier2011", "candelier2011", {"report", "--fast"}, "report.json"},
    {"report, candelier2011", "candelier2011", {"report"}, "report.json"},
    {"kfit (3D), candelier2011", "candelier2011", {"kfit"}, "kfit.json"},
    {"kfit --path meridian, flat_layer", "flat_layer", {"kfit", "--path", "meridian"}, "kfit.json"},
    {"green, candelier2011", "candelier2011", {"green"}, "summary.json"},
    {"contact (3D), candelier2011", "candelier2011", {"contact"}, "summary.json"},
    {"contact --path meridian, hertz_layer",
     "hertz_layer",
     {"contact", "--path", "meridian"},
     "summary.json"},
};

// Runs argv with its output discarded; its exit code (−1 if it could not run or was killed).
int run(const std::vector<std::string>& argv) {
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  posix_spawn_file_actions_t io;
  posix_spawn_file_actions_init(&io);
  posix_spawn_file_actions_addopen(&io, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&io, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  const int err = posix_spawn(&pid, args[0], &io, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&io);
  int status = 0;
  if (err != 0 || waitpid(pid, &status, 0) != pid) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

void BM_Command(benchmark::State& st) {
  namespace fs = std::filesystem;
  const Case& c = kCases[st.range(0)];
  const fs::path out = fs::temp_directory_path() / ("skinfem_bench_" + std::to_string(getpid()));
  nlohmann::json summary;
  for (auto _ : st) {
    fs::remove_all(out);
    std::vector<std::string> argv{SKINFEM_EXE, c.options[0],
                                  std::string(SKINFEM_SOURCE_DIR) + "/scenes/" + c.scene + ".json"};
    argv.insert(argv.end(), c.options.begin() + 1, c.options.end());
    argv.insert(argv.end(), {"--out", out.string()});
    if (const int rc = run(argv); rc != 0) {
      st.SkipWithError(("skinfem exited with " + std::to_string(rc)).c_str());
      break;
    }
    std::ifstream in(out / c.summary);
    summary = nlohmann::json::parse(in);
  }
  fs::remove_all(out);
  if (summary.is_null()) return;
  const nlohmann::json wall = summary.value("wall_s", nlohmann::json::object());
  for (const auto& [stage, seconds] : wall.items())
    if (seconds.is_number()) st.counters["s_" + stage] = seconds.get<double>();
  st.counters["s_total"] = summary.value("wall_total_s", 0.0);
  st.counters["dofs"] = summary.value("dofs", 0.0);
  st.counters["peak_mb"] = summary.value("peak_rss_mb", 0.0);
  st.SetLabel(c.label);
}
BENCHMARK(BM_Command)
    ->DenseRange(0, static_cast<int>(std::size(kCases)) - 1)
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->UseRealTime();

}  // namespace
}  // namespace skinfem
