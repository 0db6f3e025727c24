// skinfem contact — unilateral contact of the scene's rigid indenter (plate or sphere, optional holes)
// with the skin, frictionless or with friction (static residual, uncoupled or coupled sliding), on one
// factorization condensed onto the contact multipliers. All four friction modes are solved (each a
// small dense complementarity problem once the skin is condensed); the chosen one is written in full. A
// mirror-symmetric scene (pipeline/symmetry.hpp) is solved on its half y ≥ 0 at half the force and written
// whole. Where the skin is a body of revolution about the indenter (pipeline/meridian_contact.hpp) the
// contact is solved on its meridian instead (`--path meridian`, or `auto` where every reported mode is
// exact there), and a 3D run checks itself against it (meridian_check). On the neo-Hookean skin
// (material.model) a plate or a sphere, frictionless, at rest or in coupled sliding, by Newton on the
// deformed skin (pipeline/finite_contact.hpp), its zone in the reference and the current frame.
//
//   $ skinfem contact scenes/hertz_layer.json --out out/hertz
//   contact hertz_layer (none), meridian path: 0.8000 N normal, 0.0000 N tangential; a = 2.4878 mm, ...
//     32069 DOFs, 89 multipliers (second pass, graded to the edge); ...
//   $ skinfem contact scenes/candelier2011.json --out out/contact
//   contact candelier2011 (coupled): 0.8000 N normal, 2.4000 N tangential; ...
//     against the meridian (frictionless and uncoupled, exact in 2D, 67986 DOFs, 0.77 s): readings ...
//
// Writes (3D) DIR/pressure.vtp (contact zone: pressure_kPa, traction_kPa, gap_um, in_contact), DIR/fields.vtu
// (the volume solution of the chosen mode), DIR/sensors.csv (sensor,x_mm,y_mm,sigma_z_kPa,sigma_x_kPa),
// DIR/modes.csv (the same readings for every friction mode) and DIR/summary.json (path, friction_law,
// tau0_kPa, interface (interface_K_MPa_per_mm or interface_u0_um, interface_p_ref_kPa), contact_radius_mm,
// p0_kPa, indentation_um, force_N, tangential_force_N, max_penetration_um, min_pressure_kPa,
// pressure_centroid_x_mm, complementarity, every mode's metrics, coupled − uncoupled differences (centroid
// shifts along the sliding direction and as (x, y) vectors), meridian_check, not_meridian, dofs, wall_s per
// stage, peak_rss_mb); on the meridian DIR/pressure.csv (r_mm,pressure_kPa,weighted_gap_mm3), sensors.csv,
// modes.csv (the modes solved) and summary.json (path, model, left_out, the modes' readings); neo-Hookean:
// pressure.vtp (with displacement_mm), fields.vtu (Cauchy's stress), sensors.csv and summary.json (both
// frames, each load step's Newton residuals). The
// computations and summaries are pipeline/contact.hpp's and pipeline/meridian_contact.hpp's; this file
// writes and prints them.
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

#include "app/commands.hpp"
#include "app/common.hpp"
#include "app/stages.hpp"
#include "skinfem/contact/metrics.hpp"
#include "skinfem/contact/pressure_map.hpp"
#include "skinfem/fem/fields.hpp"
#include "skinfem/pipeline/contact.hpp"
#include "skinfem/pipeline/contact_setup.hpp"
#include "skinfem/pipeline/finite_contact.hpp"
#include "skinfem/pipeline/meridian_contact.hpp"

