#include "skinfem/pipeline/defect.hpp"

#include <cstdio>

#include "skinfem/contact/pressure_map.hpp"
#include "skinfem/mesh/sizing.hpp"
#include "skinfem/pipeline/clock.hpp"
#include "skinfem/pipeline/progress.hpp"
#include "skinfem/pipeline/scene_json.hpp"
#include "skinfem/pipeline/symmetry.hpp"
#include "skinfem/validation/hole_budget.hpp"

namespace skinfem::pipeline {

void require_sweep(const Scene& scene) {
  if (!scene.contact || !scene.contact->sweep)
    throw SceneError(scene.source_path +
                     ": contact.sweep: missing; skinfem defect needs a \"contact\" section with a \"sweep\"");
}

namespace {
constexpr const char* kLargest = "largest_sliding_varsigma_z";

ChainLevel sliding_level(const Scene& s, double scale) {
  Stopwatch clock;
  const auto c = contact_setup(s, skin_setup(s, contact_mesh_part(s)));
  const contact::HoleDimples dimples(*c->solver, c->mesh(), *c->top, s.material.E, s.material.nu);
  const contact::SweepResult sw =
      contact::hole_sweep(*c->solver, c->mesh(), *s.contact->sweep, FrictionMode::coupled, &dimples);
  ChainLevel l;
  l.scale = scale;
  l.dofs = c->model->solver().free_dofs();
  l.names = {kLargest};
  l.value = {contact::largest_varsigma_z(sw.varsigma)};
  l.seconds = {clock.seconds()};
  l.peak_rss_mb = peak_rss_mb();
  return l;
}
}  // namespace

std::vector<ChainLevel> largest_sliding_levels(const Scene& scene, const std::vector<double>& scales) {
  check_error_scales(scales);
  require_sweep(scene);
  std::vector<ChainLevel> out;
  for (double s : scales) {
    progress("defect error bar: level x" + std::to_string(s).substr(0, 4));
    try {
      out.push_back(sliding_level(scaled_scene(scene, s), s));
    } catch (const contact::HoleUnresolved& e) {
      out.push_back(sliding_level(scaled_scene(scene, s, true), s));
      out.back().note = "the mesh over the hole capped at its diameter (the scaled one could not see it)";
    }
  }
  return out;
}

ChainError largest_sliding_error(const DefectRun& run) {
  if (run.levels.size() < 3)
    throw std::invalid_argument("largest_sliding_error: needs two coarser levels and the run's own");
  return chain_errors(run.levels).at(0);
}

bool written_frame(int i, int n) {
  const int stride = n <= kDefectFrames ? 1 : (n - 1 + kDefectFrames - 2) / (kDefectFrames - 1);
  return i % stride == 0 || i + 1 == n;
}

DefectRun defect_run(const Scene& scene, std::shared_ptr<const ContactSetup> shared,
                     std::vector<ChainLevel> coarse, DefectFrames keep) {
  require_sweep(scene);
  DefectRun run;
  run.setup = std::move(shared);
  const ContactSetup& setup = *run.setup;
  const HoleSweep& sweep = *scene.contact->sweep;
  run.wall = setup.wall;
  const std::vector<std::pair<std::string, FrictionMode>> cases{{"static", FrictionMode::static_residual},
                                                                {"sliding", FrictionMode::coupled}};
  run.frames.resize(cases.size());
  run.frame_positions.resize(cases.size());
  for (const auto& c : cases) check_zone(scene, setup, setup.solver->solve(c.second));
  const contact::HoleDimples dimples(*setup.solver, setup.mesh(), *setup.top, scene.material.E,
                                     scene.material.nu);
  for (size_t ci = 0; ci < cases.size(); ++ci) {
    const auto& [name, mode] = cases[ci];
    run.cases.push_back(name);
    Stopwatch clock;
    run.sweeps.push_back(contact::hole_sweep(
        *setup.solver, setup.mesh(), sweep, mode, &dimples, [&](int i, const contact::ContactResult& r) {
          contact::check_hole_clearance(
              setup.mesh(), *setup.solver, r,
              {Hole{contact::sweep_center(sweep, i), sweep.hole_diameter, 0.0, sweep.hole_depth}},
              "contact.sweep");
          if (keep == DefectFrames::every || written_frame(i, sweep.positions)) {
            run.frames[ci].push_back(r);
            run.frame_positions[ci].push_back(i);
          }
          if ((i + 1) % 50 == 0 || i + 1 == sweep.positions) {
            char buf[128];
            std::snprintf(buf, sizeof buf, "sweep %s: %d/%d positions (%.1f s)", name.c_str(), i + 1,
                          sweep.positions, clock.seconds());
            progress(buf);
          }
        }));
    run.wall["sweep_" + name] = clock.seconds();
    // The jaggedness of each curve (validation::roughness), and the worst.
    const Eigen::MatrixXd& v = run.sweeps.back().varsigma;
    double rough = 0;
    int rough_col = 0;
    for (int col = 0; col < v.cols(); ++col)
      if (const double r = validation::roughness(v.col(col)); r > rough) rough = r, rough_col = col;
    run.max_roughness.push_back(rough);
    run.max_roughness_column.push_back(rough_col);
  }
  if (!coarse.empty()) {
    double seconds = 0;
    for (const ChainLevel& l : coarse) seconds += l.seconds.at(0);
    run.wall["error_bar_levels"] = seconds;
    run.levels = std::move(coarse);
    ChainLevel own;
    own.dofs = setup.model->solver().free_dofs();
    own.names = {kLargest};
    own.value = {contact::largest_varsigma_z(run.sweeps.back().varsigma)};
    own.seconds = {run.wall.total() - seconds};
    own.peak_rss_mb = peak_rss_mb();
    run.levels.push_back(own);
  }
  return run;
}

nlohmann::json sweep_peaks_json(const contact::SweepResult& res) {
  nlohmann::json sensors = nlohmann::json::array();
  for (int k = 0; 2 * k < res.varsigma.cols(); ++k) {
    Eigen::Index iz, ix;
    const double z = res.varsigma.col(2 * k).cwiseAbs().maxCoeff(&iz);
    const double x = res.varsigma.col(2 * k + 1).cwiseAbs().maxCoeff(&ix);
    sensors.push_back({{"sensor", k + 1},
                       {"peak_abs_varsigma_z_kPa", 1e3 * z},
                       {"u_at_peak_z_mm", res.centers[iz][0]},
                       {"peak_abs_varsigma_x_kPa", 1e3 * x},
                       {"u_at_peak_x_mm", res.centers[ix][0]}});
  }
  return sensors;
}

nlohmann::json defect_json(const Scene& scene, const DefectRun& run) {
  const ContactSetup& setup = *run.setup;
  const HoleSweep& sweep = *scene.contact->sweep;
  nlohmann::json summary;
  for (size_t ci = 0; ci < run.cases.size(); ++ci) {
    const auto& res = run.sweeps[ci];
    nlohmann::json c;
    c["friction"] = to_string(res.mode);
    c["ratio"] = setup.solver->ratio(res.mode);
    c["shear_kPa"] = 1e3 * setup.solver->shear(res.mode);
    c["seconds"] = res.seconds;
    c["ms_per_position"] = 1e3 * res.seconds / sweep.positions;
    c["max_complementarity"] = res.max_complementarity;
    double pivots = 0;
    for (int p : res.pivots) pivots += p;
    c["mean_pivots"] = pivots / res.pivots.size();
    const double rough = run.max_roughness.at(ci);
    const int rough_col = run.max_roughness_column.at(ci);
    c["max_roughness"] = rough;
    c["max_roughness_curve"] =
        "#" + std::to_string(rough_col / 2 + 1) + (rough_col % 2 ? " varsigma_x" : " varsigma_z");
    c["sensors"] = sweep_peaks_json(res);
    summary["cases"][run.cases[ci]] = c;
  }
  summary["scene"] = scene_json(scene);
  summary["friction_law"] = to_string(scene.contact->law);
  summary["positions"] = sweep.positions;
  summary["hole_diameter_mm"] = sweep.hole_diameter;
  summary["hole_model"] = sweep.model == HoleModel::bulge ? "bulge" : "resolved";
  if (sweep.model == HoleModel::bulge) {
    // The bulge model's next term, relative: (ε/d)² with d the skin's thickness under the contact's centre.
    const Vec2 c = contact_center(scene);
    const double eps_d = 0.5 * sweep.hole_diameter / skin_thickness(scene.geometry, setup.mesh(), c[0], c[1]);
    summary["bulge_next_term"] = eps_d * eps_d;
  }
  summary["from_mm"] = {sweep.from[0], sweep.from[1]};
  summary["to_mm"] = {sweep.to[0], sweep.to[1]};
  summary["dofs"] = setup.model->solver().free_dofs();
  summary["multipliers"] = setup.solver->zone().size();
  summary["multipliers_solved"] = setup.condensed->zone.size();
  summary["block_solves"] = setup.condensed->block_solves;
  summary["condensation"] = condensation_json(setup);
  if (run.levels.size() >= 3) {
    const ChainError e = largest_sliding_error(run);
    nlohmann::json b{{"value_kPa", 1e3 * e.value},
                     {"error_kPa", 1e3 * e.error},
                     {"relative_error", e.value > 0 ? e.error / e.value : 0.0},
                     {"asymptotic", e.asymptotic},
                     {"observed_order", e.order},
                     {"how", e.asymptotic ? "|value - Richardson limit| over the levels"
                                          : "last change between the two finest levels (" + e.why_not + ")"}};
    for (const ChainLevel& l : run.levels)
      b["levels"].push_back({{"mesh_scale", l.scale},
                             {"dofs", l.dofs},
                             {"value_kPa", 1e3 * l.value.at(0)},
                             {"seconds", l.seconds.at(0)},
                             {"peak_rss_mb", l.peak_rss_mb},
                             {"note", l.note}});
    summary["largest_sliding"] = b;
  }
  summary["wall_s"] = run.wall;
  summary["wall_total_s"] = run.wall.total();
  summary["peak_rss_mb"] = peak_rss_mb();
  return summary;
}

}  // namespace skinfem::pipeline
