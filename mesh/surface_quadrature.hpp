// Quadrature on the quadratic (6-node) boundary triangles of a TetMesh.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <vector>

#include "skinfem/mesh/tet_mesh.hpp"

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
// Their derivatives with respect to s and t.
void triangle_shape_gradient(double s, double t, double ds[6], double dt[6]);

// Dunavant's 7-point degree-5 rule on the reference triangle 0 ≤ s, t, s + t ≤ 1: (s, t, weight), the weights
// summing to 1 (multiply by the area).
struct TrianglePoint {
  double s, t, w;
};
const std::array<TrianglePoint, 7>& triangle_rule_degree5();

// 7-point degree-5 rule (Dunavant) mapped onto face f.
std::vector<FacePoint> face_quadrature(const TetMesh& mesh, int f);

// The same rule on the part of face f whose projection on (x, y) lies in the disc |(x, y) − centre| ≤
// radius (mm): where the disc's edge crosses the face, its parameter triangle is split into four, again and
// again, down to pieces of min_size (mm, across their projection), whose points then count when inside. A
// load spread over a disc is then integrated exactly on every face inside it (degree 5 on a flat face), so a
// uniform pressure on a flat layer is the hydrostatic state's load to round-off away from the disc's edge,
// which a rule over the disc (points dropped into whatever face holds them) is not.
std::vector<FacePoint> face_quadrature_in_disc(const TetMesh& mesh, int f, const Eigen::Vector2d& centre,
                                               double radius, double min_size);

}  // namespace skinfem
