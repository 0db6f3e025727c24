// Quadrature on the quadratic (6-node) boundary triangles of a TetMesh.
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "mesh/tet_mesh.hpp"

namespace skinfem {

struct FacePoint {
  Eigen::Vector3d x;              // physical point, mm
  Eigen::Matrix<double, 6, 1> N;  // face shape functions there (node order of TetMesh::faces)
  Eigen::Vector3d normal;         // outward unit normal
  double weight;                  // quadrature weight × surface Jacobian, mm²
  double weight_xy;               // quadrature weight × Jacobian of the projection onto (x, y), mm²
  double s, t;                    // face parameters of the point
};

// Quadratic triangle shape functions at parameters (s, t): nodes 0, 1, 2, then edges 01, 12, 20.
Eigen::Matrix<double, 6, 1> triangle_shape(double s, double t);

// 7-point degree-5 rule (Dunavant) mapped onto face f.
std::vector<FacePoint> face_quadrature(const TetMesh& mesh, int f);

}  // namespace skinfem
