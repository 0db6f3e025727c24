#include "app/common.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <climits>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <stdexcept>

namespace skinfem::app {

void prepare_output_dir(const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir))
    throw std::runtime_error("--out " + dir + ": cannot create output directory (" + ec.message() + ")");
}

void check_output_dir(const std::string& dir) {
  namespace fs = std::filesystem;
  if (dir.empty()) throw SceneError("--out '': must name a directory (an empty path names none)");
  std::error_code ec;
  fs::path p = fs::absolute(dir, ec);
  // A name longer than the file system takes (ENAMETOOLONG) would fail only when the first file is written.
  const std::string shown = dir.size() > 60 ? dir.substr(0, 40) + "..." + dir.substr(dir.size() - 12) : dir;
  if (p.string().size() >= PATH_MAX)
    throw SceneError("--out " + shown + ": the path has " + std::to_string(p.string().size()) +
                     " characters; allowed fewer than " + std::to_string(PATH_MAX));
  for (const fs::path& part : p)
    if (part.string().size() > NAME_MAX)
      throw SceneError("--out " + shown + ": a name in the path has " + std::to_string(part.string().size()) +
                       " characters; allowed at most " + std::to_string(NAME_MAX) + " per name");
  if (fs::exists(p, ec) && !fs::is_directory(p, ec))
    throw SceneError("--out " + dir + ": exists and is not a directory; must be a directory or a new path");
  while (!p.empty() && !fs::exists(p, ec)) p = p.parent_path();
  if (p.empty() || !fs::is_directory(p, ec) || access(p.c_str(), W_OK) != 0)
    throw SceneError("--out " + dir + ": cannot create or write the output directory (" + p.string() +
                     " is not a writable directory)");
}

void check_run_record(const std::string& dir, const std::string& command) {
  const std::string path = dir + "/run.json";
  if (!std::filesystem::exists(path)) return;
  std::string owner;
  try {
    std::ifstream in(path);
    owner = nlohmann::json::parse(in).at("command").get<std::string>();
  } catch (const std::exception&) {
    throw SceneError("--out " + dir + ": its run.json is not one skinfem wrote; give another directory");
  }
  if (owner != command)
    throw SceneError("--out " + dir + ": holds the results of `skinfem " + owner + "` (run.json); `skinfem " +
                     command + "` would mix its files in: give another directory, or remove that one");
}

void write_run_record(const std::string& dir, const std::string& command, const Scene& scene) {
  write_json(dir + "/run.json",
             {{"command", command}, {"scene", scene.source_path}, {"skinfem", SKINFEM_VERSION}});
}

void write_text_atomic(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp);
    out << text;
    if (!out) throw std::runtime_error("cannot write " + path);
  }
  std::filesystem::rename(tmp, path);
}

void write_json(const std::string& path, const nlohmann::json& j) {
  write_text_atomic(path, j.dump(2) + "\n");
}

void add_write_seconds(nlohmann::json& summary, double seconds) {
  summary["wall_s"]["write"] = seconds;
  summary["wall_total_s"] = summary.at("wall_total_s").get<double>() + seconds;
}

namespace {
volatile sig_atomic_t child_group = 0;
volatile sig_atomic_t child_signal = 0;
extern "C" void pass_to_child(int sig) {
  child_signal = sig;
  if (child_group > 0) kill(-child_group, sig);
}
}  // namespace

