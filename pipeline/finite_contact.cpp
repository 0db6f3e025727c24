#include "skinfem/pipeline/finite_contact.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "skinfem/contact/contact_solver.hpp"
#include "skinfem/contact/indenter.hpp"
#include "skinfem/fem/fields.hpp"
#include "skinfem/fem/supports.hpp"
#include "skinfem/mesh/build.hpp"
#include "skinfem/mesh/mirror.hpp"
#include "skinfem/pipeline/contact.hpp"
#include "skinfem/pipeline/contact_setup.hpp"
#include "skinfem/pipeline/progress.hpp"
#include "skinfem/pipeline/resources.hpp"
#include "skinfem/pipeline/scene_json.hpp"
#include "skinfem/pipeline/symmetry.hpp"
#include "skinfem/scene/laws.hpp"

namespace skinfem::pipeline {

namespace {

SceneError finite_refusal(const Scene& scene, const std::string& field, const std::string& why) {
  return SceneError(scene.source_path + ": " + field + ": with material.model \"neo_hookean\" " + why);
}

// The half's result seen on the whole skin: u and p mirrored, each whole multiplier taking its half one's λ
// and its gap scaled by the hats' areas (a hat on the plane y = 0 is twice its half; the others are equal).
contact::FiniteContactResult mirrored_result(const contact::FiniteContactResult& half,
                                             const contact::MortarZone& half_zone, const TetMesh& whole,
                                             const std::vector<int>& source,
                                             const contact::MirrorView& view) {
  contact::FiniteContactResult r = half;
  r.solution = mirrored_solution(whole, source, half.solution);
  const int n = view.zone.size();
  r.lambda.resize(n);
  r.shear.resize(n);
  r.gap.resize(n);
  std::vector<char> active(half_zone.size(), 0);
  for (int i : half.active) active[i] = 1;
  r.active.clear();
  for (int i = 0; i < n; ++i) {
    const int h = view.half[i];
    r.lambda[i] = half.lambda[h];
    r.shear[i] = half.shear[h];
    r.gap[i] = half.gap[h] * view.zone.area[i] / half_zone.area[h];
    if (active[h]) r.active.push_back(i);
  }
  r.internal_force.resize(0);  // the half's alone is meaningful (its reactions are read there)
  r.load.resize(0);
  return r;
}

}  // namespace

void check_finite_contact(const Scene& scene, FrictionMode mode) {
  require_contact(scene);
  const ContactLoad& c = *scene.contact;
  if (!c.force)
    throw finite_refusal(scene, "contact.depth", "the contact is force controlled: give contact.force");
  if (!c.holes.empty())
    throw finite_refusal(scene, "contact.holes",
                         "the plate has no holes (" + std::to_string(c.holes.size()) + " given)");
  if (c.interface.law != InterfaceLaw::hard)
    throw finite_refusal(scene, std::string("contact.interface.law = \"") + to_string(c.interface.law) + "\"",
                         "the interface is hard");
  require_rigid_posts(scene);
  if (mode == FrictionMode::uncoupled)
    throw SceneError(scene.source_path + ": friction mode '" + to_string(mode) +
                     "' (--friction or contact.friction.mode): with material.model \"neo_hookean\" the "
                     "contact is frictionless ('none'), at rest with its residual traction ('static') or in "
                     "coupled sliding ('coupled')");
}

FiniteContactRun finite_contact_run(const Scene& scene, FrictionMode mode,
                                    const contact::FiniteContactResult* from) {
  check_finite_contact(scene, mode);
  const ContactLoad& c = *scene.contact;
  FiniteContactRun run;
  run.mode = mode;
  run.zone_radius = contact_zone_radius(scene);
  run.zone_h = contact_zone_h(scene);
  const Vec2 centre = contact_center(scene);
  Stopwatch clock;
  auto solved_mesh = std::make_shared<TetMesh>(guarded_mesh(scene, contact_mesh_part(scene)));
  const TetMesh& solved = *solved_mesh;
  run.solved = solved_mesh;
  check_sensors_on_skin(scene, solved);
  run.wall["mesh"] = clock.seconds();

  clock = Stopwatch();
  run.held = skin_supports(solved, scene.geometry.side, {});
  run.indenter = std::make_unique<contact::Indenter>(scene, solved);
  run.solved_zone = contact::mortar_zone(solved, centre, run.zone_radius);
  const contact::MortarZone& zone = run.solved_zone;
  run.mirrored = is_half_y(solved);
  const double share = run.share();
  const double ratio = coulomb_ratio(c, mode);
  run.force_N = *c.force;
  const Eigen::Vector2d t(c.direction[0], c.direction[1]);
  run.load.force = share * *c.force;
  run.load.ratio = ratio;
  run.load.direction = t;
  // A shear strength: τ0 as given, else μF/A on the finite skin's own frictionless contact; at rest the
  // residual part static_ratio/μ of it (ContactSolver::shear's rule).
  if (kind(c.law).shear_strength && mode != FrictionMode::none) {
    const bool at_rest = mode == FrictionMode::static_residual;
    if (c.tau0)
      run.load.tau = at_rest ? (c.mu > 0 ? *c.tau0 * c.static_ratio / c.mu : 0.0) : *c.tau0;
    else
      run.load.tau_mu = at_rest ? c.static_ratio : c.mu;
  }
  const Lame lame = Lame::from(scene.material.E, scene.material.nu);
  progress(std::string("Newton on the neo-Hookean skin under the ") +
           (c.indenter == IndenterKind::sphere ? "sphere" : "plate") + " (" +
           std::to_string(solved.num_nodes()) + " nodes, " + std::to_string(zone.size()) + " multipliers)");
  run.solved_result = contact::solve_finite_contact(
      solved, lame.mu, run.held.fixed, zone, *run.indenter, run.load, {},
      [&](const contact::FiniteContactStep& s) {
        char buf[200], shear[48] = "";
        if (s.tau > 0) std::snprintf(shear, sizeof shear, ", shear %.4g kPa", 1e3 * s.tau);
        std::snprintf(buf, sizeof buf,
                      "  step to %.4g N, friction ratio %.3g%s: %zu iterations, residual %.1e",
                      s.force / share, s.ratio, shear, s.residuals.size(), s.residuals.back());
        progress(buf);
      },
      from);
  if (from) {
    contact::FiniteContactResult& r = run.solved_result;
    r.steps.insert(r.steps.begin(), from->steps.begin(), from->steps.end());
    r.factorizations += from->factorizations;
    r.rejected_steps += from->rejected_steps;
  }
  const contact::FiniteContactResult& r = run.solved_result;
  run.wall["newton"] = clock.seconds();
  run.tau_MPa = r.tau;
  if (kind(c.law).shear_strength)
    run.tau0_MPa = c.tau0                        ? *c.tau0
                   : r.frictionless_area_mm2 > 0 ? c.mu * share * *c.force / r.frictionless_area_mm2
                                                 : 0.0;
  // A vector's total over the solved nodes, for the whole skin.
  const auto whole_sum = [&](const Eigen::VectorXd& v) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (int i = 0; i < solved.num_nodes(); ++i) sum += v.segment<3>(3 * i);
    return run.mirrored ? Eigen::Vector3d(2 * sum.x(), 0.0, 2 * sum.z()) : sum;
  };
  // The indenter's load on the whole skin. A plate's is nominal: its drag along t is horizontal. A sphere's
  // pressures and drag follow its surface: their sum, whose horizontal part along t is the drag reported
  // when it slides (without friction its pressures' horizontal parts cancel but for the mesh's asymmetry).
  const bool sphere = c.indenter == IndenterKind::sphere;
  const Eigen::Vector3d sphere_load = sphere ? whole_sum(r.load) : Eigen::Vector3d::Zero();
  run.tangential_force_N = !sphere                  ? ratio * *c.force + zone.area.dot(r.shear) / share
                           : ratio > 0 || r.tau > 0 ? sphere_load.head<2>().dot(t)
                                                    : 0.0;
  run.dofs =
      static_cast<int>(std::count(run.held.fixed.begin(), run.held.fixed.end(), false)) + solved.num_vertices;

