// Scene files: JSON → Scene, with validation. The only JSON reader in skinfem.
//
// Format (units mm, N, MPa; keys marked * are optional, defaults from scene.hpp):
//   name*         string; default: the file stem. One file name (the report's folder out/<name>): 1 to 100
//                 letters, digits, space and . _ - + ( ), not starting with '.', '-' or a space
//   geometry      {"type": "cap", "R", "R_y"*, "h", "apex": [x, y], "truncation_radius", "side"*}
//                 R_y: the apex radius of curvature along y (default R: spherical; else an ellipsoid)
//               | {"type": "flat", "h", "half_width", "side"*}
//                 cap and flat: "ridges"*: {"period", "height" (crest to trough, < h), "angle_deg"* (0:
//                 crests along y), "center": [x, y], "radius" (>= 2 periods), "h"* (mesh size, at most
//                 period/3, default period/6), "profile"*: "sinusoidal" (default) | "rectangular",
//                 "edge_width"* (rectangular only: wall width in (0, period/2], default period/4)}
//                 (scene.hpp's Ridges)
//               | {"type": "surface", "path", "side"*}      path: .stl/.obj/.off, relative to the scene file
//                 side: "free" (default) | "fixed"
//   material      {"E", "nu", "model"*: "linear" (default) | "neo_hookean" (finite strain, incompressible:
//                  nu must be 0.5)}
//   sensors       {"positions": [[x, y], ...]} or {"line": {"start": [x, y], "step": [dx, dy], "count"}},
//                 plus "model"*: "disc" (default, with "disc_diameter") | "post" with "post"*: {"diameter"*
//                 (0.2), "height"* (0.4, below the skin's top), "support"*: "rigid" (default) | {"k_normal"
//                 (N/mm), "k_tangential" (N/mm), "k_tilt" (N mm/rad)}: the membrane's springs} (flat and cap
//                 skins)
//   mesh          {"h_min", "growth", "h_max", "refine_sensors"*, "sensor_h"*, "min_dihedral_deg"*,
//                  "max_radius_edge"*, "regions"*: [{"from": [x, y], "to": [x, y], "radius", "h"*}]}
//                 sensor_h: <mm, in (0, h_min]>, size at each sensor disc on the base (default min(h_min,
//                 disc radius); around a post, up to its top, min(h_min, 0.6 × its radius))
//   loads*        {"punches"*: [{"center", "diameter", "force" | "displacement"}],
//                  "patches"*: [{"center", "diameter", "direction": [x, y, z], "force"}]}
//   calibration*  {"punch_diameter"*, "scan_half_width"*, "spacing"*}
//   symmetry*     "auto" (default): mesh only the half y >= 0 where the scene is mirror-symmetric about y = 0
//                 and the command supports it (pipeline/symmetry.hpp) | "none": always the whole skin
//   contact*      {"indenter": {"type": "plane"} | {"type": "sphere", "R": <mm, > 0>, "center": [x, y]},
//                  "force": <N> | "depth": <mm>,     exactly one: total normal force (1e-9 to 1e6 N, as every
//                                                    force), or rigid approach from first touch (> 0)
//                  "holes"*: [{"center": [x, y], "diameter": <mm, > 0>,  discs where the indenter is absent
//                              "depth"*: <mm, > 0> (default 0.5, the paper's 500 um),
//                              "h"*: <mm, > 0>}],  mesh size over the disc (absent: the zone's h)
//                  "zone_radius"*: <mm, > 0>,        candidate contact zone about the first touch; absent:
//                                                    1.25 x Hertz's radius under a force, 1.25 x twice
//                                                    Hertz's sqrt(R delta) at a depth (scene.hpp)
//                  "h"*: <mm, > 0>,                  mesh size inside the zone; absent: mesh.h_min
//                  "friction"*: {"mode"*: "none" (default) | "static" | "uncoupled" | "coupled",
//                                "mu"*: >= 0 (default 0; 0 allowed with every mode),
//                                "law"*: "coulomb" (default: p_t = mu p) | "shear_strength" (p_t = tau0
//                                        where the skin touches) | "mixed" (p_t = tau0 + mu p),
//                                "tau0"*: <MPa, in [0, 1e6]> | "from_force" (default: mu F / the
//                                         frictionless contact area); shear_strength and mixed only,
//                                "static_ratio"*: in [0, mu] (default 0; used by "static": at rest the
//                                                 plate keeps static_ratio/mu of the sliding traction),
//                                "direction"*: [dx, dy] non-zero, normalised (default [1, 0])},
//                  "interface"*: {"law": "hard" (default: no interpenetration) | "linear" (a rough
//                                 interface closing by p/K) | "exponential" (p = p_ref exp(-gap/u0)),
//                                 "K": <MPa/mm, in (0, 1e12]> (linear only),
//                                 "u0": <mm, in (0, 1]>, "p_ref": <MPa, in (0, 1e6]> (exponential only)},
//                  "sweep"*: {"from": [x, y], "to": [x, y],  a hole swept for `skinfem defect`
//                             "positions"*: integer in [2, 100000] (default 201),
//                             "hole_diameter"*: > 0 (default 0.5),
//                             "hole_depth"*: > 0 (default 0.5),
//                             "h"*: > 0, mesh size along the path (absent: no refinement),
//                             "hole_model"*: "bulge" (default under a hard interface: the small
//                                            hole's bulge, seen by the contact as a dimple of the
//                                            indenter) | "resolved" (the hole's disc cuts the
//                                            multipliers' hats; the default under any other)},
//                  "texture"*: {"holes"*: [{"center": [x, y], "diameter", "depth"*}],  holes of a plate
//                               "lattice"*: {"origin": [x, y], "period": [px, py],   scanned by `skinfem
//                                            "count": [nx, ny], "diameter", "depth"*},   scan`, on the
//                               "random"*: {"from": [x, y], "to": [x, y],             plate at u = 0,
//                                           "density": <holes/mm^2>, "diameter": [min, max],
//                                           "depth"*, "seed"*: integer >= 0 (default 1),
//                                           "mirror"*: true: in pairs mirrored about y = 0},
//                               "h"*: > 0, mesh size along their tracks (absent: the zone's)},
//                  "scan"*: {"from": <mm>, "to": <mm>, "step": <mm, > 0>}}  the plate's displacement
//                                                    along the sliding direction; with "texture" only
//                 A plane needs a cap: it first touches at the apex (on a flat layer it touches everywhere at
//                 once; an imported surface has no known apex). A sphere fits any geometry. On a cap or flat
//                 layer, the sphere's centre, every hole disc and the swept hole at both ends of its path
//                 must lie on the skin's footprint (cap: within truncation_radius of the apex; flat: |x|, |y|
//                 <= half_width), and the candidate zone disc at least one skin thickness h (cap: h at the
//                 apex) inside the footprint's edge, the truncated side. Not checked on an imported surface.
// Unknown keys, duplicate keys, wrong types, missing required keys and out-of-range values are errors.
// Every error is a SceneError whose what() is one line: "<file>: <json.path> = <value>: <what is allowed>".
#include "skinfem/scene/load.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "skinfem/scene/json_text.hpp"
#include "skinfem/scene/laws.hpp"
#include "skinfem/scene/texture.hpp"

