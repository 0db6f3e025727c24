// Mirror symmetry about the plane y = 0: which scenes the Green tensor commands (green, kfit's 3D path) solve
// on their half y ≥ 0 (mesh/build.hpp's MeshPart::half_y, u_y = 0 on the cut).
//
// The reduction needs every sensor reading (σ_z, σ_x) and every load the command applies to be mirror-
// symmetric: the skin symmetric about y = 0 (a generated flat layer, or a cap whose apex lies on y = 0; no
// ridges), every sensor on y = 0 (its disc then symmetric too) and the calibration scan along x through the
// sensors (always). The commands that solve the contact too (contact, defect, report) also need the
// indenter, its holes, the hole sweep and the sliding direction symmetric (contact/contact_solver.hpp's
// MirrorView). `solve` meshes the whole skin.
#pragma once

#include <string>

#include "skinfem/mesh/tet_mesh.hpp"
#include "skinfem/scene/scene.hpp"

namespace skinfem::pipeline {

// Why the scene is not mirror-symmetric about y = 0 (a sentence naming what breaks it), or empty when it is.
std::string mirror_unavailable(const Scene& scene);
// half_y when the scene allows it ("symmetry": "auto", the default) and is symmetric; else whole.
MeshPart green_mesh_part(const Scene& scene);
// The same for the scene's contact: empty when it has none or it is symmetric.
std::string contact_mirror_unavailable(const Scene& scene);
// half_y when green_mesh_part is and the contact is symmetric (contact, defect, report).
MeshPart contact_mesh_part(const Scene& scene);

}  // namespace skinfem::pipeline
