// pressure.vtp: the contact zone's top faces with, per node, pressure_kPa (the P1 multiplier field),
// traction_kPa (3 components: the friction traction ratio·p + shear along the sliding direction), gap_um
// (mean gap over each vertex's hat, ∫ψ gap / ∫ψ: the quantity held ≥ 0) and in_contact (1 where p > 0). Only
// faces whose three corners carry multipliers. Mid-edge nodes carry the mean of their two vertices (exact for
// the linear multiplier field).
#pragma once

#include <string>

#include "contact/contact_solver.hpp"

namespace skinfem::contact {

// mesh: the mesh of solver.zone() (the whole one under a mirror view).
void write_pressure_vtp(const std::string& path, const TetMesh& mesh, const ContactSolver& solver,
                        const ContactResult& r);

}  // namespace skinfem::contact
