#include "skinfem/validation/hole_budget.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>
#include <stdexcept>

#include "skinfem/contact/holes/sweep.hpp"
#include "skinfem/contact/metrics.hpp"
#include "skinfem/scene/laws.hpp"
#include "skinfem/validation/crosscheck.hpp"

namespace skinfem::validation {

namespace {

std::string format(const char* f, double a, double b = 0, double c = 0, double d = 0) {
  char buf[256];
  std::snprintf(buf, sizeof buf, f, a, b, c, d);
  return buf;
}

double amplitude(const Eigen::MatrixXd& s, int col) { return s.col(col).cwiseAbs().maxCoeff(); }

// Sensors ordered along the sliding direction, rearmost ("left-hand" in the paper's figure) first.
std::vector<int> along(const FactsInput& in) {
  std::vector<int> order(in.sensors.positions.size());
  std::iota(order.begin(), order.end(), 0);
  const auto ahead = [&](int k) {
    const auto& p = in.sensors.positions[k];
    return (p[0] - in.center[0]) * in.direction[0] + (p[1] - in.center[1]) * in.direction[1];
  };
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return ahead(a) < ahead(b); });
  return order;
}

// '+' one positive hump, '-' one negative, 'a' antisymmetric (the smaller lobe reaches `antisym` of the
// larger).
char sign_class(const Eigen::VectorXd& c, double antisym) {
  const double hi = std::max(0.0, c.maxCoeff()), lo = std::max(0.0, -c.minCoeff());
  if (std::min(hi, lo) >= antisym * std::max(hi, lo)) return 'a';
  return hi > lo ? '+' : '-';
}

// 2 when |c| has a second local maximum reaching `comparable` of the largest with a dip of `dip` between.
int maxima(const Eigen::VectorXd& c, double comparable, double dip) {
  const Eigen::VectorXd a = c.cwiseAbs();
  Eigen::Index i1 = 0;
  const double top = a.maxCoeff(&i1);
  for (Eigen::Index i = 1; i + 1 < a.size(); ++i) {
    if (i == i1 || a[i] < comparable * top || a[i] < a[i - 1] || a[i] < a[i + 1]) continue;
    const Eigen::Index lo = std::min(i, i1), hi = std::max(i, i1);
    if (a.segment(lo, hi - lo + 1).minCoeff() <= (1 - dip) * a[i]) return 2;
  }
  return 1;
}

std::string names(const std::vector<int>& sensors) {
  std::string s;
  for (int k : sensors) s += (s.empty() ? "#" : ", #") + std::to_string(k + 1);
  return s;
}

}  // namespace

double roughness(const Eigen::VectorXd& c) {
  const double peak = c.size() ? c.cwiseAbs().maxCoeff() : 0.0;
  if (!(peak > 0) || c.size() < 3) return 0.0;
  return (c.tail(c.size() - 2) - 2 * c.segment(1, c.size() - 2) + c.head(c.size() - 2))
             .cwiseAbs()
             .maxCoeff() /
         peak;
}

double NoiseModel::threshold(int component) const {
  return k * (component == 0 ? sigma_z_MPa : sigma_x_MPa) / std::sqrt(double(passages));
}

std::array<std::vector<std::array<double, 2>>, 2> amplitude_ratios(const FactsInput& in) {
  std::array<std::vector<std::array<double, 2>>, 2> r;
  const int ns = static_cast<int>(in.sensors.positions.size());
  for (int c = 0; c < 2; ++c)
    for (int k = 0; k < ns; ++k) {
      std::array<double, 2> v{};
      for (int b = 0; b < 2; ++b) {
        const double m = amplitude(in.model[c], 2 * k + b);
        v[b] = m > 0 ? amplitude(in.fe[c], 2 * k + b) / m : std::numeric_limits<double>::infinity();
      }
      r[c].push_back(v);
    }
  return r;
}

