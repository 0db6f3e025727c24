#include "skinfem/mesh/quality.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>

#include "skinfem/mesh/p2_tet.hpp"
#include "skinfem/mesh/surface.hpp"

namespace skinfem {

namespace {
Eigen::Vector3d vertex(const TetMesh& m, int t, int k) { return m.nodes.row(m.tets(t, k)).transpose(); }
}  // namespace

double tet_volume(const TetMesh& m, int t) {
  const Eigen::Vector3d a = vertex(m, t, 0);
  return (vertex(m, t, 1) - a).cross(vertex(m, t, 2) - a).dot(vertex(m, t, 3) - a) / 6.0;
}

double tet_longest_edge(const TetMesh& m, int t) {
  double l = 0;
  for (const auto& e : p2::kEdge) l = std::max(l, (vertex(m, t, e[0]) - vertex(m, t, e[1])).norm());
  return l;
}

Eigen::Matrix3d tet_jacobian(const TetMesh& m, int t, const Eigen::Vector3d& xi) {
  const p2::Grad10 g = p2::shape_gradient(xi);
  Eigen::Matrix3d J = Eigen::Matrix3d::Zero();
  for (int a = 0; a < 10; ++a) J += m.nodes.row(m.tets(t, a)).transpose() * g.row(a);
  return J;
}

MeshQuality assess_quality(const TetMesh& m) {
  MeshQuality q;
  q.nodes = m.num_nodes();
  q.vertices = m.num_vertices;
  q.elements = m.num_tets();
  q.boundary_faces = m.faces.rows();
  q.min_dihedral_deg = 180;
  q.min_edge_mm = std::numeric_limits<double>::infinity();
  q.min_jacobian_ratio = std::numeric_limits<double>::infinity();
  const auto& rule = p2::quadrature_degree5();
  for (int t = 0; t < m.num_tets(); ++t) {
    Eigen::Vector3d p[4];
    for (int k = 0; k < 4; ++k) p[k] = vertex(m, t, k);
    double shortest = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        const double l = (p[i] - p[j]).norm();
        shortest = std::min(shortest, l);
        q.min_edge_mm = std::min(q.min_edge_mm, l);
        q.max_edge_mm = std::max(q.max_edge_mm, l);
        // the two vertices off edge ij span the faces whose angle is the dihedral at ij
        int k = 0;
        while (k == i || k == j) ++k;
        const int l2 = 6 - i - j - k;
        const Eigen::Vector3d e = p[j] - p[i];
        const Eigen::Vector3d n1 = e.cross(p[k] - p[i]), n2 = e.cross(p[l2] - p[i]);
        const double angle =
            std::acos(std::clamp(n1.dot(n2) / (n1.norm() * n2.norm()), -1.0, 1.0)) * 180.0 / M_PI;
        q.min_dihedral_deg = std::min(q.min_dihedral_deg, angle);
        q.max_dihedral_deg = std::max(q.max_dihedral_deg, angle);
      }
    // circumcentre c: 2 (p_i − p_0)·c = |p_i − p_0|², relative to p_0
    Eigen::Matrix3d A;
    Eigen::Vector3d b;
    for (int i = 1; i < 4; ++i) {
      A.row(i - 1) = 2 * (p[i] - p[0]).transpose();
      b[i - 1] = (p[i] - p[0]).squaredNorm();
    }
    q.max_radius_edge = std::max(q.max_radius_edge, A.fullPivLu().solve(b).norm() / shortest);

    const double v = tet_volume(m, t);
    q.linear_volume_mm3 += v;
    for (const auto& qp : rule) {
      const double det = tet_jacobian(m, t, qp.xi).determinant();
      q.volume_mm3 += qp.weight * det;
      q.min_jacobian_ratio = std::min(q.min_jacobian_ratio, det / (6 * v));
    }
  }
  return q;
}

bool folded(const TetMesh& m, int t) {
  static const Eigen::Vector3d kVertices[4] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  double worst = tet_volume(m, t);
  for (const auto& xi : kVertices) worst = std::min(worst, tet_jacobian(m, t, xi).determinant());
  for (const auto& qp : p2::quadrature_degree5())
    worst = std::min(worst, tet_jacobian(m, t, qp.xi).determinant());
  return !(worst > 0);
}

void check_no_inverted_element(const TetMesh& m) {
  for (int t = 0; t < m.num_tets(); ++t) {
    if (!folded(m, t)) continue;
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int k = 0; k < 4; ++k) c += 0.25 * vertex(m, t, k);
    char where[96];
    std::snprintf(where, sizeof where, "(%.3f, %.3f, %.3f) mm", c.x(), c.y(), c.z());
    throw MeshError(
        "element " + std::to_string(t) + " near " + where +
        " is inverted (det J <= 0: snapped onto the curved top, its nodes fold it); the mesh does not "
        "fit the surface there: change mesh.h_min / mesh.h_max (finer where the top is steep or "
        "strongly curved), or cut the cap farther inside its rim");
  }
}

}  // namespace skinfem
