#include "skinfem/green/halfspace.hpp"

#include <cmath>
#include <stdexcept>

namespace skinfem::green {
namespace {

// Johnson's frame (K. L. Johnson, Contact Mechanics, CUP 1985, ch. 3) has z pointing INTO the solid (z =
// depth). Our frame is z-up. Going from one to the other is the reflection Q = diag(1, 1, −1), σ' = Q σ Qᵀ:
// only the xz and yz components change sign.
Eigen::Matrix3d to_z_up(const Eigen::Matrix3d& s_johnson) {
  Eigen::Matrix3d s = s_johnson;
  s(0, 2) = s(2, 0) = -s_johnson(0, 2);
  s(1, 2) = s(2, 1) = -s_johnson(1, 2);
  return s;
}

void check_args(double x, double y, double depth, double nu) {
  if (!(depth >= 0.0)) throw std::invalid_argument("half-space stress: depth must be >= 0");
  if (!(nu >= 0.0 && nu <= 0.5)) throw std::invalid_argument("half-space stress: nu must be in [0, 0.5]");
  if (x == 0.0 && y == 0.0 && depth == 0.0)
    throw std::invalid_argument("half-space stress: at the load point");
}

}  // namespace

Eigen::Matrix3d boussinesq_stress(double x, double y, double depth, double nu) {
  check_args(x, y, depth, nu);
  // Johnson (1985) §3.2, concentrated normal force P (compressive, along +z into the solid), ρ = √(r² + z²):
  //   σ_r  =  P/2π { (1−2ν)/r² [1 − z/ρ] − 3 z r²/ρ⁵ }
  //   σ_θ  = −P/2π (1−2ν) { 1/r² [1 − z/ρ] − z/ρ³ }
  //   σ_z  = −3P/2π z³/ρ⁵
  //   τ_rz = −3P/2π r z²/ρ⁵
  // Written without the removable 1/r² singularity: (1/r²)(1 − z/ρ) = 1/(ρ(ρ+z)), and
  //   (σ_r − σ_θ)/r² = [ (1−2ν)(2ρ+z)/(ρ³(ρ+z)²) − 3z/ρ⁵ ] / 2π,
  // so that in Cartesian components σ_αβ = σ_θ δ_αβ + (σ_r − σ_θ) x_α x_β / r² for α, β ∈ {x, y}.
  const double z = depth;
  const double rho = std::sqrt(x * x + y * y + z * z);
  const double a = 1.0 - 2.0 * nu;
  const double rho3 = rho * rho * rho;
  const double rho5 = rho3 * rho * rho;
  const double rz = rho + z;
  const double c = 1.0 / (2.0 * M_PI);
  const double s_theta = -c * a * (1.0 / (rho * rz) - z / rho3);
  const double d = c * (a * (2.0 * rho + z) / (rho3 * rz * rz) - 3.0 * z / rho5);
  Eigen::Matrix3d s;
  s(0, 0) = s_theta + d * x * x;
  s(1, 1) = s_theta + d * y * y;
  s(0, 1) = s(1, 0) = d * x * y;
  s(2, 2) = -3.0 * c * z * z * z / rho5;
  s(0, 2) = s(2, 0) = -3.0 * c * x * z * z / rho5;
  s(1, 2) = s(2, 1) = -3.0 * c * y * z * z / rho5;
  return to_z_up(s);
}

Eigen::Matrix3d cerruti_stress(double x, double y, double depth, double nu) {
  check_args(x, y, depth, nu);
  // Johnson (1985) §3.3, concentrated tangential force Q along +x (z into the solid), ρ = √(x² + y² + z²):
  //   σ_x  = −Q x/(2πρ³) [ 3x²/ρ² − (1−2ν)/(ρ+z)² { ρ² − y² − 2ρy²/(ρ+z) } ]
  //   σ_y  = −Q x/(2πρ³) [ 3y²/ρ² − (1−2ν)/(ρ+z)² { 3ρ² − x² − 2ρx²/(ρ+z) } ]
  //   σ_z  = −3Q x z²/(2πρ⁵)
  //   τ_xy = −Q y/(2πρ³) [ 3x²/ρ² + (1−2ν)/(ρ+z)² { ρ² − x² − 2ρx²/(ρ+z) } ]
  //   τ_yz = −3Q x y z/(2πρ⁵)
  //   τ_zx = −3Q x² z/(2πρ⁵)
  // (Some secondary listings print τ_xy with the opposite sign of the last term; the form above is the one
  // that satisfies equilibrium and Beltrami–Michell compatibility, which tests/green/test_halfspace.cpp
  // checks numerically.)
  const double z = depth;
  const double rho2 = x * x + y * y + z * z;
  const double rho = std::sqrt(rho2);
  const double a = 1.0 - 2.0 * nu;
  const double rho3 = rho2 * rho;
  const double rho5 = rho3 * rho2;
  const double rz = rho + z;
  const double f = a / (rz * rz);
  const double c = 1.0 / (2.0 * M_PI);
  Eigen::Matrix3d s;
  s(0, 0) = -c * x / rho3 * (3.0 * x * x / rho2 - f * (rho2 - y * y - 2.0 * rho * y * y / rz));
  s(1, 1) = -c * x / rho3 * (3.0 * y * y / rho2 - f * (3.0 * rho2 - x * x - 2.0 * rho * x * x / rz));
  s(2, 2) = -3.0 * c * x * z * z / rho5;
  s(0, 1) = s(1, 0) = -c * y / rho3 * (3.0 * x * x / rho2 + f * (rho2 - x * x - 2.0 * rho * x * x / rz));
  s(1, 2) = s(2, 1) = -3.0 * c * x * y * z / rho5;
  s(0, 2) = s(2, 0) = -3.0 * c * x * x * z / rho5;
  return to_z_up(s);
}

double component(const GreenSample& g, GreenComponent c) {
  switch (c) {
    case GreenComponent::zz:
      return g.zz;
    case GreenComponent::zx:
      return g.zx;
    case GreenComponent::xz:
      return g.xz;
    case GreenComponent::xx:
      return g.xx;
  }
  return 0.0;
}

GreenSample readings_from_stress(const Eigen::Matrix3d& stress_normal,
                                 const Eigen::Matrix3d& stress_tangential) {
  // The skin lies above the sensor; the force the skin exerts on the base per unit area is σ·e_z (z-up). Its
  // z component is σ_zz (negative when pressing), its x component σ_xz.
  return GreenSample{-stress_normal(2, 2), stress_normal(0, 2), -stress_tangential(2, 2),
                     stress_tangential(0, 2)};
}

GreenSample halfspace_green(double x, double y, double h) {
  if (!(h > 0.0)) throw std::invalid_argument("halfspace_green: h must be > 0");
  const double rho2 = x * x + y * y + h * h;
  const double rho = std::sqrt(rho2);
  const double q = 3.0 / (2.0 * M_PI * rho2 * rho2 * rho);  // 3/(2πρ⁵)
  return GreenSample{q * h * h * h, -q * x * h * h, -q * x * h * h, q * x * x * h};
}

GreenSample rescaled_green(double x, double y, double h, double k) {
  if (!(k > 0.0)) throw std::invalid_argument("rescaled_green: k must be > 0");
  const double sk = std::sqrt(k);
  const GreenSample g = halfspace_green(sk * x, sk * y, h);
  return GreenSample{k * g.zz, k * g.zx, k * g.xz, k * g.xx};
}

}  // namespace skinfem::green
