#include "skinfem/pipeline/finite_defect.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "skinfem/contact/holes/dimple.hpp"
#include "skinfem/fem/face_index.hpp"
#include "skinfem/mesh/sizing.hpp"
#include "skinfem/mesh/surface_quadrature.hpp"
#include "skinfem/pipeline/clock.hpp"
#include "skinfem/pipeline/defect.hpp"
#include "skinfem/pipeline/progress.hpp"
#include "skinfem/pipeline/resources.hpp"
#include "skinfem/pipeline/scene_json.hpp"
#include "skinfem/scene/laws.hpp"
#include "skinfem/validation/hole_budget.hpp"
#include "skinfem/validation/text.hpp"

namespace skinfem::pipeline {

namespace {

// The reference point X under the spatial point c on the top: X + u_h(X) = c, u_h the top's horizontal
// displacement, by fixed-point iteration (a contraction while |∇u_h| < 1).
Vec2 material_point(const TetMesh& mesh, const PlanarFaceIndex& top, const Eigen::VectorXd& u,
                    const Vec2& c) {
  Vec2 X = c;
  for (int it = 0; it < 50; ++it) {
    double s = 0, t = 0;
    const int f = top.find(X[0], X[1], s, t);
    if (f < 0) return X;  // off the top: no material there to move
    const Eigen::Matrix<double, 6, 1> N = triangle_shape(s, t);
    double ux = 0, uy = 0;
    for (int k = 0; k < 6; ++k) {
      const int n = mesh.faces(f, k);
      ux += N[k] * u[3 * n];
      uy += N[k] * u[3 * n + 1];
    }
    const Vec2 next{c[0] - ux, c[1] - uy};
    const double step = std::hypot(next[0] - X[0], next[1] - X[1]);
    X = next;
    if (step < 1e-12) break;
  }
  return X;
}

FiniteDefectCase finite_defect_case(const Scene& scene, FrictionMode mode,
                                    const contact::FiniteContactResult* frictionless) {
  const HoleSweep& sweep = *scene.contact->sweep;
  FiniteDefectCase out;
  out.mode = mode;
  out.name = mode == FrictionMode::coupled ? "sliding" : "static";
  out.state = finite_contact_run(scene, mode, frictionless);
  const FiniteContactRun& st = out.state;

  Stopwatch clock;
  progress("the contact condensed on the tangent at the deformed " + out.name + " state");
  const double mu = Lame::from(scene.material.E, scene.material.nu).mu;
  const contact::CondensedContact tangent =
      contact::tangent_contact(*st.solved, mu, st.held.fixed, st.solved_zone, *st.indenter, *st.sensor_sites,
                               st.load, st.solved_result);
  // A shear strength from the force is the finite frictionless contact's μF/A, not the tangent's own.
  ContactLoad load = *scene.contact;
  if (kind(load.law).shear_strength) load.tau0 = st.tau0_MPa;
  const contact::ContactSolver solver(tangent, load, st.mirror ? &*st.mirror : nullptr);

  const PlanarFaceIndex top(*st.mesh, kTop);
  const contact::HoleDimples dimples(solver, *st.mesh, top, scene.material.E, scene.material.nu);
  out.tangent_seconds = clock.seconds();
  const Eigen::VectorXd& u = st.result.solution.u;
  for (int i = 0; i < sweep.positions; ++i)
    out.material_centres.push_back(material_point(*st.mesh, top, u, contact::sweep_center(sweep, i)));
  out.sweep = contact::hole_sweep(
      solver, *st.mesh, sweep, mode, &dimples,
      [&](int i, const contact::ContactResult&) {
        if ((i + 1) % 50 == 0 || i + 1 == sweep.positions)
          progress("sweep " + out.name + ": " + std::to_string(i + 1) + "/" +
                   std::to_string(sweep.positions) + " positions");
      },
      nullptr, out.material_centres);
  out.metrics = contact::contact_metrics(solver, *st.mesh, top, out.sweep.baseline, contact_center(scene));
  const Eigen::VectorXd& lam = out.sweep.baseline.lambda;
  out.baseline_rel = (lam - st.result.lambda).cwiseAbs().maxCoeff() / st.result.lambda.maxCoeff();
  const Eigen::MatrixXd& v = out.sweep.varsigma;
  for (int col = 0; col < v.cols(); ++col)
    if (const double r = validation::roughness(v.col(col)); r > out.max_roughness)
      out.max_roughness = r, out.max_roughness_column = col;
  for (size_t i = 0; i < out.material_centres.size(); ++i)
    out.largest_material_shift_mm = std::max(
        out.largest_material_shift_mm, std::hypot(out.sweep.centers[i][0] - out.material_centres[i][0],
                                                  out.sweep.centers[i][1] - out.material_centres[i][1]));
  return out;
}

}  // namespace

void check_finite_defect(const Scene& scene, const std::vector<FrictionMode>& modes) {
  require_sweep(scene);
  if (modes.empty()) throw std::invalid_argument("finite_defect_run: no case asked for");
  for (FrictionMode m : modes) {
    if (m != FrictionMode::static_residual && m != FrictionMode::coupled)
      throw std::invalid_argument("finite_defect_run: the cases are static_residual and coupled");
    check_finite_contact(scene, m);
  }
  if (scene.contact->indenter == IndenterKind::sphere)
    throw SceneError(scene.source_path +
                     ": contact.indenter = \"sphere\": with material.model \"neo_hookean\" the hole sweep "
                     "runs under a plate (its tangent contact takes the plate's fixed normal)");
  const HoleSweep& sweep = *scene.contact->sweep;
  if (sweep.model != HoleModel::bulge)
    throw SceneError(
        scene.source_path +
        ": contact.sweep.hole_model = \"resolved\": with material.model \"neo_hookean\" the hole "
        "is the bulge (\"bulge\"), a small change about the deformed state");
}

FiniteDefectRun finite_defect_run(const Scene& scene, const std::vector<FrictionMode>& modes,
                                  std::vector<ChainLevel> coarse, int sliding_stations,
                                  std::shared_ptr<const FiniteContactRun> frictionless) {
  check_finite_defect(scene, modes);
  if (sliding_stations < 1) throw std::invalid_argument("finite_defect_run: sliding_stations must be ≥ 1");
  FiniteDefectRun run;
  const auto point = [&run](const FiniteContactRun& st, double ratio) {
    run.path.push_back({ratio, st.tangential_force_N, st.result.depth_mm, st.reference, st.current});
  };
  // Every case's path starts with the same frictionless contact at the full force: solved once when shared.
  if (frictionless) {
    if (frictionless->mode != FrictionMode::none || frictionless->force_N != *scene.contact->force)
      throw std::invalid_argument("finite_defect_run: the given start is not this scene's frictionless run");
    run.frictionless = std::move(frictionless);
    point(*run.frictionless, 0);
  } else if (modes.size() > 1 || sliding_stations > 1) {
    run.frictionless =
        std::make_shared<const FiniteContactRun>(finite_contact_run(scene, FrictionMode::none));
    for (const auto& [stage, seconds] : run.frictionless->wall) run.wall[stage + "_frictionless"] = seconds;
    point(*run.frictionless, 0);
  }
  Scene station_scene = scene;
  for (FrictionMode m : modes) {
    const contact::FiniteContactResult* from = run.frictionless ? &run.frictionless->solved_result : nullptr;
    // The sliding case's ratio path through converged stations at k/K of μ, each solved from the last.
    std::optional<FiniteContactRun> station;
    for (int k = 1; m == FrictionMode::coupled && k < sliding_stations; ++k) {
      station_scene.contact->mu = scene.contact->mu * k / sliding_stations;
      station = finite_contact_run(station_scene, FrictionMode::coupled, from);
      run.wall["newton_station_" + std::to_string(k)] = station->wall.at("newton");
      point(*station, station_scene.contact->mu);
      from = &station->solved_result;
    }
    run.cases.push_back(finite_defect_case(scene, m, from));
    const FiniteDefectCase& c = run.cases.back();
    for (const auto& [stage, seconds] : c.state.wall) run.wall[stage + "_" + c.name] = seconds;
    run.wall["tangent_" + c.name] = c.tangent_seconds;
    run.wall["sweep_" + c.name] = c.sweep.seconds;
    point(c.state, solved_ratio(*scene.contact, m));
  }
  std::stable_sort(run.path.begin(), run.path.end(),
                   [](const FinitePathPoint& a, const FinitePathPoint& b) { return a.ratio < b.ratio; });
  if (!coarse.empty()) {
    run.levels = std::move(coarse);
    run.levels.push_back(finite_sliding_level(run));
  }
  return run;
}

ChainLevel finite_sliding_level(const FiniteDefectRun& run, double scale) {
  for (const FiniteDefectCase& c : run.cases)
    if (c.mode == FrictionMode::coupled) {
      ChainLevel l;
      l.scale = scale;
      l.dofs = c.state.dofs;
      l.names = {"contact_radius", "contact_p0", "indentation", "hole_signal"};
      l.value = {c.metrics.contact_radius_mm, c.metrics.p0_MPa, c.state.result.depth_mm,
                 contact::largest_varsigma_z(c.sweep.varsigma)};
      const double seconds = c.state.wall.total() + c.tangent_seconds + c.sweep.seconds;
      l.seconds.assign(l.names.size(), seconds);
      l.wall["newton"] = c.state.wall.at("newton");
      l.wall["tangent"] = c.tangent_seconds;
      l.wall["sweep"] = c.sweep.seconds;
      l.peak_rss_mb = peak_rss_mb();
      return l;
    }
  throw std::invalid_argument("finite_sliding_level: the run has no sliding (coupled) case");
}

std::vector<ChainLevel> finite_sliding_levels(const Scene& scene, const std::vector<double>& scales) {
  check_error_scales(scales);
  check_finite_defect(scene, {FrictionMode::coupled});
  // A coarser zone's outer ring is wider, and the finite contact refuses a contact reaching into it: the
  // zone grows by the ring's growth, so that the same contact keeps the scene's clearance.
  const auto level = [&](double s, bool cap_holes) {
    Scene scaled = scaled_scene(scene, s, cap_holes);
    scaled.contact->zone_radius = contact_zone_radius(scene) + contact_zone_h(scaled) - contact_zone_h(scene);
    return finite_sliding_level(finite_defect_run(scaled, {FrictionMode::coupled}), s);
  };
  std::vector<ChainLevel> out;
  for (double s : scales) {
    progress("finite-strain error bar: level x" + validation::fmt("%g", s));
    try {
      out.push_back(level(s, false));
    } catch (const contact::HoleUnresolved&) {
      out.push_back(level(s, true));
      out.back().note = "the mesh over the hole capped at its diameter (the scaled one could not see it)";
    }
    release_freed_memory();
  }
  return out;
}

nlohmann::json finite_defect_json(const Scene& scene, const FiniteDefectRun& run) {
  const HoleSweep& sweep = *scene.contact->sweep;
  nlohmann::json summary;
  double baseline = 0, shift = 0;
  for (const FiniteDefectCase& fc : run.cases) {
    const contact::SweepResult& res = fc.sweep;
    nlohmann::json c;
    c["friction"] = to_string(fc.mode);
    c["ratio"] = coulomb_ratio(*scene.contact, fc.mode);
    c["tau_kPa"] = 1e3 * fc.state.tau_MPa;
    c["seconds"] = res.seconds;
    c["ms_per_position"] = 1e3 * res.seconds / sweep.positions;
    c["max_complementarity"] = res.max_complementarity;
    c["max_roughness"] = fc.max_roughness;
    c["max_roughness_curve"] = "#" + std::to_string(fc.max_roughness_column / 2 + 1) +
                               (fc.max_roughness_column % 2 ? " varsigma_x" : " varsigma_z");
    c["sensors"] = sweep_peaks_json(res);
    c["tangent_baseline_rel"] = fc.baseline_rel;
    c["largest_material_shift_mm"] = fc.largest_material_shift_mm;
    c["state"] = finite_contact_json(scene, fc.state);
    c["state"].erase("scene");
    summary["cases"][fc.name] = c;
    baseline = std::max(baseline, fc.baseline_rel);
    shift = std::max(shift, fc.largest_material_shift_mm);
  }
  summary["scene"] = scene_json(scene);
  summary["material_model"] = "neo_hookean";
  summary["friction_law"] = to_string(scene.contact->law);
  if (run.levels.size() >= 3) {
    std::vector<double> scales;
    for (size_t i = 0; i + 1 < run.levels.size(); ++i) scales.push_back(run.levels[i].scale);
    summary["error_bars"] = error_bars_json(error_bars(chain_errors(run.levels), scales));
    summary["levels"] = chain_study_json(scene, run.levels).at("levels");
    summary["left_out"] = "the VTK frames";
  } else {
    summary["left_out"] = "the VTK frames and the error bars (the finite solve on coarser meshes)";
  }
  summary["positions"] = sweep.positions;
  summary["hole_diameter_mm"] = sweep.hole_diameter;
  summary["hole_model"] = "bulge";
  summary["from_mm"] = {sweep.from[0], sweep.from[1]};
  summary["to_mm"] = {sweep.to[0], sweep.to[1]};
  summary["largest_material_shift_mm"] = shift;
  summary["tangent_baseline_rel"] = baseline;
  summary["dofs"] = run.cases.front().state.dofs;
  summary["wall_s"] = run.wall;
  summary["wall_total_s"] = run.wall.total();
  summary["peak_rss_mb"] = peak_rss_mb();
  return summary;
}

}  // namespace skinfem::pipeline
