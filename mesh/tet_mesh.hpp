// The volume mesh every later stage works on: 10-node (quadratic) tetrahedra.
#pragma once

#include <Eigen/Dense>
#include <vector>

namespace skinfem {

// Boundary parts; a face carries exactly one, a node the OR of those of its faces.
// kSymmetry: the cut y = 0 of a mirror-symmetric scene meshed as its half y ≥ 0 (MeshPart::half_y).
// kPost: the wall and top of a post sensor standing on the base (held like the base; scene.hpp's PostSensor).
enum BoundaryMarker : int { kBase = 1, kTop = 2, kSide = 4, kSymmetry = 16, kPost = 32 };
// Extra bit on SurfaceMesh markers only: a region whose outline TetGen must keep (a punch disc).
inline constexpr int kKeepOutline = 8;

// What of the skin is meshed: all of it, or the half y ≥ 0 of a scene symmetric about the plane y = 0.
enum class MeshPart { whole, half_y };

using RowMatrixX3d = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
using RowMatrixX3i = Eigen::Matrix<int, Eigen::Dynamic, 3, Eigen::RowMajor>;
using RowMatrixX6i = Eigen::Matrix<int, Eigen::Dynamic, 6, Eigen::RowMajor>;
using RowMatrixX10i = Eigen::Matrix<int, Eigen::Dynamic, 10, Eigen::RowMajor>;

// Node numbering follows VTK_QUADRATIC_TETRA / VTK_QUADRATIC_TRIANGLE so export is a copy:
//   tet:      vertices 0–3, then mid-edge nodes of edges 01, 12, 02, 03, 13, 23;
//   triangle: vertices 0–2, then mid-edge nodes of edges 01, 12, 20.
// Vertices (corner nodes) are numbered first, 0 … num_vertices−1, so they double as P1 indices.
// Mid-edge nodes on a curved boundary lie on the exact surface (isoparametric P2 geometry).
struct TetMesh {
  RowMatrixX3d nodes;               // N×3, mm
  int num_vertices = 0;             // corner nodes are nodes.row(0 … num_vertices−1)
  RowMatrixX10i tets;               // E×10, positively oriented (det J > 0)
  RowMatrixX6i faces;               // F×6 boundary triangles, outward normal (right-hand rule)
  Eigen::VectorXi face_marker;      // F: one BoundaryMarker
  Eigen::VectorXi node_marker;      // N: OR of BoundaryMarker of the faces touching the node, 0 inside
  MeshPart part = MeshPart::whole;  // half_y: the cut y = 0 is marked kSymmetry
  int straightened = 0;  // elements given straight edges because curving folded them (mesh/build.hpp)

  int num_nodes() const { return static_cast<int>(nodes.rows()); }
  int num_tets() const { return static_cast<int>(tets.rows()); }
};

// Whether the mesh is the half y ≥ 0 of a mirror-symmetric skin (it has a kSymmetry cut). Fields on it are
// the symmetric ones: at (x, −y), u_x, u_z and the base traction's x, z components are those at (x, y).
inline bool is_half_y(const TetMesh& m) { return m.part == MeshPart::half_y; }

// A closed triangulated boundary surface, outward oriented (input to tetrahedralization).
struct SurfaceMesh {
  RowMatrixX3d vertices;   // V×3, mm
  RowMatrixX3i triangles;  // T×3
  Eigen::VectorXi marker;  // T: BoundaryMarker
};

}  // namespace skinfem