namespace skinfem {
namespace {

using json = nlohmann::json;
namespace fs = std::filesystem;

std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

std::string fmt(const Vec2& p) { return "(" + fmt(p[0]) + ", " + fmt(p[1]) + ")"; }

std::string one_line(std::string s) {
  for (char& c : s)
    if (c == '\n' || c == '\r') c = ' ';
  return s;
}

std::string join(const std::vector<std::string>& words) {
  std::string out;
  for (const auto& w : words) out += (out.empty() ? "" : ", ") + w;
  return out;
}

std::string sub(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "." + key;
}
std::string at(const std::string& path, std::size_t i) { return path + "[" + std::to_string(i) + "]"; }

// Compact rendering of a JSON value for messages. dump() would print non-finite numbers as null.
std::string show(const json& v) {
  if (v.is_number_float() && !std::isfinite(v.get<double>())) {
    const double d = v.get<double>();
    return std::isnan(d) ? "nan" : (d > 0 ? "inf" : "-inf");
  }
  std::string s = v.dump(-1, ' ', false, json::error_handler_t::replace);
  if (s.size() > 80) s = s.substr(0, 77) + "...";
  return s;
}

// An allowed range of a number: a predicate and its description ("a number > 0").
struct Rule {
  std::string desc;
  std::function<bool(double)> ok;
};
// Lengths (mm) and forces (N) are bounded so that every derived number stays far from overflow: 10 m and
// 1 MN are beyond any tactile skin. Forces also from below, so that the loads and the pressures the solvers
// scale stay normal doubles (a subnormal contact force reached the contact solver as 0): 1 nN is far below
// any tactile sensor's resolution.
constexpr double kMaxLength = 1e4, kMinForce = 1e-9, kMaxForce = 1e6;
Rule length() {
  return {"a length in (0, " + fmt(kMaxLength) + "] mm", [](double x) { return x > 0 && x <= kMaxLength; }};
}
Rule force_rule() {
  return {"a force in [" + fmt(kMinForce) + ", " + fmt(kMaxForce) + "] N",
          [](double x) { return x >= kMinForce && x <= kMaxForce; }};
}
Rule non_negative() {
  return {"a number >= 0", [](double x) { return x >= 0; }};
}
Rule at_least(double lo, const std::string& what = "") {
  return {"a number >= " + (what.empty() ? fmt(lo) : what), [lo](double x) { return x >= lo; }};
}
Rule greater(double lo) {
  return {"a number > " + fmt(lo), [lo](double x) { return x > lo; }};
}
Rule closed_interval(double lo, double hi) {
  return {"a number in [" + fmt(lo) + ", " + fmt(hi) + "]",
          [lo, hi](double x) { return lo <= x && x <= hi; }};
}
Rule half_open_interval(double lo, double hi, const std::string& hi_name) {
  return {"a number in (" + fmt(lo) + ", " + hi_name + "]", [lo, hi](double x) { return lo < x && x <= hi; }};
}
Rule open_interval(double lo, double hi) {
  return {"a number in (" + fmt(lo) + ", " + fmt(hi) + ")", [lo, hi](double x) { return lo < x && x < hi; }};
}

// Reads typed values out of the JSON tree; every failure throws a one-line SceneError.
class Reader {
 public:
  explicit Reader(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void fail(const std::string& path, const json& v, const std::string& allowed) const {
    throw SceneError(one_line(file_ + ": " + label(path) + " = " + show(v) + ": " + allowed));
  }
  [[noreturn]] void fail(const std::string& path, const std::string& msg) const {
    throw SceneError(one_line(file_ + ": " + label(path) + ": " + msg));
  }
  // A problem with the file as a whole (JSON syntax): "<file>: <msg>".
  [[noreturn]] void fail_file(const std::string& msg) const {
    throw SceneError(one_line(file_ + ": " + msg));
  }

  // `v` must be an object whose keys are all in `allowed`.
  void object(const json& v, const std::string& path, const std::vector<std::string>& allowed) const {
    if (!v.is_object()) fail(path, v, "must be an object with keys " + join(allowed));
    for (auto it = v.begin(); it != v.end(); ++it)
      if (std::find(allowed.begin(), allowed.end(), it.key()) == allowed.end())
        fail(sub(path, it.key()), "unknown key; allowed: " + join(allowed));
  }

  // obj[key], which must be present; `desc` says what it must be.
  const json& need(const json& obj, const std::string& path, const std::string& key,
                   const std::string& desc) const {
    const auto it = obj.find(key);
    if (it == obj.end()) fail(sub(path, key), "required key is missing; must be " + desc);
    return *it;
  }
  static const json* find(const json& obj, const std::string& key) {
    const auto it = obj.find(key);
    return it == obj.end() ? nullptr : &*it;
  }

  double number(const json& v, const std::string& path, const Rule& rule) const {
    if (!v.is_number()) fail(path, v, "must be " + rule.desc);
    const double d = v.get<double>();
    if (!std::isfinite(d)) fail(path, v, "must be finite, " + rule.desc);
    if (!rule.ok(d)) fail(path, v, "must be " + rule.desc);
    return d;
  }
  double number(const json& obj, const std::string& path, const std::string& key, const Rule& rule) const {
    return number(need(obj, path, key, rule.desc), sub(path, key), rule);
  }
  double number_or(const json& obj, const std::string& path, const std::string& key, double fallback,
                   const Rule& rule) const {
    const json* v = find(obj, key);
    return v ? number(*v, sub(path, key), rule) : fallback;
  }

  long long integer(const json& v, const std::string& path, long long lo, long long hi) const {
    const std::string desc = "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
    if (!v.is_number_integer()) fail(path, v, "must be " + desc);
    const double d = v.get<double>();
    if (d < static_cast<double>(lo) || d > static_cast<double>(hi)) fail(path, v, "must be " + desc);
    return v.get<long long>();
  }

  bool boolean(const json& v, const std::string& path) const {
    if (!v.is_boolean()) fail(path, v, "must be true or false");
    return v.get<bool>();
  }

  std::string string(const json& v, const std::string& path, const std::string& desc) const {
    if (!v.is_string() || v.get<std::string>().empty()) fail(path, v, "must be " + desc);
    return v.get<std::string>();
  }

  template <std::size_t N>
  std::array<double, N> vec(const json& v, const std::string& path) const {
    const std::string desc =
        N == 2 ? "a point [x, y] of 2 finite numbers" : "a vector [x, y, z] of 3 finite numbers";
    if (!v.is_array() || v.size() != N) fail(path, v, "must be " + desc);
    std::array<double, N> out{};
    for (std::size_t i = 0; i < N; ++i) {
      if (!v[i].is_number() || !std::isfinite(v[i].get<double>())) fail(path, v, "must be " + desc);
      out[i] = v[i].get<double>();
    }
    return out;
  }
  Vec2 vec2(const json& obj, const std::string& path, const std::string& key) const {
    return vec<2>(need(obj, path, key, "a point [x, y]"), sub(path, key));
  }

  const json& array(const json& obj, const std::string& path, const std::string& key,
                    const std::string& desc) const {
    const json& v = need(obj, path, key, desc);
    if (!v.is_array()) fail(sub(path, key), v, "must be " + desc);
    return v;
  }

 private:
  static std::string label(const std::string& path) { return path.empty() ? "(top level)" : path; }
  std::string file_;
};

// Parses JSON text, rejecting duplicate keys (which nlohmann would silently resolve to the last one) and
// nesting deeper than kMaxJsonDepth.
constexpr std::size_t kMaxJsonDepth = 32;
json parse_json(const std::string& text, const Reader& r) {
  struct Frame {
    bool object;
    std::string path;
    std::set<std::string> keys;
    std::string key;
    std::size_t index = 0;
  };
  std::vector<Frame> stack;
  const auto child_path = [&]() -> std::string {
    if (stack.empty()) return "";
    const Frame& f = stack.back();
    return f.object ? sub(f.path, f.key) : at(f.path, f.index);
  };
  const auto child_done = [&]() {
    if (!stack.empty() && !stack.back().object) ++stack.back().index;
  };
  const json::parser_callback_t callback = [&](int, json::parse_event_t event, json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start:
      case json::parse_event_t::array_start:
        // Each level keeps its path: an unbounded depth would cost memory as its square.
        if (stack.size() >= kMaxJsonDepth)
          r.fail(child_path(), "nested deeper than " + std::to_string(kMaxJsonDepth) +
                                   " levels; a scene needs a few (untrusted or generated input?)");
        stack.push_back({event == json::parse_event_t::object_start, child_path(), {}, {}, 0});
        break;
      case json::parse_event_t::key: {
        Frame& f = stack.back();
        std::string k = parsed.get<std::string>();
        if (!f.keys.insert(k).second)
          r.fail(sub(f.path, k), "duplicate key; each key may appear only once in an object");
        f.key = std::move(k);
        break;
      }
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        stack.pop_back();
        child_done();
        break;
      case json::parse_event_t::value:
        child_done();
        break;
    }
    return true;
  };
  try {
    return json::parse(text, callback);
  } catch (const json::parse_error& e) {
    std::string what = e.what();  // "[json.exception.parse_error.101] parse error at line L, column C: ..."
    const auto close = what.find("] ");
    if (close != std::string::npos) what = what.substr(close + 2);
    r.fail_file("invalid JSON: " + what + " (byte " + std::to_string(e.byte) + ")");
  } catch (const json::exception& e) {  // e.g. out_of_range.406: a number too large for a double
    std::string what = e.what();
    const auto close = what.find("] ");
    if (close != std::string::npos) what = what.substr(close + 2);
    r.fail_file("invalid JSON: " + what + "; numbers must be finite doubles");
  }
}

std::string off_footprint(const Geometry& g, const Vec2& p, double rad, const std::string& rad_name);
json point(const Vec2& p);

// Ridges on a cap or flat layer (scene.hpp's Ridges); `thickness` is the layer's h (the apex's for a cap).
Ridges read_ridges(const Reader& r, const json& j, const std::string& P, const Geometry& geo,
                   double thickness) {
  if (!j.is_object()) r.fail(P, j, R"(must be an object {"period", "height", "center", "radius", ...})");
  r.object(j, P, {"period", "height", "angle_deg", "center", "radius", "h", "profile", "edge_width"});
  Ridges out;
  if (const json* profile = Reader::find(j, "profile")) {
    if (*profile == "rectangular")
      out.profile = RidgeProfile::rectangular;
    else if (*profile != "sinusoidal")
      r.fail(sub(P, "profile"), *profile, R"(must be "sinusoidal" or "rectangular")");
  }
  out.period = r.number(j, P, "period", length());
  if (out.profile == RidgeProfile::rectangular)
    out.edge_width = r.number_or(j, P, "edge_width", out.period / 4,
                                 half_open_interval(0, out.period / 2, "period/2 = " + fmt(out.period / 2)));
  else if (const json* e = Reader::find(j, "edge_width"))
    r.fail(sub(P, "edge_width"), *e, R"(is only for "profile": "rectangular")");
  out.height = r.number(j, P, "height", open_interval(0, thickness));
  out.angle_deg = r.number_or(j, P, "angle_deg", 0.0, closed_interval(-360, 360));
  out.center = r.vec2(j, P, "center");
  out.radius = r.number(j, P, "radius", at_least(2 * out.period, "2 x period = " + fmt(2 * out.period)));
  // Three elements per period at least (the ridge study's coarsest level): a coarser mesh cannot hold the
  // profile (its P2 top would alias it) and the volume check would not notice.
  out.h = r.number_or(j, P, "h", 0.0,
                      half_open_interval(0, out.period / 3, "period/3 = " + fmt(out.period / 3) + " mm"));
  const std::string off = off_footprint(geo, out.center, out.radius, "radius");
  if (!off.empty())
    r.fail(sub(P, "center"), point(out.center), "the patterned disc must lie on the skin; " + off);
  return out;
}

Geometry read_geometry(const Reader& r, const json& g, const fs::path& base_dir) {
  const std::string P = "geometry";
  const std::string kinds = R"(one of "cap", "flat", "surface")";
  if (!g.is_object()) r.fail(P, g, "must be an object with \"type\" " + kinds);
  const json& type = r.need(g, P, "type", kinds);
  if (!type.is_string()) r.fail(sub(P, "type"), type, "must be " + kinds);
  const std::string t = type.get<std::string>();

  Geometry geo;
  if (t == "cap") {
    r.object(g, P, {"type", "R", "R_y", "h", "apex", "truncation_radius", "side", "ridges"});
    CapGeometry& c = geo.cap;
    geo.kind = GeometryKind::cap;
    c.R = r.number(g, P, "R", length());
    c.R_y = r.number_or(g, P, "R_y", 0.0, length());
    const double zc = c.semi_axis_z();
    const std::string semi =
        c.spherical() ? "(0, R)"
                      : "(0, sqrt(R R_y)), the ellipsoid's vertical semi-axis: (0, " + fmt(zc) + ")";
    c.h = r.number(g, P, "h",
                   Rule{"a number in " + (c.spherical() ? "(0, R) = (0, " + fmt(c.R) + ")" : semi),
                        [zc](double x) { return 0 < x && x < zc; }});
    const Vec2 apex = r.vec2(g, P, "apex");
    c.apex_x = apex[0];
    c.apex_y = apex[1];
    const double rim = c.rim_radius();
    c.truncation_radius = r.number(
        g, P, "truncation_radius",
        Rule{"a number > 0 and < " + fmt(rim) +
                 (c.spherical()
                      ? ", the radius sqrt(R^2 - (R - h)^2) where the cap thins to zero (R = " + fmt(c.R)
                      : ", the distance from the apex at which the ellipsoidal cap first thins to zero "
                        "(R = " +
                            fmt(c.R) + ", R_y = " + fmt(c.R_y)) +
                 ", h = " + fmt(c.h) + ")",
             [rim](double x) { return x > 0 && x < rim; }});
  } else if (t == "flat") {
    r.object(g, P, {"type", "h", "half_width", "side", "ridges"});
    geo.kind = GeometryKind::flat;
    geo.flat.h = r.number(g, P, "h", length());
    geo.flat.half_width = r.number(g, P, "half_width", length());
  } else if (t == "surface") {
    r.object(g, P, {"type", "path", "side"});
    geo.kind = GeometryKind::surface;
    const std::string desc = "a path to a .stl, .obj or .off file (relative to the scene file)";
    const json& v = r.need(g, P, "path", desc);
    const fs::path file = r.string(v, sub(P, "path"), desc);
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char ch) { return std::tolower(ch); });
    if (ext != ".stl" && ext != ".obj" && ext != ".off")
      r.fail(sub(P, "path"), v, "must be a .stl, .obj or .off file");
    const fs::path resolved = fs::absolute(file.is_absolute() ? file : base_dir / file).lexically_normal();
    std::error_code ec;
    if (!fs::is_regular_file(resolved, ec))
      r.fail(sub(P, "path"), v, "must name an existing file; not found: " + resolved.string());
    geo.surface.path = resolved.string();
  } else {
    r.fail(sub(P, "type"), type, "must be " + kinds);
  }
  if (const json* ridges = Reader::find(g, "ridges"))
    geo.ridges = read_ridges(r, *ridges, sub(P, "ridges"), geo, t == "cap" ? geo.cap.h : geo.flat.h);

