#include "app/chain_level.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "app/common.hpp"
#include "app/symmetry.hpp"
#include "contact/hole_sweep.hpp"
#include "contact/metrics.hpp"
#include "green/calibration.hpp"
#include "green/kfit.hpp"
#include "mesh/sizing.hpp"
#include "validation/richardson.hpp"

namespace skinfem::app {

Scene scaled_scene(const Scene& base, double s, bool cap_holes) {
  Scene scene = base;
  scene.mesh.sensor_h = sensor_mesh_size(base) * s;
  scene.mesh.h_min *= s;
  scene.mesh.h_max *= s;
  scene.mesh.growth = 1 + s * (scene.mesh.growth - 1);
  for (auto& r : scene.mesh.regions) r.h *= s;
  if (scene.contact) {
    scene.contact->h = contact_zone_h(base) * s;
    for (auto& hole : scene.contact->holes) hole.h *= s;
    if (scene.contact->sweep) scene.contact->sweep->h *= s;
  }
  if (scene.contact && cap_holes) {
    // The scene rule: the mesh over a hole at most its diameter.
    const auto cap = [&scene](double& h, double diameter) {
      if (hole_mesh_h(scene, h) > diameter) h = diameter;
    };
    for (auto& hole : scene.contact->holes) cap(hole.h, hole.diameter);
    if (scene.contact->sweep) cap(scene.contact->sweep->h, scene.contact->sweep->hole_diameter);
  }
  return scene;
}

ChainLevel chain_values(const Scene& s, const AdjointSetup& adj, const ContactSetup* c) {
  ChainLevel l;
  l.dofs = adj.model->solver().free_dofs();
  l.wall = adj.wall;
  auto add = [&](const char* name, double v, double seconds) {
    l.names.push_back(name);
    l.value.push_back(v);
    l.seconds.push_back(seconds);
  };
  Stopwatch clock;
  const Vec2 pos = s.sensors.positions[0];
  const double h = thickness_at(s, adj.mesh, pos);
  const auto prof =
      green::scan_profile(*adj.fe, 0, green::LayerLoad::punch, 0.5 * s.calibration.punch_diameter,
                          scan_half_width(s, &adj.mesh, h, pos), s.calibration.spacing);
  const green::KReport k = green::fit_profile(prof.offset_x, prof.point, h);
  const double t_green = total_seconds(adj.wall) + clock.seconds();
  add("k_central", k.k_central, t_green);
  add("k_lsq_line", k.k_lsq_line, t_green);
  if (s.contact && c) {
    clock = Stopwatch();
    const contact::ContactResult r = c->solver->solve(FrictionMode::coupled);
    const contact::ContactMetrics m =
        contact::contact_metrics(*c->solver, c->mesh(), *c->top, r, contact_center(s));
    const double t_contact = t_green + c->wall["condense"].get<double>() + clock.seconds();
    add("contact_radius", m.contact_radius_mm, t_contact);
    add("contact_p0", m.p0_MPa, t_contact);
    add("indentation", r.depth_mm, t_contact);
    l.wall["condense"] = c->wall["condense"];
    if (s.contact->sweep) {
      clock = Stopwatch();
      const contact::SweepResult sw =
          contact::hole_sweep(*c->solver, c->mesh(), *s.contact->sweep, FrictionMode::coupled);
      double peak = 0;
      for (int j = 0; j < sw.varsigma.cols(); j += 2)
        peak = std::max(peak, sw.varsigma.col(j).cwiseAbs().maxCoeff());
      add("hole_signal", peak, t_contact + clock.seconds());
      l.wall["sweep"] = clock.seconds();
    }
  }
  l.peak_rss_mb = peak_rss_mb();
  return l;
}

namespace {
ChainLevel level_of(const Scene& s, double scale) {
  const auto skin = skin_setup(s, contact_mesh_part(s));
  const auto adj = adjoint_setup(s, skin);
  const auto contact = s.contact ? contact_setup(s, skin) : nullptr;
  ChainLevel l = chain_values(s, *adj, contact.get());
  l.scale = scale;
  return l;
}
}  // namespace

ChainLevel chain_level(const Scene& base, double scale) {
  try {
    return level_of(scaled_scene(base, scale), scale);
  } catch (const contact::HoleUnresolved& e) {
    progress(std::string("level x") + std::to_string(scale) + ": " + e.what() +
             "; redone with the mesh over the hole at most its diameter");
    ChainLevel l = level_of(scaled_scene(base, scale, true), scale);
    l.note = "the mesh over the hole capped at its diameter (the scaled one could not see it)";
    return l;
  }
}

std::vector<ChainError> chain_errors(const std::vector<ChainLevel>& levels) {
  const size_t n = levels.size();
  if (n < 3) throw std::invalid_argument("chain_errors: needs at least 3 levels");
  std::vector<ChainError> out;
  for (size_t i = 0; i < levels[n - 1].names.size(); ++i) {
    const std::array<double, 3> q{levels[n - 3].value[i], levels[n - 2].value[i], levels[n - 1].value[i]};
    const validation::Richardson r = validation::richardson(
        q, {levels[n - 3].scale, levels[n - 2].scale, levels[n - 1].scale}, kMaxPlausibleOrder);
    ChainError e;
    e.name = levels[n - 1].names[i];
    e.value = q[2];
    e.asymptotic = r.asymptotic;
    e.order = r.order;
    e.reference = r.limit;
    if (r.above_max_order) {
      char buf[96];
      std::snprintf(buf, sizeof buf, "observed order %.2f above %g, not P2-P1 convergence", r.order,
                    kMaxPlausibleOrder);
      e.why_not = buf;
    } else if (!r.asymptotic) {
      e.why_not = "differences change sign or grow";
    }
    e.error = e.asymptotic ? std::abs(q[2] - r.limit) : std::abs(q[2] - q[1]);
    out.push_back(e);
  }
  return out;
}

nlohmann::json write_chain_study(const Scene& scene, const std::vector<ChainLevel>& levels,
                                 const std::string& out_dir) {
  const size_t n = levels.size();
  std::ostringstream csv;
  csv.precision(10);
  csv << "stage,level,dofs,seconds,error\n";
  nlohmann::json extrap, jlevels = nlohmann::json::array();
  for (const ChainLevel& c : levels) {
    nlohmann::json jl = {
        {"scale", c.scale}, {"dofs", c.dofs}, {"wall_s", c.wall}, {"peak_rss_mb", c.peak_rss_mb}};
    for (size_t i = 0; i < c.names.size(); ++i) jl["values"][c.names[i]] = c.value[i];
    if (!c.note.empty()) jl["note"] = c.note;
    jlevels.push_back(jl);
  }
  const auto errors = chain_errors(levels);
  for (size_t i = 0; i < errors.size(); ++i) {
    const ChainError& e = errors[i];
    extrap[e.name] = {
        {"observed_order", e.asymptotic ? nlohmann::json(e.order) : nlohmann::json("none: " + e.why_not)},
        {"reference", e.reference},
        {"reference_is", e.asymptotic ? "Richardson limit" : "finest level"}};
    std::printf("%s: %s, reference %.6g; errors", e.name.c_str(),
                e.asymptotic
                    ? ("observed order " + std::to_string(e.order)).c_str()
                    : ("no asymptotic regime (" + e.why_not + "; finest level as reference)").c_str(),
                e.reference);
    for (size_t l = 0; l < n; ++l) {
      const double err = std::abs(levels[l].value[i] - e.reference) / std::abs(e.reference);
      std::printf(" %.2e", err);
      if (e.asymptotic || l + 1 < n)
        csv << e.name << "," << l + 1 << "," << levels[l].dofs << "," << levels[l].seconds[i] << "," << err
            << "\n";
    }
    std::printf("\n");
  }
  // Seconds ∝ DOFs^e per stage, over the levels that timed it.
  nlohmann::json exponents;
  std::printf("time-vs-DOFs exponent per stage:");
  for (const auto& [stage, t] : levels.back().wall.items()) {
    std::vector<double> x, y;
    for (const ChainLevel& c : levels)
      if (c.wall.contains(stage) && c.wall[stage].is_number()) {
        x.push_back(c.dofs);
        y.push_back(c.wall[stage].get<double>());
      }
    const double e = validation::loglog_slope(x, y);
    if (std::isfinite(e)) {
      exponents[stage] = e;
      std::printf(" %s %.2f", stage.c_str(), e);
    }
  }
  std::printf("\n");
  prepare_output_dir(out_dir);
  write_text_atomic(out_dir + "/chain_study.csv", csv.str());
  const nlohmann::json study = {{"scene", scene_json(scene)},
                                {"levels", jlevels},
                                {"extrapolation", extrap},
                                {"time_vs_dofs_exponent", exponents},
                                {"peak_rss_mb", peak_rss_mb()}};
  write_json(out_dir + "/chain_study.json", study);
  std::printf("  wrote %s/chain_study.csv, chain_study.json\n", out_dir.c_str());
  return study;
}

}  // namespace skinfem::app
