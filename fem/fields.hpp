// Post-processing of a mixed solution: stresses, probes anywhere, VTK fields. The stress is Cauchy's: σ = 2μ
// ε(u) − p I for the linear skin; for the finite-strain skin σ = J⁻¹ P Fᵀ = μ (B − I)/J − p I (B = F Fᵀ, F =
// I + ∇u, fem/neo_hookean.hpp), at the material point, fields on the reference mesh (warp by displacement_mm
// for the deformed skin).
#pragma once

#include <string>
#include <vector>

#include "skinfem/fem/material.hpp"
#include "skinfem/fem/mixed_solver.hpp"
#include "skinfem/mesh/locate.hpp"
#include "skinfem/mesh/tet_mesh.hpp"

namespace skinfem {

enum class StressMeasure { small_strain, neo_hookean };

// Stress (MPa) in element `tet` at reference point xi.
Eigen::Matrix3d element_stress(const TetMesh& mesh, const Lame& lame, const MixedSolution& x, int tet,
                               const Eigen::Vector3d& xi,
                               StressMeasure measure = StressMeasure::small_strain);

// Nodal stress by averaging the element values at each node over the elements sharing it: N×9, row-major
// components (xx, xy, xz, yx, …).
Eigen::Matrix<double, Eigen::Dynamic, 9, Eigen::RowMajor> recover_stress(
    const TetMesh& mesh, const Lame& lame, const MixedSolution& x,
    StressMeasure measure = StressMeasure::small_strain);

struct Probe {
  Eigen::Vector3d u;      // mm
  double p = 0;           // MPa
  Eigen::Matrix3d sigma;  // MPa, from the element that contains the point
};
// Throws std::out_of_range when the point is outside the mesh.
Probe probe(const TetMesh& mesh, const PointLocator& locator, const Lame& lame, const MixedSolution& x,
            const Eigen::Vector3d& point);

// fields.vtu: point data displacement_mm, pressure_MPa, stress_MPa (9), cell data von_mises_MPa.
void write_fields_vtu(const std::string& path, const TetMesh& mesh, const Lame& lame, const MixedSolution& x,
                      StressMeasure measure = StressMeasure::small_strain);

// The solution of a mirror-symmetric load on a half_y mesh, seen on the whole mesh mirror_half(half, &source)
// (mesh/mirror.hpp): u_y odd in y, u_x, u_z and p even.
MixedSolution mirrored_solution(const TetMesh& whole, const std::vector<int>& source,
                                const MixedSolution& half);

}  // namespace skinfem