  // What the base feels: its reactions (the internal force at its DOFs; the plate loads none of them), read
  // over each sensor's reference disc.
  const Eigen::VectorXd reactions = support_reactions(run.held, r.internal_force - r.load);
  run.sensor_sites = std::make_shared<const SensorReadings>(solved, reading_sites(scene.sensors));
  const SensorReadings& readings = *run.sensor_sites;
  for (int k = 0; k < readings.size(); ++k) run.readings.push_back(readings.read(k, reactions));
  run.base_force_N = whole_sum(reactions);
  // At equilibrium the base takes back the indenter's whole load, friction included (the internal force's
  // test functions sum to one).
  const Eigen::Vector3d load =
      sphere ? sphere_load
             : Eigen::Vector3d(run.tangential_force_N * t.x(), run.tangential_force_N * t.y(), -run.force_N);
  run.balance_rel = (run.base_force_N + load).norm() / load.norm();

  if (run.mirrored) {
    auto whole = std::make_shared<TetMesh>(mirror_half(solved, &run.source));
    run.mirror = contact::mirror_view(*whole, run.source, zone, centre, run.zone_radius);
    run.result = mirrored_result(r, zone, *whole, run.source, *run.mirror);
    run.zone = run.mirror->zone;
    run.mesh = std::move(whole);
  } else {
    run.mesh = run.solved;
    run.result = r;
    run.zone = zone;
  }
  const TetMesh& mesh = *run.mesh;
  const contact::FiniteContactResult& w = run.result;
  run.reference = contact::zone_frame(mesh, run.zone, w, centre, t, false);
  run.current = contact::zone_frame(mesh, run.zone, w, centre, t, true);

