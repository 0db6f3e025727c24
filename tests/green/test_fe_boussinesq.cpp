// Ladder rung 4: a small uniform patch on a thick bonded block against Boussinesq at depth.
#include <gtest/gtest.h>

#include <cmath>

#include "skinfem/fem/elastic_model.hpp"
#include "skinfem/fem/fields.hpp"
#include "skinfem/green/layer_exact.hpp"
#include "skinfem/mesh/build.hpp"

namespace skinfem::green {
namespace {

TEST(FeBoussinesq, PatchStressOnTheAxisMatchesTheExactLayerAndTendsToBoussinesq) {
  // References: (i) Boussinesq for a uniform disc on a half-space, on the axis:
  // σ_zz = −q[1 − d³/(a² + d²)^{3/2}] (Johnson 1985 §3.4); (ii) the exact bonded layer of the same
  // thickness (Hankel transforms) at depth d. (ii) differs from (i) by the rigid base, a correction
  // that must grow with d/h (1.8 % at d = h/3). The FE is compared with (ii) at two mesh levels: the
  // error must fall under refinement at every depth, and the finer one must be within 1 % — below the
  // base effect at d = h/3, so the FE must resolve it (there it must be closer to (ii) than to (i)).
  // Measured: 1.8e-2 → 1.5e-3 (d = 0.5), 2.8e-3 → 1.6e-3 (1), 3.0e-3 → 1.1e-3 (2) at 16k → 41k nodes.
  const double a = 0.25, H = 6.0, F = 1.0, q = F / (M_PI * a * a);
  const std::vector<double> depths{0.5, 1.0, 2.0};
  const LayerGreen layer(H, 0.5, LayerLoad::uniform, a);
  std::vector<double> gap;
  for (double d : depths) {
    const double bous = -q * (1 - d * d * d / std::pow(a * a + d * d, 1.5));
    const double exact = -layer.at_depth(0, 0, d).zz;  // reading = −σ_zz
    gap.push_back(std::abs(exact - bous) / std::abs(bous));
    std::printf("d = %.1f: Boussinesq %.6f, exact layer %.6f MPa (base effect %.2e)\n", d, bous, exact,
                gap.back());
  }
  for (size_t i = 1; i < gap.size(); ++i) EXPECT_GT(gap[i], gap[i - 1]);  // grows toward the base

  std::vector<std::vector<double>> fe;  // [level][depth]
  for (double scale : {2.0, 1.4}) {
    Scene s;
    s.geometry.kind = GeometryKind::flat;
    s.geometry.flat = {H, 9.0};
    s.mesh.refine_sensors = false;
    s.mesh.h_min = 0.12 * scale, s.mesh.h_max = 3.0 * scale, s.mesh.growth = 1 + 0.5 * scale;
    s.mesh.regions = {{{0, 0}, {0, 0}, 0.0, 0.4 * scale}};  // the axis below the load
    s.loads.patches = {TractionPatch{{0, 0}, 2 * a, {0, 0, -1}, F}};
    const TetMesh mesh = build_mesh(s);
    const ElasticModel model(mesh, s.material, s.geometry.side, {});
    const LoadCaseResult r = model.solve(model.patch_load(s.loads.patches[0]), {});
    const PointLocator locator(mesh);
    std::vector<double> level;
    for (double d : depths)
      level.push_back(probe(mesh, locator, model.lame(), r.solution, {0, 0, H - d}).sigma(2, 2));
    fe.push_back(level);
    std::printf("scale %.1f: %d nodes; σ_zz at d = 0.5, 1, 2: %.6f %.6f %.6f\n", scale, mesh.num_nodes(),
                level[0], level[1], level[2]);
  }
  for (size_t i = 0; i < depths.size(); ++i) {
    const double exact = -layer.at_depth(0, 0, depths[i]).zz;
    const double err_coarse = std::abs(fe[0][i] - exact), err_fine = std::abs(fe[1][i] - exact);
    const double change = std::abs(fe[1][i] - fe[0][i]);
    std::printf("d = %.1f: FE error %.2e → %.2e (change %.2e)\n", depths[i], err_coarse / std::abs(exact),
                err_fine / std::abs(exact), change / std::abs(exact));
    EXPECT_LT(err_fine, err_coarse) << "d = " << depths[i];  // the refinement study converges
    EXPECT_LT(err_fine, 0.01 * std::abs(exact)) << "d = " << depths[i];
  }
  const double bous_deep = -q * (1 - 8.0 / std::pow(a * a + 4.0, 1.5)),
               exact_deep = -layer.at_depth(0, 0, 2.0).zz;
  EXPECT_LT(std::abs(fe[1][2] - exact_deep), std::abs(fe[1][2] - bous_deep));
}

}  // namespace
}  // namespace skinfem::green
