#include "skinfem/pipeline/inversion.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "skinfem/contact/holes/dimple.hpp"
#include "skinfem/contact/holes/sweep.hpp"
#include "skinfem/pipeline/contact_setup.hpp"
#include "skinfem/pipeline/progress.hpp"
#include "skinfem/pipeline/resources.hpp"
#include "skinfem/pipeline/scene_json.hpp"

namespace skinfem::pipeline {

std::vector<double> offset_grid(double range, double step) {
  std::vector<double> out;
  const int n = static_cast<int>(std::floor(range / step + 1e-9));
  for (int k = -n; k <= n; ++k) out.push_back(k * step);
  return out;
}

int dictionary_positions(const Scene& scene, double dx) {
  const double hole = scene.contact && scene.contact->sweep ? scene.contact->sweep->hole_diameter : 0;
  return static_cast<int>(std::ceil(2 * (contact_zone_radius(scene) + hole) / dx)) + 1;
}

std::string inversion_unavailable(const Scene& scene, const std::vector<double>& offsets) {
  if (!scene.contact || !scene.contact->sweep)
    return "contact.sweep: missing; the inversion takes its hole as the dictionary's";
  if (scene.contact->direction[0] != 1)
    return "contact.friction.direction: the inversion reads scans along +x";
  if (scene.sensors.model == SensorModel::post &&
      std::any_of(offsets.begin(), offsets.end(), [](double d) { return d != 0; }))
    return "sensors.model = \"post\": a post reads the skin only where it is meshed, so the dictionary "
           "cannot move the sensors by the contact's offset: give --offset-range 0 (the offset taken as "
           "known)";
  for (const Vec2& p : scene.sensors.positions)
    if (p[1] != scene.sensors.positions.at(0)[1])
      return "sensors.positions: the inversion needs the sensors on one line y = const";
  return "";
}

validation::HoleResponses hole_responses(const Scene& scene, FrictionMode mode, double dx,
                                         const std::vector<double>& offsets, Timings& wall, int& dofs) {
  if (const std::string why = inversion_unavailable(scene, offsets); !why.empty())
    throw SceneError(scene.source_path + ": " + why);
  const double y = scene.sensors.positions.at(0)[1];
  // The virtual sensors: every x_i − δ, once.
  Scene s = scene;
  validation::HoleResponses r;
  for (const Vec2& p : scene.sensors.positions)
    for (double d : offsets) {
      const double x = p[0] - d;
      bool seen = false;
      for (double o : r.sites) seen = seen || std::abs(o - x) < 1e-6;
      if (!seen) r.sites.push_back(x);
    }
  s.sensors.positions.clear();
  for (double x : r.sites) s.sensors.positions.push_back({x, y});
  // The hole from one side of the zone to the other, every dx.
  const double c = contact_center(scene)[0],
               reach = contact_zone_radius(scene) + scene.contact->sweep->hole_diameter;
  HoleSweep& sw = *s.contact->sweep;
  const int positions = dictionary_positions(scene, dx);
  sw.from = {c - reach, 0};
  sw.to = {c - reach + (positions - 1) * dx, 0};
  sw.positions = positions;
  r.x0 = sw.from[0];
  r.dx = dx;
  r.diameter = sw.hole_diameter;
  progress("invert: the dictionary, " + std::to_string(r.sites.size()) + " virtual sensors x " +
           std::to_string(positions) + " hole positions");
  const auto setup = contact_setup(s);
  wall = setup->wall;
  dofs = setup->model->solver().free_dofs();
  Stopwatch clock;
  const contact::HoleDimples dimples(*setup->solver, setup->mesh(), *setup->top, s.material.E, s.material.nu);
  const contact::SweepResult res = contact::hole_sweep(*setup->solver, setup->mesh(), sw, mode, &dimples);
  r.R = 1e3 * res.varsigma;
  wall["dictionary_sweep"] = clock.seconds();
  return r;
}

std::string dictionary_mismatch(const Scene& scene, const validation::HoleResponses& r, double dx,
                                const std::vector<double>& offsets) {
  const auto mm = [](double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.6g mm", v);
    return std::string(b);
  };
  if (std::abs(r.dx - dx) > 1e-6) return "its step is " + mm(r.dx) + ", the signals' " + mm(dx);
  if (r.R.rows() != dictionary_positions(scene, dx))
    return "it holds " + std::to_string(r.R.rows()) + " hole positions; the scene's zone needs " +
           std::to_string(dictionary_positions(scene, dx));
  for (const Vec2& p : scene.sensors.positions)
    for (double d : offsets)
      if (validation::site_column(r, p[0] - d) < 0)
        return "it has no virtual sensor at " + mm(p[0] - d) + " (sensor at " + mm(p[0]) + ", offset " +
               mm(d) + "): it was built for another --offset-range";
  return "";
}

InversionRun inversion_run(const Scene& scene, const validation::ScanSignals& signals,
                           const InversionOptions& o, const validation::HoleResponses* dictionary) {
  InversionRun run;
  const double dx = (signals.u.back() - signals.u.front()) / (signals.u.size() - 1);
  const std::vector<double> offsets = offset_grid(o.offset_range, o.offset_step);
  if (dictionary) {
    if (const std::string why = inversion_unavailable(scene, offsets); !why.empty())
      throw SceneError(scene.source_path + ": " + why);
    if (const std::string why = dictionary_mismatch(scene, *dictionary, dx, offsets); !why.empty())
      throw SceneError("--dictionary: " + why);
    run.responses = *dictionary;
  } else {
    run.responses = hole_responses(scene, o.mode, dx, offsets, run.wall, run.dofs);
  }
  Stopwatch clock;
  run.multi = validation::invert_scan(signals, run.responses, o.noise, offsets, o.p_fa);
  run.wall["invert"] = clock.seconds();
  Stopwatch naive;
  for (int k = 0; k < static_cast<int>(signals.sensors.size()); ++k)
    run.naive.push_back(validation::invert_scan(signals, run.responses, o.noise, {0.0}, o.p_fa, k));
  run.wall["invert_naive"] = naive.seconds();
  return run;
}

nlohmann::json inversion_json(const Scene& scene, const InversionRun& run, const InversionOptions& o) {
  const auto features = [](const validation::Inversion& inv) {
    nlohmann::json f = nlohmann::json::array();
    for (const validation::Feature& x : inv.features)
      f.push_back({{"position_mm", x.position_mm},
                   {"diameter_mm", x.diameter_mm},
                   {"amplitude", x.amplitude},
                   {"snr", x.snr}});
    return f;
  };
  nlohmann::json j;
  j["scene"] = scene_json(scene);
  j["case"] = to_string(o.mode);
  j["noise"] = {{"sigma_z_kPa", o.noise.sigma_z_kPa},
                {"sigma_x_kPa", o.noise.sigma_x_kPa},
                {"passages", o.noise.passages}};
  j["contact_offset_mm"] = run.multi.offset_mm;
  j["contact_offset_refined_mm"] = run.multi.offset_refined_mm;
  j["offsets_mm"] = run.multi.offsets;
  j["weighted_residuals"] = run.multi.residuals;
  j["features"] = features(run.multi);
  nlohmann::json naive = nlohmann::json::array();
  for (size_t k = 0; k < run.naive.size(); ++k)
    naive.push_back({{"sensor", k + 1}, {"features", features(run.naive[k])}});
  j["naive_single_sensor"] = naive;
  j["dictionary"] = {{"hole_diameter_mm", run.responses.diameter},
                     {"virtual_sensors", run.responses.sites.size()},
                     {"hole_positions", run.responses.R.rows()},
                     {"step_mm", run.responses.dx}};
  j["dofs"] = run.dofs;
  j["wall_s"] = run.wall;
  j["wall_total_s"] = run.wall.total();
  j["peak_rss_mb"] = peak_rss_mb();
  return j;
}

}  // namespace skinfem::pipeline
