// One Fourier mode of an axisymmetric skin on its meridian (green/meridian.hpp states the modes, strains and
// axis conditions), assembled and factored once for any number of solves: the adjoint Green maps
// (prescribed base displacements, no load) and the meridian contact (loads on the top, base held) share it.
//
// Fields and loads are the mode's amplitudes: mode 0 u_r = U, u_z = W; mode 1 u_r = U cos θ, u_θ = V sin θ,
// u_z = W cos θ. A load's nodal amplitude is the work-conjugate of its displacement amplitude, with the angle
// integrated: a traction τ_z(r) (mode 0) gives ∫ τ_z φ_k 2πr dr on node k's W; a traction τ(r) e_x (mode 1,
// τ_r = τ cos θ, τ_θ = −τ sin θ) gives π ∫ τ φ_k r dr on U and −π ∫ τ φ_k r dr on V. Units: mm, N, MPa.
#pragma once

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <memory>
#include <vector>

#include "skinfem/green/meridian.hpp"

namespace skinfem {

class MumpsLdlt;

// 1D P2 Lagrange basis on u ∈ [0, 1] with nodes 0, 1/2, 1 (an edge's end, middle, end) and its derivative.
void meridian_p2_line(double u, double L[3], double dL[3]);
// The parameter u ∈ [0, 1] at which an edge with node radii r0, r1 (middle), r2 reaches rho: Newton on the
// quadratic map from the linear guess (the map is monotone: mid-edge nodes sit between the ends).
double meridian_edge_parameter(double r0, double r1, double r2, double rho);

// The edge of nodes (s, s+1, s+2) of radii r (by increasing r, vertices at even indices) holding rho,
// clamped to r's range: returns s and writes the edge's P2 weights at rho into L.
size_t meridian_p2_weights(const std::vector<double>& r, double rho, double L[3]);
// A P2 field f along nodes of radii r (by increasing r, vertices at even indices) at radius rho, clamped.
double meridian_interpolate(const std::vector<double>& r, const Eigen::Ref<const Eigen::VectorXd>& f,
                            double rho);

class MeridianMode {
 public:
  struct Fields {
    Eigen::MatrixXd U, V, W;  // N × columns each (V empty in mode 0); an empty matrix reads as zero
    Eigen::MatrixXd P;  // the pressure's amplitude at the vertices (num_vertices × columns); solve only
  };
  struct Cost {
    double assemble_s = 0, factor_s = 0, solve_s = 0;
  };
  // mode: 0 or 1. shear_modulus μ, MPa (displacements scale as 1/μ). held: nodes whose every component
  // solve() prescribes (the base; a post's wall and top). A held side (SideCondition::fixed) is zero.
  // Throws std::runtime_error on an inverted element.
  // compliance_nodes (optional): nodes whose W compliance the factorization returns as well (compliance()),
  // from MUMPS's Schur complement on their W unknowns instead of one solve per node.
  MeridianMode(const MeridianMesh& mesh, int mode, double nu, double shear_modulus, SideCondition side,
               std::vector<int> held, const std::vector<int>& compliance_nodes = {});
  ~MeridianMode();
  MeridianMode(MeridianMode&&) noexcept;

  // held_values: |held| × columns per component, in `held`'s order (empty: zero); load: N × columns per
  // component (empty: none). Returns every node's displacement amplitudes.
  Fields solve(const Fields& held_values, const Fields& load, int columns) const;
  // The support's nodal forces on the skin, K u − f (N), non-zero only on constrained nodes; u as solve
  // returns it (with its pressure).
  Fields reactions(const Fields& u, const Fields& load) const;

  // |compliance_nodes|²: W at node i under a unit nodal force along z at node j (every other load zero, the
  // held nodes at rest), mm/N; in compliance_nodes' order. Empty without compliance nodes.
  const Eigen::MatrixXd& compliance() const { return compliance_; }
  int mode() const { return mode_; }
  int dofs() const { return free_; }  // free unknowns (displacements and pressures)
  const Cost& cost() const { return cost_; }

 private:
  // Full-length (all DOFs) column block of f's components.
  Eigen::MatrixXd gather(const Fields& f, int columns, const std::vector<int>* nodes) const;
  Fields scatter(const Eigen::MatrixXd& full) const;

  int mode_, nc_, n_, nv_;
  std::vector<int> held_;
  std::vector<char> fixed_;
  std::vector<int> index_;    // free unknown of each DOF (a tied DOF shares its partner's), −1 when fixed
  std::vector<double> sign_;  // −1 on a tied DOF (mode 1: V = −U on the axis)
  Eigen::SparseMatrix<double>
      Kc_;  // ndof × ndof: the rows of constrained DOFs (fixed or tied away), all columns
  std::unique_ptr<MumpsLdlt> solver_;
  int free_ = 0;
  // With compliance nodes their W unknowns are the last `schur_` free ones, outside the factorization: a
  // solve eliminates them through the Schur complement S (its LDLᵀ) and the coupling block K_is.
  int schur_ = 0;
  Eigen::SparseMatrix<double> coupling_;  // (free − schur) × schur
  Eigen::LDLT<Eigen::MatrixXd> schur_ldlt_;
  Eigen::MatrixXd compliance_;
  mutable Cost cost_;
};

// The traction a support exerts along the meridian's base from its nodal reactions (fem/base_traction.hpp in
// 3D): the P2 field t along r with ∫ t φ_k (angular) r dr = R_k, angular = 2π in mode 0, π in mode 1.
class MeridianTrace {
 public:
  // nodes: the base's nodes by increasing r (MeridianMesh::base).
  MeridianTrace(const MeridianMesh& mesh, std::vector<int> nodes, double angular);
  // Nodal traction amplitudes (|nodes| × columns) from reactions at every node (N × columns).
  Eigen::MatrixXd traction(const Eigen::MatrixXd& reactions) const;
  // M⁻¹ b for loads b on the trace's nodes (|nodes| × columns).
  Eigen::MatrixXd solve_mass(const Eigen::MatrixXd& b) const;
  // A nodal field's value at radius rho (clamped to the trace).
  double value(const Eigen::Ref<const Eigen::VectorXd>& t, double rho) const;
  const std::vector<int>& nodes() const { return nodes_; }
  const std::vector<double>& radii() const { return r_; }

 private:
  std::vector<int> nodes_;
  std::vector<double> r_;
  Eigen::LDLT<Eigen::MatrixXd> mass_;
};

}  // namespace skinfem
