// Exact Green tensor of a bonded flat layer (green/layer_exact.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "skinfem/green/fe_green.hpp"
#include "skinfem/green/halfspace.hpp"
#include "skinfem/green/layer_exact.hpp"
#include "skinfem/mesh/gauss_legendre.hpp"

namespace {

using skinfem::green::component;
using skinfem::green::GreenComponent;
using skinfem::green::GreenSample;
using skinfem::green::halfspace_green;
using skinfem::green::LayerGreen;
using skinfem::green::LayerKernels;
using skinfem::green::LayerLoad;
using skinfem::green::LayerQuadrature;
using skinfem::green::load_quadrature;

constexpr double kPi = 3.14159265358979323846;
constexpr double kH = 3.04;  // the paper's apex thickness [mm]

double peak(double h) { return 3.0 / (2.0 * kPi * h * h); }

double max_diff(const GreenSample& a, const GreenSample& b) {
  return std::max(
      {std::fabs(a.zz - b.zz), std::fabs(a.zx - b.zx), std::fabs(a.xz - b.xz), std::fabs(a.xx - b.xx)});
}

void gauss_legendre(int n, std::vector<double>& x, std::vector<double>& w) {  // on [−1, 1]
  const skinfem::GaussRule1d g = skinfem::gauss_legendre01(n);
  x.resize(n);
  w.resize(n);
  for (int i = 0; i < n; ++i) x[i] = 2 * g.x[i] - 1, w[i] = 2 * g.w[i];
}

// The sampling offsets used by several tests: on and off the x axis, up to 12h.
std::vector<std::array<double, 2>> offsets(double h) {
  std::vector<std::array<double, 2>> p;
  for (double x : {0.0, 0.13, 0.5, 1.0, 2.2, 4.0, 7.5, 12.0})
    for (double y : {0.0, 0.4, 1.7}) {
      p.push_back({x * h, y * h});
      p.push_back({-x * h, -0.6 * y * h});
    }
  return p;
}

TEST(LayerGreen, GlibcBesselAgreesWithStd) {
  // Both are accurate to near double precision; 1e-13 absolute (~500 ulp of an O(1) value) leaves room for
  // the asymptotic expansions libstdc++ uses at large argument.
  for (double x = 0.0; x < 120.0; x += 0.0137) {
    EXPECT_NEAR(::j0(x), std::cyl_bessel_j(0.0, x), 1e-13) << x;
    EXPECT_NEAR(::j1(x), std::cyl_bessel_j(1.0, x), 1e-13) << x;
  }
}

// The closed-form base kernels and the 4×4 linear system are independent derivations of the same transfer
// functions. The system's matrix has O(1) entries and stays nonsingular from t = 0 to t → ∞ (bounded basis),
// so both are accurate to a few ulp of their O(1) values: 1e-12.
TEST(LayerGreen, ClosedFormKernelsEqualLinearSystem) {
  for (double nu : {0.0, 0.25, 0.4999, 0.5})
    for (double t : {1e-8, 1e-3, 0.1, 0.739, 1.0, 3.0, 10.0, 40.0, 200.0}) {
      const LayerKernels a = LayerGreen::base_kernels(t, nu);
      const LayerKernels b = LayerGreen::depth_kernels(t / kH, kH, 0.0, nu);
      EXPECT_NEAR(a.nzz, b.nzz, 1e-12) << nu << " " << t;
      EXPECT_NEAR(a.nxz, b.nxz, 1e-12) << nu << " " << t;
      EXPECT_NEAR(a.tzz, b.tzz, 1e-12) << nu << " " << t;
      EXPECT_NEAR(a.txz, b.txz, 1e-12) << nu << " " << t;
      EXPECT_NEAR(a.sh, b.sh, 1e-12) << nu << " " << t;
    }
  // s → 0 is rigid-body statics: the whole load reaches the base (N_zz = T_xz = sech = 1, no cross terms).
  for (double nu : {0.0, 0.3, 0.5}) {
    const LayerKernels k = LayerGreen::base_kernels(0.0, nu);
    EXPECT_NEAR(k.nzz, 1.0, 1e-15);
    EXPECT_NEAR(k.txz, 1.0, 1e-15);
    EXPECT_NEAR(k.sh, 1.0, 1e-15);
    EXPECT_NEAR(k.nxz, 0.0, 1e-15);
    EXPECT_NEAR(k.tzz, 0.0, 1e-15);
  }
  // The traction boundary condition at the top is reproduced by the linear system (σ_zz(h) = 1, σ_xz(h) = 0
  // for the normal load and vice versa; antiplane σ_yz(h) = 1).
  const LayerKernels top = LayerGreen::depth_kernels(0.8, kH, kH, 0.3);
  EXPECT_NEAR(top.nzz, 1.0, 1e-13);
  EXPECT_NEAR(top.nxz, 0.0, 1e-13);
  EXPECT_NEAR(top.tzz, 0.0, 1e-13);
  EXPECT_NEAR(top.txz, 1.0, 1e-13);
  EXPECT_NEAR(top.sh, 1.0, 1e-13);
}

TEST(LayerGreen, BaseValuesFromClosedFormEqualLinearSystemPath) {
  // at() uses the closed forms, at_depth(·, h) the linear system with its own nodes; same tolerance
  // reasoning, scaled by the O(1)·peak size of the Hankel sums.
  for (double nu : {0.0, 0.25, 0.5}) {
    const LayerGreen g(kH, nu, LayerLoad::punch, 0.25);
    for (const auto& p : offsets(kH))
      EXPECT_LT(max_diff(g.at(p[0], p[1]), g.at_depth(p[0], p[1], kH)), 1e-12 * peak(kH)) << nu;
  }
}

// ∬ g dA over the base. g is analytic in r within |Im r| < 0.739h (the nearest complex zero of the kernels'
// denominator), so 8-point Gauss–Legendre on panels of width h/2 converges like (8.1)^−16 ≈ 3e-15 per panel;
// the angular dependence is cos nθ with n ≤ 2, integrated exactly by the 6-point trapezoid rule; beyond R =
// 40h the tail decays like exp(−0.739 r/h) ≲ 1e-12 (ν = 0.5 decays slowest). The Hankel sums themselves are
// at roundoff (see QuadratureConverges). Hence 1e-9 bounds the error with ample margin.
TEST(LayerGreen, BaseForceBalance) {
  struct Case {
    double nu;
    LayerLoad load;
    double a;
  };
  std::vector<double> gx, gw;
  gauss_legendre(8, gx, gw);
  for (const Case& c : {Case{0.5, LayerLoad::point, 0.0}, Case{0.25, LayerLoad::point, 0.0},
                        Case{0.5, LayerLoad::punch, 0.25}, Case{0.0, LayerLoad::uniform, 1.0}}) {
    const LayerGreen g(kH, c.nu, c.load, c.a);
    const double panel = 0.5 * kH, R = 40.0 * kH;
    const int n_theta = 6;
    std::array<double, 4> I{0, 0, 0, 0};
    for (double r0 = 0.0; r0 < R - 1e-9; r0 += panel)
      for (int i = 0; i < 8; ++i) {
        const double r = r0 + 0.5 * panel * (1.0 + gx[i]), wr = 0.5 * panel * gw[i] * r;
        for (int j = 0; j < n_theta; ++j) {
          const double th = 2.0 * kPi * (j + 0.3) / n_theta, w = wr * 2.0 * kPi / n_theta;
          const GreenSample s = g.at(r * std::cos(th), r * std::sin(th));
          I[0] += w * s.zz;
          I[1] += w * s.zx;
          I[2] += w * s.xz;
          I[3] += w * s.xx;
        }
      }
    EXPECT_NEAR(I[0], 1.0, 1e-9) << "∬ g_zz, nu " << c.nu;
    EXPECT_NEAR(I[1], 0.0, 1e-9) << "∬ g_zx";
    EXPECT_NEAR(I[2], 0.0, 1e-9) << "∬ g_xz";
    EXPECT_NEAR(I[3], 1.0, 1e-9) << "∬ g_xx";
  }
}

TEST(LayerGreen, Symmetries) {
  const LayerGreen g(kH, 0.5);
  const GreenSample g0 = g.at(0, 0);
  EXPECT_EQ(g0.zx, 0.0);
  EXPECT_EQ(g0.xz, 0.0);
  // Parity is exact in the formulas (x/r and cos 2θ factors), up to the rounding of hypot(): 1e-14 of the
  // peak.
  for (double x : {0.4, 2.0, 5.0})
    for (double y : {0.0, 1.1}) {
      const GreenSample a = g.at(x, y), b = g.at(-x, y), c = g.at(x, -y);
      EXPECT_NEAR(a.zz, b.zz, 1e-14 * peak(kH));
      EXPECT_NEAR(a.zz, c.zz, 1e-14 * peak(kH));
      EXPECT_NEAR(a.zx, -b.zx, 1e-14 * peak(kH));
      EXPECT_NEAR(a.zx, c.zx, 1e-14 * peak(kH));
      EXPECT_NEAR(a.xz, -b.xz, 1e-14 * peak(kH));
      EXPECT_NEAR(a.xx, b.xx, 1e-14 * peak(kH));
      EXPECT_NEAR(a.xx, c.xx, 1e-14 * peak(kH));
    }
  // The central amplification g_zz(0)·2πh²/3 (k_central) is checked against the FE meridian and 3D paths in
  // test_k_regression.cpp and across load models in test_kfit.cpp.
}

// Near the loaded surface the layer must look like a half-space. The difference between the layer field and
// the half-space field is a regular elastic field (length scale h) whose tractions vanish on the top surface,
// so at depth d its σ_zz is O(d²/h⁴) (σ_zz and ∂_zσ_zz = −∂_ασ_αz vanish there) and its σ_xz is O(d/h³); at
// offsets ∝ d the components odd in x gain a factor x/h ∝ d/h. Relative to the half-space peak 3/(2πd²) the
// errors must therefore scale as (d/h)^p with p = 4 (zz), 4 (zx), 5 (xz), 3 (xx). Checked over d/h = 1/10,
// 1/20, 1/40: each halving must reduce the error by at least 0.7·2^p (the next term is one power of d/h
// smaller, i.e. ≤ 30 % at d/h ≤ 1/10).
TEST(LayerGreen, ShallowDepthApproachesHalfSpace) {
  const std::array<int, 4> p{4, 4, 5, 3};
  const std::array<const char*, 4> name{"zz", "zx", "xz", "xx"};
  for (double nu : {0.5, 0.25}) {
    const LayerGreen g(kH, nu);
    std::vector<std::array<double, 4>> err;
    for (double ratio : {0.1, 0.05, 0.025}) {
      const double d = ratio * kH;
      std::array<double, 4> e{0, 0, 0, 0};
      for (double x : {0.0, 0.5, 1.0, -1.5})
        for (double y : {0.0, 0.6}) {
          const GreenSample a = g.at_depth(x * d, y * d, d), b = halfspace_green(x * d, y * d, d);
          e[0] = std::max(e[0], std::fabs(a.zz - b.zz) / peak(d));
          e[1] = std::max(e[1], std::fabs(a.zx - b.zx) / peak(d));
          e[2] = std::max(e[2], std::fabs(a.xz - b.xz) / peak(d));
          e[3] = std::max(e[3], std::fabs(a.xx - b.xx) / peak(d));
        }
      std::printf(
          "[layer] nu = %.2f, d/h = %.3f: |layer - half-space|/peak zz %.3e zx %.3e xz %.3e xx %.3e\n", nu,
          ratio, e[0], e[1], e[2], e[3]);
      err.push_back(e);
    }
    for (int c = 0; c < 4; ++c)
      for (int k = 0; k + 1 < 3; ++k)
        EXPECT_GT(err[k][c] / err[k + 1][c], 0.7 * std::pow(2.0, p[c]))
            << name[c] << " nu " << nu << " step " << k;
  }
}

// ν → 0.5: the kernels are rational in ν with a denominator that stays positive, so g is analytic across ν =
// 0.5 and one code path covers it. The difference to ν = 0.5 must be linear in Δν (ratio of Δν = 1e-4 to 2e-4
// differences in [0.45, 0.55]) and of order Δν times the peak (bound 10·Δν·peak: g changes by O(peak) over ν
// ∈ [0, 0.5]).
TEST(LayerGreen, IncompressibleLimitIsContinuous) {
  const LayerGreen g5(kH, 0.5, LayerLoad::punch, 0.25), g4(kH, 0.4999, LayerLoad::punch, 0.25),
      g3(kH, 0.4998, LayerLoad::punch, 0.25);
  double d1 = 0, d2 = 0;
  for (const auto& p : offsets(kH)) {
    d1 = std::max(d1, max_diff(g5.at(p[0], p[1]), g4.at(p[0], p[1])));
    d2 = std::max(d2, max_diff(g5.at(p[0], p[1]), g3.at(p[0], p[1])));
  }
  std::printf("[layer] max |g(0.5) - g(0.4999)|/peak = %.3e, ratio to 0.4998: %.4f\n", d1 / peak(kH),
              d1 / d2);
  EXPECT_LT(d1, 10.0 * 1e-4 * peak(kH));
  EXPECT_GT(d1 / d2, 0.45);
  EXPECT_LT(d1 / d2, 0.55);
}

// Doubling the quadrature resolution (half-width panels, s_max 60/h instead of 45/h) must change nothing
// beyond 1e-8 of the peak (the requirement); offsets span every precomputed level and the far-field path (r >
// 64h).
TEST(LayerGreen, QuadratureConverges) {
  LayerQuadrature fine;
  fine.panel_scale = 0.5;
  fine.s_max_depth = 60.0;
  struct Case {
    double nu;
    LayerLoad load;
    double a;
  };
  for (const Case& c : {Case{0.5, LayerLoad::point, 0.0}, Case{0.5, LayerLoad::punch, 0.25},
                        Case{0.3, LayerLoad::uniform, 2.0 * kH}}) {
    const LayerGreen g(kH, c.nu, c.load, c.a), f(kH, c.nu, c.load, c.a, fine);
    double d = 0;
    for (double r = 0.0; r < 70.0 * kH; r = r * 1.15 + 0.05 * kH) {
      d = std::max(d, max_diff(g.at(r, 0.3 * r), f.at(r, 0.3 * r)));
      d = std::max(d, max_diff(g.at(-r, 0.0), f.at(-r, 0.0)));
    }
    // The shallow-depth path too.
    d = std::max(d,
                 max_diff(g.at_depth(0.1, 0.05, 0.2), f.at_depth(0.1, 0.05, 0.2)) * (0.2 * 0.2) / (kH * kH));
    std::printf("[layer] refinement change / peak = %.3e (nu %.2f)\n", d / peak(kH), c.nu);
    EXPECT_LT(d, 1e-8 * peak(kH));
  }
  // Far field: beyond 64h the tensor has decayed to roundoff (claimed in layer_exact.cpp).
  const LayerGreen g(kH, 0.5);
  EXPECT_LT(max_diff(g.at(70.0 * kH, 0.0), GreenSample{}), 1e-15 * peak(kH));
}

// Punch and uniform loads with a → 0: L(s) = 1 − (sa)²/c + O((sa)⁴), c = 6 (punch) or 8 (uniform), so
// g_a(0) − g_point(0) = −(a²/c)·M2 + O(a⁴) with M2 = (1/2π)∫ N_zz s³ ds. The relative deviation from this
// prediction is O(a²): it must shrink by at least 3× (4× asymptotically) at each halving of a = h/10, h/20,
// h/40; the whole tensor must converge at the O(a²) rate too.
TEST(LayerGreen, SmallLoadRadiusApproachesPointLoad) {
  const double nu = 0.5;
  std::vector<double> gx, gw;
  gauss_legendre(16, gx, gw);
  double M2 = 0.0;  // integrand ~ t³ e^{−t}; panels of width 0.5/h up to 60/h: roundoff-level
  for (double s0 = 0.0; s0 < 60.0 / kH - 1e-12; s0 += 0.5 / kH)
    for (int i = 0; i < 16; ++i) {
      const double s = s0 + 0.25 / kH * (1.0 + gx[i]);
      M2 += 0.25 / kH * gw[i] * LayerGreen::base_kernels(s * kH, nu).nzz * s * s * s / (2.0 * kPi);
    }
  const LayerGreen point(kH, nu);
  const GreenSample p0 = point.at(0, 0);
  for (LayerLoad load : {LayerLoad::punch, LayerLoad::uniform}) {
    const double c = load == LayerLoad::punch ? 6.0 : 8.0;
    std::vector<double> dev, whole;
    for (double a : {kH / 10, kH / 20, kH / 40}) {
      const LayerGreen g(kH, nu, load, a);
      const double pred = -a * a / c * M2;
      dev.push_back(std::fabs((g.at(0, 0).zz - p0.zz) / pred - 1.0));
      double w = 0;
      for (const auto& p : offsets(kH)) w = std::max(w, max_diff(g.at(p[0], p[1]), point.at(p[0], p[1])));
      whole.push_back(w);
    }
    std::printf(
        "[layer] %s: deviation from the O(a^2) prediction %.3e %.3e %.3e; max |g_a - g_point|/peak %.3e %.3e "
        "%.3e\n",
        load == LayerLoad::punch ? "punch" : "uniform", dev[0], dev[1], dev[2], whole[0] / peak(kH),
        whole[1] / peak(kH), whole[2] / peak(kH));
    EXPECT_GT(dev[0] / dev[1], 3.0);
    EXPECT_GT(dev[1] / dev[2], 3.0);
    EXPECT_GT(whole[0] / whole[1], 3.0);
    EXPECT_GT(whole[1] / whole[2], 3.0);
  }
}

TEST(LayerGreen, SensorDiscMeanEqualsTheMeanOverTheDiscByQuadrature) {
  // Graf's factor 2J1(sb)/(sb) in the Hankel integral against the mean of point values over the disc by two
  // product rules (uniform disc, 12 × 32 and 16 × 48 points): the finer rule's error is bounded by the rules'
  // difference, so the factor must agree with the finer rule within twice that (plus round-off).
  const double h = 3.04, a = 0.25, b = 0.1;
  const LayerGreen point(h, 0.5, LayerLoad::punch, a), disc(h, 0.5, LayerLoad::punch, a, {}, b);
  const auto mean = [&](double x, double y, int nr, int nt) {
    GreenSample m;
    for (const auto& q : load_quadrature(LayerLoad::uniform, b, nr, nt)) {
      const GreenSample v = point.at(x - q[0], y - q[1]);
      m.zz += q[2] * v.zz, m.zx += q[2] * v.zx, m.xz += q[2] * v.xz, m.xx += q[2] * v.xx;
    }
    return m;
  };
  const double peak0 = std::abs(point.at(0, 0).zz);
  for (auto [x, y] : {std::pair{0.0, 0.0}, {0.3, 0.2}, {1.0, -0.5}, {3.0, 1.0}, {8.0, 0.0}}) {
    const GreenSample g = disc.at(x, y), coarse = mean(x, y, 12, 32), fine = mean(x, y, 16, 48);
    for (auto c : {GreenComponent::zz, GreenComponent::zx, GreenComponent::xz, GreenComponent::xx}) {
      const double rule_err = std::abs(component(fine, c) - component(coarse, c));
      EXPECT_LE(std::abs(component(g, c) - component(fine, c)), 2 * rule_err + 1e-11 * peak0)
          << "offset (" << x << ", " << y << ") component " << static_cast<int>(c);
    }
    // The disc mean differs from the point value by O(b²) of the curvature: the factor is not a no-op.
    if (x == 0.0) {
      EXPECT_GT(std::abs(g.zz - point.at(0, 0).zz), 1e-4 * peak0);
    }
  }
}

// zz_at is at().zz computed alone (J0 only): the same sum in the same order, so equal bit for bit, on the
// axis, across every node level and in the far field built on the fly.
TEST(LayerGreen, ZzAloneIsTheFullSamplesZz) {
  for (const LayerLoad load : {LayerLoad::point, LayerLoad::punch}) {
    const LayerGreen g(3.04, 0.5, load, 0.25);
    for (double x : {0.0, 0.01, 0.3, 1.7, 3.04, 9.0, 40.0, 150.0, 400.0})
      for (double y : {0.0, 0.45, -2.0}) EXPECT_EQ(g.zz_at(x, y), g.at(x, y).zz) << x << ", " << y;
  }
}

TEST(LayerGreen, RejectsBadArguments) {
  EXPECT_THROW(LayerGreen(0.0, 0.5), std::invalid_argument);
  EXPECT_THROW(LayerGreen(1.0, 0.6), std::invalid_argument);
  EXPECT_THROW(LayerGreen(1.0, 0.5, LayerLoad::punch, 0.0), std::invalid_argument);
  const LayerGreen g(1.0, 0.5);
  EXPECT_THROW(g.at_depth(0, 0, 0.0), std::invalid_argument);
  EXPECT_THROW(g.at_depth(0, 0, 1.5), std::invalid_argument);
}

}  // namespace
