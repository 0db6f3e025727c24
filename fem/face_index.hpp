// 2-D point location among boundary faces that form a graph over the (x, y) plane (the base, or the
// top of a cap or flat layer): a uniform bucket grid over the faces' corner triangles, its cell sized by the
// finer faces (a graded mesh's fine zone is where the loads are, so where most look-ups land), each face's
// inverse Jacobian computed once.
#pragma once

#include <vector>

#include "skinfem/mesh/tet_mesh.hpp"
#include "skinfem/scene/scene.hpp"

namespace skinfem {

class PlanarFaceIndex {
 public:
  // Keeps a reference to mesh, which must outlive the index (a temporary mesh does not compile).
  PlanarFaceIndex(const TetMesh& mesh, int marker);
  PlanarFaceIndex(TetMesh&&, int) = delete;

  // Mesh face index containing (x, y) and the face parameters (s, t) there; −1 when outside.
  // On curved faces (s, t) are those of the straight corner triangle (exact on flat faces). On a half_y
  // mesh a point at y < 0 is found at its mirror image (x, −y): the fields there are the symmetric ones, and
  // the caller flips what is odd in y (mirrored()).
  int find(double x, double y, double& s, double& t) const;
  // Whether find(x, y) looks up the mirror image (a half_y mesh, y < 0).
  bool mirrored(double y) const { return y < 0 && is_half_y(mesh_); }
  const std::vector<int>& faces() const { return faces_; }

 private:
  int bin(double v, double origin) const { return static_cast<int>((v - origin) / cell_); }
  struct Corner {  // a face's first corner and the inverse of its (b − a, c − a) Jacobian
    double ax, ay, i00, i01, i10, i11;
  };
  const TetMesh& mesh_;
  std::vector<int> faces_;
  std::vector<Corner> corners_;  // per entry of faces_
  double x0_ = 0, y0_ = 0, cell_ = 1;
  int nx_ = 1, ny_ = 1;
  std::vector<std::vector<int>> buckets_;  // entries of faces_
};

// The skin's thickness above the base point (x, y), mm: the exact top for caps and flat layers (a ridged one:
// its mean top, so that it compares with the smooth skin of equal mean thickness), else the
// height of the meshed top surface there (its quadratic faces), so imported skins get their own thickness.
// Throws std::out_of_range, naming the point, when no skin lies above it.
double skin_thickness(const Geometry& geometry, const TetMesh& mesh, double x, double y);
// The height of the meshed top surface above (x, y), mm; throws as skin_thickness.
double meshed_thickness(const TetMesh& mesh, double x, double y);

}  // namespace skinfem
