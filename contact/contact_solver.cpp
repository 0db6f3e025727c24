#include "skinfem/contact/contact_solver.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string>

#include "skinfem/contact/exponential_interface.hpp"
#include "skinfem/scene/texture.hpp"

namespace skinfem::contact {

MirrorView mirror_view(const TetMesh& whole, const std::vector<int>& source, const MortarZone& half_zone,
                       const Vec2& center, double radius) {
  MirrorView v;
  v.zone = mortar_zone(whole, center, radius);
  std::vector<int> local;
  for (int i = 0; i < half_zone.size(); ++i) {
    const int n = half_zone.vertices[i];
    if (n >= static_cast<int>(local.size())) local.resize(n + 1, -1);
    local[n] = i;
  }
  std::vector<int> hits(half_zone.size(), 0);
  for (int w : v.zone.vertices) {
    const int n = source.at(w);
    const int i = n < static_cast<int>(local.size()) ? local[n] : -1;
    if (i < 0)
      throw std::invalid_argument("mirror_view: whole zone vertex " + std::to_string(w) +
                                  " mirrors no multiplier of the half's zone");
    v.half.push_back(i);
    ++hits[i];
  }
  for (int i = 0; i < half_zone.size(); ++i)
    if (hits[i] == 0)
      throw std::invalid_argument("mirror_view: the half's multiplier " + std::to_string(i) +
                                  " has no image in the whole zone");
  return v;
}

ContactSolver::ContactSolver(const CondensedContact& condensed, const ContactLoad& load,
                             const MirrorView* mirror)
    : c_(condensed), load_(load), mirror_(mirror) {
  if (mirror_) {
    images_.assign(c_.zone.size(), 0);
    for (int j : mirror_->half) ++images_.at(j);
  }
}

std::vector<int> ContactSolver::whole_set(const std::vector<int>& solved) const {
  if (!mirror_) return solved;
  std::vector<char> in(c_.zone.size(), 0);
  for (int j : solved) in[j] = 1;
  std::vector<int> out;
  for (int i = 0; i < zone().size(); ++i)
    if (in[mirror_->half[i]]) out.push_back(i);
  return out;
}

std::vector<int> ContactSolver::solved_set(const std::vector<int>& whole) const {
  if (!mirror_) return whole;
  std::vector<int> out;
  for (int i : whole) out.push_back(mirror_->half.at(i));
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

Eigen::VectorXd ContactSolver::solved_lambda(const Eigen::VectorXd& lambda) const {
  if (!mirror_) return lambda;
  Eigen::VectorXd out = Eigen::VectorXd::Zero(c_.zone.size());
  for (int i = 0; i < zone().size(); ++i) out[mirror_->half[i]] = lambda[i];
  return out;
}

Eigen::VectorXd ContactSolver::solved_readings(const Eigen::VectorXd& l, double ratio) const {
  Eigen::VectorXd r = c_.S_p * l;
  if (ratio != 0) r += ratio * (c_.S_t * l);
  return r;
}

Eigen::VectorXd ContactSolver::readings(const Eigen::VectorXd& lambda, double ratio,
                                        const Eigen::VectorXd& shear) const {
  Eigen::VectorXd r = solved_readings(solved_lambda(lambda), ratio);
  if (shear.size()) r += c_.S_t * solved_lambda(shear);
  return r;
}

ContactResult ContactSolver::started(FrictionMode mode) const {
  ContactResult out;
  out.mode = mode;
  out.ratio = ratio(mode);
  out.tau = shear(mode);
  return out;
}

double ContactSolver::solved_ratio(FrictionMode mode) const { return kind(mode).coupled ? ratio(mode) : 0.0; }

double ContactSolver::ratio(FrictionMode mode) const {
  const FrictionModeKind& m = kind(mode);
  if (!m.traction || !kind(load_.law).proportional) return 0.0;
  return m.at_rest ? load_.static_ratio : load_.mu;
}

double ContactSolver::shear(FrictionMode mode) const {
  const FrictionModeKind& m = kind(mode);
  if (!m.traction || !kind(load_.law).shear_strength) return 0.0;
  if (m.at_rest) return load_.mu > 0 ? tau0() * load_.static_ratio / load_.mu : 0.0;
  return tau0();
}

// The coupled contact under a shear strength: the shear's normal displacements lift the edge it acts on, so
// the set it acts on has no fixed point (or none between touching and lifting). Named by the scene field
// that sets the shear, with its size against the contact's mean pressure.
SceneError ContactSolver::no_consistent_set(FrictionMode mode, const LcpSolution& s) const {
  double force = 0, area = 0;
  for (int i : s.active) force += s.lambda[i] * c_.zone.area[i], area += c_.zone.area[i];
  char buf[600];
  const double tau = shear(mode), mean = area > 0 ? force / area : 0;
  char field[96];
  if (load_.tau0)
    std::snprintf(field, sizeof field, "contact.friction.tau0 = %g", *load_.tau0);
  else
    std::snprintf(field, sizeof field, "contact.friction.mu = %g (tau0 from_force)", load_.mu);
  std::snprintf(
      buf, sizeof buf,
      "%s: the %s contact has no consistent contact set: its shear %.3g kPa, %.3g times the contact's "
      "mean pressure %.3g kPa, lifts the edge it acts on in the linear coupled model; give a smaller "
      "shear strength, or friction mode \"uncoupled\"",
      field, to_string(mode), 1e3 * tau, mean > 0 ? tau / mean : 0.0, 1e3 * mean);
  return SceneError(buf);
}

double ContactSolver::tau0() const {
  if (load_.tau0) return *load_.tau0;
  if (!tau0_) {
    const ContactResult r = solve(FrictionMode::none);
    double area = 0;
    for (int i : r.active) area += zone().area[i];
    tau0_ = area > 0 ? load_.mu * r.force_N / area : 0.0;
  }
  return *tau0_;
}

const Eigen::VectorXd& ContactSolver::touched(FrictionMode mode) const {
  auto it = touched_.find(mode);
  if (it != touched_.end()) return it->second;
  const ContactResult r = solve(mode);
  Eigen::VectorXd w = Eigen::VectorXd::Zero(zone().size());
  if (r.tau != 0) {
    w = r.shear / r.tau;
  } else {
    for (int i : r.active) w[i] = 1;
  }
  return touched_.emplace(mode, std::move(w)).first->second;
}

Eigen::MatrixXd ContactSolver::frictionless_matrix() const {
  Eigen::MatrixXd M = c_.C_zz;
  // A linear interface closes by p/K over each hat: ∫ψ_i p/K, lumped to ∫ψ_i · λ_i/K.
  if (load_.interface.law == InterfaceLaw::linear) M.diagonal() += c_.zone.area / load_.interface.K;
  return M;
}

ContactLcp& ContactSolver::lcp(double ratio) const {
  // find() first: an existing problem is only read (solves on several threads, contact/holes/sweep.cpp).
  if (const auto it = lcps_.find(ratio); it != lcps_.end()) return *it->second;
  auto& slot = lcps_[ratio];
  if (!slot) {
    Eigen::MatrixXd M = frictionless_matrix();
    if (ratio != 0) M += ratio * c_.C_zt;
    slot = std::make_unique<ContactLcp>(std::move(M), c_.gap0, c_.zone.area);
  }
  return *slot;
}

double ContactSolver::unique_ratio_bound() const {
  // B + r S is positive definite, B = C_zz (+ closure) > 0, symmetric as condense() leaves it, S = sym(C_zt),
  // while 1 + r μ > 0 for every μ of S v = μ B v: up to r = −1/μ_min.
  const Eigen::MatrixXd S = 0.5 * (c_.C_zt + c_.C_zt.transpose());
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(S, frictionless_matrix(),
                                                                      Eigen::EigenvaluesOnly);
  if (eig.info() != Eigen::Success) return 0.0;
  const double mu_min = eig.eigenvalues().minCoeff();
  return mu_min < 0 ? -1.0 / mu_min : std::numeric_limits<double>::infinity();
}

void ContactSolver::set_reference(FrictionMode mode, const std::vector<int>& active) const {
  lcp(solved_ratio(mode)).set_reference(solved_set(active));
  if (shear(mode) != 0)
    touched(mode);  // τ0 and the touched set, built now, before a sweep's threads read them
}

ContactResult ContactSolver::solve(FrictionMode mode, const std::vector<char>& excluded,
                                   const std::vector<int>& warm, const Eigen::VectorXd& covered) const {
  if (covered.size() && covered.size() != zone().size())
    throw std::invalid_argument("ContactSolver::solve: covered has " + std::to_string(covered.size()) +
                                " values for " + std::to_string(zone().size()) + " multipliers");
  ContactResult out = started(mode);
  const ContactLcp& problem = lcp(solved_ratio(mode));
  // Under a mirror view the half carries half the force; flags and warm starts move to its multipliers.
  std::vector<char> half_excluded;
  if (mirror_ && !excluded.empty()) {
    half_excluded.assign(c_.zone.size(), 0);
    for (int i = 0; i < zone().size(); ++i)
      if (excluded.at(i)) half_excluded[mirror_->half[i]] = 1;
  }
  const std::vector<char>& ex = mirror_ ? half_excluded : excluded;
  const double share = mirror_ ? 0.5 : 1.0;
  const auto lcp_solve = [&](const std::vector<int>& start, const Eigen::VectorXd& shift) {
    LcpSolution hard;
    try {
      hard = load_.force ? problem.solve_force(share * *load_.force, ex, start, shift)
                         : problem.solve_depth(*load_.depth, ex, start, shift);
    } catch (const std::runtime_error& e) {
      // Pivoting fails where force control loses uniqueness: name the scene's ratio and the bound.
      const double r = solved_ratio(mode), bound = r != 0 ? unique_ratio_bound() : 0.0;
      if (r == 0 || !(r >= bound)) throw;
      const char* field = mode == FrictionMode::static_residual ? "static_ratio" : "mu";
      const auto g = [](double v) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.3g", v);
        return std::string(buf);
      };
      throw SceneError(std::string("contact.friction.") + field + " = " + g(r) + ": the " + to_string(mode) +
                       " contact did not solve (" + e.what() +
                       "); the contact problem is guaranteed one solution only for " + field + " below " +
                       g(bound) + " on this skin and contact zone (there the symmetric part of C_zz + " +
                       field + " C_zt is positive definite)");
    }
    if (load_.interface.law != InterfaceLaw::exponential) return hard;
    return solve_exponential(
        problem.matrix(), shift.size() ? Eigen::VectorXd(problem.gaps() + shift) : problem.gaps(),
        problem.areas(), {load_.interface.u0, load_.interface.p_ref}, load_.force.has_value(),
        load_.force ? share * *load_.force : *load_.depth, ex, hard);
  };
  LcpSolution s = lcp_solve(solved_set(warm), {});
  // The shear's gaps where it acts while the pressure is solved: iterate its touched set to a fixed point.
  Eigen::VectorXd shear_solved;  // on the solved problem's multipliers
  if (out.tau != 0) {
    // partial: solved multipliers whose shear is a fixed fraction (edge vertices that lift under their own
    // shear and touch without it; see below).
    std::map<int, double> partial;
    const auto shear_for = [&](const std::vector<int>& active) {
      Eigen::VectorXd v = Eigen::VectorXd::Zero(zone().size());
      for (int i : whole_set(active)) v[i] = out.tau;
      for (int i = 0; i < zone().size(); ++i)
        if (const auto it = partial.find(solved_index(i)); it != partial.end()) v[i] = it->second * out.tau;
      return v;
    };
    const auto free_part = [&](const std::vector<int>& a) {
      std::vector<int> out_set;
      for (int j : a)
        if (!partial.count(j)) out_set.push_back(j);
      return out_set;
    };
    const auto solve_with = [&](const std::vector<int>& active) {
      return lcp_solve(active, c_.C_zt * solved_lambda(shear_for(active)));
    };
    const bool holed = std::find(excluded.begin(), excluded.end(), 1) != excluded.end() ||
                       (covered.size() && covered.maxCoeff() > 0);
    const bool acting = kind(mode).coupled;
    if (holed) {
      out.shear = out.tau * touched(mode);
      if (covered.size()) out.shear = out.shear.cwiseProduct((1.0 - covered.array()).matrix());
      if (acting) s = lcp_solve(s.active, c_.C_zt * solved_lambda(out.shear));
    }
    constexpr int kMaxRounds = 50, kBisections = 50;
    std::vector<std::vector<int>> seen{s.active};
    for (int round = 0; acting && !holed; ++round) {
      if (round == kMaxRounds) throw no_consistent_set(mode, s);
      LcpSolution next = solve_with(s.active);
      const bool settled = free_part(next.active) == free_part(s.active);
      if (settled) {
        s = std::move(next);
        break;
      }
      const auto again = std::find(seen.begin(), seen.end(), next.active);
      if (again == seen.end()) {
        seen.push_back(next.active);
        s = std::move(next);
        continue;
      }
      // A cycle: the multipliers D that flip touch without their own shear and lift under it. The consistent
      // state lies between: D just touching (λ_D = g_D = 0) under a fraction w of the shear. Bisect w
      // (each step one warm-started LCP solve) to round-off and keep the side where D still touches.
      std::vector<int> D;
      for (auto it = again; it != seen.end(); ++it) {
        std::vector<int> d;
        std::set_symmetric_difference(it->begin(), it->end(), next.active.begin(), next.active.end(),
                                      std::back_inserter(d));
        for (int j : d)
          if (!partial.count(j)) D.push_back(j);
      }
      std::sort(D.begin(), D.end());
      D.erase(std::unique(D.begin(), D.end()), D.end());
      const auto touches = [&](const LcpSolution& x) {
        for (int j : D)
          if (std::binary_search(x.active.begin(), x.active.end(), j)) return true;
        return false;
      };
      const auto at = [&](double w) {
        for (int j : D) partial[j] = w;
        return solve_with(next.active);
      };
      LcpSolution lo = at(0.0);
      if (!touches(lo) || touches(at(1.0))) throw no_consistent_set(mode, s);
      double wlo = 0, whi = 1;
      for (int b = 0; b < kBisections && whi - wlo > 1e-12; ++b) {
        const double w = 0.5 * (wlo + whi);
        LcpSolution x = at(w);
        if (touches(x)) {
          wlo = w;
          lo = std::move(x);
        } else {
          whi = w;
        }
      }
      for (int j : D) partial[j] = wlo;
      s = std::move(lo);
      seen.assign(1, s.active);
    }
    if (!holed) out.shear = shear_for(s.active);
    shear_solved = solved_lambda(out.shear);
    for (int i = 0; i < zone().size(); ++i) out.partial_shear += partial.count(solved_index(i)) ? 1 : 0;
  }
  Eigen::VectorXd gap = s.gap;
  if (!kind(mode).coupled) gap += out.ratio * (c_.C_zt * s.lambda);
  if (!kind(mode).coupled && out.tau != 0) gap += c_.C_zt * shear_solved;
  out.readings = solved_readings(s.lambda, out.ratio);
  if (out.tau != 0) out.readings += c_.S_t * shear_solved;
  finish(out, s, gap, excluded);
  return out;
}

ContactResult ContactSolver::solve(FrictionMode mode, const HoleCut& cut,
                                   const std::vector<int>& warm) const {
  const ContactResult plain = started(mode);
  return solve(mode, cut_problem(c_, cut, plain.ratio != 0 || plain.tau != 0), warm);
}

ContactResult ContactSolver::solve(FrictionMode mode, const CutProblem& cp,
                                   const std::vector<int>& warm) const {
  const int n = c_.zone.size();
  ContactResult out = started(mode);
  const double acting = solved_ratio(mode);
  if ((out.ratio != 0 || out.tau != 0) && cp.zt_rows.rows() != static_cast<int>(cp.rows.size()))
    throw std::logic_error("ContactSolver: a frictional cut solve needs the cut problem's tangential part");
  const Eigen::VectorXd& area = cp.area;
  const Eigen::VectorXd& q = cp.gap0;
  // Each row and column scaled by 1 / (share of the hat outside the hole): the same complementarity problem
  // in the multipliers' force per unit remaining hat, so a nearly covered hat keeps a well-scaled row (its
  // unscaled principal systems are singular to round-off: "not a P-matrix").
  constexpr double kGone = 1e-9;
  const bool exponential = load_.interface.law == InterfaceLaw::exponential;
  // Share of each hat outside the hole (exactly 1 where the hole does not reach).
  const Eigen::VectorXd outside = (area.array() / c_.zone.area.array()).max(0.0).matrix();
  std::vector<char> ex(n, 0);
  Eigen::VectorXd scale = Eigen::VectorXd::Ones(n);
  for (int i = 0; i < n; ++i) {
    if (outside[i] < kGone)
      ex[i] = 1;
    else
      scale[i] = 1 / outside[i];
  }
  Eigen::VectorXd m = area;
  for (int i = 0; i < n; ++i)
    if (ex[i]) m[i] = c_.zone.area[i];  // any positive value: λ_i = 0
  const std::vector<int>& T = cp.rows;
  const int t = static_cast<int>(T.size());
  // The hole-free matrix (C_zz + ratio C_zt + the interface's closure) with the rows and columns T replaced:
  // everything else is bit for bit the stored problem's, so it is solved on its reference factorization
  // with T removed and re-added (ContactLcp::solve_changed; hole_sweep sets the reference).
  const ContactLcp& base = lcp(acting);
  Eigen::MatrixXd M2 =
      acting != 0 ? patched(base.matrix(), T, cp.zz + acting * cp.zt_rows, cp.zz + acting * cp.zt_cols)
                  : patched(base.matrix(), T, cp.zz, cp.zz);
  std::vector<char> dirty(n, 0);
  for (int a = 0; a < t; ++a) {
    if (load_.interface.law == InterfaceLaw::linear) M2(T[a], T[a]) += area[T[a]] / load_.interface.K;
    dirty[T[a]] = 1;
  }
  // The exponential law is solved unscaled (its λ is a pressure), from the scaled hard contact.
  const Eigen::MatrixXd M2_unscaled = exponential ? M2 : Eigen::MatrixXd();
  for (int a = 0; a < t; ++a) {
    M2.row(T[a]) *= scale[T[a]];
    M2.col(T[a]) *= scale[T[a]];
  }
  // A product with C_zt, C_zt_rows (whole hats' traction on the cut rows) or S as cut, from the patch.
  const auto zt_times = [&](const Eigen::VectorXd& x, bool whole_hats) {
    Eigen::VectorXd y = c_.C_zt * x;
    if (!whole_hats)
      for (int b = 0; b < t; ++b) y += (cp.zt_cols.row(b).transpose() - c_.C_zt.col(T[b])) * x[T[b]];
    for (int a = 0; a < t; ++a) y[T[a]] = (whole_hats ? cp.zt_whole : cp.zt_rows).row(a).dot(x);
    return y;
  };
  const auto read = [&](const Eigen::MatrixXd& S0, const Eigen::MatrixXd& cols, const Eigen::VectorXd& x) {
    Eigen::VectorXd y = S0 * x;
    for (int a = 0; a < t; ++a) y += (cols.col(a) - S0.col(T[a])) * x[T[a]];
    return y;
  };
  Eigen::VectorXd shear_solved;
  Eigen::VectorXd q2 = q;
  if (out.tau != 0) {
    // The shear on the hole-free contact of this mode minus the hole, lumped on the hats.
    const Eigen::VectorXd w = solved_lambda(touched(mode));
    shear_solved = out.tau * w.cwiseProduct(outside);
    out.shear = Eigen::VectorXd::Zero(zone().size());
    for (int i = 0; i < zone().size(); ++i) out.shear[i] = shear_solved[solved_index(i)];
    if (kind(mode).coupled) q2 += zt_times(shear_solved, true);
  }
  const double share = mirror_ ? 0.5 : 1.0;
  const double value = load_.force ? share * *load_.force : *load_.depth;
  LcpSolution s = base.solve_changed(M2, q2.cwiseProduct(scale), m.cwiseProduct(scale), dirty,
                                     load_.force.has_value(), value, ex, solved_set(warm));
  // Back to multipliers (nodal pressures of the cut hats) and unscaled gaps.
  s.lambda = s.lambda.cwiseProduct(scale);
  s.gap = s.gap.cwiseQuotient(scale);
  if (exponential)
    s = solve_exponential(M2_unscaled, q2, m, {load_.interface.u0, load_.interface.p_ref},
                          load_.force.has_value(), value, ex, s);
  Eigen::VectorXd gap = s.gap;
  if (!kind(mode).coupled) {
    if (out.ratio != 0) gap += out.ratio * zt_times(s.lambda, false);
    if (out.tau != 0) gap += zt_times(shear_solved, true);
  }
  out.readings = read(c_.S_p, cp.sp, s.lambda);
  if (out.ratio != 0) out.readings += out.ratio * read(c_.S_t, cp.st, s.lambda);
  if (out.tau != 0) out.readings += c_.S_t * shear_solved;
  std::vector<char> whole_ex;
  for (int i = 0; i < zone().size(); ++i) whole_ex.push_back(ex[solved_index(i)]);
  // Reported per hat as its force over its whole area (λ_i × the share outside the hole): the nodal value
  // of a hat left with a sliver is the sliver's concentrated pressure, unbounded as the sliver vanishes.
  s.lambda = s.lambda.cwiseProduct(outside);
  finish(out, s, gap, whole_ex);
  return out;
}

ContactResult ContactSolver::solve(FrictionMode mode, const HoleDimple& dimple) const {
  if (load_.interface.law != InterfaceLaw::hard)
    throw std::invalid_argument(
        "ContactSolver::solve: the bulge is a hole's solution under a hard interface");
  ContactResult out = started(mode);
  const ContactLcp& problem = lcp(solved_ratio(mode));
  Eigen::VectorXd shift = dimple.opening, shear_solved;
  if (out.tau != 0) {
    // The shear on the hole-free contact of this mode minus the hole (as for a cut hole).
    out.shear = out.tau * touched(mode);
    if (dimple.covered.size()) out.shear = out.shear.cwiseProduct((1.0 - dimple.covered.array()).matrix());
    shear_solved = solved_lambda(out.shear);
    if (kind(mode).coupled) shift += c_.C_zt * shear_solved;
  }
  const double value = load_.force ? (mirror_ ? 0.5 : 1.0) * *load_.force : *load_.depth;
  // The hole-free set, bilateral; one principal solve on its stored factorization (set_reference).
  std::vector<char> out_of_contact(dimple.in_contact.size());
  std::vector<int> set;
  for (size_t i = 0; i < out_of_contact.size(); ++i) {
    out_of_contact[i] = !dimple.in_contact[i];
    if (dimple.in_contact[i]) set.push_back(static_cast<int>(i));
  }
  const LcpSolution s = load_.force
                            ? problem.solve_force(value, out_of_contact, set, shift, dimple.in_contact)
                            : problem.solve_depth(value, out_of_contact, set, shift, dimple.in_contact);
  Eigen::VectorXd gap = s.gap;
  if (!kind(mode).coupled) {
    if (out.ratio != 0) gap += out.ratio * (c_.C_zt * s.lambda);
    if (out.tau != 0) gap += c_.C_zt * shear_solved;
  }
  out.readings = solved_readings(s.lambda, out.ratio);
  if (out.tau != 0) out.readings += c_.S_t * shear_solved;
  finish(out, s, gap, {});
  out.opening = whole_gaps(dimple.opening);
  return out;
}

void ContactSolver::finish(ContactResult& out, const LcpSolution& s, const Eigen::VectorXd& gap,
                           const std::vector<char>& excluded) const {
  out.depth_mm = s.delta;
  if (out.tau == 0) out.shear = Eigen::VectorXd::Zero(zone().size());
  out.complementarity = s.complementarity;
  out.min_lambda = s.min_lambda;
  out.min_gap = s.min_gap;
  out.pivots = s.pivots;
  if (!mirror_) {
    out.lambda = s.lambda;
    out.gap = gap;
    out.active = s.active;
  } else {
    const int n = zone().size();
    out.lambda.resize(n);
    out.gap = whole_gaps(gap);  // a cut multiplier's row on the half is half its whole row
    std::vector<char> active(c_.zone.size(), 0);
    for (int j : s.active) active[j] = 1;
    bool first = true;
    for (int i = 0; i < n; ++i) {
      const int j = mirror_->half[i];
      out.lambda[i] = s.lambda[j];
      if (active[j]) out.active.push_back(i);
      if (excluded.empty() || !excluded[i]) {
        out.min_gap = first ? out.gap[i] : std::min(out.min_gap, out.gap[i]);
        first = false;
      }
    }
  }
  out.force_N = zone().area.dot(out.lambda);
  out.tangential_force_N = out.ratio * out.force_N + zone().area.dot(out.shear);
}

Eigen::VectorXd ContactSolver::whole_gaps(const Eigen::VectorXd& solved) const {
  if (!mirror_) return solved;
  Eigen::VectorXd out(zone().size());
  for (int i = 0; i < out.size(); ++i) {
    const int j = mirror_->half[i];
    out[i] = solved[j] * (images_[j] == 1 ? 2.0 : 1.0);
  }
  return out;
}

int hole_holding(const TetMesh& mesh, int v, const std::vector<Hole>& holes) {
  for (size_t k = 0; k < holes.size(); ++k)
    if (hole_contains(holes[k], mesh.nodes(v, 0), mesh.nodes(v, 1))) return static_cast<int>(k);
  return -1;
}

std::vector<char> excluded_by_holes(const MortarZone& zone, const TetMesh& mesh,
                                    const std::vector<Hole>& holes) {
  std::vector<char> out(zone.size(), 0);
  for (int i = 0; i < zone.size(); ++i) out[i] = hole_holding(mesh, zone.vertices[i], holes) >= 0;
  return out;
}

void require_hole_resolved(const MortarZone& zone, const TetMesh& mesh, const Hole& hole,
                           const std::vector<int>& active, const std::string& where) {
  int nearest = -1;
  double best = 1e300;
  for (int i = 0; i < zone.size(); ++i) {
    const double d = std::hypot(mesh.nodes(zone.vertices[i], 0) - hole.center[0],
                                mesh.nodes(zone.vertices[i], 1) - hole.center[1]);
    if (d < 0.5 * hole.diameter) return;  // it holds a multiplier
    if (d < best) best = d, nearest = i;
  }
  if (nearest < 0 || std::find(active.begin(), active.end(), nearest) == active.end()) return;
  char buf[256];
  std::snprintf(
      buf, sizeof buf,
      "%s: the hole of diameter %.4g mm at (%.4g, %.4g) lies in the contact but holds no contact "
      "vertex (the nearest is %.4g mm away): the mesh over it is too coarse to see it; give a finer "
      "mesh over the hole",
      where.c_str(), hole.diameter, hole.center[0], hole.center[1], best);
  throw HoleUnresolved(buf);
}

}  // namespace skinfem::contact