  // The contact may not reach the zone's outer element ring (it would be cut short there).
  double reach = 0, nearest = 1e300;
  for (int i : w.active) {
    const int v = run.zone.vertices[i];
    reach = std::max(reach, std::hypot(mesh.nodes(v, 0) - centre[0], mesh.nodes(v, 1) - centre[1]));
  }
  check_zone_reach(scene, run.zone_radius, run.zone_h, reach, mode);
  for (int i = 0; i < run.zone.size(); ++i) {
    const int v = run.zone.vertices[i];
    const double d = std::hypot(mesh.nodes(v, 0) - centre[0], mesh.nodes(v, 1) - centre[1]);
    if (d < nearest) nearest = d, run.p0_MPa = w.lambda[i];
    run.max_tangential_mm = std::max(run.max_tangential_mm,
                                     std::abs(w.solution.u[3 * v] * t.x() + w.solution.u[3 * v + 1] * t.y()));
  }
  run.p_max_MPa = w.lambda.maxCoeff();
  // Pointwise: each zone face node's current height against the indenter at its current (x, y).
  for (int face : run.zone.faces)
    for (int k = 0; k < 6; ++k) {
      const int n = mesh.faces(face, k);
      const Eigen::Vector3d x = mesh.nodes.row(n).transpose() + w.solution.u.segment<3>(3 * n);
      const double gap = run.indenter->gap_at_rest(x) - w.depth_mm;
      run.max_penetration_mm = std::max(run.max_penetration_mm, -gap);
    }
  return run;
}

namespace {
nlohmann::json frame_json(const contact::ContactZoneFrame& f) {
  return {{"area_mm2", f.area_mm2},
          {"equivalent_radius_mm", std::sqrt(f.area_mm2 / M_PI)},
          {"zone_centroid_mm", {f.zone_centroid[0], f.zone_centroid[1]}},
          {"force_centroid_mm", {f.force_centroid[0], f.force_centroid[1]}},
          {"front_edge_mm", f.front_mm},
          {"back_edge_mm", f.back_mm},
          {"half_width_mm", f.half_width_mm},
          {"anisotropy", f.anisotropy()}};
}
}  // namespace

