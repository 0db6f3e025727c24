// Element quality and size figures of a 10-node tet mesh.
#pragma once

#include "skinfem/mesh/tet_mesh.hpp"

namespace skinfem {

struct MeshQuality {
  int nodes = 0, vertices = 0, elements = 0, boundary_faces = 0;
  double min_dihedral_deg = 0, max_dihedral_deg = 0;  // of the straight-sided tets
  double max_radius_edge = 0;                         // circumradius / shortest edge
  double min_edge_mm = 0, max_edge_mm = 0;
  double volume_mm3 = 0;         // isoparametric P2 volume, degree-5 quadrature
  double linear_volume_mm3 = 0;  // straight-sided volume
  // min over elements and quadrature points of det J / (6 × straight-sided volume); ≤ 0 means inverted
  double min_jacobian_ratio = 0;
};

MeshQuality assess_quality(const TetMesh& mesh);

// Throws MeshError naming the first element that the isoparametric map folds (det J ≤ 0 at one of its
// vertices or degree-5 quadrature points) and where it lies. Mid-edge nodes moved onto a strongly curved
// surface (a steep cap near its rim, too coarse a mesh) can fold an element; the solve would be wrong.
void check_no_inverted_element(const TetMesh& mesh);
// Whether element t folds: det J ≤ 0 at one of its vertices or degree-5 quadrature points.
bool folded(const TetMesh& mesh, int t);

// Per tet: straight-sided volume (mm³) and longest edge (mm).
double tet_volume(const TetMesh& mesh, int tet);
double tet_longest_edge(const TetMesh& mesh, int tet);

// Jacobian of the isoparametric map x(ξ) = Σ N_a(ξ) x_a: J(i, k) = ∂x_i/∂ξ_k.
Eigen::Matrix3d tet_jacobian(const TetMesh& mesh, int tet, const Eigen::Vector3d& xi);

}  // namespace skinfem
