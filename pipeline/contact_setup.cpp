#include "pipeline/contact_setup.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "mesh/mirror.hpp"
#include "pipeline/clock.hpp"
#include "pipeline/progress.hpp"
#include "pipeline/symmetry.hpp"

namespace skinfem::pipeline {

std::unique_ptr<ContactSetup> contact_setup(const Scene& scene, std::shared_ptr<Skin> skin,
                                            HolePath hole_path) {
  if (!scene.contact)
    throw SceneError(scene.source_path + ": contact: missing; this command needs a \"contact\" section");
  auto s =
      std::make_unique<ContactSetup>(skin ? std::move(skin) : skin_setup(scene, contact_mesh_part(scene)));
  s->wall = s->skin->wall;
  Stopwatch clock;
  const TetMesh& solved = s->skin->mesh;
  s->zone_radius = contact_zone_radius(scene);
  s->zone_h = contact_zone_h(scene);
  s->indenter = std::make_unique<contact::Indenter>(scene, solved);
  const auto zone = contact::mortar_zone(solved, contact_center(scene), s->zone_radius);
  if (is_half_y(solved)) {
    if (!contact_mirror_unavailable(scene).empty())
      throw std::logic_error("contact_setup: a half skin for a contact that is not mirror-symmetric");
    s->whole = std::make_unique<TetMesh>(mirror_half(solved, &s->source));
    s->mirror = std::make_unique<contact::MirrorView>(
        contact::mirror_view(*s->whole, s->source, zone, contact_center(scene), s->zone_radius));
  }
  std::vector<int> watch_faces;
  const auto& sweep = scene.contact->sweep;
  if (sweep && (hole_path == HolePath::always ||
                (hole_path == HolePath::as_scene && sweep->model == HoleModel::resolved))) {
    const HoleSweep& sw = *scene.contact->sweep;
    watch_faces = contact::watch_path(solved, zone, sw.from, sw.to, 0.5 * sw.hole_diameter);
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
      watch_faces));
  s->solver = std::make_unique<contact::ContactSolver>(*s->condensed, *scene.contact, s->mirror.get());
  s->top = std::make_unique<PlanarFaceIndex>(s->mesh(), kTop);
  s->wall["condense"] = clock.seconds();
  return s;
}

void check_zone(const Scene& scene, const ContactSetup& s, const contact::ContactResult& r) {
  const auto& z = s.solver->zone();
  const Vec2 c = contact_center(scene);
  double reach = 0;
  // The active set: λ > 0 in a hard or linear contact, λ ≥ 1e-6 of its peak through an exponential one.
  for (int i : r.active)
    reach = std::max(
        reach, std::hypot(s.mesh().nodes(z.vertices[i], 0) - c[0], s.mesh().nodes(z.vertices[i], 1) - c[1]));
  // The outermost ring of multipliers lies within one element of the zone's edge: contact reaching it may be
  // cut short by the zone.
  if (reach > s.zone_radius - s.zone_h)
    throw SceneError(scene.source_path + ": contact.zone_radius = " + std::to_string(s.zone_radius) +
                     ": the contact (friction " + contact::to_string(r.mode) + ") reaches " +
                     std::to_string(reach) +
                     " mm from the centre, within one element (contact.h = " + std::to_string(s.zone_h) +
                     ")" + " mm of the zone's edge; give a larger contact.zone_radius");
}

}  // namespace skinfem::pipeline
