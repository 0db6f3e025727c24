// Contact solves on a condensed skin (contact/condensed.hpp) for each friction mode of the scene:
//   none       frictionless;
//   static     the residual traction p_t = static_ratio·p acting while pressure and zone are solved;
//   uncoupled  the frictionless pressure and zone, then p_t = μ p added (the paper's assumption): the
//              tangential traction changes the readings and the gaps, not the pressure;
//   coupled    p_t = μ p acting while pressure and zone are solved (steady Coulomb slip along the
//              sliding direction): in a bonded incompressible layer the shear tilts the pressure.
// Each is an exact linear complementarity problem on the multipliers (contact/lcp.hpp). A linear interface
// (scene.hpp, Interface) adds its closure λ_i ∫ψ_i / K to every weighted gap: C_zz + diag(area/K).
//
// The friction law (scene.hpp, FrictionLaw) says what "traction" is: coulomb p_t = ratio·p as above;
// shear_strength p_t = τ wherever the skin touches; mixed both. Without holes τ acts on the active
// multipliers' hats. Where it acts while the pressure is solved (static, coupled) it is a load that depends
// on the active set: the LCP is re-solved with that load's gaps until the set repeats (a fixed point; two or
// three warm-started solves). An edge multiplier may touch without its own shear and lift under it (a
// cycle): it then holds the fraction of τ at which it just touches, found by bisection. With holes τ acts on
// the hole-free contact of the same mode minus the holes, lumped on the hats with the share of each hat
// outside them (contact/holes/cover.hpp): the hole removes exactly τ S_d, a point force that the plate
// does not put back on the rim, and the signal varies continuously with the hole's position. (Letting the
// holed contact's own edge decide would move whole hats of τ, each larger than τ S_d on the default scene,
// in and out of the load as the hole moves: noise, not physics.)
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <vector>

#include "skinfem/contact/condensed.hpp"
#include "skinfem/contact/lcp.hpp"
#include "skinfem/scene/laws.hpp"

namespace skinfem::contact {

struct ContactResult {
  FrictionMode mode = FrictionMode::none;
  double ratio = 0;        // p_t / p applied along the sliding direction (Coulomb part)
  double tau = 0;          // MPa, shear-strength part of p_t where the skin touches
  Eigen::VectorXd shear;   // n_c nodal shear-strength traction along the sliding direction, MPa (0: none)
  int partial_shear = 0;   // edge multipliers holding a fraction of τ (touching only without their shear)
  Eigen::VectorXd lambda;  // n_c nodal pressures, MPa (through hats a hole cuts: force over the whole hat)
  // n_c weighted gaps ∫ψ_i gap, mm³, in the final state (uncoupled: traction added); under a linear
  // interface the closure is included, ∫ψ_i (gap + p/K): the quantity held ≥ 0.
  Eigen::VectorXd gap;
  // A small hole's bulge (solve with a HoleDimple): n_c weighted openings ∫ψ_i w of the indenter's surface,
  // mm³, so gap − opening is the weighted gap to the indenter's face; empty for every other solve.
  Eigen::VectorXd opening;
  double depth_mm = 0;            // rigid approach of the indenter from first touch
  double force_N = 0;             // ∫ p dA
  double tangential_force_N = 0;  // ratio·force + ∫ shear
  Eigen::VectorXd readings;       // 2·sensors, MPa: σ_z of sensor k at 2k, σ_x at 2k + 1
  // Complementarity of the solved LCP (before an uncoupled traction is added), contact/lcp.hpp.
  double complementarity = 0, min_lambda = 0, min_gap = 0;
  int pivots = 0;
  std::vector<int> active;
};

// A contact condensed on the half y ≥ 0 of a mirror-symmetric skin (mesh/build.hpp's MeshPart::half_y),
// seen whole: the zone of the mirrored mesh (mesh/mirror.hpp) and, per whole multiplier, the half's
// multiplier it is or mirrors. On the half a multiplier on the cut carries half its hat (its row of C, its
// gap0 and area are halved) and one off the cut stands for itself and its image, so the half's problem at
// half the force is the whole one restricted to symmetric λ; with a P-matrix its solution is unique, hence
// symmetric, so the two agree (tests/contact/test_mirror_contact.cpp). Needs the indenter, its holes and
// the sliding direction symmetric too (pipeline/symmetry.hpp).
struct MirrorView {
  MortarZone zone;        // on the whole mesh
  std::vector<int> half;  // zone.size(): the half's multiplier each whole one is or mirrors
};

// whole: mirror_half(half mesh, &source); half_zone: the half's zone about `center` (on y = 0) of `radius`.
// Throws std::invalid_argument if the whole zone is not the half's and its image.
MirrorView mirror_view(const TetMesh& whole, const std::vector<int>& source, const MortarZone& half_zone,
                       const Vec2& center, double radius);

// A small hole as the bulge it lets the skin make (contact/holes/dimple.hpp): the weighted gaps it opens,
// and its cut of the shear.
struct HoleDimple {
  Eigen::VectorXd opening;  // per solved multiplier (the half's under a mirror view), mm³
  // Per solved multiplier, 1 where the hole-free contact presses: the contact set of the outer solution, kept
  // (its answer to a point dilatation is linear in it; the set's motion is of higher order), the hats in it
  // bilateral and the others out of contact.
  std::vector<char> in_contact;
  Eigen::VectorXd covered;  // per whole multiplier, the share of its hat under the hole (hole_cover)
};

class ContactSolver {
 public:
  // mirror: null when `condensed` is the whole skin's; else its whole view (kept by the caller). Results,
  // excluded flags, warm starts and active sets are then the whole zone's (zone()).
  ContactSolver(const CondensedContact& condensed, const ContactLoad& load,
                const MirrorView* mirror = nullptr);

