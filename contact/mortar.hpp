// Mortar (weak) non-penetration between the skin's top and a rigid indenter, right for P2 faces.
//
// The contact pressure is p(x, y) = Σ_i λ_i ψ_i(x, y): ψ_i the piecewise-linear hat of top vertex i over
// the corner triangles of the quadratic top faces, one multiplier λ_i (MPa, the nodal pressure) per top
// vertex of the candidate zone. Its load on the P2 displacement nodes is f_j = −∫ p φ_j e_z (and the
// friction traction μ p along the sliding direction), and the constraint of vertex i is the weighted gap
// g_i = ∫ ψ_i gap ≥ 0. Testing a quadratic trace against linear multipliers is inf-sup stable and never
// asks a P2 vertex to carry the load alone: a uniform pressure gives the consistent P2 load, which is zero
// at the vertices, so node-to-surface contact on P2 nodes would misbehave (tests/contact/test_mortar.cpp).
// Integrals are over the projection onto the (x, y) plane: the indenter moves along z, and its pressure is
// force per unit horizontal area, so Σ_i λ_i ∫ψ_i = F exactly.
#pragma once

#include <Eigen/Sparse>
#include <functional>
#include <vector>

#include "skinfem/mesh/tet_mesh.hpp"
#include "skinfem/scene/scene.hpp"

namespace skinfem::contact {

struct MortarZone {
  std::vector<int> vertices;  // n_c top corner nodes carrying a multiplier (mesh node ids)
  std::vector<int> faces;     // top faces touching any of them
  // D(i, node) = ∫ ψ_i φ_node dx dy: n_c × N, mm². The load of multipliers λ along unit vector e is
  // −(Dᵀ λ) ⊗ e for pressure (e = e_z pushes down) and (Dᵀ λ) ⊗ e_t for a traction along e_t.
  Eigen::SparseMatrix<double, Eigen::RowMajor> D;
  Eigen::VectorXd area;  // n_c: ∫ ψ_i dx dy, mm²

  int size() const { return static_cast<int>(vertices.size()); }
  // ∫ ψ_i f(x) dx dy for every multiplier, f evaluated at the physical (curved) top point.
  Eigen::VectorXd weighted(const TetMesh& mesh, const std::function<double(const Eigen::Vector3d&)>& f) const;
  // A sphere (centre c, radius R, mm) against the displaced top x + u_h(x) (u: 3N, mm): the weighted normal
  // gaps g_i = ∫ ψ_i (|x + u_h − c| − R), their derivative Dn (n_c × 3N: ∫ ψ_i φ_node n, n the sphere's
  // outward normal (x + u_h − c)/|x + u_h − c| at the displaced point; the load of pressures λ along it is
  // Dnᵀ λ) and m_i = ∫ ψ_i (−n_z), by which gap i closes per mm the sphere descends (contact/finite_contact).
  // With pressures `lambda` (n_c, MPa) also the load's derivative G = ∂(Dnᵀ λ)/∂u = Σ λ_i ∫ ψ_i φ_a φ_b
  // (I − n nᵀ)/|x + u_h − c| (3N × 3N, symmetric: the normals turn as the surface moves over the sphere).
  // With a sliding direction t (unit, in the (x, y) plane) also Dt (n_c × 3N: ∫ ψ_i φ_node s, s the sphere's
  // unit tangent at the displaced point in the plane of t and n, s ∝ t − (t·n) n: a friction traction
  // ratio·λ along s has the load ratio·Dtᵀ λ, whose downward part is ratio·mtᵀ λ, mt_i = ∫ ψ_i (−s_z)).
  struct SphereGaps {
    Eigen::VectorXd g, m, mt;
    Eigen::SparseMatrix<double> Dn, G, Dt;
  };
  SphereGaps sphere_gaps(const TetMesh& mesh, const Eigen::VectorXd& u, const Eigen::Vector3d& c, double R,
                         const Eigen::VectorXd* lambda = nullptr,
                         const Eigen::Vector2d* sliding = nullptr) const;
  // 3N load vector of multipliers λ: traction −Σλψ e_z + t_dir·(ratio Σλψ + Σ shear_i ψ) (t_dir in the
  // (x, y) plane; shear: empty or n_c nodal values, MPa).
  Eigen::VectorXd load(const Eigen::VectorXd& lambda, const Eigen::Vector2d& t_dir, double ratio,
                       const Eigen::VectorXd& shear = {}) const;
};

// Multipliers at the top vertices with (x, y) within `radius` of `center` (excluding vertices on the side).
MortarZone mortar_zone(const TetMesh& mesh, const Vec2& center, double radius);

}  // namespace skinfem::contact