std::vector<FactVerdict> judge_facts(const FactsInput& in) {
  const int ns = static_cast<int>(in.sensors.positions.size());
  const auto ratio = amplitude_ratios(in);
  const FactRules& R = in.rules;
  const double tz = in.noise.threshold(0), tx = in.noise.threshold(1);
  std::vector<FactVerdict> out;
  const auto largest = [&](int c, int b, const std::vector<int>& sensors) {
    double m = 0;
    for (int k : sensors) m = std::max(m, amplitude(in.fe[c], 2 * k + b));
    return m;
  };
  std::vector<int> all(ns);
  std::iota(all.begin(), all.end(), 0);
  const std::string thresholds = format("the %.0f-passage detection thresholds %.3f kPa (z) and %.3f kPa (x)",
                                        in.noise.passages, 1e3 * tz, 1e3 * tx);

  {  // F1
    const double z = largest(0, 0, all), x = largest(0, 1, all);
    out.push_back({"F1", z < tz && x < tx,
                   format("at rest the largest |ς_z| is %.3f kPa and |ς_x| %.3f kPa, ", 1e3 * z, 1e3 * x) +
                       (z < tz && x < tx ? "below " : "not below ") + thresholds});
  }
  const std::vector<int> front = front_sensors(in.sensors, in.center, in.direction);
  std::vector<int> back;
  for (int k = 0; k < ns; ++k)
    if (std::find(front.begin(), front.end(), k) == front.end()) back.push_back(k);
  const auto range = [&](const std::vector<int>& sensors, int b) {
    double lo = std::numeric_limits<double>::infinity(), hi = 0;
    for (int k : sensors) lo = std::min(lo, ratio[1][k][b]), hi = std::max(hi, ratio[1][k][b]);
    return std::array<double, 2>{lo, hi};
  };
  {  // F2
    const double z = largest(1, 0, all), x = largest(1, 1, all);
    const bool detected = z > tz || x > tx;
    const auto rz = range(back, 0), rx = range(back, 1);
    const bool match = !back.empty() && rz[0] >= R.match_lo && rz[1] <= R.match_hi && rx[0] >= R.match_lo &&
                       rx[1] <= R.match_hi;
    std::string why =
        format("sliding, the largest |ς_z| is %.3f kPa and |ς_x| %.3f kPa (", 1e3 * z, 1e3 * x) +
        (detected ? "detected" : "not detected") + " against " + thresholds + "); ";
    if (back.empty())
      why += "no sensor lies behind the contact centre";
    else
      why += "the back sensors (" + names(back) + ") read " +
             format("%.2f-%.2f (z) and %.2f-%.2f (x) times the paper's model, ", rz[0], rz[1], rx[0], rx[1]) +
             (match ? "inside" : "not all inside") +
             format(" the match band [%.2g, %.2g]", R.match_lo, R.match_hi);
    out.push_back({"F2", detected && match, why});
  }
  {  // F3: the front louder than the model and than the back, as the paper's asymmetry
    const auto rz = range(front, 0), rx = range(front, 1);
    const double top = front.empty() ? 0.0 : std::max(rz[1], rx[1]);
    const double top_back = back.empty() ? 0.0 : std::max(range(back, 0)[1], range(back, 1)[1]);
    const bool loud = top >= R.front_min, louder = top >= R.front_over_back * top_back;
    std::string why;
    if (front.empty() || back.empty())
      why = front.empty() ? "no sensor lies ahead of the contact centre"
                          : "no sensor lies behind the contact centre to contrast the front with";
    else
      why = "the front sensors (" + names(front) + ") read " +
            format("%.2f-%.2f (z) and %.2f-%.2f (x) times the paper's model; the largest, ", rz[0], rz[1],
                   rx[0], rx[1]) +
            format("%.2f, is", top) + (loud ? " at least " : " below ") +
            format("%.2g (the paper: up to 4) and ", R.front_min) +
            format("%.2f times the back sensors' largest, %.2f (", top / top_back, top_back) +
            (louder ? "at least " : "below ") +
            format("%.2g: the paper's back sensors match the model)", R.front_over_back);
    out.push_back({"F3", !front.empty() && !back.empty() && loud && louder, why});
  }
  const std::vector<int> order = along(in);
  {  // F4
    std::string z_classes, x_counts;
    for (int k : order) {
      z_classes += sign_class(in.fe[1].col(2 * k), R.antisym);
      x_counts += std::to_string(maxima(in.fe[1].col(2 * k + 1), R.comparable, R.dip));
    }
    const auto rank = [](char c) { return c == '+' ? 0 : c == 'a' ? 1 : 2; };
    bool z_ok = ns >= 3 && z_classes.front() == '+' && z_classes.back() == '-' &&
                z_classes.find('a') != std::string::npos;
    for (size_t i = 1; i < z_classes.size(); ++i) z_ok = z_ok && rank(z_classes[i - 1]) <= rank(z_classes[i]);
    const bool x_ok = ns >= 3 && x_counts.front() == '1' && x_counts.back() == '1' &&
                      x_counts.substr(1, x_counts.size() - 2).find('2') != std::string::npos;
    out.push_back({"F4", z_ok && x_ok,
                   "sliding, rearmost sensor first: ς_z profiles " + z_classes +
                       " (+ one positive hump, - one negative, a antisymmetric: the smaller lobe reaches " +
                       format("%.2g of the larger", R.antisym) + "), " + (z_ok ? "as" : "not as") +
                       " the paper's + to - through a; maxima of |ς_x| " + x_counts +
                       format(" (2: a second maximum reaching %.2g of the first, with a dip of %.2g between)",
                              R.comparable, R.dip) +
                       ", " + (x_ok ? "as" : "not as") + " the paper's 1 outside and 2 in between"});
  }
  {  // F5
    std::string why;
    bool ok = ns >= 2;
    for (int k : {order.front(), order.back()}) {
      const auto& p = in.sensors.positions[k];
      const double d = std::hypot(p[0] - in.center[0], p[1] - in.center[1]);
      const double z = amplitude(in.fe[1], 2 * k), x = amplitude(in.fe[1], 2 * k + 1);
      const bool outside = d > in.contact_radius_mm, responds = z > tz || x > tx;
      ok = ok && outside && responds;
      why += (why.empty() ? "" : "; ") + ("#" + std::to_string(k + 1)) +
             format(
                 " lies %.2f mm from the contact centre (contact radius %.2f mm) and reads |ς_z| %.3f, "
                 "|ς_x| %.3f kPa",
                 d, in.contact_radius_mm, 1e3 * z, 1e3 * x) +
             (outside ? (responds ? ": outside and detected" : ": outside, not detected")
                      : ": inside the contact, so it cannot test the fact");
    }
    out.push_back({"F5", ok, why});
  }
  return out;
}

