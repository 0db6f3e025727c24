#include "skinfem/validation/crosscheck.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "skinfem/contact/holes/cover.hpp"
#include "skinfem/contact/holes/small_hole.hpp"
#include "skinfem/contact/layer_hertz.hpp"
#include "skinfem/scene/parallel.hpp"
#include "skinfem/validation/text.hpp"

namespace skinfem::validation {

namespace {
const FrictionMode kModes[2] = {FrictionMode::static_residual, FrictionMode::coupled};
}  // namespace

SignalMetrics compare_signals(const std::vector<double>& u, const Eigen::VectorXd& model,
                              const Eigen::VectorXd& reference) {
  SignalMetrics m;
  Eigen::Index im = 0, ir = 0;
  const double am = model.cwiseAbs().maxCoeff(&im), ar = reference.cwiseAbs().maxCoeff(&ir);
  m.amplitude_ratio = ar > 0 ? am / ar : std::numeric_limits<double>::infinity();
  m.peak_shift_mm = u[im] - u[ir];
  const double nm = model.norm(), nr = reference.norm();
  m.shape_error = nm > 0 && nr > 0 ? (model / nm - reference / nr).norm() : std::sqrt(2.0);
  return m;
}

namespace {
// Each variant's signals against the full FE's (the first variant), per case, sensor and component.
void add_metrics(Crosscheck& out, int ns) {
  for (size_t v = 0; v < out.signals.size(); ++v) {
    std::array<std::vector<std::array<SignalMetrics, 2>>, 2> m;
    for (int c = 0; c < 2; ++c)
      for (int k = 0; k < ns; ++k)
        m[c].push_back(
            {compare_signals(out.u, out.signals[v][c].col(2 * k), out.signals[0][c].col(2 * k)),
             compare_signals(out.u, out.signals[v][c].col(2 * k + 1), out.signals[0][c].col(2 * k + 1))});
    out.metrics.push_back(m);
  }
}

// The pressures through the contact along x: the closed forms', the FE's frictionless and coupled ones (and
// the coupled traction), the meridian's.
void add_pressure_profile(Crosscheck& out, const CrosscheckInput& in, const Tractions& fe_none,
                          const Tractions& fe_coupled, const std::optional<contact::HertzHalfspace>& hertz,
                          const std::optional<contact::LayerHertzResult>& layer) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double reach = hertz ? 1.3 * std::max(hertz->a_mm, layer->a_mm) : 4.0;
  for (int i = 0; i <= 400; ++i) {
    const double x = in.center[0] - reach + 2 * reach * i / 400.0, y = in.center[1];
    const double r = std::abs(x - in.center[0]);
    const double ph =
        hertz ? hertz->p0_MPa * std::sqrt(std::max(0.0, 1 - r * r / (hertz->a_mm * hertz->a_mm))) : nan;
    const double pl = layer ? layer->pressure_MPa(r) : nan;
    const double pc = fe_coupled.pressure(x, y);
    const double pm =
        in.meridian ? in.meridian->pressure_at(std::hypot(x - in.center[0], y - in.center[1])) : nan;
    out.pressure_profile.push_back({x, ph, pl, fe_none.pressure(x, y), pc, fe_coupled.tangential(x, y), pm});
  }
}
}  // namespace

