#include "skinfem/pipeline/meridian_contact.hpp"

#include <cmath>
#include <cstdio>

#include "skinfem/contact/contact_solver.hpp"
#include "skinfem/pipeline/clock.hpp"
#include "skinfem/pipeline/contact.hpp"
#include "skinfem/pipeline/scene_json.hpp"
#include "skinfem/scene/laws.hpp"

namespace skinfem::pipeline {

namespace {
std::string not_exact(const ContactLoad& c, FrictionMode m) {
  char buf[300];
  std::snprintf(
      buf, sizeof buf,
      "the %s mode's traction acts while the pressure is solved (contact.friction.%s = %g): its normal "
      "displacement varies as cos θ, so the contact zone is not a disc",
      to_string(m), kind(m).at_rest ? "static_ratio" : "mu", solved_ratio(c, m));
  return buf;
}
}  // namespace

std::string meridian_contact_unavailable(const Scene& scene, FrictionMode chosen, bool every_mode) {
  require_contact(scene);
  const Geometry& g = scene.geometry;
  const ContactLoad& c = *scene.contact;
  if (std::string why = not_of_revolution(g); !why.empty()) return why;
  if (scene.sensors.model == SensorModel::post) return "posts are read on the 3D contact path only";
  if (!c.holes.empty()) {
    const Vec2 centre = contact_center(scene);
    for (const Hole& h : c.holes)
      if (std::hypot(h.center[0] - centre[0], h.center[1] - centre[1]) > 1e-9)
        return "a hole off the contact's axis breaks its symmetry";
    return "holes are on the 3D path only (a hole on the axis keeps the symmetry, but the meridian does not "
           "model one yet)";
  }
  if (kind(c.interface.law).smooth)
    return std::string("the ") + to_string(c.interface.law) + " interface is on the 3D path only";
  if (kind(c.law).shear_strength)
    return std::string("the ") + to_string(c.law) + " friction law is on the 3D path only";
  const Vec2 centre = contact_center(scene);
  if (g.kind == GeometryKind::cap && std::hypot(centre[0] - g.cap.apex_x, centre[1] - g.cap.apex_y) > 1e-9) {
    char buf[200];
    std::snprintf(buf, sizeof buf, "the indenter at (%g, %g) mm is off the cap's axis at (%g, %g) mm",
                  centre[0], centre[1], g.cap.apex_x, g.cap.apex_y);
    return buf;
  }
  if (g.kind == GeometryKind::flat) {
    const double w = g.flat.half_width;
    const double zone = w - std::max(std::abs(centre[0]), std::abs(centre[1])) - contact_zone_radius(scene);
    if (std::string why = side_too_near(g, "the contact zone ends", zone); !why.empty()) return why;
    for (size_t i = 0; i < scene.sensors.positions.size(); ++i) {
      const Vec2& p = scene.sensors.positions[i];
      const double margin = w - std::max(std::abs(p[0]), std::abs(p[1])) - 0.5 * scene.sensors.disc_diameter;
      if (std::string why = side_too_near(g, "sensor " + std::to_string(i + 1) + " is", margin); !why.empty())
        return why;
    }
  }
  if (solved_ratio(c, chosen) > 0) return not_exact(c, chosen);
  if (every_mode)
    for (FrictionMode m : {FrictionMode::static_residual, FrictionMode::coupled})
      if (solved_ratio(c, m) > 0) return not_exact(c, m) + " (contact reports every mode)";
  return "";
}

bool contact_on_meridian(const Scene& scene, FrictionMode chosen, GreenPath path, std::string* not_meridian) {
  if (path != GreenPath::automatic) return path == GreenPath::meridian;
  const std::string why = meridian_contact_unavailable(scene, chosen, true);
  if (not_meridian) *not_meridian = why;
  return why.empty();
}

MeridianContactRun meridian_contact_run(const Scene& scene, FrictionMode chosen) {
  if (const std::string why = meridian_contact_unavailable(scene, chosen, false); !why.empty())
    throw SceneError(scene.source_path + ": the meridian (axisymmetric) contact path does not apply: " + why +
                     "; use --path 3d");
  const ContactLoad& c = *scene.contact;
  const Geometry& g = scene.geometry;
  const MeridianSkin ms = meridian_skin(scene);
  MeridianContactRun run;
  run.chosen = chosen;
  run.axis = g.kind == GeometryKind::flat ? contact_center(scene) : Vec2{g.cap.apex_x, g.cap.apex_y};
  run.zone_radius = contact_zone_radius(scene);
  if (!(run.zone_radius < ms.radius))
    throw SceneError(scene.source_path + ": contact.zone_radius = " + std::to_string(run.zone_radius) +
                     " mm reaches the meridian's edge at " + std::to_string(ms.radius) + " mm");
  contact::MeridianContactSkin skin{ms.top, ms.radius, ms.h, ms.side, scene.material.E, scene.material.nu};
  if (c.interface.law == InterfaceLaw::linear) skin.interface_K = c.interface.K;
  const auto phi = [&](double r) {  // the indenter's rise above its lowest point (contact/indenter.cpp)
    if (c.indenter == IndenterKind::plane) return 0.0;
    const double R = c.sphere_R;
    return r < R ? r * r / (R + std::sqrt(R * R - r * r)) : R;
  };
  // Both the top and the indenter are convex about the axis: first touch is there.
  const auto gap0 = [&](double r) { return ms.top(0) + phi(r) - ms.top(r); };
  std::vector<ReadingSite> sites = reading_sites(scene.sensors);
  for (ReadingSite& s : sites) s.center = {s.center[0] - run.axis[0], s.center[1] - run.axis[1]};
  contact::MeridianContactLoad load;
  if (c.force)
    load.force_N = *c.force;
  else
    load.depth_mm = *c.depth;
  if (c.mu > 0) load.direction = {c.direction[0], c.direction[1]};
  char model[400];
  std::snprintf(model, sizeof model, "%s, the indenter on its axis at (%g, %g) mm; zone r <= %.4g mm",
                ms.model.c_str(), run.axis[0], run.axis[1], run.zone_radius);
  run.model = model;
  try {
    run.solved = contact::meridian_contact(skin, run.zone_radius, gap0, load, sites,
                                           contact::MeridianContactSizes::for_zone(run.zone_radius, ms.h));
  } catch (const contact::ZoneTooSmall& e) {
    throw SceneError(scene.source_path + ": contact.zone_radius = " + std::to_string(run.zone_radius) +
                     " mm: the contact reaches its last multiplier at r = " +
                     std::to_string(e.last_multiplier_mm) + " mm; give a larger contact.zone_radius");
  }
  const contact::MeridianContactResult& s = run.solved;
  for (FrictionMode m :
       {FrictionMode::none, FrictionMode::static_residual, FrictionMode::uncoupled, FrictionMode::coupled}) {
    if (solved_ratio(c, m) > 0) {
      run.left_out.push_back(m);
      continue;
    }
    MeridianContactRun::Mode& mode = run.modes[m];
    mode.readings = s.readings;
    if (m == FrictionMode::uncoupled && c.mu > 0) {
      mode.ratio = c.mu;
      mode.readings += c.mu * s.readings_per_ratio;
    }
  }
  run.wall = {{"mesh", s.cost.mesh_s},          {"assemble", s.cost.assemble_s},
              {"factor", s.cost.factor_s},      {"condense", s.cost.condense_s},
              {"contact_solves", s.cost.lcp_s}, {"readings", s.cost.readings_s}};
  return run;
}

nlohmann::json meridian_contact_json(const Scene& scene, const MeridianContactRun& run) {
  const contact::MeridianContactResult& s = run.solved;
  const MeridianContactRun::Mode& m = run.modes.at(run.chosen);
  nlohmann::json j;
  j["scene"] = scene_json(scene);
  j["path"] = "meridian";
  j["model"] = run.model;
  j["friction"] = to_string(run.chosen);
  j["interface"] = to_string(scene.contact->interface.law);
  if (scene.contact->interface.law == InterfaceLaw::linear)
    j["interface_K_MPa_per_mm"] = scene.contact->interface.K;
  j["ratio"] = m.ratio;
  j["force_N"] = s.force_N;
  j["tangential_force_N"] = m.ratio * s.force_N;
  j["indentation_um"] = 1e3 * s.depth_mm;
  j["contact_radius_mm"] = s.contact_radius_mm;
  j["p0_kPa"] = 1e3 * s.p0_MPa;
  j["min_pressure_kPa"] = 1e3 * s.min_lambda;
  j["min_weighted_gap_mm3"] = s.min_gap;
  j["complementarity"] = s.complementarity;
  j["pivots"] = s.pivots;
  j["axis_mm"] = {run.axis[0], run.axis[1]};
  for (const auto& [mode, v] : run.modes) {
    nlohmann::json sensors = nlohmann::json::array();
    for (size_t k = 0; k < scene.sensors.positions.size(); ++k)
      sensors.push_back({{"sensor", k + 1},
                         {"x_mm", scene.sensors.positions[k][0]},
                         {"y_mm", scene.sensors.positions[k][1]},
                         {"sigma_z_kPa", 1e3 * v.readings[2 * k]},
                         {"sigma_x_kPa", 1e3 * v.readings[2 * k + 1]}});
    j["modes"][to_string(mode)] = {{"ratio", v.ratio}, {"sensors", sensors}};
  }
  j["left_out"] = nlohmann::json::array();
  for (FrictionMode mode : run.left_out) j["left_out"].push_back(to_string(mode));
  j["zone"] = {{"radius_mm", run.zone_radius}, {"multipliers", s.multipliers}};
  j["dofs"] = s.dofs;
  j["wall_s"] = run.wall;
  j["wall_total_s"] = run.wall.total();
  j["peak_rss_mb"] = peak_rss_mb();
  return j;
}

}  // namespace skinfem::pipeline