std::vector<Hypothesis> friction_hypotheses(const ContactLoad& scene_load) {
  const double mu = scene_load.mu;
  std::vector<Hypothesis> out;
  ContactLoad coulomb = scene_load;
  coulomb.law = FrictionLaw::coulomb;
  coulomb.tau0.reset();
  out.push_back({"coulomb", format("rigid smooth plate, Coulomb p_t = %.3g p", mu), coulomb});
  ContactLoad shear = coulomb;
  shear.law = FrictionLaw::shear_strength;
  out.push_back(
      {"shear_strength",
       format("shear strength p_t = tau0 where the skin touches, tau0 = mu F / A with mu = %.3g", mu),
       shear});
  ContactLoad mixed = coulomb;
  mixed.law = FrictionLaw::mixed;
  mixed.mu = 0.5 * mu;
  mixed.static_ratio = 0.5 * scene_load.static_ratio;
  out.push_back({"mixed",
                 format("half of each: p_t = tau0 + %.3g p with tau0 = %.3g F / A (the same sliding force)",
                        0.5 * mu, 0.5 * mu),
                 mixed});
  return out;
}

std::vector<Hypothesis> interface_hypotheses(const ContactLoad& scene_load, double p_mean,
                                             const std::vector<double>& u0) {
  std::vector<Hypothesis> out;
  for (const Hypothesis& base : friction_hypotheses(scene_load)) {
    if (base.load.law == FrictionLaw::mixed) continue;
    for (double u : u0) {
      Hypothesis h = base;
      const double um = 1e3 * u;
      char name[64];
      std::snprintf(name, sizeof name, "%s_interface_%s",
                    base.load.law == FrictionLaw::coulomb ? "coulomb" : "shear",
                    um < 1 ? (std::to_string(static_cast<int>(std::lround(1e3 * um))) + "nm").c_str()
                           : (std::to_string(static_cast<int>(std::lround(um))) + "um").c_str());
      h.name = name;
      h.load.interface = {InterfaceLaw::linear, p_mean / u};
      h.what = base.what +
               format("; a rough interface in series, u0 = %.3g um: K = p_mean / u0 = %.4g MPa/mm", um,
                      p_mean / u) +
               " (the hole resolved, its disc cutting the hats: the bulge is a hard interface's)";
      out.push_back(h);
    }
  }
  return out;
}

