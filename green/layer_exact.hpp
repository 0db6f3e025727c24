// Exact Green tensor at the base of a flat elastic layer bonded to a rigid base, by Hankel transforms.
//
// Geometry: layer 0 < z < h, displacement u = 0 on the base z = 0, top z = h traction-free except for the
// applied load. Linear isotropic elasticity, any 0 ≤ nu ≤ 0.5 (nu = 0.5 is the incompressible limit and needs
// no special case).
//
// What LayerGreen::at(x, y) returns: the point values of the four readings (halfspace.hpp, GreenSample) on
// the base z = 0, per unit total force of the load centred at the offset (x, y) = load centre − sensor
// position, units 1/mm²: zz = −σ_zz and zx = σ_xz for a load pressing into the skin, xz = −σ_zz and xx = σ_xz
// for a load along +x. They do not depend on the Young modulus. at_depth(x, y, d) returns the same quantities
// on the plane z = h − d inside the layer.
//
// Load model (unit total force, axisymmetric radial distribution q(r) around the load centre; the normal load
// presses along −e_z, the tangential load is a shear traction along +x with the same q(r)):
//   point   : q = δ(r)                               Hankel profile L(s) = 1
//   uniform : q = 1/(πa²) for r < a                  L(s) = 2 J1(sa)/(sa)
//   punch   : q = 1/(2πa√(a² − r²)) for r < a        L(s) = sin(sa)/(sa)    (rigid flat punch on a
//   half-space)
// with L(s) = 2π ∫ q(r) J0(sr) r dr.
//
// Formulation (layer_exact.cpp has the derivation): each horizontal wavenumber s decouples into an in-plane
// (P-SV) problem, solved with the Papkovich–Neuber potentials 2μu = 4(1−ν)ψ_z e_z − ∇(zψ_z + φ), ψ_z and φ
// harmonic (J. R. Barber, Elasticity, Springer, the Papkovich–Neuber and Boussinesq-potential chapters;
// layered solutions of this kind go back to D. M. Burmister, J. Appl. Phys. 16 (1945) 89, and I. N. Sneddon,
// Fourier Transforms, McGraw-Hill 1951), and an antiplane (SH) problem. The base transfer functions have
// closed forms for every nu; at other depths the 4×4 boundary-value system is solved per wavenumber (Eigen),
// which also cross-checks the closed forms. The spatial tensor follows from Hankel transforms of orders 0, 1,
// 2:
//   g_zz = (1/2π) ∫ L N_zz J0(sr) s ds,             g_zx =  (x/r)(1/2π) ∫ L N_xz J1(sr) s ds,
//   g_xz = −(x/r)(1/2π) ∫ L T_zz J1(sr) s ds,        g_xx = (1/2π) ∫ L [ (T_xz + C)/2 J0 − cos2θ (T_xz − C)/2
//   J2 ] s ds,
// cos2θ = (x² − y²)/r². The kernels decay like exp(−s·d) (d the depth below the loaded top), so [0, s_max =
// 45/d] is integrated with composite 16-point Gauss–Legendre panels that resolve both the kernel (whose
// nearest complex pole lies ≥ 0.73/h from the real axis) and the Bessel oscillation: the result is accurate
// to roundoff level (≲ 1e-12 of g_zz(0)).
#pragma once

#include <optional>
#include <vector>

#include "skinfem/green/halfspace.hpp"

namespace skinfem::green {

enum class LayerLoad { point, punch, uniform };

/// Quadrature controls (defaults give roundoff-level accuracy; tests halve the panels to show convergence).
struct LayerQuadrature {
  double panel_scale = 1.0;   ///< multiplies every panel width (0.5 doubles the resolution)
  double s_max_depth = 45.0;  ///< truncation s_max = s_max_depth / depth
};

/// Per-wavenumber transfer functions: the stresses on a horizontal plane for a unit-amplitude harmonic
/// traction on the top. Normal load σ_zz(h) = cos(sx): σ_zz = nzz cos(sx), σ_xz = nxz sin(sx). Longitudinal
/// shear σ_xz(h) = sin(sx): σ_zz = tzz cos(sx), σ_xz = txz sin(sx). Transverse (antiplane) shear σ_yz(h) =
/// cos(sx): σ_yz = sh cos(sx).
struct LayerKernels {
  double nzz = 0;
  double nxz = 0;
  double tzz = 0;
  double txz = 0;
  double sh = 0;
};

class LayerGreen {
 public:
  /// h > 0 layer thickness [mm], 0 ≤ nu ≤ 0.5, load model and radius a [mm] (ignored for the point load, > 0
  /// otherwise). sensor_radius b > 0: the readings are means over the sensor disc of radius b instead of
  /// point values. Averaging any 2D Fourier mode e^{ik·x} over a disc multiplies it by 2J1(|k|b)/(|k|b)
  /// (Graf's addition theorem), so the disc mean is the same Hankel integral with that factor in the load
  /// profile.
  LayerGreen(double h, double nu, LayerLoad load = LayerLoad::point, double load_radius = 0,
             LayerQuadrature quadrature = {}, double sensor_radius = 0);

  /// Readings at the base for the load centred at offset (x, y) (force − sensor), per unit force, 1/mm².
  GreenSample at(double x, double y) const;
  /// at(x, y).zz alone, bit for bit, at half the cost (J0 only): what a thickness fit on g_zz evaluates.
  double zz_at(double x, double y) const;
  /// The same quantities on the plane at `depth` (0 < depth ≤ h) below the loaded top surface.
  GreenSample at_depth(double x, double y, double depth) const;

  double thickness() const { return h_; }
  double poisson_ratio() const { return nu_; }
  LayerLoad load() const { return load_; }
  double load_radius() const { return a_; }
  /// Hankel-space load profile L(s), times the sensor disc's factor.
  double load_profile(double s) const;

  /// Closed-form base kernels (z = 0) as functions of t = s·h.
  static LayerKernels base_kernels(double t, double nu);
  /// Kernels on the plane at height z (0 ≤ z ≤ h) from the 4×4 per-wavenumber linear system.
  static LayerKernels depth_kernels(double s, double h, double z, double nu);

 private:
  struct NodeSet {
    double r_cover = 0;  // valid for radial offsets r ≤ r_cover
    std::vector<double> s;
    std::vector<double> c_zz, c_zx, c_xz, c_xx0, c_xx2;  // weight·s/(2π)·L·kernel
  };
  std::vector<double> panel_nodes(double r, double depth, std::vector<double>* weights) const;
  // Nodes and kernel-weighted coefficients for offsets r ≤ r_cover on the plane at `depth`; closed_form
  // selects base_kernels (only meaningful at depth = h) instead of depth_kernels.
  NodeSet build(double r_cover, double depth, bool closed_form) const;
  static GreenSample evaluate(const NodeSet& n, double x, double y);
  static double evaluate_zz(const NodeSet& n, double r);
  const NodeSet& nodes_for(double r, std::optional<NodeSet>& far) const;

  double h_, nu_;
  LayerLoad load_;
  double a_;
  LayerQuadrature quad_;
  double b_;                     // sensor disc radius, 0 for point readings
  std::vector<NodeSet> levels_;  // r_cover = h·2^ℓ
};

}  // namespace skinfem::green
