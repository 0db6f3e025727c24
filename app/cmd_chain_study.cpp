// skinfem study --chain — speed against error over the whole chain: every mesh size of the scene (h_min,
// h_max, grading, regions, contact zone, hole path and holes) scaled per level, and at each level the Green
// maps and k of sensor #1, the contact (coupled friction: radius, central pressure, indentation) and the
// hole sweep (largest |ς_z| over sensors and positions, sliding).
//
//   $ skinfem study scenes/candelier2011.json --chain --scales 2,1.41,1 --out out/candelier2011/study
//   level 3 (scale 1): 188,439 DOFs; k_central 1.5424 (error 0.05 %, 62 s) ...
//
// Errors are against the Richardson limit of the three finest levels (validation/richardson.hpp: Q = Q∞ + C
// sᵖ through them, p the observed order); when the differences change sign or grow, or p exceeds what P2–P1
// can give (pipeline/chain_level.hpp's kMaxPlausibleOrder), there is no asymptotic regime yet: the finest
// level is the reference and its own error is not given. The seconds of a quantity are those of every stage
// it needs (mesh, assemble, factor, then adjoints, condensation, sweep). Writes DIR/chain_study.csv
// (stage,level,dofs,seconds,error; read by scripts/figures.py for the Pareto plot) and DIR/chain_study.json
// (every level's values, stage times, orders and limits).
#include <cstdio>

#include "app/chain_study.hpp"
#include "app/commands.hpp"
#include "app/common.hpp"

namespace skinfem::app {

int run_chain_study(const Scene& scene, const std::string& out_dir, const std::vector<double>& scales) {
  if (scales.size() < 3)
    throw SceneError("--scales: the chain study needs at least 3 levels for an observed order, got " +
                     std::to_string(scales.size()));
  check_output_dir(out_dir);
  std::vector<ChainLevel> levels;
  for (size_t l = 0; l < scales.size(); ++l) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "chain study: level %zu of %zu (scale %g)", l + 1, scales.size(),
                  scales[l]);
    progress(buf);
    levels.push_back(chain_level(scene, scales[l]));
    const ChainLevel& c = levels.back();
    std::printf("level %zu (scale %g): %d DOFs", l + 1, c.scale, c.dofs);
    for (size_t i = 0; i < c.names.size(); ++i)
      std::printf("; %s %.6g (%.1f s)", c.names[i].c_str(), c.value[i], c.seconds[i]);
    std::printf("\n");
  }

  write_chain_study(levels, chain_study_json(scene, levels), out_dir, true);
  return 0;
}

}  // namespace skinfem::app
