#include "skinfem/pipeline/scan.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "skinfem/contact/pressure_map.hpp"
#include "skinfem/pipeline/progress.hpp"
#include "skinfem/pipeline/resources.hpp"
#include "skinfem/pipeline/scene_json.hpp"
#include "skinfem/scene/texture.hpp"

namespace skinfem::pipeline {

void require_texture(const Scene& scene) {
  if (!scene.contact || !scene.contact->texture)
    throw SceneError(
        scene.source_path +
        ": contact.texture: missing; skinfem scan needs a \"contact\" section with a \"texture\" "
        "and a \"scan\", or a \"sweep\" along the sliding direction");
}

Scene scanned_scene(const Scene& scene) {
  if (!scene.contact || scene.contact->texture || !scene.contact->sweep) {
    require_texture(scene);
    return scene;
  }
  const HoleSweep& sw = *scene.contact->sweep;
  const Vec2 d = scene.contact->direction;
  const double dx = sw.to[0] - sw.from[0], dy = sw.to[1] - sw.from[1], length = std::hypot(dx, dy);
  if (!(length > 0) || std::abs(dx * d[1] - dy * d[0]) > 1e-9 * length || dx * d[0] + dy * d[1] < 0)
    throw SceneError(
        scene.source_path +
        ": contact.sweep: skinfem scan moves the plate along the sliding direction; this scene has no "
        "contact.texture and its sweep runs across that direction: give a \"texture\" and a \"scan\"");
  if (hole_mesh_h(scene, sw.h) > sw.hole_diameter) {
    char line[300];
    std::snprintf(
        line, sizeof line,
        ": contact.sweep.h: skinfem scan resolves the sweep's hole (diameter %g mm) on the mesh along "
        "its path, which must be at most that diameter (here %g mm): give contact.sweep.h <= %g",
        sw.hole_diameter, hole_mesh_h(scene, sw.h), sw.hole_diameter);
    throw SceneError(scene.source_path + line);
  }
  Scene s = scene;
  Texture t;
  t.listed = {Hole{sw.from, sw.hole_diameter, 0, sw.hole_depth}};
  t.holes = t.listed;
  t.h = sw.h;
  s.contact->texture = t;
  s.contact->scan = Scan{0, length, length / (sw.positions - 1)};
  return s;
}

std::vector<double> scan_positions(const Scan& scan) {
  std::vector<double> u(scan.positions());
  for (size_t i = 0; i < u.size(); ++i) u[i] = scan.u(static_cast<int>(i));
  return u;
}

void check_texture_clearance(const ContactSetup& setup, const contact::ContactResult& r,
                             const std::vector<Hole>& holes, double u) {
  if (holes.empty()) return;
  const contact::HoleClearance c = contact::hole_clearance(setup.mesh(), *setup.solver, r, holes);
  if (c.clearance_mm > 0) return;
  const Hole& h = holes[c.hole];
  char line[400];
  std::snprintf(line, sizeof line,
                "contact.texture: the %s of depth %g mm at (%g, %g) mm at scan position u = %g mm: the skin "
                "rises %.3g um into it, %s its bottom (%s friction); the contact is solved for holes whose "
                "bottom the skin does not touch: give deeper holes",
                hole_word(h), h.depth, h.center[0], h.center[1], u, 1e3 * c.rise_mm,
                c.clearance_mm < 0 ? "past" : "to", to_string(r.mode));
  throw SceneError(line);
}

ScanRun scan_run(const Scene& scene, std::shared_ptr<const ContactSetup> shared, bool superpose,
                 DefectFrames keep) {
  require_texture(scene);
  ScanRun run;
  run.setup = std::move(shared);
  const ContactSetup& setup = *run.setup;
  const ContactLoad& load = *scene.contact;
  const std::vector<double> u = scan_positions(*load.scan);
  const int n = static_cast<int>(u.size());
  run.wall = setup.wall;
  const std::vector<std::pair<std::string, FrictionMode>> cases{{"static", FrictionMode::static_residual},
                                                                {"sliding", FrictionMode::coupled}};
  run.frames.resize(cases.size());
  run.frame_positions.resize(cases.size());
  run.frame_holes.resize(cases.size());
  for (const auto& c : cases) check_zone(scene, setup, setup.solver->solve(c.second));
  for (size_t ci = 0; ci < cases.size(); ++ci) {
    const auto& [name, mode] = cases[ci];
    run.cases.push_back(name);
    Stopwatch clock;
    run.scans.push_back(
        contact::texture_scan(*setup.solver, load.texture->holes, load.direction, u, mode,
                              [&](int i, const contact::ContactResult& r, const std::vector<Hole>& holes) {
                                check_texture_clearance(setup, r, holes, u[i]);
                                if (keep == DefectFrames::every || written_frame(i, n)) {
                                  run.frames[ci].push_back(r);
                                  run.frame_positions[ci].push_back(i);
                                  run.frame_holes[ci].push_back(holes);
                                }
                                if ((i + 1) % 100 == 0 || i + 1 == n) {
                                  char buf[128];
                                  std::snprintf(buf, sizeof buf, "scan %s: %d/%d positions (%.1f s)",
                                                name.c_str(), i + 1, n, clock.seconds());
                                  progress(buf);
                                }
                              }));
    run.wall["scan_" + name] = clock.seconds();
    if (superpose) {
      progress("scan " + name + ": the holes one at a time (superposition)");
      Stopwatch s;
      run.superposed.push_back(
          contact::superposed_scan(*setup.solver, load.texture->holes, load.direction, u, mode));
      run.wall["superpose_" + name] = s.seconds();
    }
  }
  return run;
}

nlohmann::json scan_json(const Scene& scene, const ScanRun& run) {
  const ContactSetup& setup = *run.setup;
  const ContactLoad& load = *scene.contact;
  const int n = load.scan->positions();
  nlohmann::json summary;
  for (size_t ci = 0; ci < run.cases.size(); ++ci) {
    const contact::ScanResult& res = run.scans[ci];
    nlohmann::json c;
    c["friction"] = to_string(res.mode);
    c["ratio"] = setup.solver->ratio(res.mode);
    c["shear_kPa"] = 1e3 * setup.solver->shear(res.mode);
    c["seconds"] = res.seconds;
    c["ms_per_position"] = 1e3 * res.seconds / n;
    c["max_complementarity"] = res.max_complementarity;
    int most = 0;
    double pivots = 0;
    for (int i = 0; i < n; ++i) most = std::max(most, res.holes_in[i]), pivots += res.pivots[i];
    c["most_holes_in_zone"] = most;
    c["mean_pivots"] = pivots / n;
    // Per column (σ_z of sensor k at 2k, σ_x at 2k + 1): the largest |ς| and, with the superposition, the
    // largest |ς − Σ_k ς_k|.
    const Eigen::Index cols = res.varsigma.cols();
    Eigen::VectorXd peak(cols), diff = Eigen::VectorXd::Zero(cols);
    std::vector<Eigen::Index> at(cols);
    for (Eigen::Index j = 0; j < cols; ++j) {
      peak[j] = res.varsigma.col(j).cwiseAbs().maxCoeff(&at[j]);
      if (!run.superposed.empty())
        diff[j] = (res.varsigma.col(j) - run.superposed[ci].varsigma.col(j)).cwiseAbs().maxCoeff();
    }
    nlohmann::json sensors = nlohmann::json::array();
    for (int k = 0; 2 * k < cols; ++k) {
      nlohmann::json s{{"sensor", k + 1}};
      for (int comp = 0; comp < 2; ++comp) {
        const std::string z = comp == 0 ? "z" : "x";
        const int j = 2 * k + comp;
        s["peak_abs_varsigma_" + z + "_kPa"] = 1e3 * peak[j];
        s["u_at_peak_" + z + "_mm"] = res.u[at[j]];
        if (!run.superposed.empty()) {
          s["superposition_max_diff_" + z + "_kPa"] = 1e3 * diff[j];
          s["superposition_rel_diff_" + z] = peak[j] > 0 ? diff[j] / peak[j] : 0.0;
        }
      }
      sensors.push_back(s);
    }
    c["sensors"] = sensors;
    if (!run.superposed.empty()) {
      const contact::Superposition& sp = run.superposed[ci];
      // The largest difference over the largest signal, σ_z and σ_x of all sensors each.
      double dz = 0, pz = 0, dx = 0, px = 0;
      for (Eigen::Index j = 0; j < cols; ++j) {
        (j % 2 ? dx : dz) = std::max(j % 2 ? dx : dz, diff[j]);
        (j % 2 ? px : pz) = std::max(j % 2 ? px : pz, peak[j]);
      }
      c["superposition"] = {{"single_hole_solves", sp.solves},
                            {"mirror_pair_solves", sp.mirror_pair_solves},
                            {"seconds", sp.seconds},
                            {"max_diff_z_kPa", 1e3 * dz},
                            {"max_diff_x_kPa", 1e3 * dx},
                            {"rel_diff_z", pz > 0 ? dz / pz : 0.0},
                            {"rel_diff_x", px > 0 ? dx / px : 0.0}};
    }
    summary["cases"][run.cases[ci]] = c;
  }
  summary["scene"] = scene_json(scene);
  summary["friction_law"] = to_string(load.law);
  summary["interface"] = to_string(load.interface.law);
  summary["holes"] = load.texture->holes.size();
  // The narrowest ligament between two holes' rims: below about a millimetre the rims reload each other
  // (docs/contact.md, "Where superposition holds").
  const std::vector<Hole>& holes = load.texture->holes;
  double closest = std::numeric_limits<double>::infinity();
  for (size_t a = 0; a < holes.size(); ++a)
    for (size_t b = 0; b < a; ++b) closest = std::min(closest, rim_gap(holes[a], holes[b]));
  if (holes.size() > 1) summary["closest_rims_mm"] = closest;
  summary["positions"] = n;
  summary["scan_mm"] = {{"from", load.scan->from}, {"to", load.scan->to}, {"step", load.scan->step}};
  summary["direction"] = {load.direction[0], load.direction[1]};
  summary["dofs"] = setup.model->solver().free_dofs();
  summary["multipliers"] = setup.solver->zone().size();
  summary["multipliers_solved"] = setup.condensed->zone.size();
  summary["watched_nodes"] = setup.condensed->path ? setup.condensed->path->nodes.size() : 0;
  summary["condensation"] = condensation_json(setup);
  summary["wall_s"] = run.wall;
  summary["wall_total_s"] = run.wall.total();
  summary["peak_rss_mb"] = peak_rss_mb();
  return summary;
}

}  // namespace skinfem::pipeline
