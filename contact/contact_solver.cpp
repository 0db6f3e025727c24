#include "contact/contact_solver.hpp"

#include <cmath>
#include <stdexcept>

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

ContactSolver::ContactSolver(const CondensedContact& condensed, const ContactLoad& load)
    : c_(condensed), load_(load) {}

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
  lcp(mode == FrictionMode::uncoupled ? 0.0 : ratio(mode)).set_reference(active);
}

ContactResult ContactSolver::solve(FrictionMode mode, const std::vector<char>& excluded,
                                   const std::vector<int>& warm) const {
  ContactResult out;
  out.mode = mode;
  out.ratio = ratio(mode);
  // The pressure is solved with the traction acting, except in the uncoupled mode.
  const double solved_ratio = mode == FrictionMode::uncoupled ? 0.0 : out.ratio;
  const ContactLcp& problem = lcp(solved_ratio);
  const LcpSolution s = load_.force ? problem.solve_force(*load_.force, excluded, warm)
                                    : problem.solve_depth(*load_.depth, excluded, warm);
  out.lambda = s.lambda;
  out.depth_mm = s.delta;
  out.gap = s.gap;
  if (mode == FrictionMode::uncoupled) out.gap += out.ratio * (c_.C_zt * s.lambda);
  out.force_N = c_.zone.area.dot(s.lambda);
  out.tangential_force_N = out.ratio * out.force_N;
  out.readings = c_.S_p * s.lambda;
  if (out.ratio != 0) out.readings += out.ratio * (c_.S_t * s.lambda);
  out.complementarity = s.complementarity;
  out.min_lambda = s.min_lambda;
  out.min_gap = s.min_gap;
  out.pivots = s.pivots;
  out.active = s.active;
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

}  // namespace skinfem::contact
