// A small hole in the indenter seen by the contact as the bulge it lets the skin make (docs/contact.md,
// "The hole as a bulge").
//
// A hole of radius ε much smaller than the skin's thickness and than the distance over which the contact
// pressure p varies is, near it, Sneddon's penny-shaped crack turned inside out: the plate holds the surface
// flat around it, the skin bulges into it by w(x) = p(x) ω(x − u), ω(r) = 4(1 − ν²) √(ε² − r²) / (πE)
// (one face of the crack's opening under unit pressure; by Betti the bulge's volume under any p is
// ∫_H p ω, 8(1 − ν²) p ε³ / (3E) for a uniform one), and the plate puts the load missing over the hole back
// on its rim (Sneddon 1946; Tada, Paris & Irwin, The Stress Analysis of Cracks Handbook, §24). Seen from
// farther than a few ε, that local solution is a point dilatation of the surface: the outer (contact)
// problem keeps its multipliers everywhere and only sees the indenter's surface recede by the bulge, i.e.
// multiplier i's weighted gap opens by ∫_H ψ_i p₀ ω(x − u) dA, smooth in u (the hats' kinks are averaged over
// the hole); the active set and the approach stay free (force control keeps the force).
// p₀ is the pressure the hole sits in: the hole-free contact's of the same friction mode (matched
// asymptotics: the inner solution sees the outer solution's regular part; the outer solution's own answer to
// the dilatation is singular at u, and on the hats it would feed back into p₀ at the mesh's scale — solved
// self-consistently, the default scene's peaks came out 35–40 % lower, an artefact of that feedback).
// The next terms are of relative order (ε/d)² for a sensor at distance d and (ε/ℓ)² with ℓ the length over
// which p varies (at the contact's edge ℓ → 0: there the local solution is not the crack's; measured against
// the resolved hole, tests/contact/test_hole.cpp).
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "skinfem/contact/contact_solver.hpp"
#include "skinfem/fem/face_index.hpp"

namespace skinfem::contact {

class HoleDimples {
 public:
  // solver, mesh (the results' whole mesh) and top (its top faces) must outlive this. E (MPa) and nu: the
  // skin's. Throws std::invalid_argument if E ≤ 0 or nu outside [0, 0.5].
  HoleDimples(const ContactSolver& solver, const TetMesh& mesh, const PlanarFaceIndex& top, double E,
              double nu);
  // The dimple of `hole` in the pressure p₀ (per whole multiplier, MPa: the hole-free contact's λ). On the
  // solved problem: under a mirror view each half row sees ½ the openings of the whole multipliers it
  // stands for (ContactSolver::opening_share).
  HoleDimple operator()(const Hole& hole, const Eigen::VectorXd& pressure) const;

 private:
  const ContactSolver& solver_;
  const TetMesh& mesh_;
  const PlanarFaceIndex& top_;
  double E_, nu_;
  std::vector<int> whole_index_;  // per mesh node: its whole multiplier, or −1
};

}  // namespace skinfem::contact
