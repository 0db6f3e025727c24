#include "skinfem/validation/k_sweep.hpp"

#include <cmath>
#include <stdexcept>

#include "skinfem/green/calibration.hpp"
#include "skinfem/scene/parallel.hpp"
#include "skinfem/validation/text.hpp"

namespace skinfem::validation {

KSweepPoint k_of(const KProtocol& p, double spacing) {
  const int n = static_cast<int>(std::floor(3 * p.h / spacing + 1e-9));
  std::vector<double> x;
  for (int i = -n; i <= n; ++i) x.push_back(i * spacing);
  const green::LayerGreen layer(p.h, p.nu, p.load, 0.5 * p.punch_diameter);
  const green::KReport r = green::fit_profile(x, green::exact_profile(layer, x, p.disc_diameter), p.h);
  return {"", 0, r.k_central, r.k_lsq_line};
}

namespace {
KSweepPoint evaluate(const KProtocol& p, const std::string& parameter, double value, double spacing) {
  KSweepPoint k = k_of(p, spacing);
  k.parameter = parameter;
  k.value = value;
  return k;
}
}  // namespace

std::vector<KSweepPoint> k_sweep(const KProtocol& base, double spacing) {
  struct Change {
    KProtocol protocol;
    const char* parameter;
    double value;
  };
  std::vector<Change> changes;
  for (double nu : {0.30, 0.35, 0.40, 0.45, 0.48, 0.50}) {
    KProtocol p = base;
    p.nu = nu;
    changes.push_back({p, "nu", nu});
  }
  for (double d : {0.1, 0.25, 0.5, 0.75, 1.0, 1.25, 1.5}) {
    KProtocol p = base;
    p.punch_diameter = d;
    changes.push_back({p, "punch_diameter_mm", d});
  }
  for (int l = 0; l < 3; ++l) {
    KProtocol p = base;
    p.load = l == 0 ? green::LayerLoad::point : l == 1 ? green::LayerLoad::uniform : green::LayerLoad::punch;
    changes.push_back({p, "load", static_cast<double>(l)});
  }
  for (double d : {0.0, 0.2, 0.4, 0.6, 1.0}) {
    KProtocol p = base;
    p.disc_diameter = d;
    changes.push_back({p, "disc_diameter_mm", d});
  }
  for (double h : {2.5, 2.75, 3.04, 3.25, 3.5}) {
    KProtocol p = base;
    p.h = h;
    changes.push_back({p, "h_mm", h});
  }
  // Each point is the exact layer's own fit, independent of the others: on the machine's cores.
  std::vector<KSweepPoint> out(changes.size());
  for_each_index(changes.size(), [&](std::size_t i) {
    out[i] = evaluate(changes[i].protocol, changes[i].parameter, changes[i].value, spacing);
  });
  return out;
}

std::vector<double> crossings(const std::vector<KSweepPoint>& points, const std::string& parameter,
                              const std::string& criterion, double target) {
  std::vector<double> out;
  const KSweepPoint* prev = nullptr;
  for (const auto& p : points) {
    if (p.parameter != parameter) continue;
    if (prev) {
      const double a = (criterion == "k_central" ? prev->k_central : prev->k_lsq_line) - target;
      const double b = (criterion == "k_central" ? p.k_central : p.k_lsq_line) - target;
      if (a == 0)
        out.push_back(prev->value);
      else if (a * b < 0)
        out.push_back(prev->value + (p.value - prev->value) * a / (a - b));
    }
    prev = &p;
  }
  if (prev && (criterion == "k_central" ? prev->k_central : prev->k_lsq_line) == target)
    out.push_back(prev->value);
  return out;
}

namespace {
double criterion_of(const KSweepPoint& k, const std::string& criterion) {
  return criterion == "k_central" ? k.k_central : k.k_lsq_line;
}

KProtocol with(KProtocol p, const std::string& parameter, double value) {
  if (parameter == "nu")
    p.nu = value;
  else if (parameter == "punch_diameter_mm")
    p.punch_diameter = value;
  else if (parameter == "disc_diameter_mm")
    p.disc_diameter = value;
  else if (parameter == "h_mm")
    p.h = value;
  else
    throw std::invalid_argument("crossing_root: " + parameter + " is not a continuous protocol parameter");
  return p;
}
}  // namespace

double crossing_root(const KProtocol& base, const std::string& parameter, const std::string& criterion,
                     double target, double lo, double hi) {
  const auto f = [&](double v) { return criterion_of(k_of(with(base, parameter, v)), criterion) - target; };
  double a = lo, b = hi, fa = f(a), fb = f(b);
  if (fa == 0) return a;
  if (fb == 0) return b;
  if (fa * fb > 0) throw std::invalid_argument("crossing_root: k − target has one sign on the bracket");
  const double tol = 1e-9 * std::abs(hi - lo);
  int side = 0;
  for (int it = 0; it < 40 && std::abs(b - a) > tol; ++it) {
    const double c = b - fb * (b - a) / (fb - fa), fc = f(c);
    if (fc == 0) return c;
    if (fc * fb < 0) {
      a = b, fa = fb;
      side = 0;
    } else if (++side == 2) {  // Illinois: halve the stale end's value so it moves too
      fa *= 0.5;
      side = 0;
    }
    b = c, fb = fc;
  }
  return std::abs(fa) < std::abs(fb) ? a : b;
}

namespace {
// `near` and `answer` from the points and crossings: the one part that changes as points are added.
void compose(KTargetAnswer& a) {
  const char* loads[3] = {"point", "uniform disc", "punch"};
  std::string near, cross;
  a.near.clear();
  for (const auto& p : a.points)
    for (const char* crit : {"k_central", "k_lsq_line"}) {
      const double k = std::string(crit) == "k_central" ? p.k_central : p.k_lsq_line;
      if (std::abs(k - a.target) <= a.band) {
        const std::string what = p.parameter == "load"
                                     ? std::string("load ") + loads[static_cast<int>(p.value)]
                                     : p.parameter + " = " + fmt("%.3g", p.value);
        near += (near.empty() ? "" : "; ") + what + ": " + crit + " " + fmt("%.4f", k);
        a.near.push_back({p.parameter, crit, p.value, k});
      }
    }
  for (const auto& c : a.crossings)
    cross += (cross.empty() ? "" : "; ") + c.criterion + " = " + fmt("%.2f", a.target) + " at " +
             c.parameter + " = " + fmt("%.4g", c.value);
  a.answer = "Exact layer (h " + fmt("%.3g", a.h) + " mm) with one protocol reading changed at a time" +
             (a.extra_points ? ", and the FE mesh scale" : "") + ": " +
             (near.empty() ? "no reading in the sweep gives k within " + fmt("%g", a.band) + " of " +
                                 fmt("%.2f", a.target)
                           : "within " + fmt("%g", a.band) + " of " + fmt("%.2f", a.target) + ": " + near) +
             (cross.empty() ? std::string("; no parameter's range crosses it") : "; crossings: " + cross);
}
}  // namespace

KTargetAnswer k_target_answer(const KProtocol& base, double target, double band) {
  KTargetAnswer a;
  a.target = target;
  a.band = band;
  a.h = base.h;
  a.points = k_sweep(base);
  // The sweep's points of each parameter bracket its crossings; each root is found between them, the
  // brackets on the machine's cores.
  struct Bracket {
    const char *param, *crit;
    double va, vb, linear;
  };
  std::vector<Bracket> brackets;
  for (const char* param : {"nu", "punch_diameter_mm", "disc_diameter_mm", "h_mm"})
    for (const char* crit : {"k_central", "k_lsq_line"}) {
      std::vector<const KSweepPoint*> group;
      for (const auto& p : a.points)
        if (p.parameter == param) group.push_back(&p);
      for (size_t i = 1; i < group.size(); ++i) {
        const double fa = criterion_of(*group[i - 1], crit) - target,
                     fb = criterion_of(*group[i], crit) - target;
        if (!(fa * fb < 0) && !(fa == 0)) continue;
        const double va = group[i - 1]->value, vb = group[i]->value;
        brackets.push_back({param, crit, va, vb, fa == 0 ? va : va + (vb - va) * fa / (fa - fb)});
      }
    }
  std::vector<double> roots(brackets.size());
  for_each_index(brackets.size(), [&](std::size_t i) {
    const Bracket& b = brackets[i];
    roots[i] = crossing_root(base, b.param, b.crit, target, b.va, b.vb);
  });
  for (size_t i = 0; i < brackets.size(); ++i)
    a.crossings.push_back({brackets[i].param, brackets[i].crit, roots[i], brackets[i].linear});
  compose(a);
  return a;
}

void add_points(KTargetAnswer& a, const std::vector<KSweepPoint>& extra) {
  if (extra.empty()) return;
  a.points.insert(a.points.end(), extra.begin(), extra.end());
  a.extra_points = true;
  compose(a);
}

}  // namespace skinfem::validation
