// Half-space point-load solutions (Boussinesq, Cerruti) and the half-space Green tensor of the sensor model.
//
// Conventions (docs/theory.md §Conventions): the bonded base is z = 0, the skin is z > 0, units mm, N, MPa. A
// Green tensor g_ab(x, y) is the sensor reading b ∈ {z, x} at the base for a unit surface force along a ∈ {z,
// x} applied at the offset (x, y) = force position − sensor position. "Force along z" presses INTO the skin
// (−e_z in the z-up frame). Readings: σ_z = −σ_zz > 0 when the skin presses on the sensor, σ_x = σ_xz > 0
// when the skin drags the sensor toward +x (tension-positive Cauchy stress, z-up components, on the
// horizontal plane of the sensor).
#pragma once

#include <Eigen/Core>

namespace skinfem::green {

/// Cauchy stress (tension positive, components in the z-up frame: x, y horizontal, z pointing out of the
/// solid) at the horizontal position (x, y) = field point − load point and at `depth` ≥ 0 below the free
/// surface of an elastic half-space, for a unit normal force pressing into the surface (Boussinesq). Valid
/// for 0 ≤ nu ≤ 0.5 everywhere except at the load point itself. Units: 1/mm² per N.
Eigen::Matrix3d boussinesq_stress(double x, double y, double depth, double nu);

/// Same for a unit tangential force along +x applied on the surface (Cerruti).
Eigen::Matrix3d cerruti_stress(double x, double y, double depth, double nu);

/// The four sensor readings per unit force, g_ab with a the force direction and b the reading (see file
/// comment): zz = g_zz (σ_z for a normal force), zx = g_zx (σ_x for a normal force), xz = g_xz (σ_z for a
/// force along +x), xx = g_xx (σ_x for a force along +x). Units 1/mm².
struct GreenSample {
  double zz = 0;
  double zx = 0;
  double xz = 0;
  double xx = 0;
};

/// Selects one component of a GreenSample.
enum class GreenComponent { zz, zx, xz, xx };
double component(const GreenSample& g, GreenComponent c);

/// Readings from the stress tensors at the sensor (z-up frame) caused by a unit normal force pressing into
/// the skin and by a unit force along +x: zz = −σ^n_zz, zx = σ^n_xz, xz = −σ^t_zz, xx = σ^t_xz.
GreenSample readings_from_stress(const Eigen::Matrix3d& stress_normal,
                                 const Eigen::Matrix3d& stress_tangential);

/// Half-space Green tensor on the plane at depth h (docs/theory.md §References; independent of nu), ρ = √(x²
/// + y² + h²): g_zz = 3h³/(2πρ⁵), g_zx = −3x h²/(2πρ⁵), g_xz = −3x h²/(2πρ⁵), g_xx = 3x² h/(2πρ⁵). (x, y) is
/// the force−sensor offset.
GreenSample halfspace_green(double x, double y, double h);

/// The k-rescaling (docs/theory.md §Conventions) of the half-space tensor: k · g_half(√k x, √k y) at depth h
/// (amplitude × k, width × k^−1/2, so ∬ g dA is unchanged).
GreenSample rescaled_green(double x, double y, double h, double k);

}  // namespace skinfem::green
