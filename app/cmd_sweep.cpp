// skinfem sweep — a family of scenes, one skinfem run per member, on a workflow engine (Snakemake): locally
// on N cores, or on a cluster through a Snakemake profile (sweeps/profiles/slurm/).
//
//   $ skinfem sweep sweeps/k_vs_nu_and_punch.json --out out/k_sweep --cores 2
//   sweep k_vs_nu_and_punch: 42 members of `skinfem kfit --path meridian` (grid 6 x 7), 0 already done;
//   memory per job from the spec's mem_mb 256 MB
//   ... (Snakemake's job log, on stderr) ...
//   gathered 42 members (42 ok, 0 failed) into /abs/out/k_sweep: results.csv (66 columns), results.h5,
//   2 plots
//
// The spec's format: scene/sweep.cpp. Writes DIR/scenes/<id>.json (one per member, named by a hash of its
// content and only written when absent, so that an unchanged member is recognised), DIR/manifest.json (the
// members, their parameters and memory estimates), then runs sweeps/workflow/Snakefile in DIR: each member
// into DIR/members/<id>/ (the command's own files in out/, status.json with its exit code, error line and
// time), gathered into DIR/results.csv, results.h5 and plots/ (sweeps/workflow/gather.py). A re-run runs
// only members without a status (new, changed or interrupted). --dry-run writes and does not run.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "app/commands.hpp"
#include "app/common.hpp"
#include "mesh/size_estimate.hpp"
#include "pipeline/resources.hpp"

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

// Members with a status.json (finished, or refused with their error): what a re-run does not run again.
int members_done(const Sweep& sweep, const std::string& out_dir) {
  int done = 0;
  for (const SweepMember& m : sweep.members)
    done += fs::exists(out_dir + "/members/" + m.id + "/status.json");
  return done;
}

std::string summary_file(const std::string& command) {
  return command == "kfit" ? "kfit.json" : command == "report" ? "report.json" : "summary.json";
}

}  // namespace

int run_sweep(const std::string& spec_path, const std::string& out, int cores, const std::string& profile,
              bool dry_run) {
  const Sweep sweep = load_sweep(spec_path);
  const std::string out_dir = out.empty() ? "out/" + sweep.name : out;
  check_output_dir(out_dir);
  check_run_record(out_dir, "sweep");
  prepare_output_dir(out_dir + "/scenes");

  nlohmann::json manifest;
  manifest["name"] = sweep.name;
  manifest["spec"] = fs::absolute(spec_path).lexically_normal().string();
  manifest["base_scene"] = sweep.base_scene_path;
  manifest["command"] = sweep.command;
  manifest["options"] = sweep.options;
  manifest["combine"] = sweep.combine;
  manifest["summary_file"] = summary_file(sweep.command);
  std::error_code ec;
  manifest["skinfem"] = fs::read_symlink("/proc/self/exe", ec).string();
  manifest["skinfem_version"] = SKINFEM_VERSION;
  for (const SweepAxis& a : sweep.axes) {
    nlohmann::json values = nlohmann::json::array();
    for (const auto& v : a.values) values.push_back(nlohmann::json::parse(v));
    manifest["axes"].push_back({{"pointer", a.pointer}, {"column", a.column}, {"values", values}});
  }
  long mem_lo = 1L << 40, mem_hi = 0;
  for (const SweepMember& m : sweep.members) {
    const std::string scene_file = "scenes/" + m.id + ".json";
    // An existing member's scene is left alone (its name is its content), so its results stay up to date.
    if (!fs::exists(out_dir + "/" + scene_file)) write_text_atomic(out_dir + "/" + scene_file, m.scene_json);
    double dofs = 0;
    const long estimate = member_memory_mb(m.scene, dofs);
    const long mem = sweep.mem_mb > 0 ? sweep.mem_mb : estimate;
    mem_lo = std::min(mem_lo, mem), mem_hi = std::max(mem_hi, mem);
    nlohmann::json values = nlohmann::json::array();
    for (const auto& v : m.values) values.push_back(nlohmann::json::parse(v));
    manifest["members"].push_back({{"id", m.id},
                                   {"scene", scene_file},
                                   {"values", values},
                                   {"mem_mb", mem},
                                   {"estimated_mem_mb", estimate},
                                   {"estimated_dofs", dofs}});
  }
  write_json(out_dir + "/manifest.json", manifest);
  write_json(out_dir + "/run.json",
             {{"command", "sweep"}, {"spec", manifest["spec"]}, {"skinfem", SKINFEM_VERSION}});

  std::string shape;
  for (const SweepAxis& a : sweep.axes)
    shape += (shape.empty() ? "" : " x ") + std::to_string(a.values.size());
  std::string command = "skinfem " + sweep.command;
  for (const auto& w : sweep.options) command += " " + w;
  const std::string memory = (sweep.mem_mb > 0 ? "the spec's mem_mb " : "the mesh estimate ") +
                             std::to_string(mem_lo) + (mem_hi > mem_lo ? "-" + std::to_string(mem_hi) : "");
  std::printf("sweep %s: %zu member%s of `%s` (%s %s), %d already done; memory per job from %s MB\n",
              sweep.name.c_str(), sweep.members.size(), sweep.members.size() == 1 ? "" : "s", command.c_str(),
              sweep.combine.c_str(), shape.c_str(), members_done(sweep, out_dir), memory.c_str());

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
  progress("running: " + line);
  int stopped_by = 0;
  bool killed = false;
  // Snakemake can deadlock in its own handler of the signal we pass on: 30 s after it, it is killed.
  const int rc = run_child(argv, &stopped_by, 30, &killed);
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
        rc < 0 ? "could not start or was killed (is Debian's snakemake installed? scripts/setup installs it)"
               : "exited with code " + std::to_string(rc);
    std::fprintf(stderr,
                 "skinfem: sweep: Snakemake %s; the members' errors are in %s/members/*/status.json\n",
                 what.c_str(), out_dir.c_str());
    return 1;
  }
  return 0;
}

}  // namespace skinfem::app
