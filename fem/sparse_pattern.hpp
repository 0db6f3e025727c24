// The sparsity of the Taylor–Hood blocks (fem/assembly.hpp), shared by the linear and the finite-strain
// assemblies: compressed column patterns built once from the mesh, filled element by element in place.
#pragma once

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <algorithm>
#include <vector>

#include "skinfem/mesh/tet_mesh.hpp"

namespace skinfem::pattern {

using SparseMatrixd = Eigen::SparseMatrix<double>;

// Node adjacency (sorted, including the node itself): the sparsity pattern of every P2 block.
inline std::vector<std::vector<int>> node_adjacency(const TetMesh& m) {
  std::vector<std::vector<int>> adj(m.num_nodes());
  for (int t = 0; t < m.num_tets(); ++t)
    for (int a = 0; a < 10; ++a)
      for (int b = 0; b < 10; ++b) adj[m.tets(t, a)].push_back(m.tets(t, b));
  for (auto& row : adj) {
    std::sort(row.begin(), row.end());
    row.erase(std::unique(row.begin(), row.end()), row.end());
  }
  return adj;
}

// Column-major matrix with rows_per_node × 3 blocks: column 3j + c holds rows
// rows_per_node·i + r for every i in adj[j] (restricted to i < row_limit).
inline SparseMatrixd block_pattern(const std::vector<std::vector<int>>& adj, int rows, int rows_per_node,
                                   int row_limit) {
  const int n = static_cast<int>(adj.size());
  std::vector<int> outer(3 * n + 1, 0);
  std::vector<int> inner;
  for (int j = 0; j < n; ++j) {
    const auto end = std::lower_bound(adj[j].begin(), adj[j].end(), row_limit);
    for (int c = 0; c < 3; ++c) {
      for (auto it = adj[j].begin(); it != end; ++it)
        for (int r = 0; r < rows_per_node; ++r) inner.push_back(rows_per_node * *it + r);
      outer[3 * j + c + 1] = static_cast<int>(inner.size());
    }
  }
  SparseMatrixd M(rows, 3 * n);
  M.resizeNonZeros(static_cast<Eigen::Index>(inner.size()));
  std::copy(outer.begin(), outer.end(), M.outerIndexPtr());
  std::copy(inner.begin(), inner.end(), M.innerIndexPtr());
  std::fill(M.valuePtr(), M.valuePtr() + inner.size(), 0.0);
  return M;
}

// Position of row index `row` in column `col` of a compressed matrix.
inline int slot(const SparseMatrixd& M, int row, int col) {
  const int* begin = M.innerIndexPtr() + M.outerIndexPtr()[col];
  const int* end = M.innerIndexPtr() + M.outerIndexPtr()[col + 1];
  return static_cast<int>(std::lower_bound(begin, end, row) - M.innerIndexPtr());
}

// Adds tet t's displacement block Ae (30×30, rows and columns 3a + i for its node a, component i) into A
// (3N×3N) and its pressure–displacement block Be (4×30, rows its vertices) into B (Nv×3N), both built on
// block_pattern.
inline void add_element(const TetMesh& m, int t, const Eigen::Matrix<double, 30, 30>& Ae,
                        const Eigen::Matrix<double, 4, 30>& Be, SparseMatrixd& A, SparseMatrixd& B) {
  for (int b = 0; b < 10; ++b) {
    const int nb = m.tets(t, b);
    for (int j = 0; j < 3; ++j) {
      const int col = 3 * nb + j;
      for (int a = 0; a < 10; ++a) {
        const int k = slot(A, 3 * m.tets(t, a), col);
        for (int i = 0; i < 3; ++i) A.valuePtr()[k + i] += Ae(3 * a + i, 3 * b + j);
      }
      for (int r = 0; r < 4; ++r) B.valuePtr()[slot(B, m.tets(t, r), col)] += Be(r, 3 * b + j);
    }
  }
}

}  // namespace skinfem::pattern