nlohmann::json finite_contact_json(const Scene& scene, const FiniteContactRun& run) {
  const contact::FiniteContactResult& r = run.result;
  const double share = run.share();
  nlohmann::json steps = nlohmann::json::array();
  for (const contact::FiniteContactStep& s : r.steps)
    steps.push_back({{"force_N", s.force / share},
                     {"ratio", s.ratio},
                     {"tau_kPa", 1e3 * s.tau},
                     {"residuals", s.residuals},
                     {"active_multipliers", s.active_sizes},
                     {"set_changes", s.set_changes}});
  nlohmann::json sensors = nlohmann::json::array();
  for (size_t k = 0; k < run.readings.size(); ++k)
    sensors.push_back({{"sensor", k + 1},
                       {"x_mm", scene.sensors.positions[k][0]},
                       {"y_mm", scene.sensors.positions[k][1]},
                       {"sigma_z_kPa", 1e3 * run.readings[k].sigma_z},
                       {"sigma_x_kPa", 1e3 * run.readings[k].sigma_x}});
  const auto shift = [&](const Vec2& a, const Vec2& b) { return nlohmann::json{a[0] - b[0], a[1] - b[1]}; };
  return {{"scene", scene_json(scene)},
          {"material_model", "neo_hookean"},
          {"path", "3d"},
          {"indenter", scene.contact->indenter == IndenterKind::sphere ? "sphere" : "plane"},
          {"friction", to_string(run.mode)},
          {"friction_law", to_string(scene.contact->law)},
          {"ratio", coulomb_ratio(*scene.contact, run.mode)},
          {"tau_kPa", 1e3 * run.tau_MPa},
          {"partial_shear", r.partial_shear},
          {"direction", {scene.contact->direction[0], scene.contact->direction[1]}},
          {"force_N", run.force_N},
          {"tangential_force_N", run.tangential_force_N},
          {"indentation_um", 1e3 * r.depth_mm},
          {"p0_kPa", 1e3 * run.p0_MPa},
          {"p_max_kPa", 1e3 * run.p_max_MPa},
          {"reference_frame", frame_json(run.reference)},
          {"current_frame", frame_json(run.current)},
          {"frame_shift_mm",
           {{"zone_centroid", shift(run.current.zone_centroid, run.reference.zone_centroid)},
            {"force_centroid", shift(run.current.force_centroid, run.reference.force_centroid)}}},
          {"max_tangential_displacement_mm", run.max_tangential_mm},
          {"tangential_displacement_over_indentation", run.max_tangential_mm / r.depth_mm},
          {"min_pressure_kPa", 1e3 * r.lambda.minCoeff()},
          {"min_weighted_gap_mm3", r.gap.minCoeff()},
          {"complementarity", r.complementarity},
          {"max_penetration_um", 1e3 * run.max_penetration_mm},
          {"active_multipliers", r.active.size()},
          {"base_force_N", {run.base_force_N.x(), run.base_force_N.y(), run.base_force_N.z()}},
          {"base_force_balance_rel", run.balance_rel},
          {"sensors", sensors},
          {"newton",
           {{"steps", steps}, {"rejected_steps", r.rejected_steps}, {"factorizations", r.factorizations}}},
          {"residual", r.solution.residual},
          {"zone", {{"radius_mm", run.zone_radius}, {"h_mm", run.zone_h}, {"multipliers", run.zone.size()}}},
          {"symmetry", symmetry_said(scene, run.mirrored)},
          {"dofs", run.dofs},
          {"nodes", run.mesh->num_nodes()},
          {"elements", run.mesh->num_tets()},
          {"wall_s", run.wall},
          {"wall_total_s", run.wall.total()},
          {"peak_rss_mb", peak_rss_mb()}};
}

}  // namespace skinfem::pipeline
