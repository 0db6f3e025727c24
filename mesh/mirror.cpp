#include "skinfem/mesh/mirror.hpp"

#include <stdexcept>
#include <vector>

namespace skinfem {

TetMesh mirror_half(const TetMesh& half, std::vector<int>* source) {
  if (!is_half_y(half)) throw std::invalid_argument("mirror_half: the mesh is not a half_y mesh");
  const int n = half.num_nodes(), nv = half.num_vertices;
  const auto on_cut = [&](int i) { return (half.node_marker(i) & kSymmetry) != 0; };
  int mirrored_vertices = 0, mirrored_mids = 0;
  for (int i = 0; i < n; ++i)
    if (!on_cut(i)) ++(i < nv ? mirrored_vertices : mirrored_mids);
  // New numbers: the half's vertices, their images, the half's mid-edge nodes, their images.
  std::vector<int> same(n), image(n);
  int next_vertex = nv, next_mid = nv + mirrored_vertices + (n - nv);
  for (int i = 0; i < n; ++i) {
    same[i] = i < nv ? i : i + mirrored_vertices;
    image[i] = on_cut(i) ? same[i] : i < nv ? next_vertex++ : next_mid++;
  }
  TetMesh m;
  m.num_vertices = nv + mirrored_vertices;
  m.nodes.resize(n + mirrored_vertices + mirrored_mids, 3);
  if (source) source->assign(m.nodes.rows(), -1);
  for (int i = 0; i < n; ++i) {
    if (source) (*source)[same[i]] = (*source)[image[i]] = i;
    m.nodes.row(same[i]) = half.nodes.row(i);
    m.nodes.row(image[i]) << half.nodes(i, 0), -half.nodes(i, 1), half.nodes(i, 2);
  }
  const int ne = half.tets.rows();
  m.tets.resize(2 * ne, 10);
  // The image of tet (0 1 2 3) is positively oriented as (0 2 1 3): its edges 01 12 02 03 13 23 are the
  // original's 02 12 01 03 23 13.
  constexpr int kImageOrder[10] = {0, 2, 1, 3, 6, 5, 4, 7, 9, 8};
  for (int t = 0; t < ne; ++t)
    for (int k = 0; k < 10; ++k) {
      m.tets(t, k) = same[half.tets(t, k)];
      m.tets(ne + t, k) = image[half.tets(t, kImageOrder[k])];
    }
  // Faces: all but the cut, and their images with the orientation reversed ((0 1 2) → (0 2 1)).
  constexpr int kReversed[6] = {0, 2, 1, 5, 4, 3};
  std::vector<int> kept;
  for (int f = 0; f < half.faces.rows(); ++f)
    if (half.face_marker(f) != kSymmetry) kept.push_back(f);
  const int nk = static_cast<int>(kept.size());
  m.faces.resize(2 * nk, 6);
  m.face_marker.resize(2 * nk);
  for (int i = 0; i < nk; ++i) {
    for (int k = 0; k < 6; ++k) {
      m.faces(i, k) = same[half.faces(kept[i], k)];
      m.faces(nk + i, k) = image[half.faces(kept[i], kReversed[k])];
    }
    m.face_marker(i) = m.face_marker(nk + i) = half.face_marker(kept[i]);
  }
  m.node_marker = Eigen::VectorXi::Zero(m.nodes.rows());
  for (int f = 0; f < m.faces.rows(); ++f)
    for (int k = 0; k < 6; ++k) m.node_marker(m.faces(f, k)) |= m.face_marker(f);
  m.straightened = 2 * half.straightened;
  return m;
}

}  // namespace skinfem
