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
// The reading by reciprocity, as green/fe_green.hpp in 3D: a reading of the base traction is J = w·R (R the
// base reactions) with w = M⁻¹ b (M the base trace's mass matrix, weight 2πr): b_i = ∫_disc φ_i dA / (πa²)
// for a disc mean; imposing the base displacement −w (along z) with no load gives, at each top node, the
// reading per unit force there. The point value at the axis is the limit of disc means, extrapolated from
// two small discs (a = h/40, h/20; meridian_reading.cpp, disc_weights): the trace's own axis value, b =
// e_axis, converges as a point value does, 20-40x less accurately.
#pragma once

#include <Eigen/Dense>
#include <functional>
#include <vector>

#include "skinfem/fem/sensor_reading.hpp"
#include "skinfem/green/halfspace.hpp"
#include "skinfem/green/layer_exact.hpp"
#include "skinfem/scene/scene.hpp"

namespace skinfem {

// 6-node triangles on the meridian half-plane r ≥ 0: vertices 0–2, then mid-edge nodes of edges 01, 12, 20.
// Vertices are numbered first (P1 pressure indices).
struct MeridianMesh {
  Eigen::Matrix<double, Eigen::Dynamic, 2, Eigen::RowMajor> nodes;  // N×2: (r, z), mm
  Eigen::Matrix<int, Eigen::Dynamic, 6, Eigen::RowMajor> tris;      // T×6
  int num_vertices = 0;
  // Node indices on z = 0 and on the top (both by increasing r), on the axis r = 0 and on the side r =
  // radius; with a post, `base` starts outside it and `post` holds its wall and top (with the foot's corner).
  std::vector<int> base, top, axis, side, post;
  double post_radius = 0, post_height = 0;  // mm; 0: no post
};

// Cell sizes of a meridian mesh. Radially, cells grow geometrically from the axis, where the reading is, up
// to a cap; across the thickness they cluster toward the base and the top (τ = t − c·sin(2πt)/(2π), c the
// layer grading in [0, 1)).
struct MeridianSizes {
  double axis_cell = 0.05;  // mm, radial size of the cells at the axis
  double growth = 1.1;      // ratio of neighbouring cells' radial sizes, >= 1
  double max_cell = 2.0;    // mm, cap on the radial size
  int layers = 36;          // cells across the thickness
  double layer_grading = 0.5;
  // For a skin of thickness h: h/60 at the axis, growing ×1.1 up to 2h/3, 36 layers, which gives the flat
  // layer's k_central and k_lsq_line within 4e-5 of the exact layer's (measured: tests/green/test_meridian);
  // `scale` > 1 coarsens every size by it (sizes × scale, growth^scale, layers / scale).
  static MeridianSizes for_thickness(double h, double scale = 1);
};

// The region 0 ≤ r ≤ radius, 0 ≤ z ≤ top(r): radial node rows at the sizes' spacing (stretched to end at
// radius), z = top(r)·τ. Mid-edge nodes follow the map, so those on the top lie on it exactly.
MeridianMesh meridian_mesh(const std::function<double(double)>& top, double radius,
                           const MeridianSizes& sizes);

// The same on given radial vertex rows (0 first, increasing; the last is the radius) and fractions τ of the
// thickness at every P2 row (0 to 1, increasing, vertices at even indices): z = top(r)·τ.
MeridianMesh meridian_mesh(const std::function<double(double)>& top, const std::vector<double>& rows,
                           const std::vector<double>& tau);

// Points 0 = x_0 < … < x_n = L whose cells start at c0 at 0 and at c1 at L and grow by `growth` per cell away
// from either end (a cell at distance d from an end with first cell c is about c + (growth − 1)·d), capped at
// cap. The last cell takes what is left: between half and one and a half of its size.
std::vector<double> graded_points(double L, double c0, double c1, double growth, double cap);

// A post sensor on the axis (scene.hpp's PostSensor): the rigid rectangle r ≤ radius, z ≤ height cut from
// the meridian. The stress is singular at its top rim and its foot, so cells shrink toward both corners to
// rim_cell (mm) at the sizes' growth. At the top rim the skin wraps a right angle of the held post: a 270°
// wedge held on both faces, whose stress goes as ρ^(λ−1), λ = 0.5445 when ν = 0.5 (sin λω = ±λ sin ω,
// ω = 3π/2: Williams' clamped wedge). A reading's error from it goes as rim_cell^(2λ) = rim_cell^1.09, so the
// rim cell shrinks as the square of the sizes to keep pace with the P2 error elsewhere.
struct MeridianPost {
  double radius = 0, height = 0;  // mm
  double rim_cell = 0;            // mm; 0: 7.5 axis_cell² / top(0), thickness/480 at for_thickness(h, 1)
};
// The block-structured mesh of the region less the post: radial rows graded toward the post's radius, z rows
// below the post's top graded toward both ends (beside the post only), z = height + (top(r) − height)·τ
// above it. Needs 0 < post.radius < radius and 0 < post.height < top(r) for every r.
MeridianMesh meridian_mesh(const std::function<double(double)>& top, double radius,
                           const MeridianSizes& sizes, const MeridianPost& post);

// The Green tensor of the base reading on the axis (σ_z and σ_x, green/halfspace.hpp's GreenSample
// conventions) for a unit force on the top at offset (x, y) from the axis, 1/mm²: mode 0 gives the σ_z
// reading's adjoint (g_zz, g_xz), mode 1 the σ_x reading's (g_zx, g_xx). Two readings: the point value at the
// axis and the sensor's own reading about it (fem/sensor_reading.hpp: a site whose traits say it is a body of
// revolution about its centre, which is put on the axis; a disc of diameter 0 gives the point reading only;
// a post, which the mesh must have cut out (meridian_mesh with MeridianPost), reads the force on it over its
// cross-section both ways, the post displaced rigidly with the rest of the base held, as
// fem/sensor_reading.hpp in 3D). The side r = radius is traction-free or held (u = 0).
class MeridianGreen {
 public:
  // Throws std::invalid_argument for a site that is not axisymmetric or a post the mesh does not have.
  MeridianGreen(const MeridianMesh& mesh, double nu, SideCondition side = SideCondition::free,
                const ReadingSite& sensor = {});
  // The point force's map; offsets beyond the meridian's radius are clamped to it.
  green::GreenSample at(double x, double y, bool disc = false) const;
  // A unit load centred at offset (x, y), spread as `load` over radius `radius` (green/fe_green.hpp's
  // load_rule, as FeGreen::at).
  green::GreenSample at(bool disc, double x, double y, green::LayerLoad load, double radius) const;
  // One component of the sensor's own reading (disc or post) along +x, summarized: its largest |g| and the
  // offset where it is, the outer offset where |g| has fallen to half of it, and its integral over the top's
  // projection on the base plane, ∫ g dA (the reading under a unit uniform pressure or shear: 1 for a base
  // traction on the unbounded layer, by equilibrium; a post's gain).
  struct Shape {
    double peak = 0, peak_at = 0, half_width = 0, integral = 0;  // 1/mm², mm, mm, 1
  };
  Shape shape_zz() const;
  Shape shape_xx() const;
  int dofs() const { return dofs_; }  // both modes' free DOFs
  struct Cost {
    double assemble_s = 0, factor_s = 0, solve_s = 0;  // both modes
  };
  const Cost& cost() const { return cost_; }

 private:
  // Quadratic along the top's edges, as the solution.
  double interpolate(const std::vector<double>& f, double rho) const;
  // f along +x and its integral with angular factor `angular` (2π for mode 0, π for mode 1's u − v).
  Shape shape(const std::vector<double>& along_x, const std::vector<double>& integrand, double angular) const;
  struct Maps {
    std::vector<double> zz, u0, w1, u1, v1;  // g_zz; mode 0 U; mode 1 W, U, V at the top nodes
  };
  std::vector<double> r_;  // top nodes by increasing r
  Maps maps_[2];           // point reading, disc reading
  bool has_disc_ = false;
  int dofs_ = 0;
  Cost cost_;
};

}  // namespace skinfem