  if (const json* side = Reader::find(g, "side")) {
    if (*side == "free")
      geo.side = SideCondition::free;
    else if (*side == "fixed")
      geo.side = SideCondition::fixed;
    else
      r.fail(sub(P, "side"), *side, R"(must be "free" or "fixed")");
  }
  return geo;
}

Material read_material(const Reader& r, const json& m) {
  const std::string P = "material";
  r.object(m, P, {"E", "nu", "model"});
  Material mat;
  mat.E = r.number(m, P, "E",
                   Rule{"a Young's modulus in (0, 1e12] MPa", [](double x) { return x > 0 && x <= 1e12; }});
  mat.nu = r.number(m, P, "nu", closed_interval(0, 0.5));
  if (const json* model = Reader::find(m, "model")) {
    const std::vector<std::string> names{to_string(MaterialModel::linear),
                                         to_string(MaterialModel::neo_hookean)};
    if (*model == names[0]) {
      mat.model = MaterialModel::linear;
    } else if (*model == names[1]) {
      mat.model = MaterialModel::neo_hookean;
      if (mat.nu != 0.5)
        r.fail(sub(P, "nu"), m.at("nu"),
               "must be 0.5 with \"model\": \"neo_hookean\" (the incompressible neo-Hookean solid; a "
               "compressible "
               "one is not modelled)");
    } else {
      r.fail(sub(P, "model"), *model, "must be one of " + choice_list(names));
    }
  }
  return mat;
}

// Sensors, each with the JSON path that names it in messages.
struct SensorSource {
  std::string path;
  Vec2 p;
};

