// How big the mesh of a scene will be, before meshing it: the sizing field's element density integrated
// over the skin, so that a scene asking for billions of elements is refused in milliseconds instead of
// exhausting the machine (issue: resource guards).
//
// A tetrahedron of edge h has volume h³/(6√2); TetGen's quality bounds keep elements near that shape, so
// a region of size h holds about V/(c h³) elements. Where the skin is thinner than h the quality bound
// caps the element size at about κ·t (t the local thickness), so h_eff = min(h, κ t). c and κ are fitted
// to TetGen's actual counts (size_estimate.cpp); the estimate is meant to be right within a factor 2.
#pragma once

#include "skinfem/mesh/tet_mesh.hpp"
#include "skinfem/scene/scene.hpp"

namespace skinfem {

// P2 displacements + P1 pressure per tetrahedron (graded meshes).
constexpr double kDofsPerTet = 4.3;

struct MeshEstimate {
  double tets = 0;     // quadratic tetrahedra
  double dofs = 0;     // free displacement + pressure DOFs of the Taylor–Hood system, about
  bool known = false;  // false for imported surfaces (their thickness is not known before meshing)
};

// Stops integrating (and returns what it has, already above the limit) once `tets` exceeds stop_tets.
// part half_y: the half y >= 0 (the skin's axis on y = 0) with the half's sizing field, every region mirrored
// into it (a region wholly in y > 0 makes the half as big as the whole there); the cut face's own
// refinement is not counted (resources.cpp allows for it).
MeshEstimate estimate_mesh(const Scene& scene, double stop_tets = 1e12, MeshPart part = MeshPart::whole);

// An imported surface has no estimate, but a floor: TetGen splits every element longer than mesh.h_max,
// and the regular tetrahedron is the largest with edges no longer than h_max (h_max³/(6√2)), so at least
// 6√2·volume/h_max³ elements fill the volume (a box scaled by 1e30 was meshed until killed at 9.8 GB).
double fewest_tets(double volume_mm3, double h_max);

}  // namespace skinfem
