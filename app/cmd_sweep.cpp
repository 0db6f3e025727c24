// skinfem sweep — a family of scenes, one skinfem run per member, on a workflow engine (Snakemake): locally
// on N cores, or on a cluster through a Snakemake profile (sweeps/profiles/slurm/).
//
//   $ skinfem sweep sweeps/k_vs_nu_and_punch.json --out out/k_sweep --cores 2
//   sweep k_vs_nu_and_punch: 42 members of `skinfem kfit --path meridian` (grid 6 x 7), 0 already done;
//   memory per job from the spec's mem_mb 256 MB
//   [skinfem] sweep: 12 of 42 members finished (0 failed), 31 s, about 1.3 min to go   (one line, rewritten)
//   gathered 42 members (42 ok, 0 failed) into /abs/out/k_sweep: results.csv (64 columns), results.h5,
//   2 plots
//   Snakemake's log: out/k_sweep/snakemake.log
//
// The spec's format: scene/sweep.cpp. Writes DIR/scenes/<id>.json (one per member, named by a hash of its
// content and only written when absent, so that an unchanged member is recognised), DIR/manifest.json (the
// members, their parameters and memory estimates), then runs sweeps/workflow/Snakefile in DIR: each member
// into DIR/members/<id>/ (the command's own files in out/, status.json with its exit code, error line and
// time), gathered into DIR/results.csv, results.h5 and plots/ (sweeps/workflow/gather.py). A re-run runs
// only members without a status (new, changed or interrupted) and those whose status says "retry" (killed
// by a signal or out of memory). --dry-run writes and does not run.
// One sweep per DIR: an exclusive flock on DIR/.skinfem-sweep.lock, held from before the first write to the
// end and inherited by Snakemake; a second sweep into DIR is refused in one line and writes nothing. Holding
// it, a Snakemake lock left in DIR/.snakemake/locks can only be stale and is removed. Snakemake gets SIGTERM
// if skinfem is killed outright (SIGKILL), instead of running on without it.
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <thread>
#include <vector>

#include "app/commands.hpp"
#include "app/common.hpp"
#include "skinfem/mesh/size_estimate.hpp"
#include "skinfem/pipeline/green.hpp"
#include "skinfem/pipeline/resources.hpp"
#include "skinfem/scene/commands.hpp"
#include "skinfem/scene/parallel.hpp"

namespace skinfem::app {
namespace {

namespace fs = std::filesystem;

// Memory a member's job declares, MB: the chain's memory for the mesh estimate of the whole skin (the
// meridian path and mirror halves need less; a scheduler given too much only packs fewer jobs). An imported
// surface has no estimate before meshing: 4 GB.
long member_memory_mb(const Scene& scene, double& dofs) {
  const MeshEstimate e = estimate_mesh(scene);
  dofs = e.known ? e.dofs : 0;
  return e.known ? std::max(256L, std::lround(1024 * estimated_memory_gb(e.dofs))) : 4096L;
}

// A member's status, if it has one: finished, refused with its error, or to run again ("retry": killed by a
// signal or out of memory, sweeps/workflow/gather.py).
enum class Status { none, done, retry };
Status member_status(const std::string& out_dir, const SweepMember& m) {
  std::ifstream in(out_dir + "/members/" + m.id + "/status.json");
  if (!in) return Status::none;
  const nlohmann::json status = nlohmann::json::parse(in, nullptr, false);
  return status.is_object() && status.value("retry", false) == true ? Status::retry : Status::done;
}

// Members with a status that stands (not to retry): what a re-run does not run again.
int members_done(const Sweep& sweep, const std::string& out_dir) {
  int done = 0;
  for (const SweepMember& m : sweep.members) done += member_status(out_dir, m) == Status::done;
  return done;
}

// "member 3 (/material/nu = 0.45, ...)": how load_sweep names a member in its errors.
std::string member_label(const Sweep& sweep, std::size_t i) {
  std::string where;
  for (std::size_t a = 0; a < sweep.axes.size(); ++a)
    where += (where.empty() ? "" : ", ") + sweep.axes[a].pointer + " = " + sweep.members[i].values[a];
  return "member " + std::to_string(i + 1) + " (" + where + ")";
}

// An exclusive lock on DIR/.skinfem-sweep.lock, taken before anything is written in DIR and held until we
// end: a second sweep into DIR would rewrite the manifest under the first, which would then gather the
// second's table. The descriptor is left open across exec, so a Snakemake that outlives us holds it too.
void lock_sweep_dir(const std::string& dir) {
  const std::string path = dir + "/.skinfem-sweep.lock";
  const int fd = ::open(path.c_str(), O_RDWR | O_CREAT, 0644);
  if (fd < 0)
    throw std::runtime_error("--out " + dir + ": cannot create " + path + " (" + std::strerror(errno) + ")");
  if (flock(fd, LOCK_EX | LOCK_NB) != 0) {
    const int e = errno;
    ::close(fd);
    if (e == EWOULDBLOCK)
      throw std::runtime_error("--out " + dir +
                               ": another skinfem sweep is running there (it holds .skinfem-sweep.lock); "
                               "wait for it to end, or give another directory");
    throw std::runtime_error("--out " + dir + ": cannot lock " + path + " (" + std::strerror(e) + ")");
  }
}

// One progress line while Snakemake runs (its own log goes to DIR/snakemake.log): members finished of the
// total, failed, elapsed time and an estimate from this run's pace. On a terminal the line is rewritten in
// place; elsewhere a line is printed when the count has changed, at most every 10 s, and at the end.
class SweepProgress {
 public:
  SweepProgress(const Sweep& sweep, const std::string& dir, int done_before)
      : sweep_(sweep),
        dir_(dir),
        before_(done_before),
        tty_(isatty(STDERR_FILENO) == 1),
        start_(std::chrono::steady_clock::now()),
        thread_([this] { run(); }) {}
  ~SweepProgress() {
    {
      std::lock_guard<std::mutex> lock(m_);
      stop_ = true;
    }
    cv_.notify_all();
    thread_.join();
    report(true);
  }