Sensors read_sensors(const Reader& r, const json& s, std::vector<SensorSource>& sources) {
  const std::string P = "sensors";
  r.object(s, P, {"positions", "line", "disc_diameter", "model", "post"});
  Sensors out;
  if (const json* model = Reader::find(s, "model")) {
    if (*model == "post")
      out.model = SensorModel::post;
    else if (*model != "disc")
      r.fail(sub(P, "model"), *model, R"(must be "disc" or "post")");
  }
  if (const json* post = Reader::find(s, "post")) {
    const std::string PP = sub(P, "post");
    if (out.model != SensorModel::post) r.fail(PP, *post, R"(is only for "model": "post")");
    if (!post->is_object()) r.fail(PP, *post, R"(must be an object {"diameter", "height", "support"})");
    r.object(*post, PP, {"diameter", "height", "support"});
    out.post.diameter = r.number_or(*post, PP, "diameter", out.post.diameter, length());
    out.post.height = r.number_or(*post, PP, "height", out.post.height, length());
    if (const json* support = Reader::find(*post, "support"); support && *support != "rigid") {
      const std::string PS = sub(PP, "support");
      if (!support->is_object())
        r.fail(PS, *support,
               R"(must be "rigid" or the membrane's springs {"k_normal", "k_tangential", "k_tilt"})");
      r.object(*support, PS, {"k_normal", "k_tangential", "k_tilt"});
      // Stiffnesses from 1e-6 to 1e9 N/mm: a silicon membrane's are about 1e2–1e4 N/mm (docs/posts.md).
      const auto stiffness = [](const std::string& unit) {
        return Rule{"a stiffness in [1e-06, 1e+09] " + unit, [](double x) { return x >= 1e-6 && x <= 1e9; }};
      };
      MembraneSprings& k = out.post.support;
      k.k_normal = r.number(*support, PS, "k_normal", stiffness("N/mm"));
      k.k_tangential = r.number(*support, PS, "k_tangential", stiffness("N/mm"));
      k.k_tilt = r.number(*support, PS, "k_tilt", stiffness("N mm/rad"));
    }
  }
  const json* positions = Reader::find(s, "positions");
  const json* line = Reader::find(s, "line");
  if ((positions != nullptr) == (line != nullptr))
    r.fail(P, s,
           R"(must have exactly one of "positions" ([[x, y], ...]) or "line" ({"start", "step", "count"}))");
  if (out.model == SensorModel::disc)
    out.disc_diameter = r.number(s, P, "disc_diameter", length());
  else if (const json* d = Reader::find(s, "disc_diameter"))
    r.fail(sub(P, "disc_diameter"), *d,
           R"(is only for "model": "disc" (a post's diameter is post.diameter))");

  if (positions) {
    const std::string PP = sub(P, "positions");
    if (!positions->is_array() || positions->empty())
      r.fail(PP, *positions, "must be a non-empty array of points [x, y]");
    for (std::size_t i = 0; i < positions->size(); ++i) {
      const Vec2 p = r.vec<2>((*positions)[i], at(PP, i));
      out.positions.push_back(p);
      sources.push_back({at(PP, i), p});
    }
  } else {
    const std::string PL = sub(P, "line");
    r.object(*line, PL, {"start", "step", "count"});
    const Vec2 start = r.vec2(*line, PL, "start");
    const Vec2 step = r.vec2(*line, PL, "step");
    const long long count =
        r.integer(r.need(*line, PL, "count", "an integer >= 1"), sub(PL, "count"), 1, 100000);
    for (long long i = 0; i < count; ++i) {
      const Vec2 p{start[0] + static_cast<double>(i) * step[0], start[1] + static_cast<double>(i) * step[1]};
      out.positions.push_back(p);
      sources.push_back({PL + " (sensor " + std::to_string(i + 1) + " of " + std::to_string(count) + ")", p});
    }
  }
  // Two sensors in one place read the same thing twice; a scene that does so is mistyped.
  for (std::size_t i = 0; i < sources.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (std::hypot(sources[i].p[0] - sources[j].p[0], sources[i].p[1] - sources[j].p[1]) < 1e-9)
        r.fail(sources[i].path, json::array({sources[i].p[0], sources[i].p[1]}),
               "a sensor in the same place as " + sources[j].path + "; sensors must be distinct");
  return out;
}

// Every sensor disc must lie inside the skin's footprint on the base (not checked for imported surfaces).
void check_sensor_footprint(const Reader& r, const Geometry& geo, const Sensors& sensors,
                            const std::vector<SensorSource>& sources) {
  const double rad = sensors.footprint_radius();
  const bool post = sensors.model == SensorModel::post;
  const std::string what = post ? "post (diameter " + fmt(sensors.post.diameter) + ")"
                                : "sensor disc (diameter " + fmt(sensors.disc_diameter) + ")";
  const std::string diameter = post ? "post.diameter" : "disc_diameter";
  if (post && geo.kind == GeometryKind::surface)
    r.fail("sensors.model", "post",
           "needs a generated skin (geometry type flat or cap), not an imported surface");
  const auto beyond = [](double value, double limit) { return value > limit + 1e-9 * std::max(1.0, limit); };
  for (const SensorSource& s : sources) {
    const json shown = json::array({s.p[0], s.p[1]});
    if (geo.kind == GeometryKind::cap) {
      const CapGeometry& c = geo.cap;
      const double dist = std::hypot(s.p[0] - c.apex_x, s.p[1] - c.apex_y);
      if (beyond(dist + rad, c.truncation_radius))
        r.fail(s.path, shown,
               what + " must lie inside the cap footprint: centre at most truncation_radius - " + diameter +
                   "/2 = " + fmt(c.truncation_radius - rad) + " from the apex " +
                   fmt(Vec2{c.apex_x, c.apex_y}) + ", got " + fmt(dist));
    } else if (geo.kind == GeometryKind::flat) {
      const double hw = geo.flat.half_width;
      if (beyond(std::abs(s.p[0]) + rad, hw) || beyond(std::abs(s.p[1]) + rad, hw))
        r.fail(s.path, shown,
               what + " must lie inside the flat layer: |x|, |y| <= half_width - " + diameter +
                   "/2 = " + fmt(hw - rad));
    }
    if (post) {
      // The post stands inside the skin: its top below the skin's lowest top over its cross-section (a cap's
      // ellipsoid, less any ridges' full height).
      double lowest = geo.kind == GeometryKind::flat ? geo.flat.h : geo.cap.h;
      if (geo.kind == GeometryKind::cap) {
        const CapGeometry& c = geo.cap;
        const double a = c.semi_axis_x(), b = c.semi_axis_y(), cz = c.semi_axis_z();
        for (int k = 0; k < 16; ++k) {
          const double dx = s.p[0] + rad * std::cos(M_PI * k / 8) - c.apex_x,
                       dy = s.p[1] + rad * std::sin(M_PI * k / 8) - c.apex_y;
          lowest = std::min(
              lowest,
              c.h - cz + cz * std::sqrt(std::max(0.0, 1 - (dx / a) * (dx / a) - (dy / b) * (dy / b))));
        }
      }
      if (geo.ridges.present()) lowest -= geo.ridges.height;
      if (!(sensors.post.height < 0.9 * lowest))
        r.fail("sensors.post.height", sensors.post.height,
               "must be below 0.9 x the skin's thickness over the post at " + s.path + " (" +
                   fmt(0.9 * lowest) + " mm)");
    }
  }
  // Posts are solid: two may not overlap.
  if (post)
    for (std::size_t i = 0; i < sources.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        if (std::hypot(sources[i].p[0] - sources[j].p[0], sources[i].p[1] - sources[j].p[1]) <
            sensors.post.diameter * 1.5)
          r.fail(sources[i].path, json::array({sources[i].p[0], sources[i].p[1]}),
                 "post closer than 1.5 post diameters (" + fmt(1.5 * sensors.post.diameter) + " mm) to " +
                     sources[j].path);
}

MeshControls read_mesh(const Reader& r, const json& m) {
  const std::string P = "mesh";
  r.object(m, P,
           {"h_min", "growth", "h_max", "refine_sensors", "sensor_h", "min_dihedral_deg", "max_radius_edge",
            "regions"});
  MeshControls mc;
  mc.h_min = r.number(m, P, "h_min", length());
  mc.growth = r.number(m, P, "growth", greater(1));
  mc.h_max = r.number(m, P, "h_max", at_least(mc.h_min, "mesh.h_min = " + fmt(mc.h_min)));
  if (const json* v = Reader::find(m, "refine_sensors"))
    mc.refine_sensors = r.boolean(*v, sub(P, "refine_sensors"));
  mc.sensor_h =
      r.number_or(m, P, "sensor_h", 0.0, half_open_interval(0, mc.h_min, "mesh.h_min = " + fmt(mc.h_min)));
  mc.min_dihedral_deg = r.number_or(m, P, "min_dihedral_deg", mc.min_dihedral_deg, open_interval(0, 30));
  mc.max_radius_edge = r.number_or(
      m, P, "max_radius_edge", mc.max_radius_edge,
      Rule{"a number >= 1.1 (TetGen radius-edge bound; refinement may not terminate below about 1.1)",
           [](double x) { return x >= 1.1; }});
  if (Reader::find(m, "regions")) {
    const std::string desc = R"(an array of regions {"from": [x, y], "to": [x, y], "radius", "h"})";
    const json& regions = r.array(m, P, "regions", desc);
    for (std::size_t i = 0; i < regions.size(); ++i) {
      const std::string PR = at(sub(P, "regions"), i);
      const json& g = regions[i];
      r.object(g, PR, {"from", "to", "radius", "h"});
      RegionOfInterest roi;
      roi.a = r.vec2(g, PR, "from");
      roi.b = r.vec2(g, PR, "to");
      roi.radius = r.number(g, PR, "radius", non_negative());
      roi.h = r.number_or(g, PR, "h", 0.0, length());
      mc.regions.push_back(roi);
    }
  }
  return mc;
}

Loads read_loads(const Reader& r, const json& l, bool posts_on_springs) {
  const std::string P = "loads";
  r.object(l, P, {"punches", "patches"});
  Loads loads;
  if (Reader::find(l, "punches")) {
    const json& punches =
        r.array(l, P, "punches", R"(an array of punches {"center", "diameter", "force" | "displacement"})");
    for (std::size_t i = 0; i < punches.size(); ++i) {
      const std::string PP = at(sub(P, "punches"), i);
      const json& j = punches[i];
      r.object(j, PP, {"center", "diameter", "force", "displacement"});
      Punch punch;
      punch.center = r.vec2(j, PP, "center");
      punch.diameter = r.number(j, PP, "diameter", length());
      const json* force = Reader::find(j, "force");
      const json* disp = Reader::find(j, "displacement");
      if ((force != nullptr) == (disp != nullptr))
        r.fail(PP, j, R"(must have exactly one of "force" (N) or "displacement" (mm))");
      if (force) punch.force = r.number(*force, sub(PP, "force"), force_rule());
      // A post on springs moves under the load; a punch held at its force moves with it, and the skin's
      // stiffness against the posts' motions (fem/sensor_reading.hpp) is then not the held skin's.
      if (force && posts_on_springs)
        r.fail(sub(PP, "force"), *force,
               "cannot drive a punch with posts on membrane springs: give its displacement, or use a patch");
      if (disp) punch.displacement = r.number(*disp, sub(PP, "displacement"), length());
      loads.punches.push_back(punch);
    }
  }
  if (Reader::find(l, "patches")) {
    const json& patches =
        r.array(l, P, "patches", R"(an array of patches {"center", "diameter", "direction", "force"})");
    for (std::size_t i = 0; i < patches.size(); ++i) {
      const std::string PP = at(sub(P, "patches"), i);
      const json& j = patches[i];
      r.object(j, PP, {"center", "diameter", "direction", "force"});
      TractionPatch patch;
      patch.center = r.vec2(j, PP, "center");
      patch.diameter = r.number(j, PP, "diameter", length());
      const json& dir = r.need(j, PP, "direction", "a non-zero vector [x, y, z]");
      const Vec3 d = r.vec<3>(dir, sub(PP, "direction"));
      const double norm = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      if (!(norm > 0) || !std::isfinite(norm))
        r.fail(sub(PP, "direction"), dir, "must be a non-zero vector [x, y, z]");
      patch.direction = {d[0] / norm, d[1] / norm, d[2] / norm};
      patch.force = r.number(j, PP, "force", force_rule());
      loads.patches.push_back(patch);
    }
  }
  return loads;
}

Calibration read_calibration(const Reader& r, const json& c) {
  const std::string P = "calibration";
  r.object(c, P, {"punch_diameter", "scan_half_width", "spacing"});
  Calibration cal;
  cal.punch_diameter = r.number_or(c, P, "punch_diameter", cal.punch_diameter, length());
  cal.scan_half_width = r.number_or(c, P, "scan_half_width", cal.scan_half_width, non_negative());
  cal.spacing = r.number_or(c, P, "spacing", cal.spacing, length());
  return cal;
}

// Distance from p to the footprint's edge (negative outside); +inf for imported surfaces (not known here).
double inside_margin(const Geometry& g, const Vec2& p) {
  if (g.kind == GeometryKind::cap)
    return g.cap.truncation_radius - std::hypot(p[0] - g.cap.apex_x, p[1] - g.cap.apex_y);
  if (g.kind == GeometryKind::flat) return g.flat.half_width - std::max(std::abs(p[0]), std::abs(p[1]));
  return std::numeric_limits<double>::infinity();
}

// The footprint in words, with its numbers: "truncation_radius = 12 about the apex (0.5, 0)".
std::string footprint_words(const Geometry& g) {
  if (g.kind == GeometryKind::cap)
    return "truncation_radius = " + fmt(g.cap.truncation_radius) + " about the apex " +
           fmt(Vec2{g.cap.apex_x, g.cap.apex_y});
  return "|x|, |y| <= half_width = " + fmt(g.flat.half_width);
}

// "" if the disc of radius `rad` about p lies on the skin's footprint (always, for an imported surface:
// its footprint is not known before the file is read); else the rule it breaks, with the numbers.
std::string off_footprint(const Geometry& g, const Vec2& p, double rad, const std::string& rad_name) {
  const double margin = inside_margin(g, p);
  if (!(rad > margin + 1e-9 * std::max(1.0, rad))) return "";
  const std::string minus = rad > 0 ? " - " + rad_name : "";
  if (g.kind == GeometryKind::cap) {
    const double dist = g.cap.truncation_radius - margin;
    return "its centre must be at most truncation_radius" + minus + " = " +
           fmt(g.cap.truncation_radius - rad) + " from the apex " + fmt(Vec2{g.cap.apex_x, g.cap.apex_y}) +
           ", got " + fmt(dist);
  }
  return "its centre must have |x|, |y| <= half_width" + minus + " = " + fmt(g.flat.half_width - rad) +
         ", got " + fmt(std::max(std::abs(p[0]), std::abs(p[1])));
}

json point(const Vec2& p) { return json::array({p[0], p[1]}); }

Hole read_hole(const Reader& r, const json& j, const std::string& path, std::size_t i, std::size_t n,
               const Geometry& geo) {
  r.object(j, path, {"center", "diameter", "depth", "h"});
  Hole h;
  h.center = r.vec2(j, path, "center");
  h.diameter = r.number(j, path, "diameter", length());
  h.depth = r.number_or(j, path, "depth", h.depth, length());
  h.h = r.number_or(j, path, "h", 0.0, length());
  const std::string off = off_footprint(geo, h.center, 0.5 * h.diameter, "diameter/2");
  if (!off.empty())
    r.fail(path, j,
           "hole " + std::to_string(i + 1) + " of " + std::to_string(n) + " (centre " + fmt(h.center) +
               ", diameter " + fmt(h.diameter) + ") is off the skin: it must lie on the skin's footprint; " +
               off);
  return h;
}

// Punches and patches: on the skin with at least mesh.h_min of skin around them (a load disc touching the
// footprint's edge would put its circle on the side wall), punches apart from each other by mesh.h_min
// (overlapping punches would hold the same nodes twice), and a punch depth below the skin's thickness (strain
// below 1). Forces are not bounded by E: the problem is linear, and unit loads are the norm.
void check_loads(const Reader& r, const Scene& scene) {
  const Geometry& g = scene.geometry;
  const double gap = scene.mesh.h_min;
  const double thickness = g.kind == GeometryKind::cap    ? g.cap.h
                           : g.kind == GeometryKind::flat ? g.flat.h
                                                          : 0;
  // TetGen's geometric tolerance is relative (1e-8 of the domain): a disc below 1e-6 of the footprint's
  // width is refused (a 1e-9 mm punch on a 16 mm layer crashed it).
  const double width = g.kind == GeometryKind::flat  ? 2 * g.flat.half_width
                       : g.kind == GeometryKind::cap ? 2 * g.cap.truncation_radius
                                                     : 0;
  const auto check_disc = [&](const std::string& path, const Vec2& c, double d) {
    if (d < 1e-6 * width)
      r.fail(path.substr(0, path.rfind('.')) + ".diameter", json(d),
             "must be >= 1e-6 x the skin's width = " + fmt(1e-6 * width) + " mm (mesh generator tolerance)");
    const std::string off = off_footprint(g, c, 0.5 * d + gap, "diameter/2 - mesh.h_min");
    if (!off.empty())
      r.fail(path, point(c),
             "the load disc (diameter " + fmt(d) + ") must lie on the skin with mesh.h_min = " + fmt(gap) +
                 " to spare; " + off);
  };
  const auto& punches = scene.loads.punches;
  for (std::size_t i = 0; i < punches.size(); ++i) {
    const std::string PP = at("loads.punches", i);
    check_disc(PP + ".center", punches[i].center, punches[i].diameter);
    if (punches[i].displacement && thickness > 0 && *punches[i].displacement >= thickness)
      r.fail(sub(PP, "displacement"), json(*punches[i].displacement),
             "must be < the skin's thickness " + fmt(thickness) + " mm (strain below 1)");
    for (std::size_t j = 0; j < i; ++j) {
      const double dist = std::hypot(punches[i].center[0] - punches[j].center[0],
                                     punches[i].center[1] - punches[j].center[1]);
      const double need = 0.5 * (punches[i].diameter + punches[j].diameter) + gap;
      if (dist < need)
        r.fail(PP + ".center", point(punches[i].center),
               "punches " + std::to_string(j + 1) + " and " + std::to_string(i + 1) +
                   " overlap or touch: centres " + fmt(dist) +
                   " apart, must be at least the sum of the radii + mesh.h_min = " + fmt(need));
    }
  }
  for (std::size_t i = 0; i < scene.loads.patches.size(); ++i) {
    const auto& p = scene.loads.patches[i];
    check_disc(at("loads.patches", i) + ".center", p.center, p.diameter);
  }
}

void read_friction(const Reader& r, const json& f, const std::string& path, ContactLoad& out) {
  r.object(f, path, {"mode", "law", "mu", "tau0", "static_ratio", "direction"});
  if (const json* mode = Reader::find(f, "mode")) {
    const auto m = mode->is_string() ? friction_mode_named(mode->get<std::string>()) : std::nullopt;
    if (!m) r.fail(sub(path, "mode"), *mode, "must be one of " + choice_list(friction_mode_names()));
    out.friction = *m;
  }
  // μ = 0 is allowed with every mode: coupled friction with μ = 0 must then reproduce frictionless contact.
  out.mu = r.number_or(f, path, "mu", 0.0, non_negative());
  // At rest the plate keeps what sliding left behind, bounded by Coulomb's cone: |p_t| <= mu p_z.
  out.static_ratio = r.number_or(
      f, path, "static_ratio", 0.0,
      {"a number in [0, mu = " + fmt(out.mu) + "] (a residual traction at rest stays inside Coulomb's cone " +
           "|p_t| <= mu p_z; give contact.friction.mu)",
       [mu = out.mu](double x) { return x >= 0 && x <= mu; }});
  if (const json* law = Reader::find(f, "law")) {
    const auto l = law->is_string() ? friction_law_named(law->get<std::string>()) : std::nullopt;
    if (!l) r.fail(sub(path, "law"), *law, "must be one of " + choice_list(friction_law_names()));
    out.law = *l;
  }
  if (const json* tau0 = Reader::find(f, "tau0")) {
    if (!kind(out.law).shear_strength)
      r.fail(sub(path, "tau0"), *tau0,
             R"(is the shear strength of "law": "shear_strength" or "mixed"; Coulomb friction has none)");
    if (*tau0 != "from_force")
      out.tau0 = r.number(*tau0, sub(path, "tau0"),
                          {R"(a shear strength in [0, 1e6] MPa, or "from_force" (mu F / contact area))",
                           [](double x) { return x >= 0 && x <= 1e6; }});
  }
  if (const json* d = Reader::find(f, "direction")) {
    const Vec2 v = r.vec<2>(*d, sub(path, "direction"));
    const double n = std::hypot(v[0], v[1]);
    if (!(n > 0) || !std::isfinite(n))
      r.fail(sub(path, "direction"), *d, "must be a non-zero vector [dx, dy]");
    out.direction = {v[0] / n, v[1] / n};
  }
}

// The bulge hole model's range in (ε/d)² (read_contact).
constexpr double kBulgeRange = 0.065;

HoleSweep read_sweep(const Reader& r, const json& j, const std::string& path, const Geometry& geo) {
  r.object(j, path, {"from", "to", "positions", "hole_diameter", "hole_depth", "h", "hole_model"});
  HoleSweep s;
  if (const json* m = Reader::find(j, "hole_model")) {
    if (*m == "bulge")
      s.model = HoleModel::bulge;
    else if (*m == "resolved")
      s.model = HoleModel::resolved;
    else
      r.fail(sub(path, "hole_model"), *m, R"(must be one of "bulge", "resolved")");
  }
  s.from = r.vec2(j, path, "from");
  s.to = r.vec2(j, path, "to");
  if (const json* n = Reader::find(j, "positions"))
    s.positions = static_cast<int>(r.integer(*n, sub(path, "positions"), 2, 100000));
  s.hole_diameter = r.number_or(j, path, "hole_diameter", s.hole_diameter, length());
  s.hole_depth = r.number_or(j, path, "hole_depth", s.hole_depth, length());
  s.h = r.number_or(j, path, "h", 0.0, length());
  // The footprint is convex: a hole on it at both ends stays on it all along the path.
  for (const auto& [key, p] : {std::make_pair("from", s.from), std::make_pair("to", s.to)}) {
    const std::string off = off_footprint(geo, p, 0.5 * s.hole_diameter, "hole_diameter/2");
    if (!off.empty())
      r.fail(
          sub(path, key), point(p),
          "the swept hole (diameter " + fmt(s.hole_diameter) + ") must stay on the skin's footprint; " + off);
  }
  return s;
}

// A textured plate's holes and their patterns; the holes' fit, overlaps and tracks are checked with the
// whole scene (check_texture).
Hole read_texture_hole(const Reader& r, const json& j, const std::string& path) {
  r.object(j, path, {"center", "diameter", "depth"});
  Hole h;
  h.center = r.vec2(j, path, "center");
  h.diameter = r.number(j, path, "diameter", length());
  h.depth = r.number_or(j, path, "depth", h.depth, length());
  return h;
}

Texture read_texture(const Reader& r, const json& j, const std::string& path, const Vec2& direction) {
  r.object(j, path, {"holes", "lattice", "grooves", "random", "h"});
  Texture t;
  if (Reader::find(j, "holes")) {
    const json& holes = r.array(j, path, "holes", R"(an array of holes {"center": [x, y], "diameter"})");
    for (std::size_t i = 0; i < holes.size(); ++i)
      t.listed.push_back(read_texture_hole(r, holes[i], at(sub(path, "holes"), i)));
  }
  if (const json* l = Reader::find(j, "lattice")) {
    const std::string P = sub(path, "lattice");
    r.object(*l, P, {"origin", "period", "count", "diameter", "depth"});
    HoleLattice lat;
    lat.origin = r.vec2(*l, P, "origin");
    lat.period = r.vec2(*l, P, "period");
    const json& count = r.need(*l, P, "count", "[nx, ny], integers in [1, 10000]");
    if (!count.is_array() || count.size() != 2) r.fail(sub(P, "count"), count, "must be [nx, ny]");
    lat.nx = static_cast<int>(r.integer(count[0], sub(P, "count") + "[0]", 1, 10000));
    lat.ny = static_cast<int>(r.integer(count[1], sub(P, "count") + "[1]", 1, 10000));
    lat.diameter = r.number(*l, P, "diameter", length());
    lat.depth = r.number_or(*l, P, "depth", lat.depth, length());
    for (int k = 0; k < 2; ++k)
      if ((k == 0 ? lat.nx : lat.ny) > 1 && !(lat.period[k] >= lat.diameter))
        r.fail(sub(P, "period"), point(lat.period),
               "each period along which the lattice has more than one hole must be >= its diameter " +
                   fmt(lat.diameter) + " mm, or its holes overlap");
    t.lattice = lat;
  }
  if (const json* g = Reader::find(j, "grooves")) {
    const std::string P = sub(path, "grooves");
    r.object(*g, P, {"origin", "width", "length", "period", "count", "depth"});
    Grooves gr;
    gr.direction = direction;
    gr.origin = r.vec2(*g, P, "origin");
    gr.width = r.number(*g, P, "width", length());
    gr.length = r.number(*g, P, "length", length());
    gr.count = static_cast<int>(
        r.integer(r.need(*g, P, "count", "an integer in [1, 10000]"), sub(P, "count"), 1, 10000));
    gr.period =
        gr.count > 1 ? r.number(*g, P, "period", length()) : r.number_or(*g, P, "period", gr.width, length());
    if (gr.count > 1 && !(gr.period > gr.width))
      r.fail(sub(P, "period"), json(gr.period),
             "must be > the grooves' width " + fmt(gr.width) + " mm, or they touch or overlap");
    gr.depth = r.number_or(*g, P, "depth", gr.depth, length());
    t.grooves = gr;
  }
  if (const json* rn = Reader::find(j, "random")) {
    const std::string P = sub(path, "random");
    r.object(*rn, P, {"from", "to", "density", "diameter", "depth", "seed", "mirror"});
    RandomHoles h;
    h.from = r.vec2(*rn, P, "from");
    h.to = r.vec2(*rn, P, "to");
    h.density =
        r.number(*rn, P, "density",
                 {"a density in (0, 100] holes per mm^2", [](double x) { return x > 0 && x <= 100; }});
    const json& d = r.need(*rn, P, "diameter", "[min, max] in mm");
    if (!d.is_array() || d.size() != 2) r.fail(sub(P, "diameter"), d, "must be [min, max] in mm");
    h.diameter_min = r.number(d[0], sub(P, "diameter") + "[0]", length());
    h.diameter_max = r.number(d[1], sub(P, "diameter") + "[1]", length());
    if (h.diameter_max < h.diameter_min) r.fail(sub(P, "diameter"), d, "must be [min, max] with min <= max");
    h.depth = r.number_or(*rn, P, "depth", h.depth, length());
    if (const json* seed = Reader::find(*rn, "seed"))
      h.seed = static_cast<std::uint64_t>(r.integer(*seed, sub(P, "seed"), 0, 1LL << 53));
    if (const json* m = Reader::find(*rn, "mirror")) h.mirror = r.boolean(*m, sub(P, "mirror"));
    if (h.mirror && h.from[1] != -h.to[1])
      r.fail(sub(P, "from"), (*rn)["from"],
             "with \"mirror\": true the rectangle must be symmetric about y = 0 (from's y = -to's y; here " +
                 fmt(h.from[1]) + " and " + fmt(h.to[1]) + ")");
    const double area = std::abs((h.to[0] - h.from[0]) * (h.to[1] - h.from[1]));
    if ((h.mirror ? 2 * std::lround(0.5 * h.density * area) : std::lround(h.density * area)) < 1 ||
        h.density * area > 10000)
      r.fail(sub(P, "density"), json(h.density),
             "times the rectangle's area " + fmt(area) + " mm^2 must give 1 to 10000 holes" +
                 (h.mirror ? " (2 or more in mirrored pairs)" : ""));
    t.random = h;
  }
  if (t.listed.empty() && !t.lattice && !t.grooves && !t.random)
    r.fail(path, j, R"(must have at least one of "holes", "lattice", "grooves", "random")");
  t.h = r.number_or(j, path, "h", 0.0, length());
  TextureHoles all = texture_holes(t);
  if (!all.error.empty()) r.fail(sub(path, "random.density"), j["random"]["density"], all.error);
  if (all.holes.size() > 10000)
    r.fail(path, "has " + std::to_string(all.holes.size()) + " holes; at most 10000");
  t.holes = std::move(all.holes);
  return t;
}

// The plate's scan, at most kMaxScanPositions positions.
constexpr int kMaxScanPositions = 100000;
Scan read_scan(const Reader& r, const json& j, const std::string& path) {
  r.object(j, path, {"from", "to", "step"});
  Scan s;
  const Rule any{"a displacement in [-1e4, 1e4] mm", [](double x) { return std::abs(x) <= 1e4; }};
  s.from = r.number(j, path, "from", any);
  s.to = r.number(j, path, "to", any);
  if (!(s.to > s.from)) r.fail(sub(path, "to"), j.at("to"), "must be > from = " + fmt(s.from));
  s.step = r.number(j, path, "step", length());
  if ((s.to - s.from) / s.step + 1 > kMaxScanPositions)
    r.fail(sub(path, "step"), j.at("step"),
           "gives " + fmt((s.to - s.from) / s.step + 1) + " positions; at most " +
               std::to_string(kMaxScanPositions) +
               ": give a step >= " + fmt((s.to - s.from) / (kMaxScanPositions - 1)) + " mm");
  return s;
}

ContactLoad read_contact(const Reader& r, const json& c, const Geometry& geo) {
  const std::string P = "contact";
  r.object(c, P,
           {"indenter", "force", "depth", "holes", "zone_radius", "h", "friction", "interface", "sweep",
            "texture", "scan"});
  ContactLoad out;

  const std::string PI = sub(P, "indenter");
  const std::string kinds = R"({"type": "plane"} or {"type": "sphere", "R", "center": [x, y]})";
  const json& ind = r.need(c, P, "indenter", kinds);
  if (!ind.is_object()) r.fail(PI, ind, "must be " + kinds);
  const json& type = r.need(ind, PI, "type", R"("plane" or "sphere")");
  if (type == "plane") {
    r.object(ind, PI, {"type"});
    out.indenter = IndenterKind::plane;
    if (geo.kind == GeometryKind::flat)
      r.fail(sub(PI, "type"), type,
             "a plane on a flat layer touches it everywhere at once (no first-touch point, no contact zone); "
             "a plane needs a cap geometry, or use a sphere on the flat layer");
    if (geo.kind == GeometryKind::surface)
      r.fail(
          sub(PI, "type"), type,
          "a plane needs a cap geometry (it first touches at the apex); on an imported surface use a sphere");
  } else if (type == "sphere") {
    r.object(ind, PI, {"type", "R", "center"});
    out.indenter = IndenterKind::sphere;
    // Below a micrometre the curvatures that set the zone overflow (R = 5e-324 gave a NaN zone radius).
    out.sphere_R = r.number(ind, PI, "R", {"a radius in [0.001, " + fmt(kMaxLength) + "] mm", [](double x) {
                                             return x >= 1e-3 && x <= kMaxLength;
                                           }});
    out.center = r.vec2(ind, PI, "center");
    const std::string off = off_footprint(geo, out.center, 0, "");
    if (!off.empty())
      r.fail(sub(PI, "center"), point(out.center),
             "the sphere's centre must lie on the skin's footprint; " + off);
  } else {
    r.fail(sub(PI, "type"), type, R"(must be "plane" or "sphere")");
  }

  const json* force = Reader::find(c, "force");
  const json* depth = Reader::find(c, "depth");
  if ((force != nullptr) == (depth != nullptr))
    r.fail(P, c, R"(must have exactly one of "force" (N) or "depth" (mm))");
  if (force) out.force = r.number(*force, sub(P, "force"), force_rule());
  if (depth) out.depth = r.number(*depth, sub(P, "depth"), length());

  if (Reader::find(c, "holes")) {
    const json& holes = r.array(c, P, "holes", R"(an array of holes {"center": [x, y], "diameter"})");
    for (std::size_t i = 0; i < holes.size(); ++i)
      out.holes.push_back(read_hole(r, holes[i], at(sub(P, "holes"), i), i, holes.size(), geo));
  }
  out.zone_radius = r.number_or(c, P, "zone_radius", 0.0, length());
  out.h = r.number_or(c, P, "h", 0.0, length());
  if (const json* f = Reader::find(c, "friction")) read_friction(r, *f, sub(P, "friction"), out);
  if (const json* i = Reader::find(c, "interface")) {
    const std::string path = sub(P, "interface");
    r.object(*i, path, {"law", "K", "u0", "p_ref"});
    const json& law = r.need(*i, path, "law", choice_list(interface_law_names()));
    const auto l = law.is_string() ? interface_law_named(law.get<std::string>()) : std::nullopt;
    if (!l) r.fail(sub(path, "law"), law, "must be one of " + choice_list(interface_law_names()));
    out.interface.law = *l;
    const auto only = [&](const char* key, InterfaceLaw owner, const char* what) {
      if (out.interface.law == owner) return true;
      if (const json* v = Reader::find(*i, key))
        r.fail(
            sub(path, key), *v,
            std::string("is ") + what + " of \"law\": \"" + to_string(owner) + "\"; this interface has none");
      return false;
    };
    if (only("K", InterfaceLaw::linear, "the stiffness"))
      out.interface.K = r.number(*i, path, "K", {"an interface stiffness in (0, 1e12] MPa/mm", [](double x) {
                                                   return x > 0 && x <= 1e12;
                                                 }});
    if (only("u0", InterfaceLaw::exponential, "the decay length"))
      out.interface.u0 =
          r.number(*i, path, "u0", {"a decay length in (0, 1] mm", [](double x) { return x > 0 && x <= 1; }});
    if (only("p_ref", InterfaceLaw::exponential, "the reference pressure"))
      out.interface.p_ref = r.number(
          *i, path, "p_ref", {"a pressure in (0, 1e6] MPa", [](double x) { return x > 0 && x <= 1e6; }});
    if (kind(out.interface.law).smooth && kind(out.law).shear_strength)
      r.fail(
          sub(path, "law"), law,
          R"(touches everywhere, and a shear strength acts where the skin touches: use "friction": {"law": "coulomb"} with it, or a hard or linear interface)");
  }
  if (const json* sw = Reader::find(c, "sweep")) {
    out.sweep = read_sweep(r, *sw, sub(P, "sweep"), geo);
    // The bulge is the small hole's solution under a hard interface: through a compliant one the pressure
    // missing over the hole is reloaded over E*/K, not on the rim. Unsaid, such a sweep is resolved.
    if (kind(out.interface.law).compliant) {
      if (Reader::find(*sw, "hole_model") && out.sweep->model == HoleModel::bulge)
        r.fail(sub(P, "sweep.hole_model"), "bulge",
               std::string(R"(is the hole's solution under a hard interface; with "interface": {"law": ")") +
                   to_string(out.interface.law) + R"("} use "resolved")");
      out.sweep->model = HoleModel::resolved;
    }
    // The bulge is the first term in (ε/d)², ε the hole's radius and d the skin's thickness: against resolved
    // holes on the default skin (d = 3.04 mm) 1 mm holes ((ε/d)² = 0.027) agreed within 2 %, 1.5 mm (0.061)
    // within 2.5–8 %, 3 mm (0.24) fell 35–50 % short. Beyond kBulgeRange the model is not an answer.
    const double d = geo.kind == GeometryKind::cap    ? geo.cap.h
                     : geo.kind == GeometryKind::flat ? geo.flat.h
                                                      : 0;
    const double eps_d = d > 0 ? 0.5 * out.sweep->hole_diameter / d : 0;
    if (out.sweep->model == HoleModel::bulge && eps_d * eps_d > kBulgeRange)
      r.fail(
          sub(P, "sweep.hole_diameter"), json(out.sweep->hole_diameter),
          "the bulge hole model (the default under a hard interface) holds for (hole radius / skin thickness "
          "" + fmt(d) +
              " mm)² <= " + fmt(kBulgeRange) + " (measured: within 2 % at 0.027, 8 % at 0.061), here " +
              fmt(eps_d * eps_d) + R"(: give "hole_model": "resolved")");
  }
  const json* texture = Reader::find(c, "texture");
  const json* scan = Reader::find(c, "scan");
  if ((texture != nullptr) != (scan != nullptr))
    r.fail(sub(P, texture ? "texture" : "scan"), texture ? *texture : *scan,
           R"(a textured plate is scanned: give both "texture" and "scan", or neither)");
  if (texture) {
    out.texture = read_texture(r, *texture, sub(P, "texture"), out.direction);
    out.scan = read_scan(r, *scan, sub(P, "scan"));
  }
  return out;
}

// A shear strength above the skin's shear modulus G strains the surface by more than τ0/G = 1: no linear,
// small-strain model answers there (in the coupled contact the shear then lifts the very edge it acts on).
void check_shear_strength(const Reader& r, const json& j, const Scene& scene) {
  const std::optional<double>& tau0 = scene.contact->tau0;
  const double G = scene.material.E / (2 * (1 + scene.material.nu));
  if (tau0 && *tau0 > G)
    r.fail("contact.friction.tau0", j["friction"]["tau0"],
           "must be at most the skin's shear modulus G = E / (2 (1 + nu)) = " + fmt(G) +
               " MPa: beyond it the surface strains by more than tau0 / G = 1, outside linear elasticity");
}

// The candidate contact zone must stay one skin thickness inside the footprint: the truncated side is an
// artificial boundary (free or clamped), and contact within about h of it would feel it. Not checked on an
// imported surface (footprint and thickness unknown before the file is read).
void check_contact_zone(const Reader& r, const json& j, const Scene& scene) {
  if (scene.geometry.kind == GeometryKind::surface) return;
  const ContactLoad& load = *scene.contact;
  const Vec2 c = contact_center(scene);
  const double radius = contact_zone_radius(scene), h = nominal_thickness(scene);
  const double margin = inside_margin(scene.geometry, c);
  if (radius + h <= margin * (1 + 1e-12)) return;
  // Name the field that sets the radius: zone_radius if given, else the load.
  const bool given = load.zone_radius > 0;
  const std::string key = given ? "zone_radius" : (load.force ? "force" : "depth");
  const std::string what =
      given ? "the candidate contact zone (zone_radius " + fmt(radius)
            : std::string("the automatic candidate contact zone (") +
                  (load.force ? "1.25 x Hertz radius" : "1.25 x 2 sqrt(R_eff depth), the thin-layer bound,") +
                  " = " + fmt(radius);
  const std::string thick = scene.geometry.kind == GeometryKind::cap ? "h at the apex" : "h";
  const std::string fix = given ? "give a smaller contact.zone_radius or a larger skin"
                                : "load less, give a smaller contact.zone_radius, or use a larger skin";
  r.fail(sub("contact", key), j.at(key),
         what + " about " + fmt(c) + ") must stay one skin thickness (" + thick + " = " + fmt(h) +
             ") inside the skin's side (" + footprint_words(scene.geometry) + "): zone radius + h = " +
             fmt(radius + h) + " > " + fmt(margin) + ", the distance from the zone's centre to the side; " +
             "it would reach the truncated side; " + fix);
}

// The field that sets the contact zone's mesh size, with its value: "contact.h = …" or "mesh.h_min = …".
std::string contact_h_words(const Scene& scene) {
  const double h = scene.contact->h;
  return h > 0 ? "contact.h = " + fmt(h) : "mesh.h_min = " + fmt(contact_zone_h(scene));
}

// Indentations the geometry cannot take and zones the mesh cannot hold, refused with the field that sets them
// (else the solver failed later, blaming the zone's radius or "refine the mesh there", exit 1).
void check_contact_extent(const Reader& r, const json& j, const Scene& scene) {
  const ContactLoad& load = *scene.contact;
  const bool generated = scene.geometry.kind != GeometryKind::surface;
  if (load.depth && load.indenter == IndenterKind::sphere && *load.depth >= load.sphere_R)
    r.fail(
        "contact.depth", j.at("depth"),
        "must be below the sphere's radius R = " + fmt(load.sphere_R) + " mm (the indenter is that sphere)");
  if (load.depth && generated && *load.depth >= nominal_thickness(scene))
    r.fail("contact.depth", j.at("depth"),
           "must be below the skin's thickness (" + fmt(nominal_thickness(scene)) +
               " mm): the indenter would reach the base");
  if (!generated && load.zone_radius <= 0) return;  // no automatic zone before the surface is read
  const double radius = contact_zone_radius(scene), h = contact_zone_h(scene);
  if (radius < h) {
    const bool given = load.zone_radius > 0;
    const std::string key = given ? "zone_radius" : (load.force ? "force" : "depth");
    r.fail(sub("contact", key), j.at(key),
           (given ? "the candidate contact zone (radius " : "the automatic candidate contact zone (radius ") +
               fmt(radius) + " mm) must be at least one contact element across (" + contact_h_words(scene) +
               " mm); " +
               (given ? "give a larger contact.zone_radius" : "load more, or give contact.zone_radius"));
  }
  const Vec2 c = contact_center(scene);
  for (std::size_t i = 0; i < load.holes.size(); ++i) {
    const Hole& hole = load.holes[i];
    if (std::hypot(hole.center[0] - c[0], hole.center[1] - c[1]) + radius <= 0.5 * hole.diameter)
      r.fail(at(sub("contact", "holes"), i) + ".diameter", json(hole.diameter),
             "the hole covers the whole candidate contact zone (radius " + fmt(radius) + " mm about " +
                 fmt(c) + "): nothing could touch; make it smaller than the zone");
  }
}

// A hole removes the multipliers whose vertex lies inside it: a mesh coarser than the hole can leave it
// holding none, a zero signal that means "not resolved". The mesh over a hole must be at most its diameter
// (contact/contact_solver.hpp's require_hole_resolved catches the rare position that still falls between
// vertices). A swept hole modelled as a bulge (HoleModel::bulge) is not resolved by the mesh: no rule.
void check_hole_meshes(const Reader& r, const Scene& scene) {
  const ContactLoad& c = *scene.contact;
  const double zone_h = contact_zone_h(scene);
  const std::string zone_words = contact_h_words(scene);
  const auto check = [&](const std::string& path, double diameter, double h, const std::string& h_field) {
    if (hole_mesh_h(scene, h) > diameter)
      r.fail(path, json(diameter),
             "must be >= the mesh size over the hole (" +
                 (h > 0 && h < zone_h ? h_field + " = " + fmt(h) : zone_words) +
                 " mm), or the hole can fall between contact vertices and read zero; give " + h_field +
                 " <= " + fmt(diameter));
  };
  for (std::size_t i = 0; i < c.holes.size(); ++i)
    check(at("contact.holes", i) + ".diameter", c.holes[i].diameter, c.holes[i].h,
          at("contact.holes", i) + ".h");
  if (c.sweep && c.sweep->model == HoleModel::resolved)
    check("contact.sweep.hole_diameter", c.sweep->hole_diameter, c.sweep->h, "contact.sweep.h");
  if (c.texture) {
    const Texture& t = *c.texture;
    const std::size_t listed = t.listed.size();
    const std::size_t in_lattice = t.lattice ? std::size_t(t.lattice->nx) * t.lattice->ny : 0;
    const std::size_t grooves = t.grooves ? std::size_t(t.grooves->count) : 0;
    for (std::size_t k = 0; k < t.holes.size(); ++k) {
      const std::string field = k < listed                ? at("contact.texture.holes", k) + ".diameter"
                                : k < listed + in_lattice ? std::string("contact.texture.lattice.diameter")
                                : k < listed + in_lattice + grooves
                                    ? std::string("contact.texture.grooves.width")
                                    : std::string("contact.texture.random.diameter");
      check(field, t.holes[k].diameter, t.h, "contact.texture.h");
    }
  }
}

// Where texture hole k comes from, for an error message.
std::string texture_hole_words(const Texture& t, std::size_t k) {
  const std::size_t listed = t.listed.size();
  const std::size_t in_lattice = t.lattice ? std::size_t(t.lattice->nx) * t.lattice->ny : 0;
  if (k < listed) return at("contact.texture.holes", k);
  if (k < listed + in_lattice)
    return "contact.texture.lattice (hole " + std::to_string(k - listed + 1) + " of " +
           std::to_string(in_lattice) + ")";
  const std::size_t grooves = t.grooves ? std::size_t(t.grooves->count) : 0;
  if (k < listed + in_lattice + grooves)
    return "contact.texture.grooves (groove " + std::to_string(k - listed - in_lattice + 1) + " of " +
           std::to_string(grooves) + ")";
  return "contact.texture.random (hole " + std::to_string(k - listed - in_lattice + 1) + ")";
}

// A textured plate's holes must not overlap (their cuts would count the common part twice), each must
// cross the candidate contact zone during the scan (else it is outside the scanned plate and adds nothing),
// and the scan's step must not exceed the mesh along their tracks (a coarser step skips what the mesh
// resolves: the signal changes over one element as a hole's rim crosses it).
void check_texture(const Reader& r, const json& j, const Scene& scene) {
  const ContactLoad& c = *scene.contact;
  if (!c.texture) return;
  const Texture& t = *c.texture;
  const Scan& scan = *c.scan;
  for (std::size_t a = 0; a < t.holes.size(); ++a)
    for (std::size_t b = a + 1; b < t.holes.size(); ++b)
      if (holes_overlap(t.holes[a], t.holes[b]))
        r.fail(texture_hole_words(t, b), point(t.holes[b].center),
               "overlaps " + texture_hole_words(t, a) + " (centre " + fmt(t.holes[a].center) +
                   (t.holes[a].groove() ? ", width " : ", diameter ") + fmt(t.holes[a].diameter) +
                   "): the holes and grooves of a texture must be disjoint");
  const Vec2 o = contact_center(scene);
  const double radius = contact_zone_radius(scene);
  const Vec2 d = c.direction;
  for (std::size_t k = 0; k < t.holes.size(); ++k)
    if (hole_tracks({t.holes[k]}, d, scan, o, radius).empty())
      r.fail(texture_hole_words(t, k), point(t.holes[k].center),
             "never reaches the candidate contact zone (radius " + fmt(radius) + " mm about " + fmt(o) +
                 ") while the plate moves from u = " + fmt(scan.from) + " to " + fmt(scan.to) + " mm along " +
                 fmt(d) + ": it lies outside the scanned plate; move it, or scan farther");
  const double track_h = hole_mesh_h(scene, t.h);
  if (scan.step > track_h)
    r.fail("contact.scan.step", j.at("scan").at("step"),
           "must be <= the mesh size along the holes' tracks (" +
               (t.h > 0 && t.h < contact_zone_h(scene) ? "contact.texture.h = " + fmt(t.h)
                                                       : contact_h_words(scene)) +
               " mm): a coarser step skips what the mesh resolves as a rim crosses an element");
}

}  // namespace

