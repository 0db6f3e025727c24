// The finite-strain skin's discrete equations: the incompressible neo-Hookean law (fem/neo_hookean.hpp) on
// the Taylor–Hood P2–P1 spaces of fem/assembly.hpp, total Lagrangian on the reference mesh. At a state
// (u, p) with F = I + ∇u:
//   internal force  ∫ P(F, p) : ∇φ dV                     (3N, N)
//   constraint      c = −∫ q (J − 1) dV                   (Nv, mm³; zero when every element keeps its volume)
//   tangent         [ A_t  B_tᵀ ]   A_t = ∫ ∇φ : 𝔸(F, p) : ∇φ dV,   B_t = −∫ q J F⁻ᵀ : ∇φ dV,
//                   [ B_t   0   ]   no pressure–pressure block (J = 1 exactly, as ν = 0.5 in the linear law)
// Equilibrium under a dead load f (reference configuration) is internal force = f with c = 0. At u = 0,
// p = 0 the tangent is assemble_mixed's matrices at ν = 0.5 exactly, so a Newton step from rest is the
// linear solution. Quadrature: the 14-point degree-5 rule on every element (the integrands are not
// polynomials). Units: mm, MPa, N.
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "skinfem/fem/assembly.hpp"

namespace skinfem {

// What an assembly builds: the tangent costs several times the residual, which a line search's trial states
// need alone.
enum class FiniteStrainParts { residual, residual_and_tangent };

struct FiniteStrainSystem {
  MixedMatrices tangent;           // A: A_t (3N×3N), B: B_t (Nv×3N), Mp: the pressure mass (Nv×Nv); empty
                                   // when only the residual was asked for
  Eigen::VectorXd internal_force;  // 3N, N
  Eigen::VectorXd constraint;      // Nv, mm³
  double energy = 0;               // ∫ W dV, N·mm (the stored energy less ∫ p (J − 1))
};

// u: 3N displacements (mm), p: Nv pressures (MPa), mu: shear modulus (MPa). Throws std::domain_error when
// a quadrature point inverts (det F ≤ 0).
FiniteStrainSystem assemble_finite_strain(const TetMesh& mesh, double mu, const Eigen::VectorXd& u,
                                          const Eigen::VectorXd& p,
                                          FiniteStrainParts parts = FiniteStrainParts::residual_and_tangent);

// The residual of equilibrium under the load f (3N, N), scaled to be dimensionless: the free rows of
// f − internal force over force_scale (N) and the constraint over the skin's volume (mm³), in quadrature.
// r_u, when given, receives f − internal force with the fixed rows zeroed (3N, N).
double equilibrium_residual(const FiniteStrainSystem& s, const Eigen::VectorXd& f,
                            const std::vector<bool>& fixed, double force_scale, double volume,
                            Eigen::VectorXd* r_u = nullptr);

}  // namespace skinfem