Crosscheck crosscheck(const CrosscheckInput& in) {
  if (!in.mesh || !in.solver || !in.fe || !in.sweeps || !in.frames || in.sweeps->size() != 2 ||
      in.frames->size() != 2)
    throw std::invalid_argument("crosscheck: needs the mesh, solver, FE Green maps and both FE sweeps");
  for (int c = 0; c < 2; ++c)
    if ((*in.frames)[c].size() != (*in.sweeps)[c].centers.size())
      throw std::invalid_argument("crosscheck: needs every position's frame (pipeline::DefectFrames::every)");
  const contact::ContactSolver& solver = *in.solver;
  const contact::MortarZone& zone = solver.zone();
  const int ns = static_cast<int>(in.sensors.positions.size());
  Crosscheck out;
  for (int c = 0; c < 2; ++c) {
    out.ratio[c] = solver.ratio(kModes[c]);
    out.shear[c] = solver.shear(kModes[c]);
    out.paper_ratio[c] = c == Crosscheck::kSliding ? solver.load().mu : solver.load().static_ratio;
  }
  const GreenKernel fe = fe_kernel(*in.fe);
  const GreenKernel k_paper = rescaled_halfspace_kernel(in.thickness, in.k_paper);
  const GreenKernel k_best = rescaled_halfspace_kernel(in.thickness, in.k_best);

  // Hole-free contact of each case, and the frictionless one (the paper's pressure).
  const contact::ContactResult none = solver.solve(FrictionMode::none);
  std::array<contact::ContactResult, 2> full;
  for (int c = 0; c < 2; ++c) full[c] = solver.solve(kModes[c]);

  // Analytic pressures with the same force.
  std::optional<contact::HertzHalfspace> hertz;
  std::optional<contact::LayerHertzResult> layer;
  if (in.equivalent_radius) {
    hertz = contact::hertz_halfspace(in.force, *in.equivalent_radius, in.E, in.nu);
    layer = contact::layer_hertz_force(in.force, *in.equivalent_radius, in.center_thickness, in.E, in.nu);
  }
  // The FE's traction on a frictionless solution (the paper's uncoupled friction with the FE's law).
  const auto free_shear = [&](int c, const Eigen::VectorXd& covered = {}) {
    Eigen::VectorXd v = out.shear[c] * solver.touched(FrictionMode::none);
    if (covered.size()) v = v.cwiseProduct((1.0 - covered.array()).matrix());
    return v;
  };
  const auto tractions = [&](int c, const contact::ContactResult& r) {
    return fe_tractions(zone, *in.mesh, r.lambda, out.ratio[c], r.shear);
  };

  // Mean stresses.
  const auto add_reading = [&](std::string name, std::string what, auto per_case) {
    out.reading_variants.push_back({std::move(name), std::move(what)});
    std::array<Eigen::VectorXd, 2> r;
    for (int c = 0; c < 2; ++c) r[c] = per_case(c);
    out.readings.push_back(r);
  };
  add_reading("fe", "full FE: contact, friction and Green maps", [&](int c) { return full[c].readings; });
  add_reading("green_k_paper", "FE tractions, half-space Green rescaled by the paper's k",
              [&](int c) { return convolve(tractions(c, full[c]), k_paper, in.sensors); });
  add_reading("green_k_best", "FE tractions, half-space Green rescaled by the best-fit k",
              [&](int c) { return convolve(tractions(c, full[c]), k_best, in.sensors); });
  add_reading("uncoupled", "frictionless FE pressure with the FE's traction added, FE Green",
              [&](int c) { return solver.readings(none.lambda, out.ratio[c], free_shear(c)); });
  if (hertz) {
    add_reading("pressure_hertz", "half-space Hertz pressure (uncoupled friction), FE Green", [&](int c) {
      return convolve(hertz_tractions(*hertz, in.center, out.ratio[c], out.shear[c]), fe, in.sensors);
    });
    add_reading("pressure_layer", "exact bonded-layer Hertz pressure (uncoupled friction), FE Green",
                [&](int c) {
                  return convolve(layer_hertz_tractions(*layer, in.center, out.ratio[c], out.shear[c]), fe,
                                  in.sensors);
                });
    add_reading("paper_model", "exact-layer pressure, uncoupled friction, Green rescaled by the paper's k",
                [&](int c) {
                  return convolve(layer_hertz_tractions(*layer, in.center, out.paper_ratio[c]), k_paper,
                                  in.sensors);
                });
  }

  // Hole signals.
  const auto& sweeps = *in.sweeps;
  const auto& frames = *in.frames;
  for (const Vec2& c : sweeps[0].centers) out.u.push_back(c[0]);
  const int n = static_cast<int>(out.u.size());
  const double S = M_PI * 0.25 * in.sweep.hole_diameter * in.sweep.hole_diameter;
  const auto add_signal = [&](std::string name, std::string what, auto per_case) {
    out.signal_variants.push_back({std::move(name), std::move(what)});
    std::array<Eigen::MatrixXd, 2> s;
    for (int c = 0; c < 2; ++c) s[c] = per_case(c);
    out.signals.push_back(s);
  };
  add_signal("fe",
             in.sweep.model == HoleModel::bulge
                 ? "the FE contact at each hole position, the hole as its bulge (contact/holes/dimple.hpp)"
                 : "a full FE contact solve per hole position, the hole cutting the hats",
             [&](int c) { return sweeps[c].varsigma; });
  // Every frame's tractions sit on the zone's quadrature points: the kernel is evaluated there once.
  const FeConvolution k_paper_on_zone(zone, *in.mesh, k_paper, in.sensors);
  add_signal("green_k_paper", "each position's FE tractions, Green rescaled by the paper's k", [&](int c) {
    const contact::ContactResult& b = sweeps[c].baseline;
    const Eigen::VectorXd base = k_paper_on_zone(b.lambda, out.ratio[c], b.shear);
    Eigen::MatrixXd s(n, 2 * ns);
    // Each position's row alone: on the machine's cores.
    for_each_index(n, [&](std::size_t i) {
      const contact::ContactResult& r = frames[c][i];
      s.row(i) = (k_paper_on_zone(r.lambda, out.ratio[c], r.shear) - base).transpose();
    });
    return s;
  });
  // One frictionless sweep serves both cases' uncoupled friction.
  std::vector<Eigen::VectorXd> free_lambda, covered;
  const bool any_shear = out.shear[0] != 0 || out.shear[1] != 0;
  const PlanarFaceIndex top(*in.mesh, kTop);
  const contact::HoleDimples dimples(solver, *in.mesh, top, in.E, in.nu);
  const contact::SweepResult free_sweep = contact::hole_sweep(
      solver, *in.mesh, in.sweep, FrictionMode::none, &dimples, [&](int i, const contact::ContactResult& r) {
        free_lambda.push_back(r.lambda);
        if (any_shear)
          covered.push_back(
              contact::hole_cover(zone, *in.mesh, {Hole{sweeps[0].centers[i], in.sweep.hole_diameter}}));
      });
  add_signal("uncoupled", "frictionless FE sweep with the FE's traction added", [&](int c) {
    const Eigen::VectorXd base = solver.readings(free_sweep.baseline.lambda, out.ratio[c], free_shear(c));
    Eigen::MatrixXd s(n, 2 * ns);
    for (int i = 0; i < n; ++i)
      s.row(i) = (solver.readings(free_lambda[i], out.ratio[c],
                                  any_shear ? free_shear(c, covered[i]) : Eigen::VectorXd()) -
                  base)
                     .transpose();
    return s;
  });
  std::vector<Vec2> centers(sweeps[0].centers.begin(), sweeps[0].centers.end());
  add_signal("first_order_hole", "eqs. (2)-(3) with the FE tractions and FE Green maps",
             [&](int c) { return first_order_hole(tractions(c, full[c]), fe, in.sensors, centers, S); });
  add_signal("small_hole",
             "the hole as its penny-crack bulge in the intact FE contact (contact/holes/small_hole.hpp)",
             [&](int c) {
               return contact::small_hole_signals(solver, kModes[c], *in.mesh, top, centers,
                                                  in.sweep.hole_diameter, in.E, in.nu);
             });
  if (layer)
    add_signal("paper_model",
               "eqs. (2)-(3), exact-layer pressure, uncoupled, Green rescaled by the paper's k", [&](int c) {
                 return first_order_hole(layer_hertz_tractions(*layer, in.center, out.paper_ratio[c]),
                                         k_paper, in.sensors, centers, S);
               });

  add_metrics(out, ns);
  add_pressure_profile(out, in, fe_tractions(zone, *in.mesh, none.lambda, 0),
                       tractions(Crosscheck::kSliding, full[Crosscheck::kSliding]), hertz, layer);
  return out;
}

