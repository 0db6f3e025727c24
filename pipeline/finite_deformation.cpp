#include "skinfem/pipeline/finite_deformation.hpp"

#include <algorithm>
#include <cmath>

#include "skinfem/contact/contact_solver.hpp"
#include "skinfem/contact/finite_contact.hpp"
#include "skinfem/pipeline/progress.hpp"
#include "skinfem/scene/laws.hpp"
#include "skinfem/validation/crosscheck.hpp"
#include "skinfem/validation/hole_budget.hpp"
#include "skinfem/validation/text.hpp"

namespace skinfem::pipeline {

namespace {

using validation::fmt;

constexpr const char* kCases[2] = {"static", "sliding"};

nlohmann::json beside(double linear, double finite) {
  return {{"linear", linear}, {"finite", finite}, {"change_rel", linear != 0 ? finite / linear - 1 : 0.0}};
}

// max |ς| of column col over the positions, MPa.
double peak(const Eigen::MatrixXd& s, int col) { return s.col(col).cwiseAbs().maxCoeff(); }

struct Range {
  double lo = 1e300, hi = 0;
  void add(double v) { lo = std::min(lo, v), hi = std::max(hi, v); }
};
// [lo, hi], or null for no sensor.
nlohmann::json range_json(const Range& r) { return r.hi > 0 ? nlohmann::json{r.lo, r.hi} : nlohmann::json(); }
// "x0.96–1.10 on the front sensors", or "no front sensor".
std::string on(const Range& r, const std::string& where) {
  return r.hi > 0 ? "x" + fmt("%.2f", r.lo) + "–" + fmt("%.2f", r.hi) + " on the " + where + " sensors"
                  : "no " + where + " sensor";
}

}  // namespace

FiniteDeformation finite_deformation(const Scene& scene, const DefectRun& linear, bool shear_strength) {
  if (linear.sweeps.size() != 2 || linear.sweeps[0].mode != FrictionMode::static_residual ||
      linear.sweeps[1].mode != FrictionMode::coupled)
    throw std::invalid_argument(
        "finite_deformation: the linear run's cases are static_residual, then coupled");
  FiniteDeformation f;
  f.run =
      finite_defect_run(scene, {FrictionMode::static_residual, FrictionMode::coupled}, {}, kSlidingStations);
  if (shear_strength && scene.contact->law != FrictionLaw::shear_strength) {
    // The hole budget's shear_strength hypothesis on the finite skin, from the same frictionless state.
    Scene shear = scene;
    for (const validation::Hypothesis& h : validation::friction_hypotheses(*scene.contact))
      if (h.load.law == FrictionLaw::shear_strength) shear.contact = h.load;
    progress("finite deformation under the shear strength: its static and sliding states and hole sweeps");
    try {
      f.shear = finite_defect_run(shear, {FrictionMode::static_residual, FrictionMode::coupled}, {}, 1,
                                  f.run.frictionless);
      f.shear_scene = shear;
    } catch (const SolverError& e) {
      f.shear_failed = e.what();
    }
  }
  const ContactSetup& setup = *linear.setup;
  // The linear coupled contact along the ratio: one complementarity solve each on the condensed skin.
  const Eigen::Vector2d t(scene.contact->direction[0], scene.contact->direction[1]);
  for (int i = 0; i < kLinearPathPoints; ++i) {
    ContactLoad load = *scene.contact;
    load.mu = scene.contact->mu * i / (kLinearPathPoints - 1);
    const contact::ContactSolver solver(*setup.condensed, load, setup.mirror.get());
    const contact::ContactResult r = solver.solve(FrictionMode::coupled);
    const contact::ContactZoneFrame z = contact::zone_frame(setup.mesh(), solver.zone(), r.active, r.lambda,
                                                            nullptr, contact_center(scene), t);
    f.linear_path.push_back({load.mu, r.tangential_force_N, r.depth_mm, z, z});
  }
  for (int c = 0; c < 2; ++c) {
    f.linear[c] = linear.sweeps[c].baseline;
    f.linear_metrics[c] =
        contact::contact_metrics(*setup.solver, setup.mesh(), *setup.top, f.linear[c], contact_center(scene));
    f.linear_signals[c] = linear.sweeps[c].varsigma;
  }
  const TetMesh& a = setup.skin->mesh;
  const TetMesh& b = *f.run.cases[0].state.solved;
  f.same_mesh = a.num_nodes() == b.num_nodes() && a.num_tets() == b.num_tets() && a.nodes == b.nodes;
  return f;
}

nlohmann::json finite_deformation_json(const Scene& scene, const FiniteDeformation& f,
                                       const HoleBudget* budget) {
  const int ns = static_cast<int>(scene.sensors.positions.size());
  const std::vector<int> front =
      validation::front_sensors(scene.sensors, contact_center(scene), scene.contact->direction);
  const auto is_front = [&](int k) { return std::find(front.begin(), front.end(), k) != front.end(); };
  nlohmann::json out;
  out["question"] = "Does finite deformation matter at the paper's load?";
  out["material_model"] = "neo_hookean";
  out["same_mesh"] = f.same_mesh;
  out["dofs"] = f.run.cases.at(0).state.dofs;
  out["force_N"] = f.run.cases[0].state.force_N;
  out["mu"] = scene.contact->mu;
  std::array<Range, 2> front_ratio, back_ratio;  // sliding hole amplitudes, finite over linear
  for (int c = 0; c < 2; ++c) {
    const FiniteDefectCase& fc = f.run.cases[c];
    const FiniteContactRun& st = fc.state;
    const contact::ContactMetrics &lm = f.linear_metrics[c], &fm = fc.metrics;
    nlohmann::json j;
    j["tangential_force_N"] = st.tangential_force_N;
    j["contact"] = {{"contact_radius_mm", beside(lm.contact_radius_mm, fm.contact_radius_mm)},
                    {"p0_kPa", beside(1e3 * lm.p0_MPa, 1e3 * fm.p0_MPa)},
                    {"p_max_kPa", beside(1e3 * lm.p_max_MPa, 1e3 * fm.p_max_MPa)},
                    {"indentation_um", beside(1e3 * f.linear[c].depth_mm, 1e3 * st.result.depth_mm)},
                    {"front_edge_mm", beside(lm.front_edge_mm, fm.front_edge_mm)},
                    {"back_edge_mm", beside(lm.back_edge_mm, fm.back_edge_mm)},
                    {"zone_centroid_x_mm", beside(lm.zone_centroid[0], fm.zone_centroid[0])},
                    {"pressure_centroid_x_mm", beside(lm.pressure_centroid[0], fm.pressure_centroid[0])},
                    {"frame", "material (reference): where the skin's material touches"}};
    const contact::ContactZoneFrame& cur = st.current;
    j["spatial_zone"] = {{"frame", "spatial (current): where the deformed surface touches the plate"},
                         {"front_edge_mm", cur.front_mm},
                         {"back_edge_mm", -cur.back_mm},
                         {"zone_centroid_mm", {cur.zone_centroid[0], cur.zone_centroid[1]}},
                         {"anisotropy", cur.anisotropy()},
                         {"shift_from_material_mm", cur.zone_centroid[0] - st.reference.zone_centroid[0]}};
    j["max_tangential_displacement_mm"] = st.max_tangential_mm;
    j["tangential_displacement_over_indentation"] = st.max_tangential_mm / st.result.depth_mm;
    const Eigen::VectorXd& lr = f.linear[c].readings;
    const Eigen::MatrixXd &ls = f.linear_signals[c], &fs = fc.sweep.varsigma;
    for (int k = 0; k < ns; ++k) {
      j["readings"].push_back({{"sensor", k + 1},
                               {"sigma_z_kPa", beside(1e3 * lr[2 * k], 1e3 * st.readings[k].sigma_z)},
                               {"sigma_x_kPa", beside(1e3 * lr[2 * k + 1], 1e3 * st.readings[k].sigma_x)}});
      nlohmann::json a = {{"sensor", k + 1}, {"front", is_front(k)}};
      for (int d = 0; d < 2; ++d) {
        const double l = peak(ls, 2 * k + d), g = peak(fs, 2 * k + d);
        a[d ? "x" : "z"] = {{"linear_kPa", 1e3 * l}, {"finite_kPa", 1e3 * g}, {"ratio", l > 0 ? g / l : 0.0}};
        if (l > 0) (is_front(k) ? front_ratio : back_ratio)[c].add(g / l);
      }
      j["hole_amplitudes"].push_back(a);
    }
    j["hole_amplitude_ratio"] = {{"front", range_json(front_ratio[c])}, {"back", range_json(back_ratio[c])}};
    out["cases"][kCases[c]] = j;
  }
  const auto frame = [](const contact::ContactZoneFrame& z) {
    return nlohmann::json{{"area_mm2", z.area_mm2},
                          {"equivalent_radius_mm", std::sqrt(z.area_mm2 / M_PI)},
                          {"front_edge_mm", z.front_mm},
                          {"back_edge_mm", -z.back_mm},
                          {"zone_centroid_x_mm", z.zone_centroid[0]},
                          {"force_centroid_x_mm", z.force_centroid[0]},
                          {"anisotropy", z.anisotropy()},
                          {"moment_radius_mm", z.moment_radius_mm},
                          {"moment_anisotropy", z.moment_anisotropy}};
  };
  for (const FinitePathPoint& p : f.run.path)
    out["path"]["finite"].push_back({{"ratio", p.ratio},
                                     {"tangential_force_N", p.tangential_force_N},
                                     {"indentation_um", 1e3 * p.depth_mm},
                                     {"material", frame(p.material)},
                                     {"spatial", frame(p.spatial)}});
  for (const FinitePathPoint& p : f.linear_path)
    out["path"]["linear"].push_back({{"ratio", p.ratio},
                                     {"tangential_force_N", p.tangential_force_N},
                                     {"indentation_um", 1e3 * p.depth_mm},
                                     {"material", frame(p.material)}});
  out["path"]["edges"] =
      "along the sliding direction from the first-touch point; material: the touching hats at their "
      "reference "
      "positions, spatial: at their current ones (finite only); anisotropy: length along over width across; "
      "moment_radius_mm and moment_anisotropy: from the pressure's second moments (a Hertzian contact's a, "
      "and 1 when axisymmetric), smooth where the vertex-based sizes step";
  out["wall_s"] = f.run.wall;
  out["seconds"] = f.run.wall.total();
  if (f.shear) {
    // The shear-strength hypothesis: its sliding contact on the finite skin, and its hole amplitudes over the
    // linear skin's (the budget's shear_strength row).
    const FiniteDefectCase& sc = f.shear->cases.at(1);
    const FiniteContactRun& st = sc.state;
    nlohmann::json j = {{"tau0_kPa", 1e3 * st.tau0_MPa},
                        {"tangential_force_N", st.tangential_force_N},
                        {"contact_radius_mm", sc.metrics.contact_radius_mm},
                        {"p0_kPa", 1e3 * sc.metrics.p0_MPa},
                        {"indentation_um", 1e3 * st.result.depth_mm},
                        {"partial_shear", st.result.partial_shear},
                        {"seconds", f.shear->wall.total()}};
    // The budget holds both rows' signals in its units (the same scale per sensor and component).
    const validation::HypothesisResult *lin = nullptr, *fin = nullptr;
    if (budget)
      for (const validation::HypothesisResult& r : budget->results) {
        if (r.hypothesis.name == "shear_strength") lin = &r;
        if (r.hypothesis.name == "shear_strength_finite") fin = &r;
      }
    Range fr, br;
    for (int k = 0; k < ns; ++k) {
      nlohmann::json a = {{"sensor", k + 1}, {"front", is_front(k)}};
      for (int d = 0; d < 2; ++d) {
        const int col = 2 * k + d;
        nlohmann::json& x = a[d ? "x" : "z"];
        const double g = peak(sc.sweep.varsigma, col);
        x["finite_kPa"] = 1e3 * g;
        if (!lin || !fin) continue;
        const double ls = peak(lin->signals[1], col), fs = peak(fin->signals[1], col);
        if (!(ls > 0 && fs > 0)) continue;
        x["linear_kPa"] = 1e3 * g * ls / fs;
        x["ratio"] = fs / ls;
        (is_front(k) ? fr : br).add(fs / ls);
      }
      j["hole_amplitudes"].push_back(a);
    }
    if (lin && fin) j["hole_amplitude_ratio"] = {{"front", range_json(fr)}, {"back", range_json(br)}};
    out["shear_strength"] = j;
    out["seconds"] = f.run.wall.total() + f.shear->wall.total();
  }

  // The answer, from the sliding case's numbers.
  const FiniteContactRun& st = f.run.cases[1].state;
  const contact::ContactMetrics &lm = f.linear_metrics[1], &fm = f.run.cases[1].metrics;
  const auto pct = [](double lin, double fin) { return fmt("%+.1f %%", 100 * (fin / lin - 1)); };
  const auto moved = [](double lin, double fin) {
    const std::string a = fmt("%.2f", lin), b = fmt("%.2f", fin);
    return a == b ? "stays at " + a + " mm" : "goes from " + a + " to " + b + " mm";
  };
  std::string answer =
      "Sliding at mu = " + fmt("%g", scene.contact->mu) + " under " + fmt("%g", st.force_N) +
      " N, finite strain changes the contact radius by " + pct(lm.contact_radius_mm, fm.contact_radius_mm) +
      " (" + fmt("%.3f", lm.contact_radius_mm) + " to " + fmt("%.3f", fm.contact_radius_mm) + " mm), p0 by " +
      pct(lm.p0_MPa, fm.p0_MPa) + " and the indentation by " + pct(f.linear[1].depth_mm, st.result.depth_mm) +
      "; in the material frame the zone's back edge " + moved(lm.back_edge_mm, fm.back_edge_mm) +
      " and its front edge " + moved(lm.front_edge_mm, fm.front_edge_mm) +
      ", and the deformed surface carries the zone " +
      fmt("%.2f", st.current.zone_centroid[0] - st.reference.zone_centroid[0]) +
      " mm along x (spatial against material centroid). Sliding hole amplitudes, finite over linear: " +
      on(front_ratio[1], "front") + ", " + on(back_ratio[1], "back") + ".";
  if (f.run.path.size() > 1 && f.linear_path.size() > 1) {
    // From the frictionless state to the sliding one, the pressure's moments in the material frame.
    const contact::ContactZoneFrame &f0 = f.run.path.front().material, &f1 = f.run.path.back().material,
                                    &l0 = f.linear_path.front().material, &l1 = f.linear_path.back().material;
    answer += " From no tangential load to " + fmt("%.3g", f.run.path.back().tangential_force_N) +
              " N, the zone's moment radius changes by " + pct(f0.moment_radius_mm, f1.moment_radius_mm) +
              " (linear " + pct(l0.moment_radius_mm, l1.moment_radius_mm) +
              ") and its anisotropy along/across " + "goes from " + fmt("%.3f", f0.moment_anisotropy) +
              " to " + fmt("%.3f", f1.moment_anisotropy) + " (linear " + fmt("%.3f", l0.moment_anisotropy) +
              " to " + fmt("%.3f", l1.moment_anisotropy) + ").";
  }
  if (!f.same_mesh) answer += " The two skins were meshed differently: the changes include mesh error.";
  if (budget)
    for (size_t i = 0; i < budget->results.size(); ++i) {
      const std::string& name = budget->results[i].hypothesis.name;
      if (name.size() < 7 || name.compare(name.size() - 7, 7, "_finite") != 0) continue;
      answer += " Its hole-budget row " + name + " meets " + std::to_string(budget->facts_met[i]) +
                " of the paper's 5 facts";
      for (const auto& v : budget->results[i].facts)
        if (v.fact == "F3") answer += std::string("; F3 is ") + (v.met ? "met: " : "not met: ") + v.why;
      answer += answer.back() == '.' ? "" : ".";
    }
  if (!f.shear_failed.empty())
    answer += " The shear strength on the finite skin did not solve: " + f.shear_failed;
  out["answer"] = answer;
  return out;
}

}  // namespace skinfem::pipeline
