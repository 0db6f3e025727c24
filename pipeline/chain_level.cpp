#include "skinfem/pipeline/chain_level.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "skinfem/contact/holes/sweep.hpp"
#include "skinfem/contact/metrics.hpp"
#include "skinfem/green/calibration.hpp"
#include "skinfem/green/kfit.hpp"
#include "skinfem/mesh/sizing.hpp"
#include "skinfem/pipeline/clock.hpp"
#include "skinfem/pipeline/kfit.hpp"
#include "skinfem/pipeline/progress.hpp"
#include "skinfem/pipeline/scene_json.hpp"
#include "skinfem/pipeline/symmetry.hpp"
#include "skinfem/validation/richardson.hpp"
#include "skinfem/validation/text.hpp"

namespace skinfem::pipeline {

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
  const green::KReport k =
      green::fit_profile(prof.offset_x, prof.point, h, sensor_gains(s.sensors, s.material.nu, h).gains);
  const double t_green = adj.wall.total() + clock.seconds();
  add("k_central", k.k_central, t_green);
  add("k_lsq_line", k.k_lsq_line, t_green);
  if (s.contact && c) {
    clock = Stopwatch();
    const contact::ContactResult r = c->solver->solve(FrictionMode::coupled);
    const contact::ContactMetrics m =
        contact::contact_metrics(*c->solver, c->mesh(), *c->top, r, contact_center(s));
    const double t_contact = t_green + c->wall.at("condense") + clock.seconds();
    add("contact_radius", m.contact_radius_mm, t_contact);
    add("contact_p0", m.p0_MPa, t_contact);
    add("indentation", r.depth_mm, t_contact);
    l.wall["condense"] = c->wall.at("condense");
    if (s.contact->sweep) {
      clock = Stopwatch();
      const contact::HoleDimples dimples(*c->solver, c->mesh(), *c->top, s.material.E, s.material.nu);
      const contact::SweepResult sw =
          contact::hole_sweep(*c->solver, c->mesh(), *s.contact->sweep, FrictionMode::coupled, &dimples);
      const double peak = contact::largest_varsigma_z(sw.varsigma);
      add("hole_signal", peak, t_contact + clock.seconds());
      l.wall["sweep"] = clock.seconds();
    }
  }
  l.peak_rss_mb = peak_rss_mb();
  return l;
}

namespace {
ChainLevel level_of(const Scene& s, double scale) {
  RssSampler memory;  // the level's own peak, not the larger one's before it
  ChainLevel l;
  {
    ContactSkin factored = chain_skin(s);
    const auto adj = adjoint_setup(s, factored.skin);
    const auto contact = s.contact ? contact_setup(s, std::move(factored)) : nullptr;
    l = chain_values(s, *adj, contact.get());
  }
  l.scale = scale;
  l.peak_rss_mb = memory.peak_mb();
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

void check_error_scales(const std::vector<double>& error_scales) {
  char buf[32];
  if (error_scales.size() == 1)
    throw SceneError("--error-scales: one coarser level given; Richardson needs two (e.g. 2,1.41)");
  for (double e : error_scales)
    if (!(e > 1)) {
      std::snprintf(buf, sizeof buf, "%g", e);
      throw SceneError(std::string("--error-scales: ") + buf +
                       ": the error levels are coarser than the scene, so each scale must be > 1");
    } else if (e > kMaxErrorScale) {
      std::snprintf(buf, sizeof buf, "%g", e);
      throw SceneError(std::string("--error-scales: ") + buf + ": a level at more than " +
                       std::to_string(static_cast<int>(kMaxErrorScale)) +
                       " times every mesh size no longer resolves the scene, so its change is no error bar");
    }
}

std::map<std::string, double> time_vs_dofs_exponent(const std::vector<ChainLevel>& levels) {
  std::map<std::string, double> out;
  for (const auto& [stage, t] : levels.back().wall) {
    std::vector<double> x, y;
    for (const ChainLevel& c : levels)
      if (c.wall.contains(stage)) {
        x.push_back(c.dofs);
        y.push_back(c.wall.at(stage));
      }
    const double e = validation::loglog_slope(x, y);
    if (std::isfinite(e)) out[stage] = e;
  }
  return out;
}

nlohmann::json chain_study_json(const Scene& scene, const std::vector<ChainLevel>& levels) {
  nlohmann::json extrap, jlevels = nlohmann::json::array();
  for (const ChainLevel& c : levels) {
    nlohmann::json jl = {
        {"scale", c.scale}, {"dofs", c.dofs}, {"wall_s", c.wall}, {"peak_rss_mb", c.peak_rss_mb}};
    for (size_t i = 0; i < c.names.size(); ++i) jl["values"][c.names[i]] = c.value[i];
    if (!c.note.empty()) jl["note"] = c.note;
    jlevels.push_back(jl);
  }
  for (const ChainError& e : chain_errors(levels))
    extrap[e.name] = {
        {"observed_order", e.asymptotic ? nlohmann::json(e.order) : nlohmann::json("none: " + e.why_not)},
        {"reference", e.reference},
        {"reference_is", e.asymptotic ? "Richardson limit" : "finest level"}};
  return {{"scene", scene_json(scene)},
          {"levels", jlevels},
          {"extrapolation", extrap},
          {"time_vs_dofs_exponent", time_vs_dofs_exponent(levels)},
          {"peak_rss_mb", peak_rss_mb()}};
}

const QuantityDisplay* quantity_display(const std::string& name) {
  static const QuantityDisplay table[] = {
      {"k_central", "k, central criterion (sensor #1)", "", 1},
      {"k_lsq_line", "k, line fit (sensor #1)", "", 1},
      {"contact_radius", "contact radius (coupled friction)", "mm", 1},
      {"contact_p0", "central pressure (coupled friction)", "kPa", 1e3},
      {"indentation", "indentation (coupled friction)", "um", 1e3},
      {"hole_signal", "largest sliding |varsigma_z| over sensors and hole positions", "kPa", 1e3}};
  for (const QuantityDisplay& d : table)
    if (name == d.name) return &d;
  return nullptr;
}

std::vector<ErrorBar> error_bars(const std::vector<ChainError>& errors,
                                 const std::vector<double>& coarse_scales) {
  std::string levels;
  for (double s : coarse_scales) levels += validation::fmt("%g", s) + ", ";
  levels += "1";
  std::vector<ErrorBar> out;
  for (const ChainError& e : errors)
    if (const QuantityDisplay* d = quantity_display(e.name))
      out.push_back({e.name, d->what, d->unit,
                     e.asymptotic
                         ? "|value - Richardson limit| over mesh scales " + levels + ", observed order " +
                               validation::fmt("%.2f", e.order)
                         : "last change between mesh scales " + validation::fmt("%g", coarse_scales.back()) +
                               " and 1; no asymptotic regime over " + levels + " (" + e.why_not +
                               "), so an order of magnitude only",
                     d->factor * e.value, d->factor * e.error, e.error / std::abs(e.value)});
  return out;
}

nlohmann::json error_bars_json(const std::vector<ErrorBar>& bars) {
  nlohmann::json j = nlohmann::json::array();
  for (const ErrorBar& e : bars)
    j.push_back({{"quantity", e.quantity},
                 {"what", e.what},
                 {"unit", e.unit},
                 {"value", e.value},
                 {"error", e.error},
                 {"relative_error", e.relative_error},
                 {"method", e.method}});
  return j;
}

}  // namespace skinfem::pipeline