const char* const kNameRule =
    "a file name of 1 to 100 characters: letters, digits, space and . _ - + ( ), not starting with '.', '-' "
    "or a space";
// The name becomes the report's folder (out/<name>) and appears in commands people paste into a shell: one
// path component that cannot climb out (no separator, not "." or ".."), hide, pose as an option or carry a
// quote, NUL or control character (a JSON string may hold "\u0000").
bool is_path_component(const std::string& s) {
  if (s.empty() || s.size() > 100 || s[0] == '.' || s[0] == '-' || s[0] == ' ') return false;
  return std::all_of(s.begin(), s.end(), [](char c) {
    // strchr finds the terminator too: NUL must be refused before it is looked up.
    return std::isalnum(static_cast<unsigned char>(c)) || (c != '\0' && std::strchr(" ._-+()", c));
  });
}

Scene parse_scene(const std::string& json_text, const std::string& source_path) {
  const Reader r(source_path.empty() ? std::string("<scene>") : source_path);
  const json root = parse_json(json_text, r);
  r.object(
      root, "",
      {"name", "geometry", "material", "sensors", "mesh", "loads", "calibration", "contact", "symmetry"});

  Scene scene;
  scene.source_path = source_path;
  const fs::path source(source_path);
  scene.name = source.stem().empty() ? "scene" : source.stem().string();
  const json* name = Reader::find(root, "name");
  if (name) scene.name = r.string(*name, "name", kNameRule);
  // The name becomes the report's folder (out/<name>): one path component, never a way out of out/.
  if (!is_path_component(scene.name))
    r.fail(
        "name", json(scene.name),
        std::string("must be ") + kNameRule + (name ? "" : " (taken from the file name; give a \"name\")"));

  scene.geometry = read_geometry(r, r.need(root, "", "geometry", "an object"), source.parent_path());
  if (const json* sym = Reader::find(root, "symmetry")) {
    if (*sym == "auto")
      scene.symmetry = SymmetryUse::automatic;
    else if (*sym == "none")
      scene.symmetry = SymmetryUse::none;
    else
      r.fail("symmetry", *sym, R"(must be "auto" or "none")");
  }
  scene.material = read_material(r, r.need(root, "", "material", "an object {\"E\", \"nu\", \"model\"*}"));
  std::vector<SensorSource> sources;
  scene.sensors = read_sensors(r, r.need(root, "", "sensors", "an object"), sources);
  check_sensor_footprint(r, scene.geometry, scene.sensors, sources);
  scene.mesh = read_mesh(r, r.need(root, "", "mesh", "an object"));
  if (const json* loads = Reader::find(root, "loads")) {
    scene.loads = read_loads(r, *loads,
                             scene.sensors.model == SensorModel::post && !scene.sensors.post.support.rigid());
    check_loads(r, scene);
  }
  if (const json* cal = Reader::find(root, "calibration")) {
    scene.calibration = read_calibration(r, *cal);
    // The scan's length over its spacing is the number of Green evaluations per sensor.
    const Geometry& g = scene.geometry;
    const double h = g.kind == GeometryKind::cap ? g.cap.h : g.kind == GeometryKind::flat ? g.flat.h : 0;
    const double w = scene.calibration.scan_half_width > 0 ? scene.calibration.scan_half_width : 4 * h;
    constexpr double kMaxScanPoints = 1e4;
    if (2 * w / scene.calibration.spacing > kMaxScanPoints)
      r.fail("calibration.spacing", json(scene.calibration.spacing),
             "must be >= 2 x scan half-width / " + fmt(kMaxScanPoints) + " = " + fmt(2 * w / kMaxScanPoints) +
                 " mm (scan half-width " + fmt(w) + " mm)");
  }
  if (const json* contact = Reader::find(root, "contact")) {
    scene.contact = read_contact(r, *contact, scene.geometry);
    check_contact_extent(r, *contact, scene);
    check_contact_zone(r, *contact, scene);
    check_hole_meshes(r, scene);
    check_texture(r, *contact, scene);
    check_shear_strength(r, *contact, scene);
  }
  return scene;
}

void check_load_placement(const Scene& scene, const std::string& what) {
  check_loads(Reader(scene.source_path + " (" + what + ")"), scene);
}

std::string read_text_file(const std::string& path, const std::string& what) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw SceneError(path + ": cannot read " + what + ": is a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError(path + ": cannot read " + what + ": " + std::strerror(errno));
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw SceneError(path + ": cannot read " + what + ": read error");
  return text.str();
}

nlohmann::json parse_json_text(const std::string& text, const std::string& file) {
  return parse_json(text, Reader(file));
}

Scene load_scene(const std::string& path) { return parse_scene(read_text_file(path, "scene file"), path); }

}  // namespace skinfem
