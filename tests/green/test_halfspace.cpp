// Half-space Boussinesq/Cerruti stresses and the half-space Green tensor (green/halfspace.hpp).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <vector>

#include "skinfem/green/halfspace.hpp"
#include "skinfem/mesh/gauss_legendre.hpp"

namespace {

using skinfem::green::boussinesq_stress;
using skinfem::green::cerruti_stress;
using skinfem::green::GreenSample;
using skinfem::green::halfspace_green;
using skinfem::green::readings_from_stress;
using skinfem::green::rescaled_green;

constexpr double kPi = 3.14159265358979323846;

// Gauss–Legendre nodes/weights on [0, 1] (the library rule).
void gauss_legendre01(int n, std::vector<double>& x, std::vector<double>& w) {
  const skinfem::GaussRule1d g = skinfem::gauss_legendre01(n);
  x = g.x;
  w = g.w;
}

// ∬ g dA over the whole plane with r = h tan α, α ∈ [0, π/2): ρ = h/cos α, r dr = h² tan α sec² α dα, so
// every component becomes a trigonometric polynomial in α times cos^n θ (g_zz: (3/2π) sin α cos² α; g_xx:
// (3/2π) sin³ α cos² θ; g_zx, g_xz: ∝ sin² α cos α cos θ). Gauss–Legendre in α and the trapezoid rule in θ
// integrate these exactly up to roundoff, so 1e-12 bounds the error (64 × 64 terms of O(1), each with ~1e-16
// relative rounding).
std::array<double, 4> plane_integrals(const std::function<GreenSample(double, double)>& g, double h) {
  std::vector<double> xa, wa;
  gauss_legendre01(64, xa, wa);
  const int n_theta = 64;
  std::array<double, 4> sum{0, 0, 0, 0};
  for (std::size_t i = 0; i < xa.size(); ++i) {
    const double alpha = 0.5 * kPi * xa[i], dalpha = 0.5 * kPi * wa[i];
    const double r = h * std::tan(alpha), jac = h * h * std::tan(alpha) / (std::cos(alpha) * std::cos(alpha));
    for (int j = 0; j < n_theta; ++j) {
      const double th = 2.0 * kPi * j / n_theta, wt = 2.0 * kPi / n_theta;
      const GreenSample s = g(r * std::cos(th), r * std::sin(th));
      const double f = dalpha * jac * wt;
      sum[0] += f * s.zz;
      sum[1] += f * s.zx;
      sum[2] += f * s.xz;
      sum[3] += f * s.xx;
    }
  }
  return sum;
}

TEST(HalfSpaceGreen, PlaneIntegralsAreUnitForceBalance) {
  for (double h : {0.7, 3.04}) {
    const auto I = plane_integrals([h](double x, double y) { return halfspace_green(x, y, h); }, h);
    EXPECT_NEAR(I[0], 1.0, 1e-12) << "∬ g_zz, h = " << h;
    EXPECT_NEAR(I[1], 0.0, 1e-12) << "∬ g_zx";
    EXPECT_NEAR(I[2], 0.0, 1e-12) << "∬ g_xz";
    EXPECT_NEAR(I[3], 1.0, 1e-12) << "∬ g_xx";
  }
}

TEST(HalfSpaceGreen, RescalingKeepsTotalForceAndScalesAmplitude) {
  const double h = 3.04, k = 1.48;
  const auto I =
      plane_integrals([h, k](double x, double y) { return rescaled_green(x, y, h, k); }, h / std::sqrt(k));
  // The substitution above is exact for any length scale, so the same 1e-12 roundoff bound holds.
  EXPECT_NEAR(I[0], 1.0, 1e-12);
  EXPECT_NEAR(I[3], 1.0, 1e-12);
  EXPECT_NEAR(rescaled_green(0, 0, h, k).zz, k * 3.0 / (2.0 * kPi * h * h), 1e-15);
  const GreenSample a = rescaled_green(0.8, -0.3, h, 1.0), b = halfspace_green(0.8, -0.3, h);
  EXPECT_EQ(a.zz, b.zz);
  EXPECT_EQ(a.xx, b.xx);
}

TEST(HalfSpaceGreen, CentralValueAndSymmetries) {
  const double h = 3.04, peak = 3.0 / (2.0 * kPi * h * h);
  const GreenSample g0 = halfspace_green(0, 0, h);
  EXPECT_NEAR(g0.zz, peak, 1e-15 * peak);
  EXPECT_EQ(g0.zx, 0.0);
  EXPECT_EQ(g0.xz, 0.0);
  EXPECT_EQ(g0.xx, 0.0);
  // Exact parity of the closed forms: the only rounding differences come from x → −x in products (none), so
  // equality holds to the last bit; allow 1 ulp-level relative 1e-15 anyway.
  for (double x : {0.3, 1.7, 6.0})
    for (double y : {0.0, 0.9, 4.0}) {
      const GreenSample a = halfspace_green(x, y, h), b = halfspace_green(-x, y, h),
                        c = halfspace_green(x, -y, h);
      EXPECT_NEAR(a.zz, b.zz, 1e-15 * peak);
      EXPECT_NEAR(a.zz, c.zz, 1e-15 * peak);
      EXPECT_NEAR(a.zx, -b.zx, 1e-15 * peak);
      EXPECT_NEAR(a.zx, c.zx, 1e-15 * peak);
      EXPECT_NEAR(a.xz, -b.xz, 1e-15 * peak);
      EXPECT_NEAR(a.xx, b.xx, 1e-15 * peak);
      EXPECT_NEAR(a.xx, c.xx, 1e-15 * peak);
      // Signs (docs/theory.md §References): a normal push right of the sensor drags it toward −x, a +x drag
      // puts it in tension.
      EXPECT_LT(a.zx, 0.0);
      EXPECT_LT(a.xz, 0.0);
      EXPECT_GT(a.xx, 0.0);
    }
}

// The sign check: the closed-form tensor must equal the readings derived from the full stress tensors at
// depth h for every nu (the plane components σ_zz, σ_xz of Boussinesq and Cerruti do not depend on nu). The
// stress functions take the position of the field point relative to the load, i.e. −(offset). Both sides are
// the same rational functions evaluated in different orders, so they agree to roundoff: 1e-13 of the peak.
TEST(HalfSpaceGreen, EqualsReadingsFromStressTensors) {
  const double h = 3.04, peak = 3.0 / (2.0 * kPi * h * h);
  for (double nu : {0.0, 0.25, 0.5})
    for (double x : {-7.0, -2.1, -0.4, 0.0, 0.5, 1.9, 5.5})
      for (double y : {-3.0, 0.0, 0.8, 2.6}) {
        const GreenSample g = halfspace_green(x, y, h);
        const GreenSample s =
            readings_from_stress(boussinesq_stress(-x, -y, h, nu), cerruti_stress(-x, -y, h, nu));
        EXPECT_NEAR(g.zz, s.zz, 1e-13 * peak) << nu << " " << x << " " << y;
        EXPECT_NEAR(g.zx, s.zx, 1e-13 * peak) << nu << " " << x << " " << y;
        EXPECT_NEAR(g.xz, s.xz, 1e-13 * peak) << nu << " " << x << " " << y;
        EXPECT_NEAR(g.xx, s.xx, 1e-13 * peak) << nu << " " << x << " " << y;
      }
}

// Stress field as a function of the z-up position (z < 0 inside the half-space whose surface is z = 0).
using StressFn = std::function<Eigen::Matrix3d(const Eigen::Vector3d&)>;

// 4th-order central differences. With step e = 2e-3 at distance ~1 from the load the truncation error is
// O(e⁴ max|∂⁶σ|) ≲ 1e-9 (σ is a rational function whose n-th derivatives grow like n!/R^n at distance R ≈ 1)
// and the rounding error O(ε|σ|/e²) ≲ 1e-10, so residuals of exact solutions stay below 1e-7, while a wrong
// term in any component leaves residuals of order 4e-3 and more (measured with the sign of one τ_xy term
// flipped).
Eigen::Matrix3d d1(const StressFn& f, Eigen::Vector3d p, int i, double e) {
  Eigen::Vector3d di = Eigen::Vector3d::Zero();
  di[i] = e;
  return (-f(p + 2 * di) + 8 * f(p + di) - 8 * f(p - di) + f(p - 2 * di)) / (12 * e);
}
Eigen::Matrix3d d2(const StressFn& f, Eigen::Vector3d p, int i, int j, double e) {
  if (i == j) {
    Eigen::Vector3d di = Eigen::Vector3d::Zero();
    di[i] = e;
    return (-f(p + 2 * di) + 16 * f(p + di) - 30 * f(p) + 16 * f(p - di) - f(p - 2 * di)) / (12 * e * e);
  }
  const StressFn g = [&](const Eigen::Vector3d& q) { return d1(f, q, j, e); };
  return d1(g, p, i, e);
}

void expect_elastic_solution(const StressFn& sigma, double nu, const Eigen::Vector3d& p) {
  const double e = 2e-3;
  // Equilibrium: ∂_j σ_ij = 0.
  const Eigen::Matrix3d dx = d1(sigma, p, 0, e), dy = d1(sigma, p, 1, e), dz = d1(sigma, p, 2, e);
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(dx(i, 0) + dy(i, 1) + dz(i, 2), 0.0, 1e-7) << "equilibrium row " << i;
  // Beltrami–Michell compatibility (no body force): ∇²σ_ij + ∂_i∂_j(tr σ)/(1+ν) = 0.
  const auto trace = [&](const Eigen::Vector3d& q) {
    return Eigen::Matrix3d(Eigen::Matrix3d::Identity() * sigma(q).trace());
  };
  const Eigen::Matrix3d lap = d2(sigma, p, 0, 0, e) + d2(sigma, p, 1, 1, e) + d2(sigma, p, 2, 2, e);
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j) {
      const double ddtr = d2(trace, p, i, j, e)(0, 0);
      EXPECT_NEAR(lap(i, j) + ddtr / (1.0 + nu), 0.0, 1e-7) << "compatibility " << i << j << " nu " << nu;
    }
}

