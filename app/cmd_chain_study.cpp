// skinfem study --chain — speed against error over the whole chain: every mesh size of the scene (h_min,
// h_max, grading, regions, contact zone, hole path and holes) scaled per level, and at each level the Green
// maps and k of sensor #1, the contact (coupled friction: radius, central pressure, indentation) and the
// hole sweep (largest |ς_z| over sensors and positions, sliding).
//
//   $ skinfem study scenes/candelier2011.json --chain --scales 2,1.41,1 --out out/candelier2011/study
//   level 3 (scale 1): 188,439 DOFs; k_central 1.5424 (error 0.05 %, 62 s) ...
//
// Errors are against the Richardson limit of the three finest levels (validation/richardson.hpp: Q = Q∞ + C
// sᵖ through them, p the observed order); when the differences change sign or grow (no asymptotic regime yet)
// the finest level is the reference and its own error is not given. The seconds of a quantity are those of
// every stage it needs (mesh, assemble, factor, then adjoints, condensation, sweep). Writes
// DIR/chain_study.csv (stage,level,dofs,seconds,error; read by scripts/figures.py for the Pareto plot) and
// DIR/chain_study.json (every level's values, stage times, orders and limits).
#include <cmath>
#include <cstdio>
#include <sstream>

#include "app/adjoint_setup.hpp"
#include "app/commands.hpp"
#include "app/common.hpp"
#include "app/contact_setup.hpp"
#include "contact/hole_sweep.hpp"
#include "contact/metrics.hpp"
#include "green/calibration.hpp"
#include "validation/richardson.hpp"