void judge_hypothesis(HypothesisResult& r, FactsInput base) {
  if (base.reading_scale.size())
    for (Eigen::MatrixXd& s : r.signals) s *= base.reading_scale.cwiseInverse().asDiagonal();
  base.fe = r.signals;
  base.contact_radius_mm = r.contact_radius_mm;
  r.ratio = amplitude_ratios(base);
  r.facts = judge_facts(base);
}

HypothesisResult run_hypothesis(const Hypothesis& h, const contact::CondensedContact& condensed,
                                const contact::MirrorView* mirror, const TetMesh& mesh,
                                const PlanarFaceIndex& top, const HoleSweep& sweep, const Material& material,
                                FactsInput base, const contact::HoleCuts* cuts) {
  const auto start = std::chrono::steady_clock::now();
  HypothesisResult out;
  out.hypothesis = h;
  const contact::ContactSolver solver(condensed, h.load, mirror);
  out.tau0_MPa = kind(h.load.law).shear_strength ? solver.tau0() : 0.0;
  const contact::ContactResult sliding = solver.solve(FrictionMode::coupled);
  {
    const contact::MortarZone& z = solver.zone();
    std::vector<int> local(mesh.num_vertices, -1);
    for (int i = 0; i < z.size(); ++i) local[z.vertices[i]] = i;
    std::vector<char> edge(z.size(), 0);
    for (int f : z.faces)
      if (local[mesh.faces(f, 0)] < 0 || local[mesh.faces(f, 1)] < 0 || local[mesh.faces(f, 2)] < 0)
        for (int a = 0; a < 3; ++a)
          if (local[mesh.faces(f, a)] >= 0) edge[local[mesh.faces(f, a)]] = 1;
    for (int i : sliding.active)
      if (edge[i])
        throw std::runtime_error(
            "the sliding contact reaches the candidate zone's edge: give a larger "
            "contact.zone_radius");
  }
  out.tangential_force_N = sliding.tangential_force_N;
  out.contact_radius_mm = contact::contact_metrics(solver, mesh, top, sliding, base.center).contact_radius_mm;
  const FrictionMode modes[2] = {FrictionMode::static_residual, FrictionMode::coupled};
  const contact::HoleDimples dimples(solver, mesh, top, material.E, material.nu);
  // The bulge is a hole's solution under a hard interface only (contact/holes/dimple.hpp): through a
  // compliant one the hole is resolved, which needs the path's compliance in `condensed`.
  HoleSweep hyp_sweep = sweep;
  if (kind(h.load.interface.law).compliant) {
    if (!condensed.path)
      throw std::runtime_error(
          "a hole through a compliant interface is resolved, and the condensed skin has no hole path");
    hyp_sweep.model = HoleModel::resolved;
  }
  for (int c = 0; c < 2; ++c)
    out.signals[c] = contact::hole_sweep(solver, mesh, hyp_sweep, modes[c], &dimples, {},
                                         hyp_sweep.model == HoleModel::resolved ? cuts : nullptr)
                         .varsigma;
  judge_hypothesis(out, std::move(base));
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace skinfem::validation
