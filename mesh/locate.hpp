// Point location in a 10-node tet mesh: CGAL AABB tree over the straight-sided tets, then Newton on
// the isoparametric map for the reference coordinates (exact also in curved boundary elements).
#pragma once

#include <memory>
#include <optional>

#include "skinfem/mesh/tet_mesh.hpp"

namespace skinfem {

struct Location {
  int tet = -1;
  Eigen::Vector3d xi;                 // reference coordinates (ξ, η, ζ)
  std::array<double, 4> barycentric;  // (1 − ξ − η − ζ, ξ, η, ζ)
};

class PointLocator {
 public:
  explicit PointLocator(const TetMesh& mesh);  // keeps a reference: the mesh must outlive it
  ~PointLocator();
  PointLocator(PointLocator&&) noexcept;

  // The element containing p (on a face or edge: any of the touching ones). Points outside the
  // mesh by less than `tolerance` (mm; default 1e-6 × mesh diameter) snap to the nearest element;
  // farther ones give nullopt.
  std::optional<Location> locate(const Eigen::Vector3d& p, double tolerance = -1) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace skinfem
