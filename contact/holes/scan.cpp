#include "skinfem/contact/holes/scan.hpp"

#include <chrono>
#include <map>
#include <stdexcept>
#include <tuple>

#include "skinfem/contact/condensed.hpp"
#include "skinfem/contact/holes/cut.hpp"
#include "skinfem/scene/parallel.hpp"
#include "skinfem/scene/texture.hpp"

namespace skinfem::contact {

TextureCut texture_cut(const PathCompliance& path, int n_c, const std::vector<Hole>& holes, bool mirrored) {
  TextureCut out;
  out.cut.area = Eigen::VectorXd::Zero(n_c);
  out.cut.gap0 = Eigen::VectorXd::Zero(n_c);
  out.cut.B.resize(n_c, static_cast<int>(path.nodes.size()));
  for (const Hole& h : holes) {
    if (mirrored && h.center[1] < 0) continue;
    HoleCut c = hole_cut(path, n_c, h);
    if (c.B.nonZeros() == 0) continue;
    out.n_holes += mirrored && h.center[1] > 0 ? 2 : 1;
    out.cut.B += c.B;
    out.cut.area += c.area;
    out.cut.gap0 += c.gap0;
  }
  return out;
}

namespace {
// The holes of the plate near the zone at u (within its radius, with their own, of its centre): the ones
// worth cutting.
std::vector<Hole> holes_near(const std::vector<Hole>& plate, const Vec2& direction, double u,
                             const Vec2& centre, double reach) {
  std::vector<Hole> out;
  for (const Hole& p : plate) {
    const Hole h = hole_at(p, direction, u);
    if (std::hypot(h.center[0] - centre[0], h.center[1] - centre[1]) < reach + hole_radius(h))
      out.push_back(h);
  }
  return out;
}

// The zone's centre and a radius holding every watched face, from the path's faces.
std::pair<Vec2, double> watched_disc(const PathCompliance& path) {
  Eigen::Vector2d lo(1e300, 1e300), hi(-1e300, -1e300);
  for (const auto& f : path.faces)
    for (const auto& x : f.x) lo = lo.cwiseMin(x.head<2>()), hi = hi.cwiseMax(x.head<2>());
  const Eigen::Vector2d c = 0.5 * (lo + hi);
  return {Vec2{c.x(), c.y()}, 0.5 * (hi - lo).norm()};
}

// Solves the contact with each hole set in turn (warm-started in order), their cut problems built a
// chunk at a time on the machine's cores; done(i, result, cut holes) on the calling thread.
void solve_hole_sets(const ContactSolver& solver, FrictionMode mode,
                     const std::vector<std::vector<Hole>>& sets, const ContactResult& baseline,
                     const std::function<void(int, const ContactResult&, int)>& done) {
  const CondensedContact& c = solver.condensed();
  const int n_c = c.zone.size();
  constexpr int kChunk = 32;
  std::vector<int> warm = baseline.active;
  const int n = static_cast<int>(sets.size());
  std::vector<CutProblem> problems(kChunk);
  std::vector<int> cut_holes(kChunk);
  for (int first = 0; first < n; first += kChunk) {
    const int m = std::min(kChunk, n - first);
    for_each_index(m, [&](std::size_t k) {
      const TextureCut t = texture_cut(*c.path, n_c, sets[first + k], solver.mirrored());
      cut_holes[k] = t.n_holes;
      if (t.n_holes > 0) problems[k] = cut_problem(c, t.cut, true);
    });
    for (int k = 0; k < m; ++k) {
      if (cut_holes[k] == 0) {
        done(first + k, baseline, 0);
        continue;
      }
      const ContactResult r = solver.solve(mode, problems[k], warm);
      warm = r.active;
      done(first + k, r, cut_holes[k]);
    }
  }
}
}  // namespace

ScanResult texture_scan(
    const ContactSolver& solver, const std::vector<Hole>& plate, const Vec2& direction,
    const std::vector<double>& u, FrictionMode mode,
    const std::function<void(int, const ContactResult&, const std::vector<Hole>&)>& frame) {
  if (!solver.condensed().path)
    throw std::invalid_argument("texture_scan: the condensed skin watches no track");
  const auto start = std::chrono::steady_clock::now();
  ScanResult out;
  out.mode = mode;
  out.u = u;
  out.baseline = solver.solve(mode);
  solver.set_reference(mode, out.baseline.active);
  const auto [centre, reach] = watched_disc(*solver.condensed().path);
  std::vector<std::vector<Hole>> sets;
  for (double ui : u) sets.push_back(holes_near(plate, direction, ui, centre, reach));
  out.varsigma.resize(static_cast<int>(u.size()), out.baseline.readings.size());
  out.holes_in.resize(u.size());
  out.pivots.resize(u.size());
  solve_hole_sets(solver, mode, sets, out.baseline, [&](int i, const ContactResult& r, int cut) {
    out.varsigma.row(i) = (r.readings - out.baseline.readings).transpose();
    out.holes_in[i] = cut;
    out.pivots[i] = cut ? r.pivots : 0;
    if (cut) out.max_complementarity = std::max(out.max_complementarity, r.complementarity);
    if (frame) frame(i, r, sets[i]);
  });
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

Superposition superposed_scan(const ContactSolver& solver, const std::vector<Hole>& plate,
                              const Vec2& direction, const std::vector<double>& u, FrictionMode mode) {
  if (!solver.condensed().path)
    throw std::invalid_argument("superposed_scan: the condensed skin watches no track");
  const auto start = std::chrono::steady_clock::now();
  const ContactResult baseline = solver.solve(mode);
  solver.set_reference(mode, baseline.active);
  const auto [centre, reach] = watched_disc(*solver.condensed().path);
  // One solve per distinct single hole in space (centre to 1e-9 mm, size, depth), in order of the holes
  // and positions: a row's holes at a period that is a multiple of the step meet the same ones.
  using Key = std::tuple<long long, long long, double, double, double>;
  std::map<Key, int> index;
  std::vector<std::vector<Hole>> sets;
  std::vector<std::vector<int>> uses;  // per solve: the positions it adds to
  Superposition out;
  for (const Hole& p : plate)
    for (size_t i = 0; i < u.size(); ++i) {
      if (solver.mirrored() && p.center[1] < 0) break;  // solved with its image
      const std::vector<Hole> one = holes_near({p}, direction, u[i], centre, reach);
      if (one.empty()) continue;
      const Hole& h = one[0];
      const Key key{std::llround(h.center[0] * 1e9), std::llround(h.center[1] * 1e9), h.diameter, h.length,
                    h.depth};
      auto [it, fresh] = index.emplace(key, static_cast<int>(sets.size()));
      if (fresh) {
        sets.push_back(one);
        uses.emplace_back();
        out.mirror_pair_solves += solver.mirrored() && h.center[1] > 0;
      }
      uses[it->second].push_back(static_cast<int>(i));
    }
  out.varsigma = Eigen::MatrixXd::Zero(static_cast<int>(u.size()), baseline.readings.size());
  solve_hole_sets(solver, mode, sets, baseline, [&](int s, const ContactResult& r, int) {
    const Eigen::RowVectorXd v = (r.readings - baseline.readings).transpose();
    for (int i : uses[s]) out.varsigma.row(i) += v;
  });
  out.solves = static_cast<int>(sets.size());
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace skinfem::contact
