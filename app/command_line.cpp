#include "app/command_line.hpp"

#include <cmath>
#include <cstdlib>

namespace skinfem::app {
namespace {

// A number option's check: CLI11's PositiveNumber and NonNegativeNumber print DBL_MAX in 309 digits and call
// a subnormal "not in range". Says what the value is and what is allowed.
CLI::Validator number_check(OptionKind kind) {
  return CLI::Validator(
      [kind](std::string& text) -> std::string {
        char* end = nullptr;
        const double v = std::strtod(text.c_str(), &end);
        if (text.empty() || end != text.c_str() + text.size()) return text + ": must be a number";
        if (!std::isfinite(v)) return text + ": must be a finite number";
        if (kind == OptionKind::count && (v != std::floor(v) || v < 1 || v > 4096))
          return text + ": must be an integer in [1, 4096]";
        if ((kind == OptionKind::positive || kind == OptionKind::positive_list) && !(v > 0))
          return text + ": must be a number > 0";
        if (kind == OptionKind::nonnegative && v < 0) return text + ": must be a number >= 0";
        return "";
      },
      kind == OptionKind::numbers       ? "FINITE"
      : kind == OptionKind::count       ? "1..4096"
      : kind == OptionKind::nonnegative ? "NONNEGATIVE"
                                        : "POSITIVE");
}

double to_number(const std::string& text) { return std::strtod(text.c_str(), nullptr); }

std::vector<std::string> split(const std::string& list) {
  std::vector<std::string> words;
  for (std::size_t at = 0; !list.empty();) {
    const std::size_t comma = list.find(',', at);
    words.push_back(list.substr(at, comma - at));
    if (comma == std::string::npos) break;
    at = comma + 1;
  }
  return words;
}

}  // namespace

bool ParsedOptions::has(const std::string& name) const {
  return text_.count(name) || lists_.count(name) || flags_.count(name);
}
bool ParsedOptions::given(const std::string& name) const {
  return app_->count(positional_.count(name) ? name : option_flag(name)) > 0;
}
const std::string& ParsedOptions::text(const std::string& name) const { return text_.at(name); }
double ParsedOptions::number(const std::string& name) const {
  const std::string& t = text_.at(name);
  return t.empty() ? 0 : to_number(t);
}
std::vector<double> ParsedOptions::numbers(const std::string& name) const {
  std::vector<double> values;
  for (const std::string& t : lists_.at(name)) values.push_back(to_number(t));
  return values;
}
bool ParsedOptions::flag(const std::string& name) const { return flags_.at(name); }

CommandLine::CommandLine(CLI::App& cli) {
  for (const CommandSpec& c : commands()) {
    ParsedOptions& o = parsed_[c.name];
    o.app_ = cli.add_subcommand(c.name, c.help);
    std::map<std::string, CLI::Option*> added;
    for (const OptionSpec& spec : c.options) {
      const std::string flag = option_flag(spec.name);
      CLI::Option* option = nullptr;
      switch (spec.kind) {
        case OptionKind::flag:
          option = o.app_->add_flag(flag, o.flags_[spec.name] = false, spec.help);
          break;
        case OptionKind::numbers:
        case OptionKind::positive_list: {
          auto& list = o.lists_[spec.name] = split(spec.default_value);
          option = o.app_->add_option(flag, list, spec.help)->delimiter(',')->check(number_check(spec.kind));
          option->type_name("FLOAT");
          break;
        }
        case OptionKind::positional:
          option = o.app_->add_option(spec.name, o.text_[spec.name], spec.help)->required();
          o.positional_.insert(spec.name);
          break;
        default: {
          std::string& value = o.text_[spec.name] = spec.default_value;
          option = o.app_->add_option(flag, value, spec.help);
          if (spec.kind == OptionKind::choice) option->check(CLI::IsMember(spec.choices));
          if (spec.kind != OptionKind::choice && spec.kind != OptionKind::text)
            option->type_name(spec.kind == OptionKind::count ? "INT" : "FLOAT")
                ->check(number_check(spec.kind));
        }
      }
      if (!spec.default_value.empty()) option->capture_default_str();
      for (const std::string& other : spec.excludes) option->excludes(added.at(other));
      added[spec.name] = option;
    }
  }
}

const CommandSpec& CommandLine::command() const {
  for (const auto& [name, o] : parsed_)
    if (o.app_->parsed()) return command_named(name);
  throw std::logic_error("CommandLine::command before a command was parsed");
}

const ParsedOptions& CommandLine::options() const { return parsed_.at(command().name); }

}  // namespace skinfem::app
