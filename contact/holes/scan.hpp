// A textured plate scanned over the skin (contact.texture, contact.scan; the paper's conclusion: the
// response to "any number of such holes"): at every position of the plate every hole over the zone cuts
// the multipliers' hats on its exact disc (contact/holes/cut.hpp), and the full contact is solved with its
// contact set free. ς = reading with the holes − without, for every sensor.
//
// Beside it, the paper's linear prediction: Σ_k ς_k(u), ς_k the signal of hole k alone on the plate (its
// "dynamic response function", the single-hole sweep of `skinfem defect` along its track). The holes' cuts
// add (B, area and gap0 are integrals over disjoint discs), but the cut compliance does not (C_zz' holds
// B_k Gzz B_lᵀ: the skin under one hole answers the load missing at the other) and the contact set is
// free: the difference between the two is the interaction of the holes, in the model.
#pragma once

#include <functional>
#include <vector>

#include "skinfem/contact/contact_solver.hpp"

namespace skinfem::contact {

// The cut of disjoint holes: the sum of their cuts (contact/holes/cut.hpp). n_holes: how many of them cut a
// hat (the others miss the watched faces). mirrored: the path is the half y >= 0's of a mirror-symmetric
// texture: a hole below y = 0 is the image of one above it and is cut with it (left out here), and a hole
// above y = 0 counts with its image (twice).
struct TextureCut {
  HoleCut cut;
  int n_holes = 0;
};
TextureCut texture_cut(const PathCompliance& path, int n_c, const std::vector<Hole>& holes,
                       bool mirrored = false);

struct ScanResult {
  FrictionMode mode = FrictionMode::none;
  std::vector<double> u;      // mm, the plate's displacement at each position
  ContactResult baseline;     // no hole
  Eigen::MatrixXd varsigma;   // positions × 2·sensors, MPa (σ_z of sensor k in column 2k, σ_x in 2k + 1)
  std::vector<int> holes_in;  // per position, the holes cutting a hat
  std::vector<int> pivots;    // LCP pivots per position
  double max_complementarity = 0;
  double seconds = 0;
};

// The scan of `plate` (the holes at u = 0) moving along the unit `direction`, at the positions u (mm):
// needs solver.condensed().path watching every track (pipeline/contact_setup.hpp). frame(i, result,
// holes) is called for each position in order on the calling thread, with the holes (in space) that cut a
// hat there. The positions' cut problems are built on the machine's cores, the solves run in order, each
// warm-started from the previous position's active set. Throws std::invalid_argument without a path.
ScanResult texture_scan(
    const ContactSolver& solver, const std::vector<Hole>& plate, const Vec2& direction,
    const std::vector<double>& u, FrictionMode mode,
    const std::function<void(int, const ContactResult&, const std::vector<Hole>&)>& frame = {});

// The linear prediction Σ_k ς_k(u) at the same positions (positions × 2·sensors, MPa), ς_k from the scan of
// hole k alone. Holes that sit at the same place in space at some positions (a row whose period is a
// multiple of the step) share those solves. solves: how many single-hole contacts it took. On a mirrored
// solver (the half of a mirror-symmetric texture) a hole off y = 0 can only be solved with its image: its
// term is the pair's, so the difference leaves out the interaction of each hole with its own image
// (mirror_pair_solves of the solves were pairs).
struct Superposition {
  Eigen::MatrixXd varsigma;
  int solves = 0, mirror_pair_solves = 0;
  double seconds = 0;
};
Superposition superposed_scan(const ContactSolver& solver, const std::vector<Hole>& plate,
                              const Vec2& direction, const std::vector<double>& u, FrictionMode mode);

}  // namespace skinfem::contact
