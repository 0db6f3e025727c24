// TetGen on a closed marked surface, refining until every tetrahedron's longest edge is within the
// sizing field and the quality bounds hold. TetGen is not thread-safe: calls are serialised.
#pragma once

#include "skinfem/mesh/sizing.hpp"
#include "skinfem/mesh/tet_mesh.hpp"

namespace skinfem {

struct LinearTets {
  RowMatrixX3d points;                                          // P×3, mm
  Eigen::Matrix<int, Eigen::Dynamic, 4, Eigen::RowMajor> tets;  // T×4, positive volume
  RowMatrixX3i faces;                                           // boundary triangles, outward
  Eigen::VectorXi face_marker;                                  // BoundaryMarker per face
};

// TetGen may split boundary triangles (its -Y switch, which forbids that, also stalls interior
// refinement next to the surface); new boundary points lie on the flat input triangles, and
// build_mesh snaps them onto the exact surface.
// TetGen also merges adjacent facets within 0.1° of coplanar (its facet angle tolerance) and remeshes them,
// which flattens a finely tessellated smooth surface. Hence three policies:
//  - merge: the default, for generated caps and layers (their new points are snapped afterwards);
//  - keep: an imported surface, whose facets are the geometry: only facets within 1e-4° of coplanar are
//    merged (a flat base is remeshed; a curved top moves by at most 2e-6 × its facet size);
//  - preserve: keep, and no boundary triangle is split (-Y): a top curved on the scale of its elements
//    (ridges), where snapping split points vertically would fold elements. The surface must then already
//    be as fine as the sizing field asks (layer_surface triangulates the footprint with it).
enum class FacetPolicy { merge, keep, preserve };
LinearTets tetrahedralize(const SurfaceMesh& surface, const SizingField& size, const MeshControls& controls,
                          FacetPolicy facets = FacetPolicy::merge);

}  // namespace skinfem
