#include "contact/contact_solver.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace skinfem::contact {

const char* to_string(FrictionMode mode) {
  switch (mode) {
    case FrictionMode::none:
      return "none";
    case FrictionMode::static_residual:
      return "static";
    case FrictionMode::uncoupled:
      return "uncoupled";
    case FrictionMode::coupled:
      return "coupled";
  }
  return "none";
}

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

Eigen::VectorXd ContactSolver::readings(const Eigen::VectorXd& lambda, double ratio) const {
  return solved_readings(solved_lambda(lambda), ratio);
}

double ContactSolver::ratio(FrictionMode mode) const {
  switch (mode) {
    case FrictionMode::none:
      return 0.0;
    case FrictionMode::static_residual:
      return load_.static_ratio;
    case FrictionMode::uncoupled:
    case FrictionMode::coupled:
      return load_.mu;
  }
  return 0.0;
}

ContactLcp& ContactSolver::lcp(double ratio) const {
  auto& slot = lcps_[ratio];
  if (!slot) {
    Eigen::MatrixXd M = c_.C_zz;
    if (ratio != 0) M += ratio * c_.C_zt;
    slot = std::make_unique<ContactLcp>(std::move(M), c_.gap0, c_.zone.area);
  }
  return *slot;
}

void ContactSolver::set_reference(FrictionMode mode, const std::vector<int>& active) const {
  lcp(mode == FrictionMode::uncoupled ? 0.0 : ratio(mode)).set_reference(solved_set(active));
}

ContactResult ContactSolver::solve(FrictionMode mode, const std::vector<char>& excluded,
                                   const std::vector<int>& warm) const {
  ContactResult out;
  out.mode = mode;
  out.ratio = ratio(mode);
  // The pressure is solved with the traction acting, except in the uncoupled mode.
  const double solved_ratio = mode == FrictionMode::uncoupled ? 0.0 : out.ratio;
  const ContactLcp& problem = lcp(solved_ratio);
  // Under a mirror view the half carries half the force; flags and warm starts move to its multipliers.
  std::vector<char> half_excluded;
  if (mirror_ && !excluded.empty()) {
    half_excluded.assign(c_.zone.size(), 0);
    for (int i = 0; i < zone().size(); ++i)
      if (excluded.at(i)) half_excluded[mirror_->half[i]] = 1;
  }
  const std::vector<char>& ex = mirror_ ? half_excluded : excluded;
  const double share = mirror_ ? 0.5 : 1.0;
  const LcpSolution s = load_.force ? problem.solve_force(share * *load_.force, ex, solved_set(warm))
                                    : problem.solve_depth(*load_.depth, ex, solved_set(warm));
  Eigen::VectorXd gap = s.gap;
  if (mode == FrictionMode::uncoupled) gap += out.ratio * (c_.C_zt * s.lambda);
  out.depth_mm = s.delta;
  out.readings = solved_readings(s.lambda, out.ratio);
  out.complementarity = s.complementarity;
  out.min_lambda = s.min_lambda;
  out.min_gap = s.min_gap;
  out.pivots = s.pivots;
  if (!mirror_) {
    out.lambda = s.lambda;
    out.gap = gap;
    out.active = s.active;
  } else {
    // A cut multiplier's row on the half is half its whole row; one off the cut is its whole row.
    const int n = zone().size();
    out.lambda.resize(n);
    out.gap.resize(n);
    std::vector<char> active(c_.zone.size(), 0);
    for (int j : s.active) active[j] = 1;
    bool first = true;
    for (int i = 0; i < n; ++i) {
      const int j = mirror_->half[i];
      out.lambda[i] = s.lambda[j];
      out.gap[i] = gap[j] * (images_[j] == 1 ? 2.0 : 1.0);
      if (active[j]) out.active.push_back(i);
      if (excluded.empty() || !excluded[i]) {
        out.min_gap = first ? out.gap[i] : std::min(out.min_gap, out.gap[i]);
        first = false;
      }
    }
  }
  out.force_N = zone().area.dot(out.lambda);
  out.tangential_force_N = out.ratio * out.force_N;
  return out;
}

std::vector<char> excluded_by_holes(const MortarZone& zone, const TetMesh& mesh,
                                    const std::vector<Hole>& holes) {
  std::vector<char> out(zone.size(), 0);
  for (int i = 0; i < zone.size(); ++i)
    for (const Hole& h : holes)
      if (std::hypot(mesh.nodes(zone.vertices[i], 0) - h.center[0],
                     mesh.nodes(zone.vertices[i], 1) - h.center[1]) < 0.5 * h.diameter)
        out[i] = 1;
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
