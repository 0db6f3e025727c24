#include "skinfem/pipeline/contact_setup.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>

#include "skinfem/mesh/mirror.hpp"
#include "skinfem/pipeline/clock.hpp"
#include "skinfem/pipeline/progress.hpp"
#include "skinfem/pipeline/resources.hpp"
#include "skinfem/pipeline/symmetry.hpp"
#include "skinfem/scene/laws.hpp"
#include "skinfem/scene/texture.hpp"

namespace skinfem::pipeline {

namespace {
void throw_unless_contact(const Scene& scene) {
  if (!scene.contact)
    throw SceneError(scene.source_path + ": contact: missing; this command needs a \"contact\" section");
}

// The segment from → to run on along its line, each end to where a hole of the sweep's leaves the zone (if
// that is farther).
std::pair<Vec2, Vec2> line_through_zone(const Scene& scene, const Vec2& from, const Vec2& to) {
  const Eigen::Vector2d a(from[0], from[1]), b(to[0], to[1]);
  const double length = (b - a).norm();
  if (!(length > 0)) return {from, to};
  const Eigen::Vector2d d = (b - a) / length, c(contact_center(scene)[0], contact_center(scene)[1]);
  const double reach = contact_zone_radius(scene) + 0.5 * scene.contact->sweep->hole_diameter;
  const double t = (c - a).dot(d), off = (c - a - t * d).norm();
  if (off >= reach) return {from, to};
  const double half = std::sqrt(reach * reach - off * off);
  const Eigen::Vector2d p = a + std::min(0.0, t - half) * d, q = a + std::max(length, t + half) * d;
  return {Vec2{p.x(), p.y()}, Vec2{q.x(), q.y()}};
}

// The zone and the faces a swept hole reaches, found once, on the skin's mesh.
void find_zone(const Scene& scene, const TetMesh& mesh, ContactSkin& cs) {
  const auto& sweep = scene.contact->sweep;
  const bool watch = sweep && (cs.hole_path == HolePath::always ||
                               (cs.hole_path == HolePath::as_scene && sweep->model == HoleModel::resolved));
  cs.zone = contact::mortar_zone(mesh, contact_center(scene), contact_zone_radius(scene));
  if (watch) {
    Vec2 from = sweep->from, to = sweep->to;
    // The report's path (always) runs on along the sweep's line to the zone's edge: the perception
    // section's holes enter and leave the zone there (pipeline/report_perception.hpp).
    if (cs.hole_path == HolePath::always) std::tie(from, to) = line_through_zone(scene, from, to);
    cs.watch_faces = contact::watch_path(mesh, *cs.zone, from, to, 0.5 * sweep->hole_diameter);
  }
  // A textured plate's holes are resolved: every track through the zone is watched.
  if (const auto& t = scene.contact->texture; t && cs.hole_path != HolePath::none) {
    for (const HoleTrack& k : hole_tracks(t->holes, scene.contact->direction, *scene.contact->scan,
                                          contact_center(scene), contact_zone_radius(scene))) {
      const std::vector<int> faces = contact::watch_path(mesh, *cs.zone, k.from, k.to, k.radius);
      cs.watch_faces.insert(cs.watch_faces.end(), faces.begin(), faces.end());
    }
    std::sort(cs.watch_faces.begin(), cs.watch_faces.end());
    cs.watch_faces.erase(std::unique(cs.watch_faces.begin(), cs.watch_faces.end()), cs.watch_faces.end());
  }
}
}  // namespace

ContactSkin contact_skin(const Scene& scene, HolePath hole_path) {
  throw_unless_contact(scene);
  ContactSkin cs;
  cs.hole_path = hole_path;
  const bool springs = scene.sensors.model == SensorModel::post && !scene.sensors.post.support.rigid();
  if (springs) {
    cs.skin = skin_setup(scene, contact_mesh_part(scene));
    return cs;
  }
  cs.skin = skin_setup(scene, contact_mesh_part(scene), [&](const TetMesh& mesh) {
    find_zone(scene, mesh, cs);
    cs.columns = std::make_unique<contact::CondenseColumns>(contact::condense_columns(
        mesh, *cs.zone, SensorReadings(mesh, reading_sites(scene.sensors)).weight_block(),
        scene.contact->direction, cs.watch_faces));
    // Within the memory the run was admitted with (check_resources found this estimate available): a
    // bound that depends on the scene only, so its choice does not change with the machine's load.
    cs.columns->coupling.memory_limit_mb = 1024 * estimated_memory_gb(unknowns_bound(mesh));
    return &cs.columns->coupling;
  });
  return cs;
}

ContactSkin chain_skin(const Scene& scene, HolePath hole_path) {
  if (scene.contact) return contact_skin(scene, hole_path);
  ContactSkin cs;
  cs.skin = skin_setup(scene, contact_mesh_part(scene));
  return cs;
}

std::unique_ptr<ContactSetup> contact_setup(const Scene& scene, std::shared_ptr<Skin> skin,
                                            HolePath hole_path) {
  if (skin) {
    ContactSkin cs;
    cs.skin = std::move(skin);
    cs.hole_path = hole_path;
    return contact_setup(scene, std::move(cs));
  }
  return contact_setup(scene, contact_skin(scene, hole_path));
}

std::unique_ptr<ContactSetup> contact_setup(const Scene& scene, ContactSkin cs) {
  throw_unless_contact(scene);
  const Vec2 centre = contact_center(scene);
  auto s = std::make_unique<ContactSetup>(cs.skin);
  s->wall = s->skin->wall;
  Stopwatch clock;
  const TetMesh& solved = s->skin->mesh;
  s->zone_radius = contact_zone_radius(scene);
  s->zone_h = contact_zone_h(scene);
  s->indenter = std::make_unique<contact::Indenter>(scene, solved);
  if (!cs.zone) find_zone(scene, solved, cs);
  const contact::MortarZone& zone = *cs.zone;
  if (is_half_y(solved)) {
    if (!contact_mirror_unavailable(scene).empty())
      throw std::logic_error("contact_setup: a half skin for a contact that is not mirror-symmetric");
    s->whole = std::make_unique<TetMesh>(mirror_half(solved, &s->source));
    s->mirror = std::make_unique<contact::MirrorView>(
        contact::mirror_view(*s->whole, s->source, zone, centre, s->zone_radius));
  }
  Stopwatch condense_clock;
  s->readings = std::make_unique<SensorReadings>(solved, reading_sites(scene.sensors), &s->model->solver());
  s->condensed = std::make_unique<contact::CondensedContact>(contact::condense(
      *s->model, zone, *s->indenter, *s->readings, scene.contact->direction,
      [&](double fraction, const std::string& what) {
        char buf[160];
        std::snprintf(buf, sizeof buf, "%s: %.0f %% (%.1f s)", what.c_str(), 100 * fraction,
                      condense_clock.seconds());
        progress(buf);
      },
      cs.watch_faces, cs.columns.get(),
      [&](const contact::CondensedContact& hole_free) {
        // Fail before the path's solves (minutes on a textured plate), not after them: the commands that
        // watch a path solve these two hole-free contacts first and refuse a zone they outgrow.
        if (!scene.contact->holes.empty()) return;
        const contact::ContactSolver solver(hole_free, *scene.contact, s->mirror.get());
        for (FrictionMode mode : {FrictionMode::static_residual, FrictionMode::coupled})
          check_zone(scene, s->mesh(), solver, s->zone_radius, s->zone_h, solver.solve(mode));
      }));
  s->solver = std::make_unique<contact::ContactSolver>(*s->condensed, *scene.contact, s->mirror.get());
  s->top = std::make_unique<PlanarFaceIndex>(s->mesh(), kTop);
  s->wall["condense"] = clock.seconds();
  return s;
}

nlohmann::json condensation_json(const ContactSetup& setup) {
  nlohmann::json j = {
      {"method", setup.condensed->block_solves > 0 ? "block solves" : "bordered factorization"},
      {"block_solves", setup.condensed->block_solves}};
  if (const auto& c = setup.model->solver().border_choice())
    j["choice"] = {{"bordered", c->bordered},
                   {"bordered_factor_flops", c->bordered_flops},
                   {"plain_factor_flops", c->plain_flops},
                   {"block_solve_flops", c->solve_flops},
                   {"bordered_factor_mb", c->bordered_mb},
                   {"block_solves_instead", c->solves},
                   {"plain_factor_mb", c->plain_mb},
                   {"memory_limit_mb", c->memory_limit_mb}};
  return j;
}

std::string condensation_said(const ContactSetup& setup) {
  const int rhs = setup.condensed->block_solves;
  const std::string how = rhs > 0 ? std::to_string(rhs) + " rhs" : "from a bordered factorization";
  const auto& c = setup.model->solver().border_choice();
  if (!c || c->plain_flops == 0) return how;  // no choice was made
  char buf[300];
  std::snprintf(
      buf, sizeof buf,
      "%s, chosen on MUMPS's estimates: bordered %.2g flops, %.0f MB; plain %.2g flops and %d block "
      "solves %.2g, %.0f MB",
      how.c_str(), c->bordered_flops, c->bordered_mb, c->plain_flops, c->solves, c->solve_flops, c->plain_mb);
  std::string said = buf;
  if (c->cheaper() && !c->fits())
    said += "; the bordered one is cheaper but needs more than the run's " +
            std::to_string(static_cast<long>(c->memory_limit_mb)) + " MB";
  return said;
}

constexpr double kZoneTailFraction = 1e-3;

void check_zone(const Scene& scene, const ContactSetup& s, const contact::ContactResult& r) {
  check_zone(scene, s.mesh(), *s.solver, s.zone_radius, s.zone_h, r);
}

void check_zone(const Scene& scene, const TetMesh& mesh, const contact::ContactSolver& solver,
                double zone_radius, double zone_h, const contact::ContactResult& r) {
  const auto& z = solver.zone();
  const Vec2 c = contact_center(scene);
  const auto distance = [&](int i) {
    return std::hypot(mesh.nodes(z.vertices[i], 0) - c[0], mesh.nodes(z.vertices[i], 1) - c[1]);
  };
  // The outermost ring of multipliers lies within one element of the zone's edge.
  const double ring = zone_radius - zone_h;
  if (kind(scene.contact->interface.law).smooth) {
    // An exponential interface touches everywhere: its tail is cut at the zone's edge whatever the radius.
    // The outer ring's share of the force measures the cut (it bounds what lies beyond where the tail
    // decays within the ring's width, as on the paper's skin: R u0 / (zone radius · h) = 0.2 at u0 = 5 µm).
    double total = 0, outer = 0;
    for (int i = 0; i < z.size(); ++i) {
      const double f = std::max(0.0, r.lambda[i]) * z.area[i];
      total += f;
      if (distance(i) > ring) outer += f;
    }
    if (total > 0 && outer > kZoneTailFraction * total) {
      char buf[400];
      std::snprintf(
          buf, sizeof buf,
          "%s: contact.zone_radius = %g: the exponential interface carries %.2g of the force in the "
          "zone's outer element ring (friction %s; allowed %.0e): its tail is cut short there; give a "
          "larger contact.zone_radius",
          scene.source_path.c_str(), zone_radius, outer / total, to_string(r.mode), kZoneTailFraction);
      throw SceneError(buf);
    }
    return;
  }
  double reach = 0;
  for (int i : r.active) reach = std::max(reach, distance(i));
  check_zone_reach(scene, zone_radius, zone_h, reach, r.mode);
}

void check_zone_reach(const Scene& scene, double zone_radius, double zone_h, double reach,
                      FrictionMode mode) {
  // Contact reaching the outer ring may be cut short by the zone.
  if (reach > zone_radius - zone_h)
    throw SceneError(scene.source_path + ": contact.zone_radius = " + std::to_string(zone_radius) +
                     ": the contact (friction " + to_string(mode) + ") reaches " + std::to_string(reach) +
                     " mm from the centre, within one element (contact.h = " + std::to_string(zone_h) + ")" +
                     " mm of the zone's edge; give a larger contact.zone_radius");
}

}  // namespace skinfem::pipeline