  // excluded: per multiplier, 1 where the indenter is absent (a hole); warm: an active set to start from;
  // covered: empty or, per multiplier, the share of its hat under a hole (hole_cover; the shear's cut).
  // Throws std::runtime_error when the shear's touched set does not settle.
  ContactResult solve(FrictionMode mode, const std::vector<char>& excluded = {},
                      const std::vector<int>& warm = {}, const Eigen::VectorXd& covered = {}) const;
  // A hole that cuts the hats on its exact disc (contact/holes/cut.hpp; needs condensed().path): `cut` is the
  // solved problem's (the half's under a mirror view), warm the whole zone's active set. Multipliers with
  // less than 1e-9 of their hat outside the hole drop out (their rows have vanished with it). The result's
  // λ_i is hat i's force over its whole area (the nodal pressure times the share outside the hole).
  ContactResult solve(FrictionMode mode, const HoleCut& cut, const std::vector<int>& warm = {}) const;
  // The same from the cut's problem (cut_problem(condensed(), cut, true)), which depends on the hole alone:
  // sweeps of several laws or modes over the same positions share it (HoleCuts, holes/sweep.hpp).
  ContactResult solve(FrictionMode mode, const CutProblem& cp, const std::vector<int>& warm = {}) const;
  // A small hole as a bulge (contact/holes/dimple.hpp): the hole-free problem with the dimple's gaps opened
  // on its contact set (solved on the stored reference, set_reference), the shear-strength part cut by
  // `covered`. Throws std::invalid_argument under an interface that is not hard. Several threads may call
  // it at once after set_reference(mode, …), as long as set_reference is not called meanwhile.
  ContactResult solve(FrictionMode mode, const HoleDimple& dimple) const;
  // From now on solves of `mode` reuse the factorized principal system of this active set (sweeps). It also
  // builds what solves of `mode` would build on first use (τ0 and the touched set under a shear strength).
  void set_reference(FrictionMode mode, const std::vector<int>& active) const;
  double ratio(FrictionMode mode) const;  // Coulomb part p_t / p of `mode`
  // The Coulomb ratio below which force control has exactly one solution (+inf: every ratio): there the
  // symmetric part of C_zz + ratio C_zt (+ the interface's closure) is positive definite, so the LCP matrix
  // is a P-matrix (Cottle, Pang & Stone, The Linear Complementarity Problem, thm 3.3.7). A sufficient bound:
  // a larger ratio may still solve. Its smallest generalized eigenvalue, O(n³) on the multipliers.
  double unique_ratio_bound() const;
  double shear(FrictionMode mode) const;  // shear-strength part of `mode`, MPa
  // τ0 of the scene, MPa: contact.friction.tau0, else μ F / A with F and A the force and the area Σ∫ψ_i
  // of the active multipliers of the hole-free frictionless contact (so the sliding shear totals μF).
  double tau0() const;
  FrictionLaw law() const { return load_.law; }
  const ContactLoad& load() const { return load_; }
  // Where the hole-free contact of `mode` touches, per whole multiplier: 1 if active, 0 if not, the
  // fraction of the shear an edge multiplier holds (ContactResult::partial_shear). The shear of a holed
  // contact is τ·touched·(1 − covered).
  const Eigen::VectorXd& touched(FrictionMode mode) const;
  bool force_controlled() const { return load_.force.has_value(); }
  // The problem as solved (the half's under a mirror view): holes/small_hole.hpp works on its matrices.
  const CondensedContact& condensed() const { return c_; }
  // The zone results refer to: the whole one.
  const MortarZone& zone() const { return mirror_ ? mirror_->zone : c_.zone; }
  bool mirrored() const { return mirror_ != nullptr; }  // solved on the half y >= 0
  const Eigen::Vector2d& direction() const { return c_.direction; }
  // Whole multiplier i's index in condensed(), and the share of a gap opening at i that its row sees (½
  // under a mirror view: an opening at i and its image average to that row's; 1 otherwise).
  int solved_index(int i) const { return mirror_ ? mirror_->half[i] : i; }
  // A set of whole multipliers as the solved problem's (ascending, each once).
  std::vector<int> solved_set(const std::vector<int>& whole) const;
  // A set of the solved problem's multipliers as the whole zone's (ascending).
  std::vector<int> whole_set(const std::vector<int>& solved) const;
  double opening_share() const { return mirror_ ? 0.5 : 1.0; }
  // Sensor readings (2·sensors, MPa) of whole-zone multipliers λ (symmetric under a mirror view) with
  // traction ratio·p.
  Eigen::VectorXd readings(const Eigen::VectorXd& lambda, double ratio,
                           const Eigen::VectorXd& shear = {}) const;
  // λ on the solved problem's multipliers (the half's values of a symmetric λ).
  Eigen::VectorXd solved_lambda(const Eigen::VectorXd& lambda) const;

