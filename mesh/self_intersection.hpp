// Self-intersections of a closed surface (CGAL Polygon Mesh Processing): TetGen cannot mesh a surface that
// crosses itself (it crashes), so imported surfaces are checked first.
#pragma once

#include <Eigen/Core>
#include <optional>

#include "skinfem/mesh/tet_mesh.hpp"

namespace skinfem {

// A point where two non-adjacent triangles of the surface intersect (the centroid of the first such
// triangle), or nothing when the surface does not intersect itself. The surface must be manifold.
std::optional<Eigen::Vector3d> first_self_intersection(const SurfaceMesh& surface);

}  // namespace skinfem
