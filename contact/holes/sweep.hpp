// A hole in the indenter swept along a path through the contact (the paper's §IV): at every position a
// full contact solve, and the signal ς = reading with the hole − reading without, for every sensor.
// Everything that does not depend on the hole's position is reused: the condensed skin, the LCP matrix,
// the factorized principal system of the hole-free active set (low-rank updates, contact/lcp.hpp), and
// the previous position's active set as warm start.
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "skinfem/contact/contact_solver.hpp"
#include "skinfem/contact/holes/dimple.hpp"

namespace skinfem::contact {

struct SweepResult {
  FrictionMode mode = FrictionMode::none;
  std::vector<Vec2> centers;  // hole centre at each position, mm
  ContactResult baseline;     // no hole
  Eigen::MatrixXd varsigma;   // positions × 2·sensors, MPa (σ_z of sensor k in column 2k, σ_x in 2k + 1)
  std::vector<int> pivots;    // LCP pivots per position
  double max_complementarity = 0;
  double seconds = 0;
};

// The largest |ς_z| over sensors and positions of a sweep's varsigma (MPa).
double largest_varsigma_z(const Eigen::MatrixXd& varsigma);

// The hole's centre at position i of the sweep (evenly spaced from sweep.from to sweep.to).
Vec2 sweep_center(const HoleSweep& sweep, int i);

// A resolved sweep's cut problems, one per position (with their tangential parts): they depend on the
// condensed skin and the hole alone, so the sweeps of several friction laws, interfaces and modes over the
// same positions share them (80 % of a resolved sweep's time on the default scene). None (nullopt) when
// they would hold more than max_mb (a long sweep): then each sweep computes its own, position by position.
struct HoleCuts {
  std::vector<CutProblem> at;
};
std::optional<HoleCuts> hole_cuts(const CondensedContact& condensed, const HoleSweep& sweep, double max_mb);

// The hole per sweep.model: HoleModel::bulge through `dimples` (required then; contact/holes/dimple.hpp),
// resolved by cutting the hats (needs solver.condensed().path, contact/holes/cut.hpp; without a path, by
// removing the multipliers whose vertex it holds). frame(i, result) is called for each position in order, on
// the calling thread (to write its pressure map, report progress). cuts: hole_cuts(solver.condensed(),
// sweep), or none (computed per position). material_centres: per position, where the hole's centre (in
// space) lies on the reference skin, for a solver on a deformed state's tangent (contact/finite_contact.hpp's
// tangent_contact: the hole acts on the material under it); empty for the centres themselves, bulge sweeps
// only. A bulge sweep's positions are solved on the machine's cores. Throws std::invalid_argument for a
// bulge sweep without dimples, or material centres with another hole model or another count.
SweepResult hole_sweep(const ContactSolver& solver, const TetMesh& mesh, const HoleSweep& sweep,
                       FrictionMode mode, const HoleDimples* dimples,
                       const std::function<void(int, const ContactResult&)>& frame = {},
                       const HoleCuts* cuts = nullptr, const std::vector<Vec2>& material_centres = {});

}  // namespace skinfem::contact
