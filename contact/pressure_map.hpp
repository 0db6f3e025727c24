// pressure.vtp: the contact zone's top faces with, per node, pressure_kPa (the P1 multiplier field),
// traction_kPa (3 components: the friction traction ratio·p + shear along the sliding direction), gap_um
// (mean gap over each vertex's hat, ∫ψ gap / ∫ψ: the quantity held ≥ 0; at a vertex inside a hole, to the
// hole's bottom: the skin bulges above the indenter's face there, which is not a penetration), in_hole (1 at
// the vertices inside a hole) and in_contact (1 where p > 0). Only
// faces whose three corners carry multipliers. Mid-edge nodes carry the mean of their two vertices (exact for
// the linear multiplier field).
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "skinfem/contact/contact_solver.hpp"
#include "skinfem/contact/finite_contact.hpp"

namespace skinfem::contact {

// mesh: the mesh of solver.zone() (the whole one under a mirror view); holes: the indenter's, where it is.
void write_pressure_vtp(const std::string& path, const TetMesh& mesh, const ContactSolver& solver,
                        const ContactResult& r, const std::vector<Hole>& holes = {});

// pressure.vtp of a plate on the finite-strain skin (contact/finite_contact.hpp): the same faces on the
// reference mesh with pressure_kPa, traction_kPa (ratio·p + the shear along direction), gap_um, in_contact
// and displacement_mm (ParaView's Warp By Vector shows the zone in the current frame).
void write_finite_pressure_vtp(const std::string& path, const TetMesh& mesh, const MortarZone& zone,
                               const FiniteContactResult& r, const Eigen::Vector2d& direction, double ratio);

// The hole whose bottom the skin comes closest to, and the clearance left, mm (the mean gap of the hats of
// the vertices inside it, to its bottom; +inf without holes). A clearance ≤ 0 means the skin touches a
// bottom the solve knows nothing of: the hole is too shallow for this contact.
struct HoleClearance {
  int hole = -1;
  double clearance_mm = std::numeric_limits<double>::infinity(), rise_mm = 0;  // rise above the face
};
HoleClearance hole_clearance(const TetMesh& mesh, const ContactSolver& solver, const ContactResult& r,
                             const std::vector<Hole>& holes);
// Throws SceneError when the skin reaches a hole's bottom, naming the depth's field: `field` is
// "contact.holes" (the scene's holes: contact.holes[k].depth) or "contact.sweep" (contact.sweep.hole_depth).
void check_hole_clearance(const TetMesh& mesh, const ContactSolver& solver, const ContactResult& r,
                          const std::vector<Hole>& holes, const std::string& field);

}  // namespace skinfem::contact
