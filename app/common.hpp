// Shared plumbing of the skinfem subcommands: output files, timing, memory, progress.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "skinfem/pipeline/clock.hpp"
#include "skinfem/pipeline/progress.hpp"
#include "skinfem/pipeline/scene_json.hpp"
#include "skinfem/scene/scene.hpp"

namespace skinfem::app {

// The front end calls the pipeline (pipeline/) by its unqualified names.
using namespace skinfem::pipeline;

// Fails early (before any computation) when DIR could not be created or written; creates nothing.
void check_output_dir(const std::string& dir);
// An output directory belongs to one command: DIR/run.json (written after a run succeeds) names the command
// that wrote it, and another command refuses it rather than mix its files in (contact and defect both
// write summary.json). Throws SceneError naming both.
void check_run_record(const std::string& dir, const std::string& command);
void write_run_record(const std::string& dir, const std::string& command, const Scene& scene);
// Creates DIR if needed; throws with a one-line message when it cannot.
void prepare_output_dir(const std::string& dir);
// Writes text to path through a temporary file and a rename: never a half-written file.
void write_text_atomic(const std::string& path, const std::string& text);
void write_json(const std::string& path, const nlohmann::json& j);
// A stage's summary built before its files were written gains their time: wall_s's "write" and the total.
void add_write_seconds(nlohmann::json& summary, double seconds);

// Runs argv[0] (found on PATH unless it has a slash) with these arguments, no shell in between (nothing in
// them is ever parsed as a command), its stdout sent to our stderr so that stdout stays the summary; waits
// for it. Returns its exit code, or -1 when it could not start or was killed.
// The child runs in its own process group. SIGINT, SIGTERM or SIGHUP sent to us while it runs (a Ctrl-C, a
// scheduler's stop, a closed terminal) is passed once to that whole group and we go on waiting: the child's
// own shutdown (Snakemake removing its unfinished outputs) ends before we return, so a re-run started
// after we exit never races it. *interrupted_by (when given) is that signal's number, or 0. A child whose
// group has not ended `grace_s` seconds after the signal (> 0; Snakemake can deadlock in its own signal
// handler) is killed with SIGKILL, and *killed (when given) says so. end_with_us: the child gets SIGTERM
// when we end without passing it a signal (killed by SIGKILL), so that it does not outlive us.
// Our open file descriptors without close-on-exec are inherited (the sweep's lock on its folder). log_path:
// the child's stdout and stderr go to that file (created or truncated), else both to our stderr.
int run_child(const std::vector<std::string>& argv, int* interrupted_by = nullptr, double grace_s = 0,
              bool* killed = nullptr, bool end_with_us = false, const std::string& log_path = {});

// A child started in the background, its stdout sent to our stderr, in our process group (a terminal's
// Ctrl-C reaches it as it reaches us), ended with SIGTERM when we end first. Returns its id, or -1 when it
// could not start. wait_background_child: its exit code, or 128 + the signal that ended it (127: no exec).
// go_fd, when given: the child's stdin is a socket whose other end comes back here, for a child that starts
// before its inputs are ready and waits for a line (tell_background_child sends it and closes the socket; our
// end closing unsaid, as when we stop early, gives the child an end of file).
int start_background_child(const std::vector<std::string>& argv, int* go_fd = nullptr);
void tell_background_child(int& go_fd, const std::string& line);
int wait_background_child(int pid);

// Study levels given on the command line (--scales, --ridges, --error-scales): each finite, no two equal,
// in the order the option states (coarse to fine); otherwise the finest level, the reference of every
// error, would be the wrong one. Throws SceneError naming the option and the offending value.
void check_levels(const std::string& option, const std::vector<double>& levels, bool decreasing);

// "[skinfem] stage…" on stderr, so stdout stays the human summary.
void progress(const std::string& message);
// printf onto `to` when given (a stage computed beside others, its lines printed later in their place), else
// to stdout.
void say(std::string* to, const char* format, ...) __attribute__((format(printf, 2, 3)));

// scripts/figures.py: installed beside the command (../share/skinfem/figures.py from its directory), else
// the source tree's (a build tree's command).
std::string figures_script();
// The sweep's Snakemake workflow: ../share/skinfem/workflow/Snakefile beside the command, else the source
// tree's sweeps/workflow/Snakefile.
std::string sweep_workflow();

}  // namespace skinfem::app
