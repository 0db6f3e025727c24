// Quadratic (10-node) tetrahedron on the reference element {ξ, η, ζ ≥ 0, ξ + η + ζ ≤ 1}, in the
// VTK node order of tet_mesh.hpp, and tetrahedral quadrature rules.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <vector>

namespace skinfem::p2 {

// Local vertex pairs of the six mid-edge nodes 4 … 9.
inline constexpr int kEdge[6][2] = {{0, 1}, {1, 2}, {0, 2}, {0, 3}, {1, 3}, {2, 3}};

using Vec10 = Eigen::Matrix<double, 10, 1>;
using Grad10 = Eigen::Matrix<double, 10, 3>;  // row a: ∂N_a/∂(ξ, η, ζ)

inline std::array<double, 4> barycentric(const Eigen::Vector3d& xi) {
  return {1.0 - xi[0] - xi[1] - xi[2], xi[0], xi[1], xi[2]};
}

// Vertex a: L_a(2L_a − 1); edge (i, j): 4 L_i L_j.
inline Vec10 shape(const Eigen::Vector3d& xi) {
  const auto L = barycentric(xi);
  Vec10 n;
  for (int a = 0; a < 4; ++a) n[a] = L[a] * (2 * L[a] - 1);
  for (int e = 0; e < 6; ++e) n[4 + e] = 4 * L[kEdge[e][0]] * L[kEdge[e][1]];
  return n;
}

inline Grad10 shape_gradient(const Eigen::Vector3d& xi) {
  const auto L = barycentric(xi);
  static const double dL[4][3] = {{-1, -1, -1}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  Grad10 g;
  for (int a = 0; a < 4; ++a)
    for (int k = 0; k < 3; ++k) g(a, k) = (4 * L[a] - 1) * dL[a][k];
  for (int e = 0; e < 6; ++e) {
    const int i = kEdge[e][0], j = kEdge[e][1];
    for (int k = 0; k < 3; ++k) g(4 + e, k) = 4 * (L[j] * dL[i][k] + L[i] * dL[j][k]);
  }
  return g;
}

struct QuadPoint {
  Eigen::Vector3d xi;
  double weight;  // weights sum to the reference volume 1/6
};

// Exact for polynomials of degree ≤ 2 (4 points).
const std::vector<QuadPoint>& quadrature_degree2();
// Exact for polynomials of degree ≤ 5 (14 points; Walkington, "Quadrature on simplices", 2000).
const std::vector<QuadPoint>& quadrature_degree5();

}  // namespace skinfem::p2
