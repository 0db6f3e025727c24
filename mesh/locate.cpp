#include "skinfem/mesh/locate.hpp"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <Eigen/LU>
#include <algorithm>
#include <vector>

#include "skinfem/mesh/p2_tet.hpp"
#include "skinfem/mesh/quality.hpp"

namespace skinfem {

namespace {
using K = CGAL::Exact_predicates_inexact_constructions_kernel;

struct TetPrimitive {
  using Id = int;
  using Point = K::Point_3;
  using Datum = K::Tetrahedron_3;
  TetPrimitive() = default;
  TetPrimitive(int id, const Datum& tet) : id_(id), tet_(tet) {}
  // AABB_tree builds primitives from the iterators of the range it is given
  template <class Iterator>
  explicit TetPrimitive(Iterator it) : id_(it->id_), tet_(it->tet_) {}
  Id id() const { return id_; }
  Datum datum() const { return tet_; }
  Point reference_point() const { return tet_.vertex(0); }
  int id_ = -1;
  Datum tet_;
};
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, TetPrimitive>>;

// Reference coordinates of p in element t: start from the straight-sided tet, then Newton on x(ξ) = p.
Eigen::Vector3d reference_coordinates(const TetMesh& m, int t, const Eigen::Vector3d& p) {
  const Eigen::Vector3d a = m.nodes.row(m.tets(t, 0)).transpose();
  Eigen::Matrix3d A;
  for (int k = 0; k < 3; ++k) A.col(k) = m.nodes.row(m.tets(t, k + 1)).transpose() - a;
  Eigen::Vector3d xi = A.fullPivLu().solve(p - a);
  for (int it = 0; it < 8; ++it) {
    const p2::Vec10 n = p2::shape(xi);
    Eigen::Vector3d x = Eigen::Vector3d::Zero();
    for (int k = 0; k < 10; ++k) x += n[k] * m.nodes.row(m.tets(t, k)).transpose();
    const Eigen::Vector3d step = tet_jacobian(m, t, xi).fullPivLu().solve(p - x);
    xi += step;
    if (step.norm() < 1e-14) break;
  }
  return xi;
}
}  // namespace

struct PointLocator::Impl {
  const TetMesh& mesh;
  Tree tree;
  double diameter;
  double bulge;  // largest distance of a mid-edge node from its straight edge's midpoint
};

PointLocator::PointLocator(const TetMesh& mesh) {
  std::vector<TetPrimitive> prims;
  prims.reserve(mesh.num_tets());
  auto pt = [&](int t, int k) {
    return K::Point_3(mesh.nodes(mesh.tets(t, k), 0), mesh.nodes(mesh.tets(t, k), 1),
                      mesh.nodes(mesh.tets(t, k), 2));
  };
  for (int t = 0; t < mesh.num_tets(); ++t)
    prims.emplace_back(t, K::Tetrahedron_3(pt(t, 0), pt(t, 1), pt(t, 2), pt(t, 3)));
  const double diameter = (mesh.nodes.colwise().maxCoeff() - mesh.nodes.colwise().minCoeff()).norm();
  double bulge = 0;
  for (int t = 0; t < mesh.num_tets(); ++t)
    for (int e = 0; e < 6; ++e) {
      const auto mid = 0.5 * (mesh.nodes.row(mesh.tets(t, p2::kEdge[e][0])) +
                              mesh.nodes.row(mesh.tets(t, p2::kEdge[e][1])));
      bulge = std::max(bulge, (mesh.nodes.row(mesh.tets(t, 4 + e)) - mid).norm());
    }
  impl_.reset(new Impl{mesh, Tree(prims.begin(), prims.end()), diameter, bulge});
}

PointLocator::~PointLocator() = default;
PointLocator::PointLocator(PointLocator&&) noexcept = default;

std::optional<Location> PointLocator::locate(const Eigen::Vector3d& p, double tolerance) const {
  if (tolerance < 0) tolerance = 1e-6 * impl_->diameter;
  // Candidates: every element whose straight-sided box is within the tolerance plus the largest
  // bulge of a curved edge (a P2 element reaches at most about that far beyond its box).
  const double margin = tolerance + 2 * impl_->bulge;
  const CGAL::Bbox_3 box(p.x() - margin, p.y() - margin, p.z() - margin, p.x() + margin, p.y() + margin,
                         p.z() + margin);
  std::vector<int> candidates;
  impl_->tree.all_intersected_primitives(box, std::back_inserter(candidates));
  std::sort(candidates.begin(), candidates.end());  // deterministic choice among ties
  std::optional<Location> best;
  double best_score = -1e300;
  for (int t : candidates) {
    const Eigen::Vector3d xi = reference_coordinates(impl_->mesh, t, p);
    const auto L = p2::barycentric(xi);
    const double score = *std::min_element(L.begin(), L.end());  // ≥ 0 inside
    if (score > best_score) {
      best_score = score;
      best = Location{t, xi, L};
    }
    if (score >= 0) break;
  }
  if (!best) return std::nullopt;
  if (best_score < 0) {
    // outside every candidate: accept only within the tolerance, measured in mm
    const double scale = tet_longest_edge(impl_->mesh, best->tet);
    if (-best_score * scale > tolerance) return std::nullopt;
  }
  return best;
}

}  // namespace skinfem
