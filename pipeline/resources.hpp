// Resource guards: refuse, before meshing, a scene whose mesh would not fit the machine
// (mesh/size_estimate.hpp), with one line that gives the estimate, the limit and the scene fields that set
// the size.
#pragma once

#include "skinfem/mesh/size_estimate.hpp"
#include "skinfem/mesh/tet_mesh.hpp"
#include "skinfem/scene/scene.hpp"

namespace skinfem::pipeline {

// Memory the chain needs per DOF, GB: 19 kB per DOF (measured at 188k DOFs, the default scene's whole-skin
// report before mirror symmetry) up to 200k DOFs, growing as DOFs^(1/3) beyond (the factor's fill in 3D).
// Conservative today: the default report on its half peaks at 1.13 GB for 88.9k DOFs, 12.7 kB per DOF.
double estimated_memory_gb(double dofs);
// MemAvailable of /proc/meminfo, GB (0 if unknown).
double available_memory_gb();

// Throws SceneError when the estimate exceeds scene.limits.max_dofs (if > 0) or the available memory; else
// reports the estimate as a progress line and returns it.
// part: what will be meshed; a half y >= 0 is integrated over its side with its own sizing field (every
// region mirrored into it), and counted 1.1× for the cut face TetGen refines.
MeshEstimate check_resources(const Scene& scene, MeshPart part = MeshPart::whole);

// The most tetrahedra memory and max_dofs (if > 0) allow, at kDofsPerTet (mesh/size_estimate.hpp):
// build_mesh's floor for imported surfaces, which have no estimate.
double max_tets_allowed(double max_dofs);

// The Taylor–Hood unknowns before boundary conditions, 3 per node plus 1 per vertex: an upper bound on the
// free DOFs.
double unknowns_bound(const TetMesh& mesh);

// The same limits on a built mesh, before anything is assembled: the backstop where no estimate exists
// (imported surfaces) or where the estimate fell short. DOFs counted by unknowns_bound.
void check_meshed_dofs(const Scene& scene, const TetMesh& mesh);

// The guarded meshing every command starts with: check_resources, build_mesh within the limits, then
// check_meshed_dofs; `estimate`, if given, receives check_resources's.
TetMesh guarded_mesh(const Scene& scene, MeshPart part = MeshPart::whole, MeshEstimate* estimate = nullptr);

}  // namespace skinfem::pipeline