namespace skinfem::app {

namespace {
// sensors.csv; r: 2·sensors readings (σ_z of sensor k at 2k, σ_x at 2k + 1), MPa.
void write_sensors_csv(const std::string& out_dir, const Scene& scene, const Eigen::VectorXd& r) {
  std::ostringstream csv;
  csv.precision(10);
  csv << "sensor,x_mm,y_mm,sigma_z_kPa,sigma_x_kPa\n";
  for (size_t k = 0; k < scene.sensors.positions.size(); ++k) {
    const auto& p = scene.sensors.positions[k];
    csv << k + 1 << "," << p[0] << "," << p[1] << "," << 1e3 * r[2 * k] << "," << 1e3 * r[2 * k + 1] << "\n";
  }
  write_text_atomic(out_dir + "/sensors.csv", csv.str());
}

// sensors.csv (the chosen mode) and modes.csv (every mode solved); readings: 2·sensors per mode, MPa.
void write_readings(const std::string& out_dir, const Scene& scene, FrictionMode chosen,
                    const std::map<FrictionMode, Eigen::VectorXd>& readings) {
  std::ostringstream modes;
  modes.precision(10);
  modes << "sensor,x_mm,y_mm,friction,sigma_z_kPa,sigma_x_kPa\n";
  write_sensors_csv(out_dir, scene, readings.at(chosen));
  for (size_t k = 0; k < scene.sensors.positions.size(); ++k) {
    const auto& p = scene.sensors.positions[k];
    for (const auto& [mode, v] : readings)
      modes << k + 1 << "," << p[0] << "," << p[1] << "," << to_string(mode) << "," << 1e3 * v[2 * k] << ","
            << 1e3 * v[2 * k + 1] << "\n";
  }
  write_text_atomic(out_dir + "/modes.csv", modes.str());
}
}  // namespace

void write_contact(const Scene& scene, const ContactRun& run, nlohmann::json& summary,
                   const std::string& out_dir) {
  const FrictionMode chosen = run.chosen;
  const ContactSetup& setup = *run.setup;
  const TetMesh& mesh = setup.mesh();
  const contact::ContactSolver& solver = *setup.solver;
  const auto& c = *setup.condensed;
  const contact::ContactResult& r = run.result();
  const contact::ContactMetrics& m = run.metric();
  const MixedSolution& x = run.solution;
  Stopwatch clock;
  prepare_output_dir(out_dir);
  write_fields_vtu(out_dir + "/fields.vtu", mesh, setup.model->lame(),
                   setup.whole ? mirrored_solution(mesh, setup.source, x) : x);
  contact::write_pressure_vtp(out_dir + "/pressure.vtp", mesh, solver, r, scene.contact->holes);
  std::map<FrictionMode, Eigen::VectorXd> readings;
  for (const auto& [mode, res] : run.results) readings[mode] = res.readings;
  write_readings(out_dir, scene, chosen, readings);
  add_write_seconds(summary, clock.seconds());
  write_json(out_dir + "/summary.json", summary);
  const Interface& interface = scene.contact->interface;
  const Vec2 t = scene.contact->direction;
  const auto& cu = run.metrics.at(FrictionMode::coupled);
  const auto& un = run.metrics.at(FrictionMode::uncoupled);
  const auto& shift = run.coupling_shift;

  char p0[64];
  std::snprintf(p0, sizeof p0, m.p0_in_hole ? "p0 - (the first-touch point is in a hole)" : "p0 = %.2f kPa",
                1e3 * m.p0_MPa);
  std::printf(
      "contact %s (%s): %.4f N normal, %.4f N tangential; a = %.4f mm (area-equivalent %.4f mm), %s, "
      "indentation %.3f um\n",
      scene.name.c_str(), to_string(chosen), r.force_N, r.tangential_force_N, m.contact_radius_mm,
      m.equivalent_radius_mm, p0, 1e3 * r.depth_mm);
  if (interface.law == InterfaceLaw::linear && !m.p0_in_hole)
    std::printf("  linear interface: K = %.4g MPa/mm, it closes by %.3g um under p0\n", interface.K,
                1e3 * m.p0_MPa / interface.K);
  if (interface.law == InterfaceLaw::exponential)
    std::printf("  exponential interface: u0 = %.4g um, p_ref = %.4g kPa; %d Newton steps, residual %.1e\n",
                1e3 * interface.u0, 1e3 * interface.p_ref, r.pivots, r.complementarity);
  std::printf(
      "  complementarity %.1e, min pressure %.2e kPa, max pointwise penetration %.3g um, condensed vs "
      "reaction readings %.1e\n",
      r.complementarity, 1e3 * r.min_lambda, 1e3 * run.max_penetration_mm,
      run.readings_condensed_vs_reactions_rel);
  std::printf(
      "  coupled - uncoupled (mu %.3g, sliding along (%.3g, %.3g)): pressure centroid %+.4f mm ahead "
      "(x %+.4f, y %+.4f), contact zone %+.4f mm ahead, front/back peak %.4f vs %.4f\n",
      scene.contact->mu, t[0], t[1], shift.pressure_mm, shift.pressure_xy_mm[0], shift.pressure_xy_mm[1],
      shift.zone_mm, cu.front_back_peak_ratio, un.front_back_peak_ratio);
  std::printf(
      "  %d DOFs, %d multipliers (%s); mesh %.2f s, assemble %.2f s, factor %.2f s, "
      "condense %.2f s (%s), contact %.3f s; peak %.0f MB\n",
      setup.model->solver().free_dofs(), c.zone.size(), symmetry_used(scene, setup).c_str(),
      run.wall.at("mesh"), run.wall.at("assemble"), run.wall.at("factor"), run.wall.at("condense"),
      condensation_said(setup).c_str(), run.wall.at("contact_solves"), peak_rss_mb());
  if (const auto& mc = run.meridian_check)
    std::printf(
        "  against the meridian (frictionless and uncoupled, exact in 2D, %d DOFs, %.2f s): readings within "
        "%.1e of the largest; a %+.1e, p0 %+.1e, indentation %+.1e\n",
        mc->dofs, mc->seconds, mc->readings_rel, mc->a_rel, mc->p0_rel, mc->indentation_rel);
  if (!run.not_meridian.empty())
    std::printf("  3D path: the meridian does not apply: %s\n", run.not_meridian.c_str());
  std::printf("  wrote %s/pressure.vtp, fields.vtu, sensors.csv, modes.csv, summary.json\n", out_dir.c_str());
}

namespace {
void meridian_contact_stage(const Scene& scene, const std::string& out_dir, FrictionMode chosen) {
  MeridianContactRun run = meridian_contact_run(scene, chosen);
  const contact::MeridianContactResult& s = run.solved;
  const MeridianContactRun::Mode& m = run.modes.at(chosen);
  Stopwatch clock;
  prepare_output_dir(out_dir);
  std::ostringstream pressure;
  pressure.precision(10);
  pressure << "r_mm,pressure_kPa,weighted_gap_mm3\n";
  for (size_t i = 0; i < s.r.size(); ++i)
    pressure << s.r[i] << "," << 1e3 * s.lambda[i] << "," << s.gap[i] << "\n";
  write_text_atomic(out_dir + "/pressure.csv", pressure.str());
  std::map<FrictionMode, Eigen::VectorXd> readings;
  for (const auto& [mode, v] : run.modes) readings[mode] = v.readings;
  write_readings(out_dir, scene, chosen, readings);
  run.wall["write"] = clock.seconds();
  const nlohmann::json summary = meridian_contact_json(scene, run);
  write_json(out_dir + "/summary.json", summary);
  const Timings& wall = run.wall;
  std::printf(
      "contact %s (%s), meridian path: %.4f N normal, %.4f N tangential; a = %.4f mm, p0 = %.2f kPa, "
      "indentation %.3f um\n",
      scene.name.c_str(), to_string(chosen), s.force_N, m.ratio * s.force_N, s.contact_radius_mm,
      1e3 * s.p0_MPa, 1e3 * s.depth_mm);
  std::printf("  %s\n", run.model.c_str());
  if (scene.contact->interface.law == InterfaceLaw::linear)
    std::printf("  linear interface: K = %.4g MPa/mm, it closes by %.3g um under p0\n",
                scene.contact->interface.K, 1e3 * s.p0_MPa / scene.contact->interface.K);
  std::printf("  complementarity %.1e, min pressure %.2e kPa\n", s.complementarity, 1e3 * s.min_lambda);
  std::string left;
  for (FrictionMode mode : run.left_out) left += std::string(left.empty() ? "" : ", ") + to_string(mode);
  if (!left.empty())
    std::printf(
        "  left out (not exact on the meridian, their contact zone is not a disc): %s; --path 3d solves "
        "them\n",
        left.c_str());
  std::printf(
      "  %d DOFs, %d multipliers (second pass, graded to the edge); mesh %.3f s, assemble %.3f s, factor "
      "%.3f s, "
      "condense %.3f s, contact %.3f s, readings %.3f s; peak %.0f MB\n",
      s.dofs, s.multipliers, wall.at("mesh"), wall.at("assemble"), wall.at("factor"), wall.at("condense"),
      wall.at("contact_solves"), wall.at("readings"), peak_rss_mb());
  std::printf("  wrote %s/pressure.csv, sensors.csv, modes.csv, summary.json\n", out_dir.c_str());
}
}  // namespace

namespace {
void print_frame(const char* name, const contact::ContactZoneFrame& f) {
  std::printf(
      "  %s frame: area %.4f mm2, force centroid (%.4f, %.4f) mm, zone centroid (%.4f, %.4f) mm, front %.4f "
      "and back %.4f mm, half width %.4f mm\n",
      name, f.area_mm2, f.force_centroid[0], f.force_centroid[1], f.zone_centroid[0], f.zone_centroid[1],
      f.front_mm, f.back_mm, f.half_width_mm);
}

int finite_contact_stage(const Scene& scene, const std::string& out_dir, FrictionMode chosen) {
  const FiniteContactRun run = finite_contact_run(scene, chosen);
  const contact::FiniteContactResult& r = run.result;
  nlohmann::json summary = finite_contact_json(scene, run);
  Stopwatch clock;
  prepare_output_dir(out_dir);
  write_fields_vtu(out_dir + "/fields.vtu", *run.mesh, Lame::from(scene.material.E, scene.material.nu),
                   r.solution, StressMeasure::neo_hookean);
  const Eigen::Vector2d t(scene.contact->direction[0], scene.contact->direction[1]);
  contact::write_finite_pressure_vtp(out_dir + "/pressure.vtp", *run.mesh, run.zone, r, t,
                                     summary["ratio"].get<double>());
  Eigen::VectorXd readings(2 * run.readings.size());
  for (size_t k = 0; k < run.readings.size(); ++k)
    readings[2 * k] = run.readings[k].sigma_z, readings[2 * k + 1] = run.readings[k].sigma_x;
  write_sensors_csv(out_dir, scene, readings);
  add_write_seconds(summary, clock.seconds());
  write_json(out_dir + "/summary.json", summary);

  std::printf(
      "contact %s (%s), neo-Hookean skin: %.4f N normal, %.4f N tangential; indentation %.3f um, p0 %.2f "
      "kPa, "
      "largest pressure %.2f kPa, %zu multipliers in contact\n",
      scene.name.c_str(), to_string(chosen), run.force_N, run.tangential_force_N, 1e3 * r.depth_mm,
      1e3 * run.p0_MPa, 1e3 * run.p_max_MPa, r.active.size());
  print_frame("reference", run.reference);
  print_frame("current", run.current);
  std::printf(
      "  largest tangential displacement in the zone %.4f mm (%.2f x the indentation); base force balance "
      "%.1e, "
      "complementarity %.1e, max pointwise penetration %.3g um\n",
      run.max_tangential_mm, run.max_tangential_mm / r.depth_mm, run.balance_rel, r.complementarity,
      1e3 * run.max_penetration_mm);
  if (run.tau_MPa > 0)
    std::printf(
        "  shear strength %.4g kPa where the skin touches (tau0 %.4g kPa%s), %d edge multipliers "
        "holding a fraction of it\n",
        1e3 * run.tau_MPa, 1e3 * run.tau0_MPa,
        scene.contact->tau0 ? "" : ": mu F / A on this skin's frictionless contact", r.partial_shear);
  const double share = run.share();
  for (const contact::FiniteContactStep& s : r.steps) {
    std::printf("  step to %.4g N, ratio %.3g", s.force / share, s.ratio);
    if (s.tau > 0) std::printf(", shear %.4g kPa", 1e3 * s.tau);
    std::printf(": residuals");
    for (double x : s.residuals) std::printf(" %.1e", x);
    std::printf("\n");
  }
  std::printf(
      "  %d DOFs (%s); mesh %.2f s, Newton %.2f s (%d factorizations, %d steps halved); peak %.0f MB\n",
      run.dofs, symmetry_said(scene, run.mirrored).c_str(), run.wall.at("mesh"), run.wall.at("newton"),
      r.factorizations, r.rejected_steps, peak_rss_mb());
  std::printf("  wrote %s/pressure.vtp, fields.vtu, sensors.csv, summary.json\n", out_dir.c_str());
  return 0;
}
}  // namespace

int run_contact(const Scene& scene, const std::string& out_dir, const std::string& friction, GreenPath path) {
  const FrictionMode chosen = friction_mode_named(scene, friction);  // or a SceneError without a contact
  check_output_dir(out_dir);
  if (scene.material.model == MaterialModel::neo_hookean) {
    if (path == GreenPath::meridian)
      throw SceneError("--path meridian: with material.model \"neo_hookean\" the contact is solved in 3D");
    return finite_contact_stage(scene, out_dir, chosen);
  }
  std::string why;
  if (contact_on_meridian(scene, chosen, path, &why)) {
    meridian_contact_stage(scene, out_dir, chosen);
    return 0;
  }
  ContactRun run = contact_run(scene, contact_setup(scene, nullptr, HolePath::none), chosen);
  run.not_meridian = why;
  nlohmann::json summary = contact_json(scene, run);
  write_contact(scene, run, summary, out_dir);
  return 0;
}

}  // namespace skinfem::app
