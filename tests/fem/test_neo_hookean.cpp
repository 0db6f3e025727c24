// The incompressible neo-Hookean point (fem/neo_hookean.hpp) against: its own energy and stress by central
// differences (a second method), the linear law it must reduce to at rest (fem/assembly.hpp's σ = 2μ ε − p I,
// exactly), and the classical homogeneous closed forms: Treloar's uniaxial stretch P₁₁ = μ (λ − λ⁻²), and
// simple shear's σ₁₂ = μ γ with the Poynting normal-stress difference σ₁₁ − σ₂₂ = μ γ² (Holzapfel 2000,
// §6.5; Ogden, Non-linear Elastic Deformations, §5.3).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "skinfem/fem/neo_hookean.hpp"

namespace skinfem {
namespace {

constexpr double kMu = 1.0;  // MPa: the paper's PDMS, E = 3 MPa at ν = 0.5

// A deformation well away from rest (stretches of ±30 %, shears) with det F > 0, and a pressure.
Eigen::Matrix3d general_F() {
  Eigen::Matrix3d F;
  F << 1.25, 0.18, -0.07, -0.11, 0.86, 0.21, 0.05, -0.16, 1.09;
  return F;
}
constexpr double kP = 0.37;  // MPa

// Central differences with step h = 1e-6 on quantities of order 1: truncation h²·|third derivative| ≲ 1e-11
// and round-off ε·|value|/h ≲ 1e-9, so agreement to 1e-7 (relative to the largest entry) leaves a margin.
constexpr double kStep = 1e-6, kFdTolerance = 1e-7;

TEST(NeoHookean, StressIsTheEnergysGradient) {
  const Eigen::Matrix3d F = general_F();
  const NeoHookeanPoint at = neo_hookean(F, kP, kMu);
  for (int i = 0; i < 3; ++i)
    for (int a = 0; a < 3; ++a) {
      Eigen::Matrix3d Fp = F, Fm = F;
      Fp(i, a) += kStep;
      Fm(i, a) -= kStep;
      const double fd = (neo_hookean(Fp, kP, kMu).energy - neo_hookean(Fm, kP, kMu).energy) / (2 * kStep);
      EXPECT_NEAR(at.P(i, a), fd, kFdTolerance * at.P.cwiseAbs().maxCoeff()) << "P(" << i << "," << a << ")";
    }
  // The constraint: ∂W/∂p = −(J − 1), and ∂P/∂p = −J F⁻ᵀ (P is linear in p: the difference is exact).
  EXPECT_NEAR((neo_hookean(F, kP + kStep, kMu).energy - at.energy) / kStep, -(at.J - 1), kFdTolerance);
  const Eigen::Matrix3d dP = neo_hookean(F, kP + 1, kMu).P - at.P;
  EXPECT_LT((dP - at.dP_dp).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((at.dP_dp + at.dJ_dF).cwiseAbs().maxCoeff(), 1e-15);
}

TEST(NeoHookean, TangentIsTheStresssGradientAndSymmetric) {
  const Eigen::Matrix3d F = general_F();
  const NeoHookeanPoint at = neo_hookean(F, kP, kMu);
  const double scale = at.A.cwiseAbs().maxCoeff();
  for (int k = 0; k < 3; ++k)
    for (int b = 0; b < 3; ++b) {
      Eigen::Matrix3d Fp = F, Fm = F;
      Fp(k, b) += kStep;
      Fm(k, b) -= kStep;
      const Eigen::Matrix3d fd = (neo_hookean(Fp, kP, kMu).P - neo_hookean(Fm, kP, kMu).P) / (2 * kStep);
      for (int i = 0; i < 3; ++i)
        for (int a = 0; a < 3; ++a)
          EXPECT_NEAR(at.A(3 * i + a, 3 * k + b), fd(i, a), kFdTolerance * scale)
              << "A(" << i << a << "," << k << b << ")";
    }
  // A hyperelastic law's tangent is a second derivative of W: symmetric to round-off.
  EXPECT_LT((at.A - at.A.transpose()).cwiseAbs().maxCoeff(), 1e-14 * scale);
}

TEST(NeoHookean, AtRestItIsTheLinearIncompressibleLaw) {
  // P(I, 0) = 0; the tangent maps a displacement gradient G to μ (G + Gᵀ) = 2μ ε(G); ∂P/∂p = −I; the
  // constraint's gradient is I (J − 1 ≈ tr G = div u). All exact at F = I.
  const NeoHookeanPoint rest = neo_hookean(Eigen::Matrix3d::Identity(), 0, kMu);
  EXPECT_LT(rest.P.cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_DOUBLE_EQ(rest.energy, 0);
  Eigen::Matrix3d G;
  G << 0.3, -0.2, 0.5, 0.7, -0.1, 0.4, -0.6, 0.2, 0.9;
  const Tensor9 g = Eigen::Map<const Tensor9>(Eigen::Matrix3d(G.transpose()).data());  // row-major
  const Tensor9 ag = rest.A * g;
  const Eigen::Matrix3d linear = kMu * (G + G.transpose());
  for (int i = 0; i < 3; ++i)
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(ag(3 * i + a), linear(i, a), 1e-14);
  EXPECT_LT((rest.dP_dp + Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_LT((rest.dJ_dF - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff(), 1e-15);
}

TEST(NeoHookean, UniaxialStretchIsTreloarsClosedForm) {
  // F = diag(λ, λ^-1/2, λ^-1/2) with the lateral faces free: P₂₂ = 0 sets p = μ (1/λ − 1), and then
  // P₁₁ = μ (λ − λ⁻²), in tension and in compression.
  for (double lambda : {0.6, 0.9, 1.1, 1.5, 2.5}) {
    const double t = 1 / std::sqrt(lambda);
    const Eigen::Matrix3d F = Eigen::Vector3d(lambda, t, t).asDiagonal();
    const NeoHookeanPoint at = neo_hookean(F, kMu * (1 / lambda - 1), kMu);
    EXPECT_NEAR(at.J, 1, 1e-15);
    EXPECT_NEAR(at.P(1, 1), 0, 1e-14) << "lambda " << lambda;
    EXPECT_NEAR(at.P(2, 2), 0, 1e-14) << "lambda " << lambda;
    EXPECT_NEAR(at.P(0, 0), kMu * (lambda - 1 / (lambda * lambda)), 1e-14) << "lambda " << lambda;
  }
}

TEST(NeoHookean, SimpleShearHasLinearShearStressAndThePoyntingEffect) {
  // F = I + γ e₁⊗e₂ (isochoric): σ = P Fᵀ = μ (F Fᵀ − I) − p I whatever p, so σ₁₂ = μ γ and
  // σ₁₁ − σ₂₂ = μ γ².
  for (double gamma : {0.1, 0.5, 1.0, 2.0}) {
    Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
    F(0, 1) = gamma;
    const NeoHookeanPoint at = neo_hookean(F, kP, kMu);
    const Eigen::Matrix3d sigma = at.P * F.transpose();  // J = 1
    EXPECT_NEAR(sigma(0, 1), kMu * gamma, 1e-14);
    EXPECT_NEAR(sigma(1, 0), kMu * gamma, 1e-14);
    EXPECT_NEAR(sigma(0, 0) - sigma(1, 1), kMu * gamma * gamma, 1e-13);
    EXPECT_NEAR(sigma(2, 2), -kP, 1e-14);
  }
}

TEST(NeoHookean, AnInvertedPointIsRefused) {
  Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
  F(2, 2) = -0.1;
  EXPECT_THROW(neo_hookean(F, 0, kMu), std::domain_error);
  F(2, 2) = 0;
  EXPECT_THROW(neo_hookean(F, 0, kMu), std::domain_error);
}

}  // namespace
}  // namespace skinfem
