// Taylor–Hood P2–P1 assembly of incompressible (and compressible) linear elasticity.
//
// Unknowns: displacement u (P2, 3 per node, DOF 3·node + component) and pressure p (continuous P1,
// one per mesh vertex), with σ = 2μ ε(u) − p I and div u + p/λ = 0. The symmetric saddle-point system
//     [ A   Bᵀ ] [u]   [f]
//     [ B  −C  ] [p] = [g]
// has A = ∫ 2μ ε(u):ε(v) (3N×3N), B = −∫ q div u (Nv×3N), C = (1/λ) M_p, M_p = ∫ p q (Nv×Nv).
// Quadrature: 4-point degree-2 rule on straight-sided elements, where every integrand is a
// polynomial of degree ≤ 2 (exact); 14-point degree-5 rule on curved (isoparametric) ones.
#pragma once

#include <Eigen/Sparse>
#include <functional>

#include "skinfem/fem/material.hpp"
#include "skinfem/mesh/tet_mesh.hpp"

namespace skinfem {

using SparseMatrixd = Eigen::SparseMatrix<double>;

struct MixedMatrices {
  SparseMatrixd A;   // 3N×3N, MPa·mm
  SparseMatrixd B;   // Nv×3N, mm²
  SparseMatrixd Mp;  // Nv×Nv, mm³
};

MixedMatrices assemble_mixed(const TetMesh& mesh, const Lame& lame);

// The pressure mass M_p = ∫ p q over the reference mesh (Nv×Nv, mm³), on the same rules as assemble_mixed.
SparseMatrixd pressure_mass(const TetMesh& mesh);

// ∫ f·v over the volume for a body force density f(x) (N/mm³): a 3N load vector.
using VectorField = std::function<Eigen::Vector3d(const Eigen::Vector3d&)>;
Eigen::VectorXd body_load(const TetMesh& mesh, const VectorField& f);

// ∫ t·v over the boundary faces with one of `markers` for a traction t(x, n) (MPa; n the outward unit
// normal): a 3N load vector. Degree-5 7-point triangle rule on the quadratic faces.
using TractionField = std::function<Eigen::Vector3d(const Eigen::Vector3d& x, const Eigen::Vector3d& n)>;
Eigen::VectorXd traction_load(const TetMesh& mesh, int markers, const TractionField& t);

// ∫ t·v over the faces with one of `markers` for a traction given per node (N×3, MPa; rows of nodes
// off those faces are ignored), interpolated with the faces' quadratic shape functions.
Eigen::VectorXd nodal_traction_load(const TetMesh& mesh, int markers, const Eigen::MatrixX3d& traction);

// True when the element's mid-edge nodes sit at the midpoints of its straight edges.
bool is_affine(const TetMesh& mesh, int tet);

}  // namespace skinfem
