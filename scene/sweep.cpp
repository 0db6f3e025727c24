// A sweep spec (JSON; units those of the scene: mm, N, MPa):
//   {"name": "k_vs_nu",                      optional; default the file's stem
//    "scene": "../scenes/flat_layer.json",   the base scene, relative to the spec's folder
//    "command": "kfit",                      kfit, green, contact, defect or report
//    "options": {"path": "meridian"},        optional; the command's options (below)
//    "combine": "grid",                      optional; grid (default) or zip
//    "mem_mb": 512,                          optional; each job's memory, MB (default: the mesh estimate)
//    "axes": [{"pointer": "/material/nu", "values": [0.45, 0.5]},
//             {"pointer": "/calibration/punch_diameter", "range": {"from": 0.25, "to": 1.0, "count": 4}}]}
// A range is {"from", "to", "count" >= 2} (evenly spaced, both ends in) or {"from", "to", "step" > 0} (from,
// from + step, ... up to `to`, never past it; a last value within 1e-9 step of `to` is `to`). No axis may lie
// inside another (/sensors/positions and /sensors/positions/0/0). Grid or zip, at most 10000 members. A
// relative geometry.path, in the base scene or as an axis value, names a file beside the base scene; a
// member's id hashes that file's bytes too, so editing it runs the member again.
// Options: the command's options marked in_sweeps in the command table (scene/commands.cpp), by their names
// there (error_scales for --error-scales), accepted as the command line accepts them: path (kfit, green,
// contact), load (kfit), grid (green: spacing > 0, mm; each member's kernel grid within green's point
// limits, app/cmd_sweep.cpp), friction (contact), error_scales (defect, report: at least two scales in
// (1, 4], strictly decreasing; not checked with no_error_bars, which ignores them) and no_error_bars,
// max_dofs (every command).
#include "skinfem/scene/sweep.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

#include "skinfem/scene/commands.hpp"
#include "skinfem/scene/json_text.hpp"
#include "skinfem/scene/load.hpp"
#include "skinfem/scene/parallel.hpp"

