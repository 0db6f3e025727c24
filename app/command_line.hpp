// The command line, registered from the command table (scene/commands.hpp): one subcommand per command, one
// option per row with its check, and what the user gave read back by the option's table name.
#pragma once

#include <CLI/CLI.hpp>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "skinfem/scene/commands.hpp"

namespace skinfem::app {

// One command's options as parsed, by their table names (error_scales, not --error-scales).
class ParsedOptions {
 public:
  bool has(const std::string& name) const;    // the command has this option
  bool given(const std::string& name) const;  // on the command line, not by default
  const std::string& text(const std::string& name) const;
  double number(const std::string& name) const;                // 0 when not given and without a default
  std::vector<double> numbers(const std::string& name) const;  // a list option's values
  bool flag(const std::string& name) const;

 private:
  friend class CommandLine;
  CLI::App* app_ = nullptr;
  std::map<std::string, std::string> text_;
  std::map<std::string, std::vector<std::string>> lists_;
  std::map<std::string, bool> flags_;
  std::set<std::string> positional_;  // named as such on the command line, not as --flags
};

class CommandLine {
 public:
  explicit CommandLine(CLI::App& cli);       // registers every command of the table on `cli`
  CommandLine(const CommandLine&) = delete;  // the parser holds pointers into the options
  CommandLine& operator=(const CommandLine&) = delete;
  // After cli.parse: the command given and its options.
  const CommandSpec& command() const;
  const ParsedOptions& options() const;

 private:
  std::map<std::string, ParsedOptions> parsed_;
};

}  // namespace skinfem::app
