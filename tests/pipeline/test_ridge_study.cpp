// The ridge study (pipeline/ridge_study.hpp) on a tiny ridged layer (a 1 mm period, coarse on purpose: the
// study's arithmetic, not its numbers, is checked here; app/ridge_study.sh runs it at real settings).
// References: the header's rules (at least 3 levels, sorted by increasing resolution, each meshed at
// period / L on the pattern; a scene without ridges refused naming geometry.ridges); each level's changes
// recomputed here from its typed ridged and control results (ridged / control − 1); each limit against
// validation::richardson over the three finest levels with mesh scales 1/L, recomputed here, its mesh error
// |finest − limit| when asymptotic else the last change, plus the control's share kRidgeControl·|finest|;
// on a flat layer the exact smooth layer's k beside each level.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "skinfem/pipeline/ridge_study.hpp"

namespace skinfem::pipeline {
namespace {

bool has(const std::string& text, const std::string& what) { return text.find(what) != std::string::npos; }

Scene ridged_layer() {
  Scene s;
  s.name = "ridge_layer";
  s.source_path = "ridge_layer.json";
  s.geometry.kind = GeometryKind::flat;
  s.geometry.flat = {1.5, 4.0};
  Ridges& r = s.geometry.ridges;
  r.period = 1.0;
  r.height = 0.05;
  r.radius = 1.2;
  s.sensors.positions = {{0, 0}};
  s.mesh.h_min = 0.7;
  s.mesh.growth = 1.7;
  s.mesh.h_max = 1.5;
  s.mesh.sensor_h = 0.5;
  s.calibration.spacing = 0.25;
  return s;
}

TEST(RidgeStudy, AStudyNeedsRidgesAndThreeLevels) {
  Scene smooth = ridged_layer();
  smooth.geometry.ridges = {};
  try {
    ridge_study(smooth, {2, 3, 4});
    ADD_FAILURE() << "a smooth skin was studied";
  } catch (const SceneError& e) {
    EXPECT_TRUE(has(e.what(), "geometry.ridges")) << e.what();
  }
  try {
    ridge_study(ridged_layer(), {2, 3});
    ADD_FAILURE() << "two levels were accepted";
  } catch (const SceneError& e) {
    EXPECT_TRUE(has(e.what(), "at least 3 levels")) << e.what();
  }
}

TEST(RidgeStudy, EachLevelAndLimitIsWhatTheHeaderDefines) {
  const Scene scene = ridged_layer();
  std::vector<double> seen;
  const RidgeStudy study =
      ridge_study(scene, {2.5, 2, 3}, [&](const RidgeLevel& l) { seen.push_back(l.per_period); });
  ASSERT_EQ(study.levels.size(), 3u);
  EXPECT_EQ(seen,
            (std::vector<double>{2, 2.5, 3}));  // by increasing resolution, each reported as it completes
  for (const RidgeLevel& l : study.levels) {
    std::printf("L %g: %d dofs, mesh %.2f s, ridged %.2f s, control %.2f s\n", l.per_period, l.dofs, l.mesh_s,
                l.wall_ridged.total(), l.wall_control.total());
    EXPECT_DOUBLE_EQ(l.ridge_h_mm, 1.0 / l.per_period);
    EXPECT_GT(l.dofs, 0);
    EXPECT_NEAR(l.k_central_change, l.ridged.k_central / l.control.k_central - 1, 1e-15);
    EXPECT_NEAR(l.k_lsq_line_change, l.ridged.k_lsq_line / l.control.k_lsq_line - 1, 1e-15);
    for (int c = 0; c < 4; ++c)
      EXPECT_NEAR(l.peak_change[c], l.peak_ridged[c] / l.peak_control[c] - 1, 1e-15);
    ASSERT_TRUE(l.exact_smooth.has_value());  // a flat layer
    EXPECT_GT(l.exact_smooth->k_central, 0);
  }
  // Finer levels, more unknowns.
  EXPECT_LT(study.levels[0].dofs, study.levels[2].dofs);

  const std::vector<std::string> names{"k_central_change", "k_lsq_line_change", "peak_zz_change",
                                       "peak_zx_change",   "peak_xz_change",    "peak_xx_change"};
  ASSERT_EQ(study.limits.size(), names.size());
  const std::array<double, 3> scales{1.0 / 2, 1.0 / 2.5, 1.0 / 3};
  for (size_t i = 0; i < names.size(); ++i) {
    const RidgeLimit& lim = study.limits[i];
    EXPECT_EQ(lim.name, names[i]);
    const auto value = [&](const RidgeLevel& l) {
      return i == 0 ? l.k_central_change : i == 1 ? l.k_lsq_line_change : l.peak_change[i - 2];
    };
    const std::array<double, 3> v{value(study.levels[0]), value(study.levels[1]), value(study.levels[2])};
    EXPECT_EQ(lim.finest, v[2]);
    const validation::Richardson r = validation::richardson(v, scales);
    EXPECT_EQ(lim.richardson.asymptotic, r.asymptotic) << lim.name;
    EXPECT_EQ(lim.richardson.limit, r.limit) << lim.name;
    EXPECT_EQ(lim.mesh_error, r.asymptotic ? std::abs(v[2] - r.limit) : std::abs(v[2] - v[1])) << lim.name;
    EXPECT_NEAR(lim.control_error, kRidgeControl * std::abs(v[2]), 1e-15);
    EXPECT_EQ(lim.error(), lim.mesh_error + lim.control_error);
  }
}

}  // namespace
}  // namespace skinfem::pipeline
