// The incompressible neo-Hookean skin at one material point, total Lagrangian, mixed displacement–pressure
// (the finite-strain counterpart of fem/assembly.hpp's σ = 2μ ε(u) − p I, div u = 0):
//     Π(u, p) = ∫ [ μ/2 (tr C − 3) − μ ln J − p (J − 1) ] dV,   F = I + ∇u, C = FᵀF, J = det F,
// so that the first Piola stress is P = μ (F − F⁻ᵀ) − p J F⁻ᵀ and the constraint is J = 1. The −μ ln J
// term makes the undeformed state stress-free at p = 0, and linearizing P about F = I gives exactly
// 2μ ε − p I (and J − 1 gives div u): the first Newton step from rest is the linear solution.
// Reference: Holzapfel, Nonlinear Solid Mechanics (2000), §6.5; the homogeneous closed forms it is checked
// against are in docs/theory.md §References. Units: MPa.
#pragma once

#include <Eigen/Dense>

namespace skinfem {

// Row-major flattening of a 3×3 tensor: index 3i + J for the component (i, J).
using Tensor9 = Eigen::Matrix<double, 9, 1>;
using Tangent9 = Eigen::Matrix<double, 9, 9>;

struct NeoHookeanPoint {
  double energy = 0;      // μ/2 (tr C − 3) − μ ln J − p (J − 1), MPa
  Eigen::Matrix3d P;      // first Piola stress ∂W/∂F, MPa
  Tangent9 A;             // ∂P_iJ/∂F_kL at (3i + J, 3k + L), MPa; symmetric (a hyperelastic law)
  Eigen::Matrix3d dP_dp;  // ∂P/∂p = −J F⁻ᵀ
  double J = 1;           // det F
  Eigen::Matrix3d dJ_dF;  // J F⁻ᵀ, the constraint's gradient
};

// F: the deformation gradient (det F > 0; throws std::domain_error otherwise: an inverted element), p: the
// pressure (MPa), mu: the shear modulus (MPa).
NeoHookeanPoint neo_hookean(const Eigen::Matrix3d& F, double p, double mu);

}  // namespace skinfem