 private:
  void run() {
    std::unique_lock<std::mutex> lock(m_);
    while (!cv_.wait_for(lock, std::chrono::seconds(1), [this] { return stop_; })) report(false);
  }
  void report(bool last) {
    int finished = 0, failed = 0;
    for (const SweepMember& m : sweep_.members) {
      std::ifstream in(dir_ + "/members/" + m.id + "/status.json");
      if (!in) continue;
      const nlohmann::json st = nlohmann::json::parse(in, nullptr, false);
      ++finished;
      failed += !(st.is_object() && st.value("exit_code", -1) == 0);
    }
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const bool changed = finished != shown_;
    if (!last && !tty_ && !(changed && elapsed - shown_at_ >= 10)) return;
    if (!last && tty_ && !changed && elapsed - shown_at_ < 1) return;
    const int total = static_cast<int>(sweep_.members.size()), now = finished - before_;
    std::string eta;
    if (now > 0 && finished < total)
      eta = ", about " + duration(elapsed / now * (total - finished)) + " to go";
    char buf[200];
    std::snprintf(buf, sizeof buf, "sweep: %d of %d members finished (%d failed), %s%s", finished, total,
                  failed, duration(elapsed).c_str(), eta.c_str());
    if (tty_)
      std::fprintf(stderr, "\r[skinfem] %s\033[K%s", buf, last ? "\n" : "");
    else
      std::fprintf(stderr, "[skinfem] %s\n", buf);
    std::fflush(stderr);
    shown_ = finished, shown_at_ = elapsed;
  }
  static std::string duration(double s) {
    char buf[32];
    if (s < 90)
      std::snprintf(buf, sizeof buf, "%.0f s", s);
    else
      std::snprintf(buf, sizeof buf, "%.1f min", s / 60);
    return buf;
  }
  const Sweep& sweep_;
  const std::string dir_;
  const int before_;
  const bool tty_;
  const std::chrono::steady_clock::time_point start_;
  int shown_ = -1;
  double shown_at_ = -1e9;
  std::mutex m_;
  std::condition_variable cv_;
  bool stop_ = false;
  std::thread thread_;
};

// The last lines of a file, for a failure's context.
std::string tail_of(const std::string& path, int lines) {
  std::ifstream in(path);
  std::vector<std::string> all;
  for (std::string line; std::getline(in, line);) all.push_back(line);
  std::string out;
  for (std::size_t i = all.size() > static_cast<std::size_t>(lines) ? all.size() - lines : 0; i < all.size();
       ++i)
    out += "  " + all[i] + "\n";
  return out;
}

// Whether PATH holds an executable `name`: a sweep without Snakemake is refused before anything is written.
bool on_path(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "";
  for (std::size_t start = 0; start <= dirs.size();) {
    std::size_t end = dirs.find(':', start);
    if (end == std::string::npos) end = dirs.size();
    const std::string dir = end > start ? dirs.substr(start, end - start) : ".";
    if (::access((dir + "/" + name).c_str(), X_OK) == 0) return true;
    start = end + 1;
  }
  return false;
}

}  // namespace

int run_sweep(const std::string& spec_path, const std::string& out, int cores, const std::string& profile,
              bool dry_run) {
  const Sweep sweep = load_sweep(spec_path);
  const std::string out_dir = out.empty() ? "out/" + sweep.name : out;
  check_output_dir(out_dir);
  check_run_record(out_dir, "sweep");
  if (!dry_run && !on_path("snakemake"))
    throw std::runtime_error(
        "sweep: Snakemake is not installed (not on PATH); install it and the results' HDF5 writer with "
        "`apt-get install snakemake python3-h5py` (scripts/test installs both), or write the members with "
        "--dry-run");

  // Every member's kernel grid as `skinfem green --grid` would check it, before anything is written.
  const auto grid = std::find(sweep.options.begin(), sweep.options.end(), "--grid");
  if (grid != sweep.options.end() && grid + 1 != sweep.options.end())
    for (std::size_t i = 0; i < sweep.members.size(); ++i) try {
        pipeline::check_kernel_grid(sweep.members[i].scene, std::stod(*(grid + 1)));
      } catch (const SceneError& e) {
        throw SceneError(spec_path + ": " + member_label(sweep, i) + ": " + e.what());
      }
  std::vector<long> estimates(sweep.members.size());
  std::vector<double> dofs(sweep.members.size());
  for_each_index(sweep.members.size(),
                 [&](std::size_t i) { estimates[i] = member_memory_mb(sweep.members[i].scene, dofs[i]); });

  prepare_output_dir(out_dir);
  lock_sweep_dir(out_dir);
  prepare_output_dir(out_dir + "/scenes");

  nlohmann::json manifest;
  manifest["name"] = sweep.name;
  manifest["spec"] = fs::absolute(spec_path).lexically_normal().string();
  manifest["base_scene"] = sweep.base_scene_path;
  manifest["command"] = sweep.command;
  manifest["options"] = sweep.options;
  manifest["combine"] = sweep.combine;
  const CommandSpec& spec = command_named(sweep.command);
  manifest["summary_file"] = spec.summary_file;
  manifest["plotted"] = spec.plotted;
  std::error_code ec;
  manifest["skinfem"] = fs::read_symlink("/proc/self/exe", ec).string();
  manifest["skinfem_version"] = SKINFEM_VERSION;
  for (const SweepAxis& a : sweep.axes) {
    nlohmann::json values = nlohmann::json::array();
    for (const auto& v : a.values) values.push_back(nlohmann::json::parse(v));
    manifest["axes"].push_back({{"pointer", a.pointer}, {"column", a.column}, {"values", values}});
  }
  // An existing member's scene is left alone (its name is its content), so its results stay up to date.
  for_each_index(sweep.members.size(), [&](std::size_t i) {
    const std::string scene_file = out_dir + "/scenes/" + sweep.members[i].id + ".json";
    if (!fs::exists(scene_file)) write_text_atomic(scene_file, sweep.members[i].scene_json);
  });
  long mem_lo = 1L << 40, mem_hi = 0;
  for (std::size_t i = 0; i < sweep.members.size(); ++i) {
    const SweepMember& m = sweep.members[i];
    const long mem = sweep.mem_mb > 0 ? sweep.mem_mb : estimates[i];
    mem_lo = std::min(mem_lo, mem), mem_hi = std::max(mem_hi, mem);
    nlohmann::json values = nlohmann::json::array();
    for (const auto& v : m.values) values.push_back(nlohmann::json::parse(v));
    manifest["members"].push_back({{"id", m.id},
                                   {"scene", "scenes/" + m.id + ".json"},
                                   {"values", values},
                                   {"mem_mb", mem},
                                   {"estimated_mem_mb", estimates[i]},
                                   {"estimated_dofs", dofs[i]}});
  }
  write_json(out_dir + "/manifest.json", manifest);
  write_json(out_dir + "/run.json",
             {{"command", "sweep"}, {"spec", manifest["spec"]}, {"skinfem", SKINFEM_VERSION}});

  // Members killed by a signal or out of memory run again: their status goes before Snakemake starts (not in
  // a dry run, which changes no member).
  int done = 0, retry = 0;
  for (const SweepMember& m : sweep.members) {
    const Status st = member_status(out_dir, m);
    done += st == Status::done, retry += st == Status::retry;
    if (st == Status::retry && !dry_run) fs::remove(out_dir + "/members/" + m.id + "/status.json");
  }

  std::string shape;
  for (const SweepAxis& a : sweep.axes)
    shape += (shape.empty() ? "" : " x ") + std::to_string(a.values.size());
  std::string command = "skinfem " + sweep.command;
  for (const auto& w : sweep.options) command += " " + w;
  const std::string memory = (sweep.mem_mb > 0 ? "the spec's mem_mb " : "the mesh estimate ") +
                             std::to_string(mem_lo) + (mem_hi > mem_lo ? "-" + std::to_string(mem_hi) : "");
  const std::string retrying = retry > 0 ? ", " + std::to_string(retry) + " to retry" : "";
  std::printf("sweep %s: %zu member%s of `%s` (%s %s), %d already done%s; memory per job from %s MB\n",
              sweep.name.c_str(), sweep.members.size(), sweep.members.size() == 1 ? "" : "s", command.c_str(),
              sweep.combine.c_str(), shape.c_str(), done, retrying.c_str(), memory.c_str());

  std::vector<std::string> argv{"snakemake", "--snakefile",        sweep_workflow(), "--directory",
                                out_dir,     "--rerun-incomplete", "--keep-going"};
  if (!profile.empty()) {
    argv.insert(argv.end(), {"--profile", profile});
  } else {
    // Locally the jobs are packed by the memory they declare into what the machine has free.
    const long avail_mb = std::lround(1024 * available_memory_gb());
    // Equal one-core jobs need no ILP scheduling (the default spawns a solver per round).
    argv.insert(argv.end(), {"--cores", std::to_string(cores), "--scheduler", "greedy"});
    if (avail_mb > 0) argv.insert(argv.end(), {"--resources", "mem_mb=" + std::to_string(avail_mb)});
  }
  std::string line;
  for (const auto& a : argv) line += (line.empty() ? "" : " ") + a;
  std::fflush(stdout);
  if (dry_run) {
    std::printf("dry run: wrote %s/manifest.json and %zu scenes; to run: %s\n", out_dir.c_str(),
                sweep.members.size(), line.c_str());
    return 0;
  }
  // Our lock proves that no other sweep, nor a Snakemake one started, runs in DIR: a Snakemake lock there
  // is left by one that was killed, and would refuse this run.
  const fs::path snakemake_locks = fs::path(out_dir) / ".snakemake" / "locks";
  if (fs::exists(snakemake_locks, ec) && !fs::is_empty(snakemake_locks, ec)) {
    fs::remove_all(snakemake_locks, ec);
    progress("removed " + snakemake_locks.string() +
             ", left by a Snakemake that did not end cleanly (no other sweep runs in " + out_dir + ")");
  }
  progress("running: " + line);
  int stopped_by = 0;
  bool killed = false;
  // Snakemake can deadlock in its own handler of the signal we pass on: 30 s after it, it is killed. If we
  // are killed outright, it gets SIGTERM (and shuts its members down) rather than running on.
  const std::string log = out_dir + "/snakemake.log";
  int rc = 0;
  {
    SweepProgress watch(sweep, out_dir, done);
    rc = run_child(argv, &stopped_by, 30, &killed, true, log);
  }
  if (stopped_by != 0) {
    // A killed Snakemake leaves its lock, which would refuse every re-run; its process is gone, so the lock
    // holds nothing (its unfinished members are marked incomplete and run again).
    if (killed) std::filesystem::remove_all(std::filesystem::path(out_dir) / ".snakemake" / "locks");
    const int done_now = members_done(sweep, out_dir);
    std::fprintf(stderr,
                 "skinfem: sweep: stopped by signal %d (%s) after Snakemake %s; %d of %zu members done, "
                 "results not gathered; the same command resumes with the other %zu\n",
                 stopped_by, strsignal(stopped_by),
                 killed ? "was killed (it had not ended 30 s after the signal)" : "ended", done_now,
                 sweep.members.size(), sweep.members.size() - done_now);
    return 128 + stopped_by;
  }
  if (rc != 0) {
    const std::string what =
        rc < 0 ? "could not start or was killed" : "exited with code " + std::to_string(rc);
    std::fprintf(
        stderr,
        "skinfem: sweep: Snakemake %s; the members' errors are in %s/members/*/status.json, its log in "
        "%s; its last lines:\n%s",
        what.c_str(), out_dir.c_str(), log.c_str(), tail_of(log, 5).c_str());
    return 1;
  }
  // The gather's own summary line (gathered N members ... into DIR: results.csv ...), from the log.
  std::ifstream in(log);
  for (std::string line; std::getline(in, line);)
    if (line.rfind("gathered ", 0) == 0) std::printf("%s\n", line.c_str());
  std::printf("Snakemake's log: %s\n", log.c_str());
  return 0;
}

}  // namespace skinfem::app
