#include "skinfem/contact/holes/dimple.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "skinfem/contact/holes/cover.hpp"
#include "skinfem/mesh/gauss_legendre.hpp"

namespace skinfem::contact {

namespace {
// The rule over the hole: r = ε sin θ turns ∫ f √(ε² − r²) r dr into ε³ ∫ f cos²θ sin θ dθ, smooth in θ
// (Gauss–Legendre); uniform angles are exact for trigonometric polynomials. Under a uniform pressure the hats
// sum to 1 and the rule gives the crack's volume to 1e-10 (tests/contact/test_hole.cpp); the hats' kinks
// inside the disc are what it cannot follow exactly (its error there was not measured).
constexpr int kRadii = 24, kAngles = 96;
}  // namespace

HoleDimples::HoleDimples(const ContactSolver& solver, const TetMesh& mesh, const PlanarFaceIndex& top,
                         double E, double nu)
    : solver_(solver), mesh_(mesh), top_(top), E_(E), nu_(nu), whole_index_(mesh.num_nodes(), -1) {
  if (!(E > 0) || !(nu >= 0 && nu <= 0.5))
    throw std::invalid_argument("HoleDimples: E must be > 0 and nu in [0, 0.5]");
  const MortarZone& z = solver.zone();
  for (int i = 0; i < z.size(); ++i) whole_index_.at(z.vertices[i]) = i;
}

HoleDimple HoleDimples::operator()(const Hole& hole, const Eigen::VectorXd& pressure) const {
  if (pressure.size() != solver_.zone().size())
    throw std::invalid_argument("HoleDimples: the pressure has " + std::to_string(pressure.size()) +
                                " values for " + std::to_string(solver_.zone().size()) + " multipliers");
  const double eps = 0.5 * hole.diameter;
  const double c = 4 * (1 - nu_ * nu_) / (M_PI * E_);
  static const GaussRule1d rule = gauss_legendre01(kRadii);
  HoleDimple out;
  out.opening = Eigen::VectorXd::Zero(solver_.condensed().zone.size());
  for (int a = 0; a < kRadii; ++a) {
    const double th = 0.5 * M_PI * rule.x[a];
    const double r = eps * std::sin(th);
    // c ε³ cos²θ sin θ dθ dφ, dθ = (π/2) dx, dφ = 2π / kAngles.
    const double w = c * eps * eps * eps * std::cos(th) * std::cos(th) * std::sin(th) * 0.5 * M_PI *
                     rule.w[a] * 2 * M_PI / kAngles;
    for (int b = 0; b < kAngles; ++b) {
      const double phi = 2 * M_PI * (b + 0.5) / kAngles;
      double s = 0, t = 0;
      const int f = top_.find(hole.center[0] + r * std::cos(phi), hole.center[1] + r * std::sin(phi), s, t);
      if (f < 0) continue;
      const double psi[3] = {1 - s - t, s, t};
      int idx[3];
      double p = 0;
      for (int k = 0; k < 3; ++k) {
        idx[k] = whole_index_[mesh_.faces(f, k)];
        if (idx[k] >= 0) p += psi[k] * pressure[idx[k]];
      }
      if (p <= 0) continue;
      for (int k = 0; k < 3; ++k)
        if (idx[k] >= 0)
          out.opening[solver_.solved_index(idx[k])] += solver_.opening_share() * w * psi[k] * p;
    }
  }
  out.in_contact.assign(out.opening.size(), 0);
  for (int i = 0; i < solver_.zone().size(); ++i)
    if (pressure[i] > 0) out.in_contact[solver_.solved_index(i)] = 1;
  out.covered = hole_cover(solver_.zone(), mesh_, {hole});
  return out;
}

}  // namespace skinfem::contact
