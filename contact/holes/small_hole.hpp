// The signal of a small hole in the indenter, from the hole-free contact alone (docs/contact.md).
//
// A hole of radius ε much smaller than the skin's thickness, inside the contact, lets the skin bulge into it
// by the volume of Sneddon's penny-shaped crack under the local pressure p, V = 8(1 − ν²) p ε³ / (3E), and
// the plate puts the missing load back on the hole's rim. Seen from the sensors the hole is a dimple of
// volume V in the indenter: the weighted gaps of the multipliers around u open by V ψ_i(u), the contact
// zone is kept (the active set of the hole-free solution) and the force too, so with the bordered matrix
// K = [M_AA, −m_A; m_Aᵀ, 0] of contact/lcp.hpp the readings change by
//   ς(u) = −V(u) · S_A [K⁻¹]_λ ψ_A(u),
// for every sensor (S = S_p + ratio S_t, contact/condensed.hpp). Under a shear strength τ the hole also
// removes the shear τ S_d, lumped on the hats at u: read through S_t, and through the gaps C_zt opens where
// the shear acts while the pressure is solved (static, coupled). One factorization of K and one solve with
// the 2·sensors reading rows give every position at the cost of a hat evaluation. Accurate to the next
// multipole, (ε/d)² for a sensor at distance d, and to the pressure's variation over the hole; checked
// against resolved holes in tests/contact/test_hole.cpp.
#pragma once

#include <vector>

#include "skinfem/contact/contact_solver.hpp"
#include "skinfem/fem/face_index.hpp"

namespace skinfem::contact {

// positions × 2·sensors (MPa, σ_z of sensor k in column 2k, σ_x in 2k + 1), like SweepResult::varsigma.
// E (MPa) and nu: the skin's; the friction mode as in ContactSolver::solve. Centres outside the zone's
// faces or where the hole-free pressure is zero give no signal.
Eigen::MatrixXd small_hole_signals(const ContactSolver& solver, FrictionMode mode, const TetMesh& mesh,
                                   const PlanarFaceIndex& top, const std::vector<Vec2>& centers,
                                   double hole_diameter, double E, double nu);

}  // namespace skinfem::contact
