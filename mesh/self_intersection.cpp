#include "skinfem/mesh/self_intersection.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <iterator>
#include <utility>
#include <vector>

namespace skinfem {

std::optional<Eigen::Vector3d> first_self_intersection(const SurfaceMesh& s) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Mesh = CGAL::Surface_mesh<K::Point_3>;
  Mesh m;
  std::vector<Mesh::Vertex_index> v;
  v.reserve(s.vertices.rows());
  for (int i = 0; i < s.vertices.rows(); ++i)
    v.push_back(m.add_vertex(K::Point_3(s.vertices(i, 0), s.vertices(i, 1), s.vertices(i, 2))));
  for (int t = 0; t < s.triangles.rows(); ++t)
    m.add_face(v[s.triangles(t, 0)], v[s.triangles(t, 1)], v[s.triangles(t, 2)]);
  std::vector<std::pair<Mesh::Face_index, Mesh::Face_index>> pairs;
  CGAL::Polygon_mesh_processing::self_intersections(m, std::back_inserter(pairs));
  if (pairs.empty()) return std::nullopt;
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (auto vd : m.vertices_around_face(m.halfedge(pairs.front().first))) {
    const auto& p = m.point(vd);
    c += Eigen::Vector3d(p.x(), p.y(), p.z()) / 3.0;
  }
  return c;
}

}  // namespace skinfem
