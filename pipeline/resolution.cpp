#include "skinfem/pipeline/resolution.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "skinfem/pipeline/defect.hpp"
#include "skinfem/pipeline/progress.hpp"

namespace skinfem::pipeline {

namespace {
// The smallest spacing from which on every one reaches `required` (spacings ascending).
void limit_of(const std::vector<double>& spacing, const std::vector<double>& fraction, double required,
              std::optional<double>& mm, bool& below) {
  size_t from = spacing.size();
  while (from > 0 && fraction[from - 1] >= required) --from;
  if (from == spacing.size()) return;
  mm = spacing[from];
  below = from == 0;
}
}  // namespace

ResolutionRun resolution_run(const Scene& scene, const ResolutionOptions& o) {
  require_sweep(scene);
  if (o.spacings_mm.empty() || o.passages.empty() || o.draws < 1 || !(o.required > 0 && o.required <= 1) ||
      !(o.offset_step > 0) || !(o.offset_range >= 0))
    throw std::invalid_argument(
        "resolution_run: spacings and passages given, draws >= 1, required in (0, 1], offset_step > 0");
  for (double s : o.spacings_mm)
    if (!(s > 0)) throw std::invalid_argument("resolution_run: spacings must be > 0");
  for (int n : o.passages)
    if (n < 1) throw std::invalid_argument("resolution_run: passages must be >= 1");
  const HoleSweep& sw = *scene.contact->sweep;
  ResolutionRun run;
  run.step_mm = std::hypot(sw.to[0] - sw.from[0], sw.to[1] - sw.from[1]) / std::max(1, sw.positions - 1);
  const double step = run.step_mm;
  const std::vector<double> offsets = offset_grid(o.offset_range, o.offset_step);
  const validation::HoleResponses r = hole_responses(scene, o.mode, step, offsets, run.wall, run.dofs);
  std::vector<double> sensors;
  for (const Vec2& p : scene.sensors.positions) sensors.push_back(p[0]);
  const int ns = static_cast<int>(sensors.size()), rows = static_cast<int>(r.R.rows());
  // The spacings on the step's grid, each once, ascending.
  std::vector<int> gaps;
  for (double s : o.spacings_mm) gaps.push_back(std::max(1, static_cast<int>(std::lround(s / step))));
  std::sort(gaps.begin(), gaps.end());
  gaps.erase(std::unique(gaps.begin(), gaps.end()), gaps.end());
  std::vector<double> spacing;
  for (int g : gaps) spacing.push_back(g * step);

  const Stopwatch clock;
  for (int n : o.passages) {
    progress("resolution: N = " + std::to_string(n) + ", " + std::to_string(gaps.size()) + " spacings x " +
             std::to_string(o.draws) + " draws");
    validation::SensorNoise noise = o.noise;
    noise.passages = n;
    std::vector<double> multi_fraction, naive_fraction;
    for (size_t g = 0; g < gaps.size(); ++g) {
      const double s = spacing[g];
      // Hole 1 at 0 enters the dictionary's grid at its start; hole 2, s behind, leaves it at its end.
      std::vector<double> u;
      for (int i = 0; i < rows + gaps[g]; ++i) u.push_back(r.x0 + i * step);
      std::vector<validation::Feature> truth(2);
      truth[0].amplitude = truth[1].amplitude = 1;
      truth[1].position_mm = -s;
      const Eigen::MatrixXd clean = validation::simulated_signals(u, sensors, r, truth, 0.0);
      // Each hole its own feature: a feature between them goes to one of them only.
      const auto resolved = [&](const validation::Inversion& inv) {
        return validation::score_inversion(inv.features, {0.0, -s}, 0.5 * s).found == 2;
      };
      int multi = 0;
      std::vector<int> naive(ns, 0);
      for (int d = 0; d < o.draws; ++d) {
        validation::ScanSignals sig;
        sig.u = u;
        sig.sensors = sensors;
        // The same draws at every N (common random numbers): N scales them, so that the fractions compare.
        sig.y = validation::with_noise(clean, noise, o.seed * 1000003ULL + gaps[g] * 101ULL + d);
        multi += resolved(validation::invert_scan(sig, r, noise, offsets, o.p_fa));
        for (int k = 0; k < ns; ++k)
          naive[k] += resolved(validation::invert_scan(sig, r, noise, {0.0}, o.p_fa, k));
      }
      ResolutionPoint pt;
      pt.passages = n;
      pt.spacing_mm = s;
      pt.multi = static_cast<double>(multi) / o.draws;
      const int best = static_cast<int>(std::max_element(naive.begin(), naive.end()) - naive.begin());
      pt.naive_best = static_cast<double>(naive[best]) / o.draws;
      pt.naive_sensor = best + 1;
      run.points.push_back(pt);
      multi_fraction.push_back(pt.multi);
      naive_fraction.push_back(pt.naive_best);
    }
    ResolutionLimit lim;
    lim.passages = n;
    limit_of(spacing, multi_fraction, o.required, lim.multi_mm, lim.multi_below);
    limit_of(spacing, naive_fraction, o.required, lim.naive_mm, lim.naive_below);
    run.limits.push_back(lim);
  }
  run.wall["resolution"] = clock.seconds();
  return run;
}

}  // namespace skinfem::pipeline
