#include "skinfem/pipeline/contact.hpp"

#include <algorithm>
#include <cmath>

#include "skinfem/contact/holes/cover.hpp"
#include "skinfem/contact/pressure_map.hpp"
#include "skinfem/pipeline/clock.hpp"
#include "skinfem/pipeline/meridian_contact.hpp"
#include "skinfem/pipeline/scene_json.hpp"
#include "skinfem/pipeline/symmetry.hpp"
#include "skinfem/scene/laws.hpp"

namespace skinfem::pipeline {

namespace {
using contact::ContactResult;

// null where the first-touch point lies in a hole (a 0 there would read as a measured pressure).
nlohmann::json p0_json(const contact::ContactMetrics& m) {
  return m.p0_in_hole ? nlohmann::json() : nlohmann::json(1e3 * m.p0_MPa);
}

nlohmann::json metrics_json(const contact::ContactMetrics& m, const ContactResult& r) {
  return {{"friction", to_string(r.mode)},
          {"ratio", r.ratio},
          {"shear_kPa", 1e3 * r.tau},
          {"force_N", r.force_N},
          {"tangential_force_N", r.tangential_force_N},
          {"indentation_um", 1e3 * r.depth_mm},
          {"contact_radius_mm", m.contact_radius_mm},
          {"equivalent_radius_mm", m.equivalent_radius_mm},
          {"p0_kPa", p0_json(m)},
          {"p_max_kPa", 1e3 * m.p_max_MPa},
          {"pressure_centroid_mm", {m.pressure_centroid[0], m.pressure_centroid[1]}},
          {"zone_centroid_mm", {m.zone_centroid[0], m.zone_centroid[1]}},
          {"front_back_peak_ratio", m.front_back_peak_ratio},
          {"front_edge_mm", m.front_edge_mm},
          {"back_edge_mm", m.back_edge_mm},
          {"min_pressure_kPa", 1e3 * r.min_lambda},
          {"min_weighted_gap_mm3", r.min_gap},
          {"complementarity", r.complementarity},
          {"active_multipliers", r.active.size()},
          {"pivots", r.pivots}};
}
}  // namespace

void require_contact(const Scene& scene) {
  if (!scene.contact)
    throw SceneError(scene.source_path + ": contact: missing; skinfem contact needs a \"contact\" section");
}

FrictionMode friction_mode_named(const Scene& scene, const std::string& name) {
  require_contact(scene);
  if (name.empty() || name == "scene") return scene.contact->friction;
  if (const auto mode = skinfem::friction_mode_named(name)) return *mode;
  throw SceneError("friction: '" + name + "' is not one of " + choice_list(friction_mode_names(), false));
}

ContactRun contact_run(const Scene& scene, std::shared_ptr<const ContactSetup> shared, FrictionMode chosen,
                       const MeridianContactRun* frictionless) {
  require_contact(scene);
  ContactRun run;
  run.setup = std::move(shared);
  run.chosen = chosen;
  const ContactSetup& setup = *run.setup;
  const TetMesh& mesh = setup.mesh();
  Timings& wall = run.wall;
  wall = setup.wall;
  Stopwatch clock;
  const contact::ContactSolver& solver = *setup.solver;
  const auto excluded = contact::excluded_by_holes(solver.zone(), mesh, scene.contact->holes);
  const Eigen::VectorXd covered = contact::hole_cover(solver.zone(), mesh, scene.contact->holes);
  auto& results = run.results;
  auto& metrics = run.metrics;
  const Vec2 centre = contact_center(scene);
  for (FrictionMode mode :
       {FrictionMode::none, FrictionMode::static_residual, FrictionMode::uncoupled, FrictionMode::coupled}) {
    results[mode] = solver.solve(mode, excluded, {}, covered);
    check_zone(scene, setup, results[mode]);
    for (size_t h = 0; h < scene.contact->holes.size(); ++h)
      contact::require_hole_resolved(solver.zone(), mesh, scene.contact->holes[h], results[mode].active,
                                     "contact.holes[" + std::to_string(h) + "]");
    metrics[mode] =
        contact::contact_metrics(solver, mesh, *setup.top, results[mode], centre, scene.contact->holes);
  }
  wall["contact_solves"] = clock.seconds();
  if (meridian_contact_unavailable(scene, FrictionMode::none, false).empty()) {
    Stopwatch check_clock;
    std::optional<MeridianContactRun> here;
    if (!frictionless) here = meridian_contact_run(scene, FrictionMode::none);
    const MeridianContactRun& m = frictionless ? *frictionless : *here;
    ContactRun::MeridianCheck c;
    double gap = 0, scale = 0;
    for (FrictionMode mode : {FrictionMode::none, FrictionMode::uncoupled}) {
      gap = std::max(gap, (results[mode].readings - m.modes.at(mode).readings).cwiseAbs().maxCoeff());
      scale = std::max(scale, m.modes.at(mode).readings.cwiseAbs().maxCoeff());
    }
    c.readings_rel = scale > 0 ? gap / scale : 0.0;
    const contact::ContactMetrics& fm = metrics[FrictionMode::none];
    c.a_rel = fm.contact_radius_mm / m.solved.contact_radius_mm - 1;
    c.p0_rel = fm.p0_MPa / m.solved.p0_MPa - 1;
    c.indentation_rel = results[FrictionMode::none].depth_mm / m.solved.depth_mm - 1;
    c.dofs = m.solved.dofs;
    c.seconds = frictionless ? m.wall.total() : check_clock.seconds();
    c.frictionless = m.solved;
    run.meridian_check = c;
    wall["meridian_check"] = c.seconds;
  }
  const ContactResult& r = results[chosen];

  // The volume solution of the chosen mode: one more solve with the contact load, on the solved skin (the
  // half under mirror symmetry: its zone, its multipliers).
  clock = Stopwatch();
  const auto& c = *setup.condensed;
  const TetMesh& solved = setup.skin->mesh;
  const Eigen::VectorXd f =
      c.zone.load(solver.solved_lambda(r.lambda), c.direction, r.ratio, solver.solved_lambda(r.shear));
  run.solution = setup.model->solver().solve(f);
  const MixedSolution& x = run.solution;
  run.reactions = setup.model->solver().reactions(x, f);
  const Eigen::VectorXd& reactions = run.reactions;
  // Pointwise gap at every node of the zone's faces (the constraint holds it ≥ 0 in the hat-weighted mean).
  double max_penetration = 0;
  for (int face : c.zone.faces)
    for (int k = 0; k < 6; ++k) {
      const int n = solved.faces(face, k);
      const double gap = setup.indenter->z_touch() - r.depth_mm +
                         setup.indenter->phi(solved.nodes(n, 0), solved.nodes(n, 1)) - solved.nodes(n, 2) -
                         x.u[3 * n + 2];
      const bool under_hole = [&] {
        for (const Hole& h : scene.contact->holes)
          if (std::hypot(solved.nodes(n, 0) - h.center[0], solved.nodes(n, 1) - h.center[1]) <
              0.5 * h.diameter + 1e-12)
            return true;
        return false;
      }();
      if (!under_hole) max_penetration = std::max(max_penetration, -gap);
    }
  // The condensed readings (adjoints) against the reactions of the full solve: a second method.
  double reading_gap = 0, reading_scale = 0;
  for (int k = 0; k < setup.readings->size(); ++k) {
    const SensorReading v = setup.readings->read(k, reactions);
    reading_gap = std::max(
        {reading_gap, std::abs(v.sigma_z - r.readings[2 * k]), std::abs(v.sigma_x - r.readings[2 * k + 1])});
    reading_scale = std::max({reading_scale, std::abs(v.sigma_z), std::abs(v.sigma_x)});
  }
  wall["full_solve"] = clock.seconds();
  run.max_penetration_mm = max_penetration;
  run.readings_condensed_vs_reactions_rel = reading_scale > 0 ? reading_gap / reading_scale : 0.0;
  const auto& cu = run.metrics.at(FrictionMode::coupled);
  const auto& un = run.metrics.at(FrictionMode::uncoupled);
  const Vec2 t = scene.contact->direction;
  auto& shift = run.coupling_shift;
  shift.pressure_xy_mm = {cu.pressure_centroid[0] - un.pressure_centroid[0],
                          cu.pressure_centroid[1] - un.pressure_centroid[1]};
  shift.zone_xy_mm = {cu.zone_centroid[0] - un.zone_centroid[0], cu.zone_centroid[1] - un.zone_centroid[1]};
  shift.pressure_mm = shift.pressure_xy_mm[0] * t[0] + shift.pressure_xy_mm[1] * t[1];
  shift.zone_mm = shift.zone_xy_mm[0] * t[0] + shift.zone_xy_mm[1] * t[1];
  contact::check_hole_clearance(mesh, solver, run.result(), scene.contact->holes, "contact.holes");
  return run;
}

std::string symmetry_used(const Scene& scene, const ContactSetup& setup) {
  return symmetry_said(scene, setup.whole != nullptr);
}

std::string symmetry_said(const Scene& scene, bool half_solved) {
  if (half_solved) return "mirror y = 0: the half y >= 0 solved";
  const std::string why_whole = scene.symmetry == SymmetryUse::none  ? "\"symmetry\": \"none\""
                                : !mirror_unavailable(scene).empty() ? mirror_unavailable(scene)
                                                                     : contact_mirror_unavailable(scene);
  return "whole skin solved: " + why_whole;
}

nlohmann::json contact_json(const Scene& scene, const ContactRun& run) {
  const ContactSetup& setup = *run.setup;
  const contact::ContactSolver& solver = *setup.solver;
  const auto& c = *setup.condensed;
  const TetMesh& mesh = setup.mesh();
  const ContactResult& r = run.result();
  const contact::ContactMetrics& m = run.metric();
  const auto& results = run.results;
  const auto& metrics = run.metrics;
  nlohmann::json summary = metrics_json(m, r);
  summary["scene"] = scene_json(scene);
  summary["path"] = "3d";
  if (!run.not_meridian.empty()) summary["not_meridian"] = run.not_meridian;
  summary["friction_law"] = to_string(scene.contact->law);
  if (kind(scene.contact->law).shear_strength) summary["tau0_kPa"] = 1e3 * solver.tau0();
  const Interface& interface = scene.contact->interface;
  summary["interface"] = to_string(interface.law);
  if (interface.law == InterfaceLaw::linear) summary["interface_K_MPa_per_mm"] = interface.K;
  if (interface.law == InterfaceLaw::exponential) {
    summary["interface_u0_um"] = 1e3 * interface.u0;
    summary["interface_p_ref_kPa"] = 1e3 * interface.p_ref;
  }
  summary["indenter"] = scene.contact->indenter == IndenterKind::plane ? "plane" : "sphere";
  summary["p0_kPa"] = p0_json(m);
  if (m.p0_in_hole) summary["p0_note"] = "the first-touch point lies in a hole: no pressure there";
  summary["max_penetration_um"] = 1e3 * run.max_penetration_mm;
  summary["pressure_centroid_x_mm"] = m.pressure_centroid[0];
  summary["readings_condensed_vs_reactions_rel"] = run.readings_condensed_vs_reactions_rel;
  if (const auto& c = run.meridian_check)
    summary["meridian_check"] = {
        {"readings_rel", c->readings_rel},
        {"contact_radius_rel", c->a_rel},
        {"p0_rel", c->p0_rel},
        {"indentation_rel", c->indentation_rel},
        {"dofs", c->dofs},
        {"modes", {to_string(FrictionMode::none), to_string(FrictionMode::uncoupled)}}};
  summary["residual"] = run.solution.residual;
  for (const auto& [mode, res] : results)
    summary["modes"][to_string(mode)] = metrics_json(metrics.at(mode), res);
  // What coupling changes: coupled − uncoupled at the same μ (the paper's assumption is "nothing").
  const auto& cu = metrics.at(FrictionMode::coupled);
  const auto& un = metrics.at(FrictionMode::uncoupled);
  // Shifts along the sliding direction t (positive: ahead), and their (x, y) vectors.
  const Vec2 t = scene.contact->direction;
  const auto& shift = run.coupling_shift;
  nlohmann::json coupling = {
      {"mu", scene.contact->mu},
      {"direction", {t[0], t[1]}},
      {"pressure_centroid_shift_mm", shift.pressure_mm},
      {"pressure_centroid_shift_xy_mm", {shift.pressure_xy_mm[0], shift.pressure_xy_mm[1]}},
      {"zone_centroid_shift_mm", shift.zone_mm},
      {"zone_centroid_shift_xy_mm", {shift.zone_xy_mm[0], shift.zone_xy_mm[1]}},
      {"front_back_peak_ratio_coupled", cu.front_back_peak_ratio},
      {"front_back_peak_ratio_uncoupled", un.front_back_peak_ratio},
      {"indentation_change_um",
       1e3 * (results.at(FrictionMode::coupled).depth_mm - results.at(FrictionMode::uncoupled).depth_mm)}};
  for (size_t k = 0; k < scene.sensors.positions.size(); ++k) {
    const auto& a = results.at(FrictionMode::coupled).readings;
    const auto& b = results.at(FrictionMode::uncoupled).readings;
    coupling["sensors"].push_back({{"sensor", k + 1},
                                   {"x_mm", scene.sensors.positions[k][0]},
                                   {"dsigma_z_kPa", 1e3 * (a[2 * k] - b[2 * k])},
                                   {"dsigma_x_kPa", 1e3 * (a[2 * k + 1] - b[2 * k + 1])}});
  }
  summary["coupled_minus_uncoupled"] = coupling;
  summary["zone"] = {{"radius_mm", setup.zone_radius},
                     {"h_mm", setup.zone_h},
                     {"multipliers", solver.zone().size()},
                     {"multipliers_solved", c.zone.size()}};
  summary["symmetry"] = symmetry_used(scene, setup);
  summary["dofs"] = setup.model->solver().free_dofs();
  summary["nodes"] = mesh.num_nodes();
  summary["elements"] = mesh.num_tets();
  summary["block_solves"] = c.block_solves;
  summary["condensation"] = condensation_json(setup);
  summary["wall_s"] = run.wall;
  summary["wall_total_s"] = run.wall.total();
  summary["peak_rss_mb"] = peak_rss_mb();
  return summary;
}

}  // namespace skinfem::pipeline
