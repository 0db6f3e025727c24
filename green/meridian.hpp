// Axisymmetric skins solved on their meridian: the Green map of a sensor on the axis of a body of revolution
// (a flat layer's calibration sensor, a cap's apex) from one 2D solve instead of a 3D one (issue: model only
// what a scene needs).
//
// Fields are Fourier modes in the angle θ about the axis; mode 0 (u_r = U(r, z), u_z = W(r, z), p = P(r, z),
// no u_θ) carries everything an axisymmetric reading sees: the normal reading σ_z at the axis responds to a
// point force pressing at radius ρ exactly as to that force spread evenly over the circle of radius ρ. The
// solve is the 3D one restricted to that mode: Taylor–Hood P2–P1 on the meridian, strains ε_rr = ∂_r U,
// ε_θθ = U/r, ε_zz = ∂_z W, 2ε_rz = ∂_z U + ∂_r W, every integral carrying 2πr (Zienkiewicz & Taylor, The
// Finite Element Method, vol. 1, axisymmetric stress analysis), U = 0 on the axis.
//
// The reading by reciprocity, as green/fe_green.hpp in 3D: the base traction's point value at the axis is
// t(0) = φ(0)ᵀ M⁻¹ R (R the base reactions, M the base trace's mass matrix, weight 2πr), i.e. J = w·R with
// w = M⁻¹ e_axis; imposing the base displacement −w (along z) with no load gives, at each top node, the
// reading per unit force there.
#pragma once

#include <Eigen/Dense>
#include <functional>
#include <vector>

namespace skinfem {

// 6-node triangles on the meridian half-plane r ≥ 0: vertices 0–2, then mid-edge nodes of edges 01, 12, 20.
// Vertices are numbered first (P1 pressure indices).
struct MeridianMesh {
  Eigen::Matrix<double, Eigen::Dynamic, 2, Eigen::RowMajor> nodes;  // N×2: (r, z), mm
  Eigen::Matrix<int, Eigen::Dynamic, 6, Eigen::RowMajor> tris;      // T×6
  int num_vertices = 0;
  std::vector<int> base, top, axis;  // node indices on z = 0, on the top (both by increasing r), on r = 0
};

// The region 0 ≤ r ≤ radius, 0 ≤ z ≤ top(r) on a mapped nr × nz grid: r = radius·(e^{βs} − 1)/(e^β − 1)
// (s uniform, β the axis grading ≥ 0, so cells grow geometrically away from the axis where the reading is), z
// = top(r)·τ(t) with τ clustering toward the base and the top (τ = t − sin(2πt)·c/(2π), c the layer grading
// in [0, 1)). Mid-edge nodes follow the map, so those on the top lie on it exactly.
MeridianMesh meridian_mesh(const std::function<double(double)>& top, double radius, int nr, int nz,
                           double axis_grading, double layer_grading);

// The normal reading σ_z (point value at the base on the axis) per unit force pressing into the top at
// radius ρ: g_zz(ρ), 1/mm², the side r = radius traction-free.
class MeridianGreen {
 public:
  MeridianGreen(const MeridianMesh& mesh, double nu);
  // g_zz at radius rho on the top (quadratic along the top's edges; clamped to [0, radius]).
  double zz(double rho) const;
  int dofs() const { return dofs_; }

 private:
  std::vector<double> r_, g_;  // top nodes by increasing r, and g_zz there
  int dofs_ = 0;
};

}  // namespace skinfem