int run_child(const std::vector<std::string>& argv, int* interrupted_by, double grace_s, bool* killed,
              bool end_with_us, const std::string& log_path) {
  const int log_fd =
      log_path.empty() ? -1 : ::open(log_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (!log_path.empty() && log_fd < 0)
    throw std::runtime_error("cannot write " + log_path + " (" + std::strerror(errno) + ")");
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  // Handlers first, with the signals held until the child's group is known, so that none is lost between.
  struct sigaction pass = {}, saved[3], fallback = {};
  pass.sa_handler = pass_to_child;
  sigemptyset(&pass.sa_mask);
  fallback.sa_handler = SIG_DFL;
  sigemptyset(&fallback.sa_mask);
  const int passed[3] = {SIGINT, SIGTERM, SIGHUP};
  sigset_t held, previous;
  sigemptyset(&held);
  for (int s : passed) sigaddset(&held, s);
  sigprocmask(SIG_BLOCK, &held, &previous);
  child_signal = 0;
  for (int i = 0; i < 3; ++i) sigaction(passed[i], &pass, &saved[i]);
  // fork and exec, not posix_spawn, which cannot set the parent-death signal. exec's errno comes back on a
  // close-on-exec pipe: its end closes unread when exec succeeds.
  int report[2];
  int err = pipe2(report, O_CLOEXEC) == 0 ? 0 : errno;
  const pid_t parent = getpid();
  pid_t pid = err != 0 ? -1 : fork();
  if (pid == 0) {
    // The child: only async-signal-safe calls until exec.
    setpgid(0, 0);
    // A parent killed outright (SIGKILL: no handler runs) would otherwise leave the child running, e.g. a
    // Snakemake that goes on with the members and keeps its lock.
    if (end_with_us && (prctl(PR_SET_PDEATHSIG, SIGTERM) != 0 || getppid() != parent)) _exit(128 + SIGTERM);
    if (log_fd >= 0) {
      dup2(log_fd, STDOUT_FILENO);
      dup2(log_fd, STDERR_FILENO);
    } else {
      dup2(STDERR_FILENO, STDOUT_FILENO);
    }
    // Defaults before unblocking: a signal arriving before exec must act on the child, not run our handler.
    for (int s : passed) sigaction(s, &fallback, nullptr);
    sigprocmask(SIG_SETMASK, &previous, nullptr);
    execvp(args[0], args.data());
    const int e = errno;
    [[maybe_unused]] const ssize_t sent = write(report[1], &e, sizeof e);
    _exit(127);
  }
  if (pid < 0 && err == 0) {
    err = errno;
    close(report[0]), close(report[1]);
  }
  if (pid > 0) {
    setpgid(pid, pid);  // as the child does: the group exists before any signal is passed to it
    close(report[1]);
    int e = 0;
    ssize_t got;
    while ((got = read(report[0], &e, sizeof e)) < 0 && errno == EINTR) {
    }
    close(report[0]);
    if (got == static_cast<ssize_t>(sizeof e)) {
      err = e;
      waitpid(pid, nullptr, 0);
    }
  }
  if (log_fd >= 0) close(log_fd);
  child_group = err == 0 ? pid : 0;
  sigprocmask(SIG_SETMASK, &previous, nullptr);
  int status = 0, rc = -1;
  if (killed) *killed = false;
  if (err == 0) {
    pid_t got;
    // Polled (every 20 ms) once a signal has been passed, so that a child that does not end can be killed.
    std::optional<std::chrono::steady_clock::time_point> signalled;
    for (;;) {
      got = waitpid(pid, &status, child_signal && grace_s > 0 ? WNOHANG : 0);
      if (got == pid || (got < 0 && errno != EINTR)) break;
      if (got == 0) {
        if (!signalled) signalled = std::chrono::steady_clock::now();
        if (std::chrono::duration<double>(std::chrono::steady_clock::now() - *signalled).count() > grace_s) {
          kill(-pid, SIGKILL);
          if (killed) *killed = true;
          grace_s = 0;  // and wait for it
        } else {
          usleep(20000);
        }
      }
    }
    rc = got == pid && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  child_group = 0;
  for (int i = 0; i < 3; ++i) sigaction(passed[i], &saved[i], nullptr);
  if (interrupted_by) *interrupted_by = child_signal;
  return rc;
}

int start_background_child(const std::vector<std::string>& argv, int* go_fd) {
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  int go[2] = {-1, -1};
  // A socket pair rather than a pipe: a line sent to a child that has already ended must not raise SIGPIPE.
  if (go_fd && socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, go) != 0) return -1;
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid == 0) {
    // Only async-signal-safe calls until exec.
    if (prctl(PR_SET_PDEATHSIG, SIGTERM) != 0 || getppid() != parent) _exit(128 + SIGTERM);
    dup2(STDERR_FILENO, STDOUT_FILENO);
    if (go_fd) dup2(go[0], STDIN_FILENO);
    execvp(args[0], args.data());
    _exit(127);
  }
  if (go_fd) {
    close(go[0]);
    if (pid < 0) close(go[1]);
    *go_fd = pid < 0 ? -1 : go[1];
  }
  return pid;
}

void tell_background_child(int& go_fd, const std::string& line) {
  if (go_fd < 0) return;
  const std::string text = line + "\n";
  ssize_t n;
  while ((n = send(go_fd, text.data(), text.size(), MSG_NOSIGNAL)) < 0 && errno == EINTR) {
  }
  close(go_fd);
  go_fd = -1;
}

int wait_background_child(int pid) {
  if (pid <= 0) return 127;
  int status = 0;
  pid_t got;
  while ((got = waitpid(pid, &status, 0)) < 0 && errno == EINTR) {
  }
  if (got != pid) return 127;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

void check_levels(const std::string& option, const std::vector<double>& levels, bool decreasing) {
  const auto show = [](double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return std::string(buf);
  };
  for (size_t i = 0; i < levels.size(); ++i) {
    if (!std::isfinite(levels[i]))
      throw SceneError(option + ": level " + std::to_string(i + 1) + " = " + show(levels[i]) +
                       ": every level must be a finite number");
    if (i > 0 && (decreasing ? !(levels[i] < levels[i - 1]) : !(levels[i] > levels[i - 1])))
      throw SceneError(option + ": " + show(levels[i - 1]) + " then " + show(levels[i]) +
                       ": levels must be distinct and " +
                       (decreasing ? "decreasing (coarse to fine)" : "increasing (coarse to fine)"));
  }
}

void progress(const std::string& message) { std::cerr << "[skinfem] " << message << std::endl; }

void say(std::string* to, const char* format, ...) {
  va_list args;
  va_start(args, format);
  if (!to) {
    std::vprintf(format, args);
  } else {
    va_list copy;
    va_copy(copy, args);
    const int n = std::vsnprintf(nullptr, 0, format, copy);
    va_end(copy);
    if (n > 0) {
      std::string text(static_cast<size_t>(n) + 1, '\0');
      std::vsnprintf(text.data(), text.size(), format, args);
      text.pop_back();
      *to += text;
    }
  }
  va_end(args);
}

namespace {
// A file shipped beside the command when installed (share/skinfem/NAME), else the source tree's.
std::string shipped_file(const std::string& name, const std::string& in_source) {
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const std::filesystem::path installed = exe.parent_path() / ".." / "share" / "skinfem" / name;
    if (std::filesystem::exists(installed, ec))
      return std::filesystem::weakly_canonical(installed, ec).string();
  }
  return std::string(SKINFEM_SOURCE_DIR) + "/" + in_source;
}
}  // namespace

std::string figures_script() { return shipped_file("figures.py", "scripts/figures.py"); }

std::string sweep_workflow() { return shipped_file("workflow/Snakefile", "sweeps/workflow/Snakefile"); }

}  // namespace skinfem::app