std::vector<int> front_sensors(const Sensors& sensors, const Vec2& center, const Vec2& direction) {
  constexpr double kOnLine = 1e-9;  // mm
  std::vector<int> out;
  bool any_ahead = false;
  for (size_t k = 0; k < sensors.positions.size(); ++k) {
    const auto& p = sensors.positions[k];
    const double ahead = (p[0] - center[0]) * direction[0] + (p[1] - center[1]) * direction[1];
    if (ahead >= -kOnLine) out.push_back(static_cast<int>(k));
    any_ahead = any_ahead || ahead > kOnLine;
  }
  return any_ahead ? out : std::vector<int>{};
}

namespace {
int variant_index(const std::vector<Variant>& v, const std::string& name) {
  for (size_t i = 0; i < v.size(); ++i)
    if (v[i].name == name) return static_cast<int>(i);
  return -1;
}
}  // namespace

FrontSensorAnswer front_sensor_answer(const Crosscheck& x, const std::vector<int>& front,
                                      const Vec2& direction) {
  const int unc = variant_index(x.signal_variants, "uncoupled"),
            paper = variant_index(x.signal_variants, "paper_model");
  FrontSensorAnswer a;
  a.front = front;
  std::array<double, 2> plo{1e300, 1e300}, phi{0, 0};
  a.coupling_lo = {1e300, 1e300};
  std::string names;
  for (const int k : front) {
    names += (names.empty() ? "#" : ", #") + std::to_string(k + 1);
    for (int b = 0; b < 2; ++b) {
      // FE coupled / FE uncoupled is 1 / (uncoupled / FE).
      const double coupling = 1 / x.metrics[unc][1][k][b].amplitude_ratio;
      a.coupling_lo[b] = std::min(a.coupling_lo[b], coupling);
      a.coupling_hi[b] = std::max(a.coupling_hi[b], coupling);
      if (paper >= 0) {
        const double fe_over_model = 1 / x.metrics[paper][1][k][b].amplitude_ratio;
        plo[b] = std::min(plo[b], fe_over_model);
        phi[b] = std::max(phi[b], fe_over_model);
      }
    }
  }
  if (front.empty()) {
    a.answer = "No sensor lies ahead of the contact centre along the sliding direction (" +
               fmt("%.3g", direction[0]) + ", " + fmt("%.3g", direction[1]) +
               "): the front sensors' excess cannot be examined on this scene";
    return a;
  }
  const double best = std::max(a.coupling_hi[0], a.coupling_hi[1]);
  a.answer = "Coupled against uncoupled friction, the front sensors' (" + names +
             ") sliding hole-signal amplitudes change by x" + fmt("%.2f", a.coupling_lo[0]) + "-" +
             fmt("%.2f", a.coupling_hi[0]) + " (varsigma_z) and x" + fmt("%.2f", a.coupling_lo[1]) + "-" +
             fmt("%.2f", a.coupling_hi[1]) + " (varsigma_x); the paper measured up to x" +
             fmt("%.0f", kPaperFrontExcess) + " over its model, so coupling " +
             (best >= kPaperFrontExcess ? std::string("is large enough to explain it")
                                        : "explains at most x" + fmt("%.2f", best) + " of it");
  if (paper >= 0) {
    a.model_lo = plo;
    a.model_hi = phi;
    a.answer += "; full FE over the paper's model on these sensors: x" + fmt("%.3g", plo[0]) + "-" +
                fmt("%.3g", phi[0]) + " (z), x" + fmt("%.3g", plo[1]) + "-" + fmt("%.3g", phi[1]) + " (x)";
  }
  return a;
}

}  // namespace skinfem::validation