namespace skinfem::app {

namespace {
Scene scaled(const Scene& base, double s) {
  Scene scene = base;
  scene.mesh.h_min *= s;
  scene.mesh.h_max *= s;
  scene.mesh.growth = 1 + s * (scene.mesh.growth - 1);
  for (auto& r : scene.mesh.regions) r.h *= s;
  if (scene.contact) {
    scene.contact->h = contact_zone_h(base) * s;
    for (auto& hole : scene.contact->holes) hole.h *= s;
    if (scene.contact->sweep) scene.contact->sweep->h *= s;
  }
  return scene;
}

struct Quantity {
  Quantity(const char* n) : name(n) {}  // NOLINT: implicit, so a list of names builds the list
  std::string name;
  std::vector<double> value, seconds;
};
}  // namespace

int run_chain_study(const Scene& scene, const std::string& out_dir, const std::vector<double>& scales) {
  if (scales.size() < 3)
    throw SceneError("--scales: the chain study needs at least 3 levels for an observed order, got " +
                     std::to_string(scales.size()));
  check_output_dir(out_dir);
  std::vector<Quantity> q{{"k_central"}, {"k_lsq_line"}};
  if (scene.contact) q.insert(q.end(), {{"contact_radius"}, {"contact_p0"}, {"indentation"}});
  if (scene.contact && scene.contact->sweep) q.push_back({"hole_signal"});
  std::vector<int> dofs;
  nlohmann::json levels = nlohmann::json::array();
  for (size_t l = 0; l < scales.size(); ++l) {
    const Scene s = scaled(scene, scales[l]);
    char buf[160];
    std::snprintf(buf, sizeof buf, "chain study: level %zu of %zu (scale %g)", l + 1, scales.size(),
                  scales[l]);
    progress(buf);
    const auto skin = skin_setup(s);
    const auto adj = adjoint_setup(s, skin);
    Stopwatch clock;
    const Vec2 pos = s.sensors.positions[0];
    const double h = thickness_at(s, pos);
    const auto prof =
        green::scan_profile(*adj->fe, 0, green::LayerLoad::punch, 0.5 * s.calibration.punch_diameter,
                            scan_half_width(s, h, pos), s.calibration.spacing);
    const green::KReport k = green::fit_profile(prof.offset_x, prof.point, h);
    const double t_green = total_seconds(adj->wall) + clock.seconds();
    q[0].value.push_back(k.k_central);
    q[1].value.push_back(k.k_lsq_line);
    q[0].seconds.push_back(t_green);
    q[1].seconds.push_back(t_green);
    nlohmann::json jl = {
        {"scale", scales[l]}, {"dofs", skin->model->solver().free_dofs()}, {"wall_s", adj->wall}};
    if (s.contact) {
      const auto c = contact_setup(s, skin);
      clock = Stopwatch();
      const contact::ContactResult r = c->solver->solve(FrictionMode::coupled);
      const contact::ContactMetrics m =
          contact::contact_metrics(*c->condensed, skin->mesh, *c->top, r, contact_center(s));
      const double t_contact = t_green + c->wall["condense"].get<double>() + clock.seconds();
      for (auto [i, v] : {std::pair{2, m.contact_radius_mm}, {3, m.p0_MPa}, {4, r.depth_mm}}) {
        q[i].value.push_back(v);
        q[i].seconds.push_back(t_contact);
      }
      jl["wall_s"]["condense"] = c->wall["condense"];
      if (s.contact->sweep) {
        clock = Stopwatch();
        const contact::SweepResult sw =
            contact::hole_sweep(*c->solver, skin->mesh, *s.contact->sweep, FrictionMode::coupled);
        double peak = 0;
        for (int k2 = 0; k2 < sw.varsigma.cols(); k2 += 2)
          peak = std::max(peak, sw.varsigma.col(k2).cwiseAbs().maxCoeff());
        q[5].value.push_back(peak);
        q[5].seconds.push_back(t_contact + clock.seconds());
        jl["wall_s"]["sweep"] = clock.seconds();
      }
    }
    dofs.push_back(skin->model->solver().free_dofs());
    jl["peak_rss_mb"] = peak_rss_mb();
    for (const auto& x : q) jl["values"][x.name] = x.value.back();
    levels.push_back(jl);
    std::printf("level %zu (scale %g): %d DOFs", l + 1, scales[l], dofs.back());
    for (const auto& x : q)
      std::printf("; %s %.6g (%.1f s)", x.name.c_str(), x.value.back(), x.seconds.back());
    std::printf("\n");
  }

  // Richardson over the three finest levels.
  const size_t n = scales.size();
  std::ostringstream csv;
  csv.precision(10);
  csv << "stage,level,dofs,seconds,error\n";
  nlohmann::json extrap;
  for (const auto& x : q) {
    const validation::Richardson rich = validation::richardson(
        {x.value[n - 3], x.value[n - 2], x.value[n - 1]}, {scales[n - 3], scales[n - 2], scales[n - 1]});
    const bool asymptotic = rich.asymptotic;
    const double limit = rich.limit, p = rich.order;
    extrap[x.name] = {
        {"observed_order", asymptotic ? nlohmann::json(p) : nlohmann::json("none: not asymptotic")},
        {"reference", limit},
        {"reference_is", asymptotic ? "Richardson limit" : "finest level"}};
    std::printf("%s: %s, reference %.6g; errors", x.name.c_str(),
                asymptotic
                    ? ("observed order " + std::to_string(p)).c_str()
                    : "no asymptotic regime (differences change sign or grow; finest level as reference)",
                limit);
    for (size_t l = 0; l < n; ++l) {
      const double e = std::abs(x.value[l] - limit) / std::abs(limit);
      std::printf(" %.2e", e);
      if (asymptotic || l + 1 < n)
        csv << x.name << "," << l + 1 << "," << dofs[l] << "," << x.seconds[l] << "," << e << "\n";
    }
    std::printf("\n");
  }
  prepare_output_dir(out_dir);
  write_text_atomic(out_dir + "/chain_study.csv", csv.str());
  write_json(out_dir + "/chain_study.json", {{"scene", scene_json(scene)},
                                             {"levels", levels},
                                             {"extrapolation", extrap},
                                             {"peak_rss_mb", peak_rss_mb()}});
  std::printf("  wrote %s/chain_study.csv, chain_study.json\n", out_dir.c_str());
  return 0;
}

}  // namespace skinfem::app
