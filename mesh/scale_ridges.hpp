// The same-mesh control of a ridge study: a ridged skin's mesh with its ridges scaled down, node for node.
//
// Comparing a ridged skin with a separately meshed smooth one mixes the ridges' effect with the two meshes'
// different discretization errors, which for 220 µm ridges on a 3 mm layer are of the same size (0.1 %).
// Moving the nodes of the ridged mesh vertically by (f − 1)·ridge(x, y) at the top, fading to zero within a
// ridge period below it, gives the skin with ridges f times as high on the same elements and connectivity, so
// the difference of the two solves is the ridges' effect with most of the discretization error cancelled
// (app/cmd_ridge_study.cpp). f = 0 (a smooth top) is out of reach: in a trough TetGen fills the space between
// neighbouring top triangles with elements whose four vertices all lie on the top, and a flat top would crush
// them. A small f squashes them by f instead.
#pragma once

#include "skinfem/mesh/tet_mesh.hpp"
#include "skinfem/scene/scene.hpp"

namespace skinfem {

// mesh: a mesh of `geometry` (a cap or flat layer with ridges); factor in (0, 1]. Every node on the top ends
// on the top with ridges `factor` times as high, except the mid-edge nodes of elements this curves into a
// fold, which are straightened again (mesh/build.hpp; mesh.straightened counts both); nodes deeper than a
// ridge period or half the skin do not move. Throws MeshError if an element folds (mesh/quality.hpp).
TetMesh scale_ridges(TetMesh mesh, const Geometry& geometry, double factor);

}  // namespace skinfem
