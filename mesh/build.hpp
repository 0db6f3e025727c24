// The whole meshing pipeline for a scene: boundary surface → TetGen → 10-node tets with mid-edge
// nodes on the exact surface → markers.
#pragma once

#include "mesh/sizing.hpp"
#include "mesh/tet_mesh.hpp"
#include "scene/scene.hpp"

namespace skinfem {

// Throws MeshError when the surface is unusable or TetGen fails.
TetMesh build_mesh(const Scene& scene);

// The P2 completion alone: adds the six mid-edge nodes per tet, placed on the exact top/side
// surface of `geometry` when the edge lies on a curved boundary face (straight otherwise).
TetMesh make_quadratic(const RowMatrixX3d& points,
                       const Eigen::Matrix<int, Eigen::Dynamic, 4, Eigen::RowMajor>& tets,
                       const RowMatrixX3i& faces, const Eigen::VectorXi& face_marker,
                       const Geometry& geometry);

}  // namespace skinfem
