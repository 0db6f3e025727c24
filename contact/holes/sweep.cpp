#include "skinfem/contact/holes/sweep.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "skinfem/contact/holes/cover.hpp"
#include "skinfem/contact/holes/cut.hpp"
#include "skinfem/scene/parallel.hpp"

namespace skinfem::contact {

double largest_varsigma_z(const Eigen::MatrixXd& varsigma) {
  double peak = 0;
  for (int j = 0; j < varsigma.cols(); j += 2) peak = std::max(peak, varsigma.col(j).cwiseAbs().maxCoeff());
  return peak;
}

Vec2 sweep_center(const HoleSweep& sweep, int i) {
  const double s = sweep.positions > 1 ? double(i) / (sweep.positions - 1) : 0.0;
  return {sweep.from[0] + s * (sweep.to[0] - sweep.from[0]),
          sweep.from[1] + s * (sweep.to[1] - sweep.from[1])};
}

std::optional<HoleCuts> hole_cuts(const CondensedContact& condensed, const HoleSweep& sweep, double max_mb) {
  if (!condensed.path) throw std::invalid_argument("hole_cuts: the condensed skin has no hole path");
  HoleCuts out;
  out.at.resize(sweep.positions);
  double bytes = 0;
  // The positions are independent (each reads the condensed skin only): a chunk at a time on the machine's
  // cores, the bound checked after each, so that at most one chunk is computed past it.
  constexpr int kChunk = 16;
  for (int first = 0; first < sweep.positions; first += kChunk) {
    const int n = std::min(kChunk, sweep.positions - first);
    for_each_index(n, [&](std::size_t k) {
      const int i = first + static_cast<int>(k);
      out.at[i] = cut_problem(
          condensed,
          hole_cut(*condensed.path, condensed.zone.size(), Hole{sweep_center(sweep, i), sweep.hole_diameter}),
          true);
    });
    for (int i = first; i < first + n; ++i) {
      const CutProblem& c = out.at[i];
      for (const Eigen::MatrixXd* m : {&c.zz, &c.zt_rows, &c.zt_cols, &c.zt_whole, &c.sp, &c.st})
        bytes += 8.0 * static_cast<double>(m->size());
      bytes += 8.0 * static_cast<double>(c.gap0.size() + c.area.size()) + 4.0 * c.rows.size();
    }
    if (bytes > max_mb * 1024 * 1024) return std::nullopt;
  }
  return out;
}

SweepResult hole_sweep(const ContactSolver& solver, const TetMesh& mesh, const HoleSweep& sweep,
                       FrictionMode mode, const HoleDimples* dimples,
                       const std::function<void(int, const ContactResult&)>& frame, const HoleCuts* cuts,
                       const std::vector<Vec2>& material_centres) {
  if (cuts && static_cast<int>(cuts->at.size()) != sweep.positions)
    throw std::invalid_argument("hole_sweep: the cuts are another sweep's");
  if (sweep.model == HoleModel::bulge && !dimples)
    throw std::invalid_argument("hole_sweep: a bulge sweep needs the hole's dimples");
  if (!material_centres.empty() &&
      (sweep.model != HoleModel::bulge || static_cast<int>(material_centres.size()) != sweep.positions))
    throw std::invalid_argument("hole_sweep: material centres are for bulge sweeps, one per position");
  const auto start = std::chrono::steady_clock::now();
  SweepResult out;
  out.mode = mode;
  out.baseline = solver.solve(mode);
  solver.set_reference(mode, out.baseline.active);
  const int n = sweep.positions;
  out.varsigma.resize(n, out.baseline.readings.size());
  // A bulge's positions are independent (no warm start: each solves on the stored reference): on the
  // machine's cores, each in its own slot.
  std::vector<ContactResult> bulged;
  if (sweep.model == HoleModel::bulge) {
    bulged.resize(n);
    for_each_index(n, [&](std::size_t i) {
      const Hole at{material_centres.empty() ? sweep_center(sweep, static_cast<int>(i)) : material_centres[i],
                    sweep.hole_diameter};
      bulged[i] = solver.solve(mode, (*dimples)(at, out.baseline.lambda));
    });
  }
  std::vector<int> warm = out.baseline.active;
  for (int i = 0; i < n; ++i) {
    const Vec2 c = sweep_center(sweep, i);
    out.centers.push_back(c);
    const std::vector<Hole> hole{Hole{c, sweep.hole_diameter}};
    ContactResult r;
    if (sweep.model == HoleModel::bulge) {
      r = std::move(bulged[i]);
    } else if (cuts) {
      r = solver.solve(mode, cuts->at[i], warm);
    } else if (const auto& path = solver.condensed().path) {
      r = solver.solve(mode, hole_cut(*path, solver.condensed().zone.size(), hole[0]), warm);
    } else {
      r = solver.solve(mode, excluded_by_holes(solver.zone(), mesh, hole), warm,
                       solver.shear(mode) != 0 ? hole_cover(solver.zone(), mesh, hole) : Eigen::VectorXd());
      require_hole_resolved(solver.zone(), mesh, hole[0], r.active,
                            "contact.sweep.hole_diameter (contact.sweep.h)");
    }
    warm = r.active;
    out.varsigma.row(i) = (r.readings - out.baseline.readings).transpose();
    out.pivots.push_back(r.pivots);
    out.max_complementarity = std::max(out.max_complementarity, r.complementarity);
    if (frame) frame(i, r);
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace skinfem::contact
