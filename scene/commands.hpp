// skinfem's commands and their options, as one table: the command line (app/main.cpp) registers from it, a
// sweep spec's "command" and "options" are checked against it (scene/sweep.cpp), and a sweep's gather reads
// each command's summary file and plotted keys from it (through manifest.json). An option, a choice or a
// command is therefore spelled once, here; its code is the command's run_* function in app/.
#pragma once

#include <string>
#include <vector>

namespace skinfem {

enum class OptionKind {
  choice,         // one word of `choices`
  positive,       // a finite number > 0
  nonnegative,    // a finite number >= 0
  numbers,        // comma-separated numbers, checked by the command (mesh levels)
  positive_list,  // comma-separated finite numbers > 0
  flag,           // present or not
  count,          // an integer in [1, 4096]
  text,           // any word (a path, a profile)
  positional,     // a positional argument (the scene or sweep spec; invert: its signals file first), required
};

struct OptionSpec {
  std::string name;  // as a sweep spec writes it (error_scales); on the command line --error-scales
  OptionKind kind;
  std::string help;
  std::string default_value{};          // as command-line text; shown in --help; "" none
  std::vector<std::string> choices{};   // kind choice
  std::vector<std::string> excludes{};  // options it may not be given with
  bool in_sweeps = false;               // a sweep spec's "options" may set it
};

struct CommandSpec {
  std::string name, help;
  std::vector<OptionSpec> options;     // including the positional, --out and --max-dofs where it takes them
  bool in_sweeps = false;              // a sweep spec's "command" may name it
  std::string summary_file{};          // the file a sweep's table reads (commands in sweeps)
  std::vector<std::string> plotted{};  // keys of it a sweep plots; empty: the cost (dofs, wall_total_s)
};

// Every command, in the order `skinfem --help` lists them.
const std::vector<CommandSpec>& commands();
// The command of that name; throws std::out_of_range naming it.
const CommandSpec& command_named(const std::string& name);
// An option's command-line flag: "error_scales" -> "--error-scales".
std::string option_flag(const std::string& name);

}  // namespace skinfem
