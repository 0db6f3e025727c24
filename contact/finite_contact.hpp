// Contact of a rigid plane or sphere with the finite-strain skin (fem/finite_strain.hpp), force controlled:
// the indenter meets the deformed surface x = X + u. A plane is frictionless or in steady sliding under
// Coulomb friction, a shear strength τ wherever the skin touches, or both (scene/laws.hpp's friction laws); a
// sphere the same, its drag along its surface.
//
// Mortar multipliers on the reference top (contact/mortar.hpp): λ_i is the nodal pressure per unit of the
// hat's reference horizontal area. Under a plane it pushes along −e_z with the friction traction ratio·λ
// along the sliding direction t (dead directions: the plate's normal and its sliding direction do not
// turn); because the plate is flat, the weighted gap is exactly linear in u, g_i = gap0_i − δ·area_i −
// (D u_z)_i, whatever the lateral motion, and the nonlinearity is the skin's alone. Under a sphere (centre
// c − δ e_z, radius R) the gap is the normal one on the displaced top, g_i = ∫ψ_i (|x + u − c| − R), and λ
// pushes along the sphere's normal there (MortarZone::sphere_gaps): both turn with the surface. A sliding
// sphere's drag (ratio·λ, a shear strength's τ) acts along its tangent s ∝ t − (t·n) n there (Dt), and the
// force is the sphere's whole downward load Σ λ_i m_i + Σ (ratio·λ_i + τ_i) mt_i, the drag's part included
// (taken at the iterate's λ and τ, exact once they settle). Each Newton iterate solves, on the tangent at
// (u_k, p_k), the condensed complementarity problem of contact/lcp.hpp:
//   M = C_zz + ratio·C_zt (the tangent's compliances, condensed.hpp's definitions; a sphere's along its
//       normals and tangents at the iterate: Dn K⁻¹ Dnᵀ, Dn K⁻¹ Dtᵀ),
//   q = gap0 − D_z (u_k + du_r) (a plane), g_k + δ_k m + Dn du_r (a sphere),  du_r the tangent's answer
//       to the residual alone,
// then steps to u_k + du_r + (the multipliers' answer). A shear strength's traction τ acts on the touched
// hats, a load that depends on the set: its gaps C_zt·τw join q and the iterate's set is iterated to a fixed
// point with contact_solver.hpp's rules (w: 1 on touched hats, the fraction at which an edge hat just
// touches). This is Newton's method on the whole complementarity system (Josephy-Newton): once the active set
// stops changing it is Newton on a smooth system, quadratic (a sphere's tangent includes its pressures'
// turning with the surface, at the last iterate's λ; not its drag's, whose derivative is not symmetric while
// the tangent is factored LDLᵀ, so a sliding sphere's Newton is linear, dividing the residual each iterate by
// about ratio·p h / (μ R): 0.02 on a 3 mm layer under R = 20 mm at 0.3 N, tests/contact/test_finite_sphere).
// The first iterate from rest is the linear contact exactly under a plane. Load path: the normal force ramps
// to F frictionless, then the ratio and τ ramp together to their values at F, in adaptive steps (a step that
// fails is halved). Units: mm, N, MPa.
#pragma once

#include <Eigen/Dense>
#include <functional>
#include <optional>
#include <vector>

#include "skinfem/contact/condensed.hpp"
#include "skinfem/contact/indenter.hpp"
#include "skinfem/contact/mortar.hpp"
#include "skinfem/fem/mixed_solver.hpp"
#include "skinfem/fem/newton.hpp"

