// The inversion's solver and estimator (validation/inversion.hpp) on an analytic dictionary, independent of
// any FE: smooth site-dependent responses on a 0.1 mm site grid. References: the Karush–Kuhn–Tucker
// conditions of non-negative least squares (x ≥ 0, the gradient's sign, complementarity) and the
// unconstrained solution when it is positive; planted features recovered from noise-free signals, with the
// offset that made them, to the scan's step; and with the paper's noise the position error within 2× the
// Cramér–Rao bound of the same model (rms over 40 seeded draws: a finite sample of an efficient estimator
// sits within 1.3× of the bound with probability > 0.99, by the χ² law of its mean square; the grid and the
// merging of adjacent atoms cost some efficiency, and the issue asks for 2×). Also the matching of features
// to holes, by hand, and the noise's standard deviation within 4 of its sampling errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "skinfem/scene/random.hpp"
#include "skinfem/validation/inversion.hpp"

namespace skinfem::validation {
namespace {

TEST(Inversion, NnlsMeetsItsOptimalityConditions) {
  SplitMix64 rng{5};
  for (int trial = 0; trial < 20; ++trial) {
    Eigen::MatrixXd A(12, 6);
    Eigen::VectorXd b(12);
    for (int i = 0; i < 12; ++i) {
      b[i] = rng.normal();
      for (int j = 0; j < 6; ++j) A(i, j) = rng.normal();
    }
    const Eigen::VectorXd x = nnls(A, b);
    const Eigen::VectorXd w = A.transpose() * (b - A * x);
    for (int j = 0; j < 6; ++j) {
      EXPECT_GE(x[j], 0);
      EXPECT_LE(w[j], 1e-9);
      EXPECT_LT(std::abs(x[j] * w[j]), 1e-9);
    }
  }
  // A positive unconstrained solution is the answer.
  Eigen::MatrixXd A = Eigen::MatrixXd::Identity(3, 3);
  A(0, 1) = 0.5;
  const Eigen::Vector3d x_true(1, 2, 3);
  EXPECT_LT((nnls(A, A * x_true) - x_true).norm(), 1e-12);
}

// Responses of sites every `site_step` mm on [−7, 7] to a hole at x: a hump in σ_z that turns antisymmetric
// with the site's place, and a derivative-like σ_x, each about 1 mm wide.
HoleResponses analytic_responses(double dx, double site_step = 0.1) {
  HoleResponses r;
  r.dx = dx;
  r.x0 = -5;
  r.diameter = 0.5;
  const int sites = static_cast<int>(std::lround(14 / site_step));
  for (int k = 0; k <= sites; ++k) r.sites.push_back(-7 + site_step * k);
  const int rows = static_cast<int>(std::lround(10 / dx)) + 1;
  r.R.resize(rows, 2 * r.sites.size());
  for (int m = 0; m < rows; ++m)
    for (size_t k = 0; k < r.sites.size(); ++k) {
      const double x = r.x0 + m * dx, s = r.sites[k], d = x - s, e = std::exp(-d * d / 0.8);
      const double envelope = std::exp(-x * x / 8);  // the contact's pressure the hole sits in
      r.R(m, 2 * k) = envelope * e * (0.15 + 0.05 * s * d);
      r.R(m, 2 * k + 1) = envelope * 0.1 * d * e;
    }
  return r;
}

std::vector<double> grid(double from, double to, double step) {
  std::vector<double> u;
  for (int i = 0; from + i * step <= to + 1e-9; ++i) u.push_back(from + i * step);
  return u;
}

// Ten sensors 1 mm apart on [−4.5, 4.5] (the paper's), a 6 mm scan every dx; no signals yet.
ScanSignals ten_sensor_scan(double dx) {
  ScanSignals sig;
  sig.u = grid(0, 6, dx);
  sig.sensors = grid(-4.5, 4.5, 1.0);
  return sig;
}

TEST(Inversion, NoiseFreeSignalsGiveThePlantedFeaturesAndTheOffset) {
  const double dx = 0.05;
  const HoleResponses r = analytic_responses(dx);
  ScanSignals sig = ten_sensor_scan(dx);
  const double offset = 0.3;
  // Plate positions 2 mm apart, one between grid points, amplitudes of holes 0.5, 0.4 and 0.6 mm across.
  const std::vector<Feature> planted{{-6.0, 0.5, 1.0, 0}, {-4.025, 0.4, 0.512, 0}, {-2.0, 0.6, 1.728, 0}};
  sig.y = simulated_signals(sig.u, sig.sensors, r, planted, offset);
  std::vector<double> offsets = grid(-1, 1, 0.1);
  const Inversion inv = invert_scan(sig, r, SensorNoise{0.6, 0.4, 14}, offsets);
  EXPECT_NEAR(inv.offset_mm, offset, 1e-9);
  ASSERT_EQ(inv.features.size(), planted.size());
  for (size_t k = 0; k < planted.size(); ++k) {
    EXPECT_NEAR(inv.features[k].position_mm, planted[k].position_mm, dx) << k;
    EXPECT_NEAR(inv.features[k].diameter_mm, planted[k].diameter_mm, 0.02 * planted[k].diameter_mm) << k;
  }
}

// An offset between grid points (0.27 mm, on grids of 0.2, 0.1 and 0.05 mm): the parabola through the least
// residual and its neighbours finds it closer than the grid's own answer, and within a twentieth of the
// grid's step (the grid alone is off by up to half a step: the refinement must gain at least tenfold to be
// worth reporting). Observed: 1e-3, 6e-5 and 8e-5 mm; the floor is the fit's, not the parabola's.
TEST(Inversion, AnOffsetBetweenGridPointsIsFoundByTheResidualsParabola) {
  const double dx = 0.05, offset = 0.27;
  ScanSignals sig = ten_sensor_scan(dx);
  // On the grid of hole positions q = position − δ (the scan's step): the model exact at the true offset.
  const std::vector<Feature> planted{{-5.73, 0.5, 1.0, 0}, {-3.73, 0.4, 0.512, 0}, {-1.73, 0.6, 1.728, 0}};
  sig.y = simulated_signals(sig.u, sig.sensors, analytic_responses(dx, 0.01), planted, offset);
  const HoleResponses r = analytic_responses(dx, 0.05);
  for (double h : {0.2, 0.1, 0.05}) {
    const Inversion inv = invert_scan(sig, r, SensorNoise{0.6, 0.4, 14}, grid(-1, 1, h));
    const double error = std::abs(inv.offset_refined_mm - offset);
    std::printf("offset grid %.2f mm: best %.3f mm, refined %.5f mm (error %.2e)\n", h, inv.offset_mm,
                inv.offset_refined_mm, error);
    EXPECT_LT(error, std::abs(inv.offset_mm - offset)) << h;
    EXPECT_LT(error, h / 20) << h;
  }
}

// invert_scan forms the normal equations from the design's Hankel structure (a recurrence along G's
// diagonals). Against the explicit design, each column a unit hole simulated at its atom's place and solved
// by nnls on the product AᵀA: the same residual at every offset to 1e-9, with noise, and so the same offset.
TEST(Inversion, TheStructuredNormalEquationsGiveTheExplicitDesignsFit) {
  const double dx = 0.05;
  const HoleResponses r = analytic_responses(dx);
  ScanSignals sig = ten_sensor_scan(dx);
  const SensorNoise noise{0.6, 0.4, 14};
  const std::vector<Feature> planted{{-4.0, 0.5, 1.0, 0}, {-2.5, 0.5, 0.7, 0}};
  sig.y = with_noise(simulated_signals(sig.u, sig.sensors, r, planted, 0.1), noise, 5);
  const std::vector<double> offsets{-0.1, 0.0, 0.1, 0.2};
  const Inversion inv = invert_scan(sig, r, noise, offsets);
  const int nu = static_cast<int>(sig.u.size()), atoms = static_cast<int>(r.R.rows()) + nu - 1;
  const auto whiten = [&](const Eigen::MatrixXd& y) {  // rows (i, sensor, component), as invert_scan's
    Eigen::VectorXd w(y.size());
    for (int i = 0; i < nu; ++i)
      for (int j = 0; j < y.cols(); ++j)
        w[i * y.cols() + j] = std::sqrt(14.0) / (j % 2 ? 0.4 : 0.6) * y(i, j);
    return w;
  };
  const Eigen::VectorXd b = whiten(sig.y);
  std::vector<double> brute;
  for (size_t o = 0; o < offsets.size(); ++o) {
    Eigen::MatrixXd A(b.size(), atoms);
    for (int j = 0; j < atoms; ++j) {
      const double q = r.x0 - sig.u[0] + (j - (nu - 1)) * dx;
      A.col(j) =
          whiten(simulated_signals(sig.u, sig.sensors, r, {{q + offsets[o], 0.5, 1.0, 0}}, offsets[o]));
    }
    const double floor = 1e-6 * A.colwise().norm().maxCoeff();
    for (int j = 0; j < atoms; ++j)
      if (A.col(j).norm() <= floor) A.col(j).setZero();
    brute.push_back((b - A * nnls(A, b)).squaredNorm());
    EXPECT_NEAR(inv.residuals[o], brute.back(), 1e-9 * brute.back()) << "offset " << offsets[o];
  }
  // The fit's choice is the explicit residuals' least.
  EXPECT_EQ(inv.offset_mm, offsets[std::min_element(brute.begin(), brute.end()) - brute.begin()]);
}

TEST(Inversion, WithThePapersNoiseThePositionErrorIsWithinTwiceTheCramerRaoBound) {
  const double dx = 0.05;
  const HoleResponses r = analytic_responses(dx);
  ScanSignals sig = ten_sensor_scan(dx);
  const SensorNoise noise{0.6, 0.4, 14};
  const Feature planted{-3.0, 0.5, 1.0, 0};
  const Eigen::MatrixXd clean = simulated_signals(sig.u, sig.sensors, r, {planted}, 0.0);
  SplitMix64 rng{11};
  double sq = 0;
  const int draws = 40;
  for (int t = 0; t < draws; ++t) {
    sig.y = clean;
    for (int i = 0; i < sig.y.rows(); ++i)
      for (int j = 0; j < sig.y.cols(); ++j)
        sig.y(i, j) += (j % 2 ? 0.4 : 0.6) / std::sqrt(14.0) * rng.normal();
    const Inversion inv = invert_scan(sig, r, noise, {0.0});
    ASSERT_FALSE(inv.features.empty()) << "draw " << t;
    // The strongest feature is the hole.
    const Feature* f = &inv.features[0];
    for (const Feature& g : inv.features)
      if (g.snr > f->snr) f = &g;
    sq += std::pow(f->position_mm - planted.position_mm, 2);
  }
  const double rms = std::sqrt(sq / draws);
  const double crb = position_crb(sig, r, noise, planted.position_mm, planted.amplitude, 0.0);
  EXPECT_LT(rms, 2 * crb) << "rms " << rms << " mm, bound " << crb << " mm";
}

TEST(ScoreInversion, EachFeatureGoesToTheNearestHoleWithinReach) {
  std::vector<validation::Feature> f(4);
  f[0].position_mm = 0.1;
  f[1].position_mm = 2.05;
  f[2].position_mm = 2.3;  // a second feature for hole 2: the nearer one counts, this one is false
  f[3].position_mm = 7;    // near no hole: false
  const InversionScore s = score_inversion(f, {0, 2, 4}, 1.0);
  EXPECT_EQ(s.found, 2);
  EXPECT_EQ(s.missed, 1);
  EXPECT_EQ(s.false_features, 2);
  EXPECT_NEAR(s.rms_error_mm, std::sqrt((0.01 + 0.0025) / 2), 1e-12);
  EXPECT_NEAR(s.largest_error_mm, 0.1, 1e-12);
}

TEST(WithNoise, SeededAndOfTheMeanOfNPassages) {
  const Eigen::MatrixXd zero = Eigen::MatrixXd::Zero(10000, 4);
  const validation::SensorNoise noise{0.6, 0.4, 14};
  const Eigen::MatrixXd a = with_noise(zero, noise, 3), b = with_noise(zero, noise, 3);
  EXPECT_EQ((a - b).cwiseAbs().maxCoeff(), 0);
  const double n = 2.0 * zero.rows();  // samples per component
  for (int comp = 0; comp < 2; ++comp) {
    double sum2 = 0;
    for (int j = comp; j < 4; j += 2) sum2 += a.col(j).squaredNorm();
    const double sd = std::sqrt(sum2 / n), want = (comp ? 0.4 : 0.6) / std::sqrt(14.0);
    // The sample standard deviation's error is sd/√(2n).
    EXPECT_NEAR(sd, want, 4 * want / std::sqrt(2 * n)) << comp;
  }
}

}  // namespace
}  // namespace skinfem::validation