 private:
  SceneError no_consistent_set(FrictionMode mode, const LcpSolution& s) const;
  ContactLcp& lcp(double ratio) const;
  // C_zz with the interface's closure: the LCP matrix without friction.
  Eigen::MatrixXd frictionless_matrix() const;
  // A result with its mode, Coulomb ratio and shear strength set.
  ContactResult started(FrictionMode mode) const;
  // The Coulomb ratio acting while the pressure is solved: none in the uncoupled mode.
  double solved_ratio(FrictionMode mode) const;
  // The result's common tail: depth, diagnostics, and λ, gaps and active set seen whole.
  void finish(ContactResult& out, const LcpSolution& s, const Eigen::VectorXd& gap,
              const std::vector<char>& excluded) const;
  // Weighted gaps of the solved multipliers as the whole zone's (a cut row on the half is half its own).
  Eigen::VectorXd whole_gaps(const Eigen::VectorXd& solved) const;
  Eigen::VectorXd solved_readings(const Eigen::VectorXd& solved_lambda, double ratio) const;
  const CondensedContact& c_;
  ContactLoad load_;
  const MirrorView* mirror_;
  std::vector<int> images_;  // under a mirror view, per half multiplier: 1 on the cut, else 2
  mutable std::map<double, std::unique_ptr<ContactLcp>> lcps_;
  mutable std::optional<double> tau0_;
  mutable std::map<FrictionMode, Eigen::VectorXd> touched_;
};

// The first of the holes (discs, grooves) holding mesh node v strictly inside (seen from above), −1 if none.
int hole_holding(const TetMesh& mesh, int v, const std::vector<Hole>& holes);
// Multipliers whose vertex lies strictly inside one of the holes (the indenter is absent there).
std::vector<char> excluded_by_holes(const MortarZone& zone, const TetMesh& mesh,
                                    const std::vector<Hole>& holes);
// A hole in the contact that the mesh cannot see (require_hole_resolved).
struct HoleUnresolved : SceneError {
  using SceneError::SceneError;
};
// Throws HoleUnresolved when `hole` holds no multiplier's vertex although the vertex nearest its centre is in
// contact (`active`: zone indices): the indenter is absent there and the mesh cannot see it, so the signal
// would read zero for "not resolved". `where` names the hole in the message (its scene field).
void require_hole_resolved(const MortarZone& zone, const TetMesh& mesh, const Hole& hole,
                           const std::vector<int>& active, const std::string& where);

}  // namespace skinfem::contact
