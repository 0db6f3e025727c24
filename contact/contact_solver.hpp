// Contact solves on a condensed skin (contact/condensed.hpp) for each friction mode of the scene:
//   none       frictionless;
//   static     the residual traction p_t = static_ratio·p acting while pressure and zone are solved;
//   uncoupled  the frictionless pressure and zone, then p_t = μ p added (the paper's assumption): the
//              tangential traction changes the readings and the gaps, not the pressure;
//   coupled    p_t = μ p acting while pressure and zone are solved (steady Coulomb slip along the
//              sliding direction): in a bonded incompressible layer the shear tilts the pressure.
// Each is an exact linear complementarity problem on the multipliers (contact/lcp.hpp).
#pragma once

#include <map>
#include <memory>
#include <vector>

#include "contact/condensed.hpp"
#include "contact/lcp.hpp"

namespace skinfem::contact {

const char* to_string(FrictionMode mode);

struct ContactResult {
  FrictionMode mode = FrictionMode::none;
  double ratio = 0;        // p_t / p applied along the sliding direction
  Eigen::VectorXd lambda;  // n_c nodal pressures, MPa
  Eigen::VectorXd gap;  // n_c weighted gaps ∫ψ_i gap, mm³, in the final state (uncoupled: traction added)
  double depth_mm = 0;  // rigid approach of the indenter from first touch
  double force_N = 0;   // ∫ p dA
  double tangential_force_N = 0;
  Eigen::VectorXd readings;  // 2·sensors, MPa: σ_z of sensor k at 2k, σ_x at 2k + 1
  // Complementarity of the solved LCP (before an uncoupled traction is added), contact/lcp.hpp.
  double complementarity = 0, min_lambda = 0, min_gap = 0;
  int pivots = 0;
  std::vector<int> active;
};

class ContactSolver {
 public:
  ContactSolver(const CondensedContact& condensed, const ContactLoad& load);

  // excluded: per multiplier, 1 where the indenter is absent (a hole); warm: an active set to start from.
  ContactResult solve(FrictionMode mode, const std::vector<char>& excluded = {},
                      const std::vector<int>& warm = {}) const;
  // From now on solves of `mode` reuse the factorized principal system of this active set (sweeps).
  void set_reference(FrictionMode mode, const std::vector<int>& active) const;
  double ratio(FrictionMode mode) const;
  bool force_controlled() const { return load_.force.has_value(); }
  const CondensedContact& condensed() const { return c_; }

 private:
  ContactLcp& lcp(double ratio) const;
  const CondensedContact& c_;
  ContactLoad load_;
  mutable std::map<double, std::unique_ptr<ContactLcp>> lcps_;
};

// Multipliers whose vertex lies strictly inside one of the holes (the indenter is absent there).
std::vector<char> excluded_by_holes(const MortarZone& zone, const TetMesh& mesh,
                                    const std::vector<Hole>& holes);

}  // namespace skinfem::contact
