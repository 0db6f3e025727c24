// skinfem contact — unilateral contact of the scene's rigid indenter (plate or sphere, optional holes)
// with the skin, frictionless or with friction (static residual, uncoupled or coupled sliding), on one
// factorization condensed onto the contact multipliers. All four friction modes are solved (each a
// small dense complementarity problem once the skin is condensed); the chosen one is written in full. A
// mirror-symmetric scene (pipeline/symmetry.hpp) is solved on its half y ≥ 0 at half the force and written
// whole.
//
//   $ skinfem contact scenes/hertz_layer.json --out out/hertz
//   contact hertz_layer (none): 0.8000 N normal, 0.0000 N tangential; a = 2.4776 mm, p0 = 63.74 kPa, ...
//     80680 DOFs, 257 multipliers (mirror y = 0: the half y >= 0 solved); ...
//
// Writes DIR/pressure.vtp (contact zone: pressure_kPa, traction_kPa, gap_um, in_contact), DIR/fields.vtu
// (the volume solution of the chosen mode), DIR/sensors.csv (sensor,x_mm,y_mm,sigma_z_kPa,sigma_x_kPa),
// DIR/modes.csv (the same readings for every friction mode) and DIR/summary.json (friction_law, tau0_kPa,
// interface (interface_K_MPa_per_mm or interface_u0_um, interface_p_ref_kPa), contact_radius_mm, p0_kPa,
// indentation_um, force_N, tangential_force_N, max_penetration_um, min_pressure_kPa, pressure_centroid_x_mm,
// complementarity, every mode's metrics, coupled − uncoupled differences (centroid shifts along the sliding
// direction and as (x, y) vectors), dofs, wall_s per stage, peak_rss_mb).
#include <cmath>
#include <cstdio>
#include <sstream>

#include "app/commands.hpp"
#include "app/common.hpp"
#include "app/stages.hpp"
#include "contact/hole_cover.hpp"
#include "contact/metrics.hpp"
#include "contact/pressure_map.hpp"
#include "fem/fields.hpp"
#include "pipeline/contact_setup.hpp"
#include "pipeline/symmetry.hpp"