TEST(HalfSpaceStress, EquilibriumAndCompatibility) {
  for (double nu : {0.0, 0.25, 0.5}) {
    const StressFn bou = [nu](const Eigen::Vector3d& q) { return boussinesq_stress(q[0], q[1], -q[2], nu); };
    const StressFn cer = [nu](const Eigen::Vector3d& q) { return cerruti_stress(q[0], q[1], -q[2], nu); };
    for (const Eigen::Vector3d& p : {Eigen::Vector3d(0.7, -0.4, -0.9), Eigen::Vector3d(-0.3, 0.5, -0.6),
                                     Eigen::Vector3d(0.0, 0.0, -1.1), Eigen::Vector3d(1.2, 0.2, -0.3)}) {
      expect_elastic_solution(bou, nu, p);
      expect_elastic_solution(cer, nu, p);
    }
  }
}

TEST(HalfSpaceStress, TractionFreeSurfaceAndKnownSurfaceStress) {
  for (double nu : {0.0, 0.25, 0.5}) {
    for (double x : {-1.3, 0.4, 2.0})
      for (double y : {-0.5, 0.0, 0.7}) {
        const Eigen::Matrix3d b = boussinesq_stress(x, y, 0.0, nu), c = cerruti_stress(x, y, 0.0, nu);
        for (int i = 0; i < 3; ++i) {
          EXPECT_EQ(b(i, 2), 0.0);  // every term carries a factor z
          EXPECT_EQ(c(i, 2), 0.0);
        }
      }
    // Johnson §3.2: on the surface outside the load, σ_r = −σ_θ = (1−2ν)/(2πr²) (per unit force).
    const double r = 1.7;
    const Eigen::Matrix3d b = boussinesq_stress(r, 0.0, 0.0, nu);
    EXPECT_NEAR(b(0, 0), (1 - 2 * nu) / (2 * kPi * r * r), 1e-15);
    EXPECT_NEAR(b(1, 1), -(1 - 2 * nu) / (2 * kPi * r * r), 1e-15);
    // On the axis σ_r = σ_θ = (1−2ν)/(4πz²) − 0 and σ_z = −3/(2πz²) (Johnson's cylindrical forms at r → 0).
    const double z = 0.8;
    const Eigen::Matrix3d a = boussinesq_stress(0.0, 0.0, z, nu);
    EXPECT_NEAR(a(0, 0), (1 - 2 * nu) / (4 * kPi * z * z), 1e-15);
    EXPECT_NEAR(a(1, 1), (1 - 2 * nu) / (4 * kPi * z * z), 1e-15);
    EXPECT_NEAR(a(2, 2), -3.0 / (2 * kPi * z * z), 1e-15);
  }
}

TEST(HalfSpaceStress, RejectsBadArguments) {
  EXPECT_THROW(boussinesq_stress(0, 0, 0, 0.3), std::invalid_argument);
  EXPECT_THROW(cerruti_stress(1, 0, -1, 0.3), std::invalid_argument);
  EXPECT_THROW(cerruti_stress(1, 0, 1, 0.6), std::invalid_argument);
  EXPECT_THROW(halfspace_green(1, 0, 0), std::invalid_argument);
}

}  // namespace
