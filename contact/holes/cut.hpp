// A hole that cuts the multipliers' hats on its exact disc (docs/contact.md, "Hole sweep").
//
// Removing the multipliers whose vertex lies in the hole makes the signal jump whenever a vertex enters or
// leaves it. Here the pressure is p = Σ λ_i ψ_i (1 − 1_H) and the constraint of multiplier i is the weighted
// gap over its hat outside the hole, ∫ψ_i (1 − 1_H) gap ≥ 0: both the load and the constraint of
// multiplier i become D_i − B_i with B(i, k) = ∫_H ψ_i φ_k, which varies continuously with the hole's centre,
// and a multiplier whose hat the hole covers entirely drops out with a row that has shrunk to zero.
//
// The condensed problem then needs, besides C_zz and C_zt (contact/condensed.hpp), how the skin answers a
// load at the P2 nodes a hole can reach ("watched" nodes, n_w): the multipliers' displacements there, the
// nodes' own compliances (one block of n_w more FE solves) and the sensor adjoints there. With them, every
// cut matrix is a low-rank correction of the hole-free one:
//   C_zz' = C_zz − B Wz − Wzᵀ Bᵀ + B Gzz Bᵀ,
//   C_zt' = C_zt − Utᵀ Bᵀ − B DtGᵀ + B Gtzᵀ Bᵀ,
//   S_p'  = S_p − (B Rz)ᵀ,   S_t' = S_t − (B Rt)ᵀ,   gap0' = gap0 − ∫_H ψ (z_touch + φ − s),  area' = area −
//   ∫_H ψ,
// (shapes below). The hole's integrals use the disc as a polygon of kHoleSides sides with its area (a
// groove: its rectangle), clipped against the straight projection of each face and integrated with the
// curved face's Jacobian by the same degree-5 rule as D, so a face the hole covers entirely removes exactly
// its part of D.
#pragma once

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <array>
#include <memory>
#include <vector>

#include "skinfem/contact/indenter.hpp"
#include "skinfem/contact/mortar.hpp"

namespace skinfem::contact {

struct PathCompliance {
  // Faces a hole can reach: the 6 nodes' (x, y, z), mm, their watched indices, the corner multipliers
  // (zone-local, −1 if none).
  struct Face {
    std::array<Eigen::Vector3d, 6> x;
    std::array<int, 6> watched;
    std::array<int, 3> multiplier;
  };
  std::vector<Face> faces;
  std::vector<int> nodes;                    // n_w watched mesh nodes
  std::shared_ptr<const Indenter> indenter;  // for the gap under the hole
  Eigen::MatrixXd Wz;      // n_w × n_c: downward u_z at node k under multiplier j's pressure, mm/MPa
  Eigen::MatrixXd Ut;      // n_w × n_c: u_t (sliding direction) at node k under multiplier j's pressure
  Eigen::MatrixXd Gzz;     // n_w × n_w: downward u_z at k under a unit downward force at l, mm/N
  Eigen::MatrixXd Gtz;     // n_w × n_w: u_t at k under a unit downward force at l
  Eigen::MatrixXd DtG;     // n_c × n_w: ∫ψ_j u_t under a unit downward force at l, mm³/N
  Eigen::MatrixXd Rz, Rt;  // n_w × 2·sensors: readings under a unit downward / sliding-direction force at k
  // D on the watched nodes (n_c × n_w), and per multiplier whether its whole hat lies on watched faces:
  // then its cut row D_i − B_i is known node by node and its cut rows are computed from it directly (no
  // cancellation when the hole leaves only a sliver of the hat).
  Eigen::SparseMatrix<double, Eigen::RowMajor> Dw;
  std::vector<char> watched_hat;
  int block_solves = 0;
};

// The top faces of `zone` within `reach` (mm, in the (x, y) plane) of the segment from → to: where a hole
// of radius ≤ reach swept along it can cut (condense watches their P2 nodes).
std::vector<int> watch_path(const TetMesh& mesh, const MortarZone& zone, const Vec2& from, const Vec2& to,
                            double reach);

struct HoleCut {
  Eigen::SparseMatrix<double, Eigen::RowMajor> B;  // n_c × n_w: ∫_H ψ_i φ_k, mm²
  Eigen::VectorXd area;                            // n_c: ∫_H ψ_i, mm²
  Eigen::VectorXd gap0;                            // n_c: ∫_H ψ_i (z_touch + φ − s), mm³
};

// The cut of a hole (disc `hole`) on the watched faces; n_c = the zone's multipliers.
HoleCut hole_cut(const PathCompliance& path, int n_c, const Hole& hole);

}  // namespace skinfem::contact
