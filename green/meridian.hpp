// Axisymmetric skins solved on their meridian: the Green map of a sensor on the axis of a body of revolution
// (a flat layer's calibration sensor, a cap's apex) from one 2D solve instead of a 3D one (issue: model only
// what a scene needs).
//
// Fields are Fourier modes in the angle θ about the axis. A reading at the axis is a functional of one mode
// only: σ_z of mode 0 (u_r = U(r, z), u_z = W(r, z), p = P(r, z)), σ_x of mode 1 (u_r = U cos θ, u_θ = V sin
// θ, u_z = W cos θ, p = P cos θ; single-valued on the axis: W = 0, U + V = 0, P = 0). Each adjoint solve is
// the 3D one restricted to its mode: Taylor–Hood P2–P1 on the meridian, strains ε_rr = ∂_r U, ε_θθ = U/r,
// ε_zz = ∂_z W, 2ε_rz = ∂_z U + ∂_r W, every integral carrying 2πr (Zienkiewicz & Taylor, The Finite Element
// Method, vol. 1, axisymmetric stress analysis), U = 0 on the axis; mode 1 adds ε_θθ = (U + V)/r, γ_rθ = −U/r
// + ∂_r V − V/r, γ_θz = ∂_z V − W/r, and the angle integrates to π instead of 2π.
//
// The reading by reciprocity, as green/fe_green.hpp in 3D: the base traction's point value at the axis is
// t(0) = φ(0)ᵀ M⁻¹ R (R the base reactions, M the base trace's mass matrix, weight 2πr), i.e. J = w·R with
// w = M⁻¹ e_axis; imposing the base displacement −w (along z) with no load gives, at each top node, the
// reading per unit force there.
#pragma once

#include <Eigen/Dense>
#include <functional>
#include <vector>

#include "green/halfspace.hpp"

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

// The Green tensor of the point reading at the base on the axis (σ_z and σ_x, green/halfspace.hpp's
// GreenSample conventions) for a unit force on the top at offset (x, y) from the axis, 1/mm²: mode 0 gives
// the σ_z reading's adjoint (g_zz, g_xz), mode 1 the σ_x reading's (g_zx, g_xx). The side r = radius is
// traction-free.
class MeridianGreen {
 public:
  MeridianGreen(const MeridianMesh& mesh, double nu);
  // Offsets beyond the meridian's radius are clamped to it.
  green::GreenSample at(double x, double y) const;
  double zz(double rho) const { return interpolate(zz_, rho); }
  int dofs() const { return dofs_; }  // both modes' free DOFs

 private:
  // Quadratic along the top's edges, as the solution.
  double interpolate(const std::vector<double>& f, double rho) const;
  std::vector<double> r_;                       // top nodes by increasing r
  std::vector<double> zz_, u0_, w1_, u1_, v1_;  // g_zz; mode 0 U; mode 1 W, U, V at those nodes
  int dofs_ = 0;
};

}  // namespace skinfem
