// How much of each multiplier's hat a hole covers, integrated over the exact hole disc (a groove's
// rectangle).
//
// A shear that acts wherever the skin touches (FrictionLaw::shear_strength, mixed) is missing over a hole:
// its traction is τ0 (1 − 1_hole) on the touched region. On the multipliers' hats (contact/mortar.hpp) it is
// lumped as τ0 Σ_i (1 − covered_i) ψ_i, with covered_i = ∫ψ_i 1_hole / ∫ψ_i, so the shear the hole removes,
// Σ_i covered_i ∫ψ_i, is the hole's area S_d to the disc polygon's accuracy, and it varies continuously as
// the hole moves: a multiplier entering the hole loses its shear gradually, not at once. The integrals are
// over the (x, y) projections of the top faces' corner triangles (straight; the P2 faces' projections
// differ from them by the top's curvature, ~h²/(8R) r/R, below 1e-6 mm on the paper's cap) and of the disc
// as a polygon of kSides sides with the disc's area.
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "skinfem/contact/mortar.hpp"

namespace skinfem::contact {

// Sides of the polygon standing for a hole's circle: its area is the disc's; its largest radial departure
// from the circle, 2π²/(3 kSides²) of the radius (2.5e-5), bounds the error of each covered fraction.
inline constexpr int kHoleSides = 512;

// The hole's polygon clipped to the triangle v (counter-clockwise, (x, y)): empty if they do not overlap.
// A disc is the kHoleSides-gon of its area; a groove its exact rectangle.
std::vector<Eigen::Vector2d> hole_in_triangle(const Hole& hole, const Eigen::Vector2d v[3]);

// Per multiplier of `zone` (zone.size()): the share of ∫ψ_i that lies inside any of `holes`, in [0, 1].
// Holes must not overlap (scene rules): overlapping discs count twice (clamped to 1).
Eigen::VectorXd hole_cover(const MortarZone& zone, const TetMesh& mesh, const std::vector<Hole>& holes);

}  // namespace skinfem::contact