namespace skinfem {
namespace {

using json = nlohmann::json;
namespace fs = std::filesystem;

constexpr std::size_t kMaxMembers = 10000;

std::string show_value(const json& v) {
  std::string s = v.dump();
  return s.size() > 60 ? s.substr(0, 57) + "..." : s;
}

// FNV-1a, 64 bits: a stable short name for a member's content (not a security hash: the names only let a
// re-run recognise an unchanged member).
std::string content_id(const std::string& text) {
  std::uint64_t h = 14695981039346656037ull;
  for (unsigned char c : text) h = (h ^ c) * 1099511628211ull;
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return std::string(buf, 12);
}

// A relative geometry.path made absolute against `dir`, the base scene's folder: members live in another
// folder, and a relative axis value names a file beside the base scene as the base's own path does.
void absolute_surface(json& scene, const fs::path& dir) {
  if (!scene.contains("geometry") || !scene["geometry"].is_object()) return;
  json& g = scene["geometry"];
  if (!g.contains("path") || !g["path"].is_string()) return;
  const fs::path surface = g["path"].get<std::string>();
  if (surface.is_relative()) g["path"] = (dir / surface).lexically_normal().string();
}

// The FNV-1a digest of a file's bytes ("" when it cannot be read: the scene rules then refuse the member).
std::string file_digest(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return "";
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return content_id(bytes);
}

struct SpecReader {
  std::string file;
  [[noreturn]] void fail(const std::string& field, const json& v, const std::string& allowed) const {
    throw SceneError(file + ": " + field + " = " + show_value(v) + ": " + allowed);
  }
};

double number(const SpecReader& r, const json& v, const std::string& field) {
  if (!v.is_number() || !std::isfinite(v.get<double>())) r.fail(field, v, "must be a finite number");
  return v.get<double>();
}

std::string joined(const std::set<std::string>& words) {
  std::string list;
  for (const auto& w : words) list += (list.empty() ? "" : ", ") + w;
  return list;
}

std::string word(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

// The command's options as command-line words, each checked against what the command accepts (the command
// table, scene/commands.hpp).
std::vector<std::string> read_options(const SpecReader& r, const json& o, const CommandSpec& command) {
  std::map<std::string, const OptionSpec*> allowed;
  for (const OptionSpec& option : command.options)
    if (option.in_sweeps) allowed[option.name] = &option;
  if (!o.is_object()) r.fail("options", o, "must be an object of the command's options");
  std::vector<std::string> words;
  for (const auto& [key, v] : o.items()) {
    const std::string field = "options." + key;
    if (!allowed.count(key)) {
      std::set<std::string> names;
      for (const auto& entry : allowed) names.insert(entry.first);
      r.fail(field, v, "not an option of " + command.name + "; allowed: " + joined(names));
    }
    const OptionSpec& option = *allowed.at(key);
    const std::string flag = option_flag(key);
    if (option.kind == OptionKind::choice) {
      const std::set<std::string> choices(option.choices.begin(), option.choices.end());
      if (!v.is_string() || !choices.count(v.get<std::string>()))
        r.fail(field, v, "must be one of " + joined(choices));
      words.insert(words.end(), {flag, v.get<std::string>()});
    } else if (option.kind == OptionKind::flag) {
      if (!v.is_boolean()) r.fail(field, v, "must be true or false");
      if (v.get<bool>()) words.push_back(flag);
    } else if (option.kind == OptionKind::numbers) {  // error_scales
      // As `--error-scales` on the command line: at least two levels, each in (1, kMaxErrorScale], coarse
      // to fine (strictly decreasing, so no level twice); unchecked with no_error_bars, which ignores them.
      const std::string rule = "must be an array of at least two mesh scales in (1, " +
                               std::to_string(static_cast<int>(kMaxErrorScale)) +
                               "], strictly decreasing (coarse to fine)";
      if (!v.is_array() || v.empty()) r.fail(field, v, rule);
      const bool unchecked = o.contains("no_error_bars") && o["no_error_bars"] == true;
      std::string list;
      double previous = 0;
      for (const json& s : v) {
        const double x = number(r, s, field);
        if (!unchecked && (!(x > 1 && x <= kMaxErrorScale) || (!list.empty() && !(x < previous))))
          r.fail(field, v, rule);
        previous = x;
        list += (list.empty() ? "" : ",") + word(s.get<double>());
      }
      if (!unchecked && v.size() < 2) r.fail(field, v, rule);
      words.insert(words.end(), {flag, list});
    } else {  // grid (> 0) or max_dofs (>= 0)
      const double x = number(r, v, field);
      const bool positive = option.kind == OptionKind::positive;
      if (positive ? !(x > 0) : !(x >= 0))
        r.fail(field, v, positive ? "must be a spacing > 0 (mm)" : "must be a number >= 0");
      words.insert(words.end(), {flag, word(x)});
    }
  }
  return words;
}

std::vector<std::string> read_values(const SpecReader& r, const json& a, const std::string& P) {
  const bool has_values = a.contains("values"), has_range = a.contains("range");
  if (has_values == has_range) r.fail(P, a, "must have exactly one of \"values\" (a list) or \"range\"");
  std::vector<std::string> out;
  if (has_values) {
    const json& v = a["values"];
    if (!v.is_array() || v.empty()) r.fail(P + ".values", v, "must be a non-empty array");
    for (const json& x : v) out.push_back(x.dump());
    return out;
  }
  const json& g = a["range"];
  if (!g.is_object()) r.fail(P + ".range", g, "must be an object {\"from\", \"to\", \"count\" or \"step\"}");
  for (const auto& [key, v] : g.items())
    if (key != "from" && key != "to" && key != "count" && key != "step")
      r.fail(P + ".range." + key, v, "unknown key; allowed: from, to, count, step");
  if (!g.contains("from") || !g.contains("to") || g.contains("count") == g.contains("step"))
    r.fail(P + ".range", g, "must have \"from\", \"to\" and exactly one of \"count\" or \"step\"");
  const double from = number(r, g["from"], P + ".range.from"), to = number(r, g["to"], P + ".range.to");
  if (g.contains("count")) {
    const json& c = g["count"];
    if (!c.is_number_integer() || c.get<long long>() < 2 || c.get<long long>() > 10000)
      r.fail(P + ".range.count", c, "must be an integer in [2, 10000]");
    const long long n = c.get<long long>();
    for (long long i = 0; i < n; ++i)
      out.push_back(json(i == n - 1 ? to : from + (to - from) * double(i) / double(n - 1)).dump());
    return out;
  }
  const double step = number(r, g["step"], P + ".range.step");
  if (!(step > 0) || !(to > from) || (to - from) / step > 10000)
    r.fail(P + ".range", g, "a step range needs from < to and 0 < step, at most 10000 steps");
  const long long n = static_cast<long long>(std::floor((to - from) / step + 1e-9));
  for (long long i = 0; i <= n; ++i) {
    // from + i·step rounds: 0.1 + 2 × 0.1 is 0.30000000000000004, past `to`, a value the user never asked
    // for. A last value that close to `to` (either side) is `to` itself.
    double v = from + step * double(i);
    if (i == n && (v > to || to - v <= 1e-9 * step)) v = to;
    out.push_back(json(v).dump());
  }
  return out;
}

SweepAxis read_axis(const SpecReader& r, const json& a, const std::string& P, const json& base) {
  if (!a.is_object()) r.fail(P, a, "must be an object {\"pointer\", \"values\" or \"range\"}");
  for (const auto& [key, v] : a.items())
    if (key != "pointer" && key != "values" && key != "range")
      r.fail(P + "." + key, v, "unknown key; allowed: pointer, values, range");
  if (!a.contains("pointer") || !a["pointer"].is_string())
    r.fail(P + ".pointer", a.value("pointer", json()),
           "must be a JSON pointer string such as \"/material/nu\"");
  SweepAxis axis;
  axis.pointer = a["pointer"].get<std::string>();
  json::json_pointer ptr;
  try {
    ptr = json::json_pointer(axis.pointer);
  } catch (const json::exception&) {
    r.fail(P + ".pointer", a["pointer"], "must be a JSON pointer (\"/key/key\", RFC 6901)");
  }
  if (ptr.empty())
    r.fail(P + ".pointer", a["pointer"], "must name a key inside the scene, not the whole scene");
  // A key the base scene lacks is allowed where its parent exists (the scene rules then say whether it may
  // be there); a parent that does not exist is a misspelt pointer.
  const json::json_pointer parent = ptr.parent_pointer();
  if (!base.contains(ptr) && (!base.contains(parent) || !base[parent].is_object()))
    r.fail(P + ".pointer", a["pointer"],
           "names nothing in the base scene: " + (parent.empty() ? std::string("/") : parent.to_string()) +
               " is not an object there");
  for (json::json_pointer p = ptr; !p.empty(); p = p.parent_pointer())
    axis.column = p.back() + (axis.column.empty() ? "" : "." + axis.column);
  axis.values = read_values(r, a, P);
  return axis;
}

}  // namespace

Sweep load_sweep(const std::string& path) {
  const SpecReader r{path};
  const json spec = parse_json_text(read_text_file(path, "sweep spec"), path);
  if (!spec.is_object()) r.fail("(top level)", spec, "must be an object");
  static const std::set<std::string> keys{"name", "scene", "command", "options", "combine", "mem_mb", "axes"};
  for (const auto& [key, v] : spec.items())
    if (!keys.count(key))
      r.fail(key, v, "unknown key; allowed: name, scene, command, options, combine, mem_mb, axes");
  Sweep s;
  s.spec_path = path;
  s.name = spec.contains("name") && spec["name"].is_string() ? spec["name"].get<std::string>()
                                                             : fs::path(path).stem().string();
  // The name becomes the default output folder, out/<name>.
  if (!is_path_component(s.name) || (spec.contains("name") && !spec["name"].is_string()))
    r.fail(
        "name", spec.value("name", json(s.name)),
        std::string("must be ") + kNameRule + (spec.contains("name") ? "" : " (taken from the file name)"));
  if (!spec.contains("scene") || !spec["scene"].is_string())
    r.fail("scene", spec.value("scene", json()),
           "must be the base scene's file, relative to the spec's folder");
  const fs::path spec_dir = fs::absolute(path).parent_path();
  s.base_scene_path = fs::weakly_canonical(spec_dir / spec["scene"].get<std::string>()).string();
  std::set<std::string> commands;
  for (const CommandSpec& c : skinfem::commands())
    if (c.in_sweeps) commands.insert(c.name);
  if (!spec.contains("command") || !spec["command"].is_string() ||
      !commands.count(spec["command"].get<std::string>()))
    r.fail("command", spec.value("command", json()), "must be one of " + joined(commands));
  s.command = spec["command"].get<std::string>();
  if (spec.contains("options")) s.options = read_options(r, spec["options"], command_named(s.command));
  const json combine = spec.value("combine", json("grid"));
  if (combine != "grid" && combine != "zip") r.fail("combine", combine, "must be \"grid\" or \"zip\"");
  s.combine = combine.get<std::string>();

  if (spec.contains("mem_mb")) {
    const json& m = spec["mem_mb"];
    if (!m.is_number_integer() || m.get<long long>() < 1 || m.get<long long>() > 100000000)
      r.fail("mem_mb", m, "must be an integer number of MB in [1, 1e8]");
    s.mem_mb = m.get<long>();
  }

  json base = parse_json_text(read_text_file(s.base_scene_path, "base scene"), s.base_scene_path);
  if (!base.is_object()) throw SceneError(s.base_scene_path + ": (top level) must be an object");
  const fs::path base_dir = fs::path(s.base_scene_path).parent_path();
  absolute_surface(base, base_dir);
  if (!base.contains("name")) base["name"] = fs::path(s.base_scene_path).stem().string();

  const json& axes = spec.value("axes", json());
  if (!axes.is_array() || axes.empty()) r.fail("axes", axes, "must be a non-empty array of axes");
  std::set<std::string> pointers;
  for (std::size_t i = 0; i < axes.size(); ++i) {
    const std::string P = "axes[" + std::to_string(i) + "]";
    s.axes.push_back(read_axis(r, axes[i], P, base));
    if (!pointers.insert(s.axes.back().pointer).second)
      r.fail(P + ".pointer", axes[i]["pointer"], "is already an axis; each key may vary along one axis only");
    // An axis inside another's value would be overwritten by it, or overwrite part of it, and the table
    // would show a value that never ran.
    for (std::size_t j = 0; j < i; ++j) {
      const std::string &a = s.axes[j].pointer, &b = s.axes[i].pointer;
      const bool b_in_a = b.size() > a.size() && b.compare(0, a.size(), a) == 0 && b[a.size()] == '/';
      const bool a_in_b = a.size() > b.size() && a.compare(0, b.size(), b) == 0 && a[b.size()] == '/';
      if (b_in_a || a_in_b)
        r.fail(P + ".pointer", axes[i]["pointer"],
               std::string(b_in_a ? "lies inside" : "contains") + " axes[" + std::to_string(j) +
                   "].pointer " + a + "; one axis may not vary a key inside another's");
    }
  }

  // The members: every combination (the last axis fastest), or the i-th value of every axis.
  std::vector<std::vector<std::size_t>> picks;
  if (s.combine == "zip") {
    for (std::size_t i = 1; i < s.axes.size(); ++i)
      if (s.axes[i].values.size() != s.axes[0].values.size())
        r.fail("axes[" + std::to_string(i) + "]", axes[i],
               "has " + std::to_string(s.axes[i].values.size()) + " values, axes[0] has " +
                   std::to_string(s.axes[0].values.size()) + ": zipped axes need equal lengths");
    if (s.axes[0].values.size() > kMaxMembers)
      r.fail("axes", json(s.axes[0].values.size()),
             "the zipped axes have this many members; allowed at most " + std::to_string(kMaxMembers));
    for (std::size_t k = 0; k < s.axes[0].values.size(); ++k) picks.emplace_back(s.axes.size(), k);
  } else {
    double count = 1;
    for (const auto& a : s.axes) count *= double(a.values.size());
    if (count > kMaxMembers)
      r.fail("axes", json(count),
             "the grid has this many members; allowed at most " + std::to_string(kMaxMembers));
    std::vector<std::size_t> at(s.axes.size(), 0);
    for (std::size_t m = 0; m < std::size_t(count); ++m) {
      picks.push_back(at);
      for (std::size_t i = s.axes.size(); i-- > 0;) {
        if (++at[i] < s.axes[i].values.size()) break;
        at[i] = 0;
      }
    }
  }
  std::string options_text = s.command;
  for (const auto& w : s.options) options_text += " " + w;
  std::vector<json::json_pointer> where_ptr;
  std::vector<std::vector<json>> value_json(s.axes.size());
  for (std::size_t i = 0; i < s.axes.size(); ++i) {
    where_ptr.emplace_back(s.axes[i].pointer);
    for (const auto& v : s.axes[i].values) value_json[i].push_back(json::parse(v));
  }
  const auto where = [&](std::size_t m) {
    std::string w;
    for (std::size_t i = 0; i < s.axes.size(); ++i)
      w += (w.empty() ? "" : ", ") + s.axes[i].pointer + " = " + s.axes[i].values[picks[m][i]];
    return path + ": member " + std::to_string(m + 1) + " (" + w + "): ";
  };
  // Each member's scene is built and validated on its own (20-40 ms each with the scene rules): in parallel,
  // each into its own slot, so the order and the error reported (the first member's) are as in one thread.
  s.members.resize(picks.size());
  for_each_index(picks.size(), [&](std::size_t m) {
    json scene = base;
    SweepMember& member = s.members[m];
    for (std::size_t i = 0; i < s.axes.size(); ++i) {
      scene[where_ptr[i]] = value_json[i][picks[m][i]];
      member.values.push_back(s.axes[i].values[picks[m][i]]);
    }
    absolute_surface(scene, base_dir);
    member.scene_json = scene.dump(2) + "\n";
    try {
      member.scene = parse_scene(member.scene_json, s.base_scene_path);
    } catch (const SceneError& e) {
      throw SceneError(where(m) + e.what());
    }
  });
  // The id also hashes the files the scene names (an imported surface), so that editing one runs the members
  // again; a scene that names none keeps the id of its text alone.
  std::map<std::string, std::string> digests;
  std::set<std::string> ids;
  for (std::size_t m = 0; m < s.members.size(); ++m) {
    SweepMember& member = s.members[m];
    std::string files;
    if (member.scene.geometry.kind == GeometryKind::surface) {
      const std::string& file = member.scene.geometry.surface.path;
      auto it = digests.find(file);
      if (it == digests.end()) it = digests.emplace(file, file_digest(file)).first;
      files = "\nfile " + file + " " + it->second;
    }
    member.id = content_id(member.scene_json + options_text + files);
    if (!ids.insert(member.id).second)
      throw SceneError(where(m) + "the same scene as an earlier member; every member must differ");
  }
  return s;
}

}  // namespace skinfem