namespace skinfem::app {

namespace {
using contact::ContactResult;

nlohmann::json metrics_json(const contact::ContactMetrics& m, const ContactResult& r) {
  return {{"friction", contact::to_string(r.mode)},
          {"ratio", r.ratio},
          {"shear_kPa", 1e3 * r.tau},
          {"force_N", r.force_N},
          {"tangential_force_N", r.tangential_force_N},
          {"indentation_um", 1e3 * r.depth_mm},
          {"contact_radius_mm", m.contact_radius_mm},
          {"equivalent_radius_mm", m.equivalent_radius_mm},
          {"p0_kPa", 1e3 * m.p0_MPa},
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

nlohmann::json contact_stage(const Scene& scene, const ContactSetup& setup, const std::string& out_dir,
                             FrictionMode chosen) {
  const TetMesh& mesh = setup.mesh();
  nlohmann::json wall = setup.wall;
  Stopwatch clock;
  const contact::ContactSolver& solver = *setup.solver;
  const auto excluded = contact::excluded_by_holes(solver.zone(), mesh, scene.contact->holes);
  const Eigen::VectorXd covered = contact::hole_cover(solver.zone(), mesh, scene.contact->holes);
  std::map<FrictionMode, ContactResult> results;
  std::map<FrictionMode, contact::ContactMetrics> metrics;
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
  const ContactResult& r = results[chosen];
  const contact::ContactMetrics& m = metrics[chosen];

  // The volume solution of the chosen mode: one more solve with the contact load, on the solved skin (the
  // half under mirror symmetry: its zone, its multipliers).
  clock = Stopwatch();
  const auto& c = *setup.condensed;
  const TetMesh& solved = setup.skin->mesh;
  const Eigen::VectorXd f =
      c.zone.load(solver.solved_lambda(r.lambda), c.direction, r.ratio, solver.solved_lambda(r.shear));
  const MixedSolution x = setup.model->solver().solve(f);
  const Eigen::VectorXd reactions = setup.model->solver().reactions(x, f);
  const BaseTraction base(solved, reactions);
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
  for (size_t k = 0; k < scene.sensors.positions.size(); ++k) {
    const auto& p = scene.sensors.positions[k];
    const SensorReading v = base.disc_mean(p[0], p[1], scene.sensors.disc_diameter);
    reading_gap = std::max(
        {reading_gap, std::abs(v.sigma_z - r.readings[2 * k]), std::abs(v.sigma_x - r.readings[2 * k + 1])});
    reading_scale = std::max({reading_scale, std::abs(v.sigma_z), std::abs(v.sigma_x)});
  }
  wall["full_solve"] = clock.seconds();

  clock = Stopwatch();
  prepare_output_dir(out_dir);
  write_fields_vtu(out_dir + "/fields.vtu", mesh, setup.model->lame(),
                   setup.whole ? mirrored_solution(mesh, setup.source, x) : x);
  contact::write_pressure_vtp(out_dir + "/pressure.vtp", mesh, solver, r);
  std::ostringstream csv, modes;
  csv.precision(10);
  modes.precision(10);
  csv << "sensor,x_mm,y_mm,sigma_z_kPa,sigma_x_kPa\n";
  modes << "sensor,x_mm,y_mm,friction,sigma_z_kPa,sigma_x_kPa\n";
  for (size_t k = 0; k < scene.sensors.positions.size(); ++k) {
    const auto& p = scene.sensors.positions[k];
    csv << k + 1 << "," << p[0] << "," << p[1] << "," << 1e3 * r.readings[2 * k] << ","
        << 1e3 * r.readings[2 * k + 1] << "\n";
    for (const auto& [mode, res] : results)
      modes << k + 1 << "," << p[0] << "," << p[1] << "," << contact::to_string(mode) << ","
            << 1e3 * res.readings[2 * k] << "," << 1e3 * res.readings[2 * k + 1] << "\n";
  }
  write_text_atomic(out_dir + "/sensors.csv", csv.str());
  write_text_atomic(out_dir + "/modes.csv", modes.str());
  wall["write"] = clock.seconds();

  nlohmann::json summary = metrics_json(m, r);
  summary["scene"] = scene_json(scene);
  summary["friction_law"] = contact::to_string(scene.contact->law);
  if (scene.contact->law != FrictionLaw::coulomb) summary["tau0_kPa"] = 1e3 * solver.tau0();
  const Interface& interface = scene.contact->interface;
  summary["interface"] = contact::to_string(interface.law);
  if (interface.law == InterfaceLaw::linear) summary["interface_K_MPa_per_mm"] = interface.K;
  if (interface.law == InterfaceLaw::exponential) {
    summary["interface_u0_um"] = 1e3 * interface.u0;
    summary["interface_p_ref_kPa"] = 1e3 * interface.p_ref;
  }
  summary["indenter"] = scene.contact->indenter == IndenterKind::plane ? "plane" : "sphere";
  summary["p0_kPa"] = 1e3 * m.p0_MPa;
  summary["max_penetration_um"] = 1e3 * max_penetration;
  summary["pressure_centroid_x_mm"] = m.pressure_centroid[0];
  summary["readings_condensed_vs_reactions_rel"] = reading_scale > 0 ? reading_gap / reading_scale : 0.0;
  summary["residual"] = x.residual;
  for (const auto& [mode, res] : results)
    summary["modes"][contact::to_string(mode)] = metrics_json(metrics[mode], res);
  // What coupling changes: coupled − uncoupled at the same μ (the paper's assumption is "nothing").
  const auto& cu = metrics[FrictionMode::coupled];
  const auto& un = metrics[FrictionMode::uncoupled];
  // Shifts along the sliding direction t (positive: ahead), and their (x, y) vectors.
  const Vec2 t = scene.contact->direction;
  const Vec2 dp{cu.pressure_centroid[0] - un.pressure_centroid[0],
                cu.pressure_centroid[1] - un.pressure_centroid[1]};
  const Vec2 dz{cu.zone_centroid[0] - un.zone_centroid[0], cu.zone_centroid[1] - un.zone_centroid[1]};
  nlohmann::json coupling = {{"mu", scene.contact->mu},
                             {"direction", {t[0], t[1]}},
                             {"pressure_centroid_shift_mm", dp[0] * t[0] + dp[1] * t[1]},
                             {"pressure_centroid_shift_xy_mm", {dp[0], dp[1]}},
                             {"zone_centroid_shift_mm", dz[0] * t[0] + dz[1] * t[1]},
                             {"zone_centroid_shift_xy_mm", {dz[0], dz[1]}},
                             {"front_back_peak_ratio_coupled", cu.front_back_peak_ratio},
                             {"front_back_peak_ratio_uncoupled", un.front_back_peak_ratio},
                             {"indentation_change_um", 1e3 * (results[FrictionMode::coupled].depth_mm -
                                                              results[FrictionMode::uncoupled].depth_mm)}};
  for (size_t k = 0; k < scene.sensors.positions.size(); ++k) {
    const auto& a = results[FrictionMode::coupled].readings;
    const auto& b = results[FrictionMode::uncoupled].readings;
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
  const std::string why_whole = scene.symmetry == SymmetryUse::none  ? "\"symmetry\": \"none\""
                                : !mirror_unavailable(scene).empty() ? mirror_unavailable(scene)
                                                                     : contact_mirror_unavailable(scene);
  summary["symmetry"] =
      setup.whole ? "mirror y = 0: the half y >= 0 solved" : "whole skin solved: " + why_whole;
  summary["dofs"] = setup.model->solver().free_dofs();
  summary["nodes"] = mesh.num_nodes();
  summary["elements"] = mesh.num_tets();
  summary["block_solves"] = c.block_solves;
  summary["wall_s"] = wall;
  summary["wall_total_s"] = total_seconds(wall);
  summary["peak_rss_mb"] = peak_rss_mb();
  write_json(out_dir + "/summary.json", summary);

  std::printf(
      "contact %s (%s): %.4f N normal, %.4f N tangential; a = %.4f mm, p0 = %.2f kPa, indentation %.3f um\n",
      scene.name.c_str(), contact::to_string(chosen), r.force_N, r.tangential_force_N, m.contact_radius_mm,
      1e3 * m.p0_MPa, 1e3 * r.depth_mm);
  if (interface.law == InterfaceLaw::linear)
    std::printf("  linear interface: K = %.4g MPa/mm, it closes by %.3g um under p0\n", interface.K,
                1e3 * m.p0_MPa / interface.K);
  if (interface.law == InterfaceLaw::exponential)
    std::printf("  exponential interface: u0 = %.4g um, p_ref = %.4g kPa; %d Newton steps, residual %.1e\n",
                1e3 * interface.u0, 1e3 * interface.p_ref, r.pivots, r.complementarity);
  std::printf(
      "  complementarity %.1e, min pressure %.2e kPa, max pointwise penetration %.3g um, condensed vs "
      "reaction readings %.1e\n",
      r.complementarity, 1e3 * r.min_lambda, 1e3 * max_penetration,
      summary["readings_condensed_vs_reactions_rel"].get<double>());
  std::printf(
      "  coupled - uncoupled (mu %.3g, sliding along (%.3g, %.3g)): pressure centroid %+.4f mm ahead "
      "(x %+.4f, y %+.4f), contact zone %+.4f mm ahead, front/back peak %.4f vs %.4f\n",
      scene.contact->mu, t[0], t[1], coupling["pressure_centroid_shift_mm"].get<double>(), dp[0], dp[1],
      coupling["zone_centroid_shift_mm"].get<double>(), cu.front_back_peak_ratio, un.front_back_peak_ratio);
  std::printf(
      "  %d DOFs, %d multipliers (%s); mesh %.2f s, assemble %.2f s, factor %.2f s, "
      "condense %.2f s (%d rhs), contact %.3f s; peak %.0f MB\n",
      setup.model->solver().free_dofs(), c.zone.size(), summary["symmetry"].get<std::string>().c_str(),
      wall["mesh"].get<double>(), wall["assemble"].get<double>(), wall["factor"].get<double>(),
      wall["condense"].get<double>(), c.block_solves, wall["contact_solves"].get<double>(), peak_rss_mb());
  std::printf("  wrote %s/pressure.vtp, fields.vtu, sensors.csv, modes.csv, summary.json\n", out_dir.c_str());
  return summary;
}

int run_contact(const Scene& scene, const std::string& out_dir, const std::string& friction) {
  if (!scene.contact)
    throw SceneError(scene.source_path + ": contact: missing; skinfem contact needs a \"contact\" section");
  FrictionMode chosen = scene.contact->friction;
  if (friction == "none") chosen = FrictionMode::none;
  if (friction == "static") chosen = FrictionMode::static_residual;
  if (friction == "uncoupled") chosen = FrictionMode::uncoupled;
  if (friction == "coupled") chosen = FrictionMode::coupled;
  check_output_dir(out_dir);
  contact_stage(scene, *contact_setup(scene, nullptr, false), out_dir, chosen);
  return 0;
}

}  // namespace skinfem::app