namespace skinfem::contact {

struct FiniteContactLoad {
  double force = 0;                 // N, the plate's total normal force on the solved skin (> 0)
  double ratio = 0;                 // Coulomb p_t / p acting while the contact is solved (coupled), ≥ 0
  Eigen::Vector2d direction{1, 0};  // unit sliding direction in the (x, y) plane
  // n_c weighted gaps opened where the plate's face recedes (a hole's dimple, contact/holes/dimple.hpp), mm³;
  // empty for none.
  Eigen::VectorXd opening;
  // The shear strength acting wherever the skin touches, MPa: tau when given, else tau_mu·F/A with A the
  // reference area Σ∫ψ_i of the active multipliers of the path's frictionless contact at F (the linear
  // contact's τ0 from_force, ContactSolver::tau0); neither: none.
  std::optional<double> tau;
  double tau_mu = 0;
};

struct FiniteContactStep {
  double force = 0, ratio = 0;    // what this step reached
  double tau = 0;                 // MPa
  std::vector<double> residuals;  // relative equilibrium residual after each iteration
  std::vector<int> active_sizes;  // the LCP's active set size at each iteration
  std::vector<int> set_changes;   // multipliers that entered or left the set at each iteration (0: repeated)
};

// A contact zone seen in one frame: the active multipliers' vertices at their reference positions X or their
// current ones X + u (both horizontal).
struct ContactZoneFrame {
  double area_mm2 = 0;               // Σ ∫ψ_i over the active multipliers (reference hats in both frames)
  Vec2 zone_centroid{0, 0};          // the active hats' area-weighted centroid, mm
  Vec2 force_centroid{0, 0};         // Σ λ_i area_i x_i / Σ λ_i area_i: where the plate's force acts, mm
  double front_mm = 0, back_mm = 0;  // farthest active vertex ahead of / behind `center` along t
  double half_width_mm = 0;          // largest |offset across t| of an active vertex from `center`
  // The pressure's second moments about force_centroid, along t and across it: smooth in the load where the
  // vertex-based sizes above step as a vertex enters or leaves. moment_radius_mm = √(5/2 ⟨|x − x_f|²⟩_p) is
  // a for a Hertzian p = p0 √(1 − r²/a²); moment_anisotropy = √(⟨(x − x_f)·t)²⟩_p / ⟨((x − x_f)·n)²⟩_p), 1
  // for an axisymmetric contact.
  double moment_radius_mm = 0, moment_anisotropy = 0;
  // The vertex-based length along t over width across, (front + back) / (2 half_width); 0 for no zone.
  double anisotropy() const { return half_width_mm > 0 ? (front_mm + back_mm) / (2 * half_width_mm) : 0.0; }
};

struct FiniteContactResult {
  MixedSolution solution;            // u (3N, mm), p (Nv, MPa)
  Eigen::VectorXd internal_force;    // 3N at the solution: at held DOFs the supports' reactions (N)
  Eigen::VectorXd load;              // 3N: the plate's load on the skin at the solution (N)
  Eigen::VectorXd lambda;            // n_c nodal pressures, MPa
  Eigen::VectorXd gap;               // n_c weighted gaps at the solution, mm³
  double depth_mm = 0;               // the plate's approach from first touch
  double ratio = 0;                  // the friction ratio solved at
  double tau = 0;                    // the shear strength solved at, MPa
  Eigen::VectorXd shear;             // n_c nodal shear traction along t, MPa (zero without a shear strength)
  int partial_shear = 0;             // edge multipliers holding a fraction of τ
  double frictionless_area_mm2 = 0;  // the path's frictionless contact's A (τ's from tau_mu), mm²
  std::vector<int> active;           // multipliers in contact, ascending
  double complementarity = 0;        // of the last LCP (contact/lcp.hpp's measure)
  std::vector<FiniteContactStep> steps;
  int rejected_steps = 0;
  int factorizations = 0;  // tangents factored (one per iteration)
};

// Called with each load step as it converges.
using FiniteContactStepSink = std::function<void(const FiniteContactStep&)>;

// mesh: the skin (a half mesh's cut held by `fixed`); fixed: 3N held DOFs (base, cut), not moved;
// zone: the candidate multipliers; indenter: a plane or a sphere; mu: shear modulus, MPa. Throws SolverError
// (one line: the force and ratio reached, and why) when no step converges. from: null to start at rest and
// follow the load path; or a converged state of the same force: at the same ratio (another opening) one step
// goes straight to `load`; at a smaller ratio (the frictionless state shared by a static and a sliding case)
// the ratio's and τ's path goes on from it.
FiniteContactResult solve_finite_contact(const TetMesh& mesh, double mu, const std::vector<bool>& fixed,
                                         const MortarZone& zone, const Indenter& indenter,
                                         const FiniteContactLoad& load, const NewtonOptions& options = {},
                                         const FiniteContactStepSink& on_step = {},
                                         const FiniteContactResult* from = nullptr);

// The contact linearized about r's converged state (a solve of `load`): the condensed skin of
// contact/condensed.hpp on the tangent at (u, p), its compliances C_zz, C_zt and readings S_p, S_t (sensor
// readings of the base's reactions, `readings` on mesh), with gap0 set so that the weighted gaps are
// g = gap0 − δ·area + (C_zz + ratio·C_zt) λ + C_zt·shear to first order about (λ, δ, shear) of r: the
// complementarity problem on it (with r's shear where r has one) has r's λ and δ as its solution, and a small
// change of the gaps (a hole's opening) moves the contact and the readings by its derivative. One
// factorization of the tangent, bordered by the columns.
CondensedContact tangent_contact(const TetMesh& mesh, double mu, const std::vector<bool>& fixed,
                                 const MortarZone& zone, const Indenter& indenter,
                                 const SensorReadings& readings, const FiniteContactLoad& load,
                                 const FiniteContactResult& r);

// The zone of `r` in the reference frame (u = 0) or the current one (u = r.solution.u), about `center`
// along the sliding direction t.
ContactZoneFrame zone_frame(const TetMesh& mesh, const MortarZone& zone, const FiniteContactResult& r,
                            const Vec2& center, const Eigen::Vector2d& t, bool current);
// The same for any contact: active multipliers of `zone`, their pressures λ (MPa), and u (3N, mm) for the
// current frame or null for the reference one.
ContactZoneFrame zone_frame(const TetMesh& mesh, const MortarZone& zone, const std::vector<int>& active,
                            const Eigen::VectorXd& lambda, const Eigen::VectorXd* u, const Vec2& center,
                            const Eigen::Vector2d& t);

}  // namespace skinfem::contact
