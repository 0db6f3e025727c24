// The whole meshing pipeline for a scene: boundary surface → TetGen → 10-node tets with mid-edge
// nodes on the exact surface → markers.
#pragma once

#include "skinfem/mesh/footprint.hpp"
#include "skinfem/mesh/sizing.hpp"
#include "skinfem/mesh/tet_mesh.hpp"
#include "skinfem/scene/scene.hpp"

namespace skinfem {

// Throws MeshError when the surface is unusable, TetGen fails, or an element stays folded. part: the whole
// skin, or its half y ≥ 0 (generated skins whose axis lies on y = 0), the cut marked kSymmetry.
// max_tets > 0: an imported surface whose volume needs more elements than that at mesh.h_max
// (size_estimate.hpp's fewest_tets) is refused before TetGen runs (generated skins are estimated before
// this).
TetMesh build_mesh(const Scene& scene, MeshPart part = MeshPart::whole, double max_tets = 0);

// Mid-edge nodes placed on a surface curved on the scale of the elements (a steep cap near its rim,
// ridges) can fold a thin element (det J ≤ 0). Each folded element gets straight edges, its mid-edge
// nodes back at the chord midpoints: a local O(h²) geometry error instead of a wrong solve. Counts them in
// mesh.straightened.
void straighten_folded_elements(TetMesh& mesh);

// The P2 completion alone: adds the six mid-edge nodes per tet, placed on the exact top/side
// surface of `geometry` when the edge lies on a curved boundary face, and on the exact cylinder of a post
// (`posts`, their outlines) when it runs along a post's wall or rim (straight otherwise).
TetMesh make_quadratic(const RowMatrixX3d& points,
                       const Eigen::Matrix<int, Eigen::Dynamic, 4, Eigen::RowMajor>& tets,
                       const RowMatrixX3i& faces, const Eigen::VectorXi& face_marker,
                       const Geometry& geometry, const std::vector<Circle>& posts = {});

}  // namespace skinfem
