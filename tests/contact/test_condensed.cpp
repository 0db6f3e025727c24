// The condensation onto the contact multipliers by a bordered factorization (MUMPS's Schur complement of the
// skin bordered by every load and readout, contact/condensed.hpp) against the same condensation by block
// solves of the plain factorization: the second method inside skinfem. Every matrix the contact and the
// hole sweep read must agree to 1e-10 of its largest entry.
#include <gtest/gtest.h>

#include "layer_fixture.hpp"

namespace skinfem {
namespace {

double worst(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  EXPECT_EQ(a.rows(), b.rows());
  EXPECT_EQ(a.cols(), b.cols());
  return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff();
}

TEST(Condensed, BorderedFactorizationEqualsBlockSolves) {
  ContactLoad load;
  load.force = 0.5;
  load.mu = 0.4;
  HoleSweep sweep;
  sweep.from = {-0.8, 0};
  sweep.to = {0.8, 0};
  sweep.hole_diameter = 0.5;
  sweep.model = HoleModel::resolved;
  load.sweep = sweep;
  const Scene s = testing::layer_scene("bordered", 0.5, {{0, 0}, {1.0, 0.5}}, load, 2.0);
  const TetMesh mesh = build_mesh(s);
  const auto zone = contact::mortar_zone(mesh, {0, 0}, 2.0);
  const std::vector<int> faces = contact::watch_path(mesh, zone, sweep.from, sweep.to, 0.25);
  const SensorReadings readings(mesh, reading_sites(s.sensors));
  const contact::Indenter indenter(s, mesh);
  const Vec2 t{0.6, 0.8};
  contact::CondenseColumns cols = contact::condense_columns(mesh, zone, readings.weight_block(), t, faces);
  EXPECT_EQ(cols.coupling.solves_instead, zone.size() + cols.nw + 4);
  cols.coupling.solves_instead = 0;  // bordered whatever it costs
  EXPECT_EQ(cols.size(), 2 * zone.size() + 2 * cols.nw + 4);
  ASSERT_GT(cols.nw, 0);
  ModelOptions bordered_options;
  bordered_options.coupling = &cols.coupling;
  const ElasticModel plain(mesh, s.material, s.geometry.side, {}),
      bordered(mesh, s.material, s.geometry.side, {}, bordered_options);
  const auto a = contact::condense(plain, zone, indenter, readings, t, {}, faces);
  const auto b = contact::condense(bordered, zone, indenter, readings, t, {}, faces, &cols);
  ASSERT_TRUE(bordered.solver().border_choice() && bordered.solver().border_choice()->bordered);
  EXPECT_EQ(b.block_solves, 0);
  EXPECT_GT(a.block_solves, zone.size());
  EXPECT_LT(worst(b.C_zz, a.C_zz), 1e-10);
  EXPECT_LT(worst(b.C_zt, a.C_zt), 1e-10);
  EXPECT_LT(worst(b.S_p, a.S_p), 1e-10);
  EXPECT_LT(worst(b.S_t, a.S_t), 1e-10);
  ASSERT_TRUE(a.path && b.path);
  EXPECT_LT(worst(b.path->Wz, a.path->Wz), 1e-10);
  EXPECT_LT(worst(b.path->Ut, a.path->Ut), 1e-10);
  EXPECT_LT(worst(b.path->Gzz, a.path->Gzz), 1e-10);
  EXPECT_LT(worst(b.path->Gtz, a.path->Gtz), 1e-10);
  EXPECT_LT(worst(b.path->DtG, a.path->DtG), 1e-10);
  EXPECT_LT(worst(b.path->Rz, a.path->Rz), 1e-10);
  EXPECT_LT(worst(b.path->Rt, a.path->Rt), 1e-10);
  EXPECT_EQ(b.gap0, a.gap0);

  // Asked to weigh the cost, the factorization takes the plain road when a single solve would do instead,
  // the bordered one when a million would, unless its memory is above the limit; the estimates it chose on
  // are MUMPS's own.
  double between_mb = 0;  // a limit between the two roads' memory, once they are known
  for (int solves : {1, 1000000, -1}) {
    cols.coupling.solves_instead = solves > 0 ? solves : 1000000;
    cols.coupling.memory_limit_mb = solves > 0 ? 0 : between_mb;
    const ElasticModel weighed(mesh, s.material, s.geometry.side, {}, bordered_options);
    const auto& choice = *weighed.solver().border_choice();
    between_mb = 0.5 * (choice.plain_mb + choice.bordered_mb);
    EXPECT_EQ(choice.bordered, solves > 1) << solves;
    EXPECT_EQ(choice.fits(), solves > 0) << solves;
    EXPECT_GT(choice.bordered_mb, choice.plain_mb);
    EXPECT_GT(choice.bordered_flops, choice.plain_flops);
    EXPECT_GT(choice.solve_flops, 0);
    EXPECT_EQ(weighed.solver().coupling_products().size() > 0, choice.bordered);
    const auto w = contact::condense(weighed, zone, indenter, readings, t, {}, faces, &cols);
    EXPECT_EQ(w.block_solves > 0, !choice.bordered);
    EXPECT_LT(worst(w.C_zz, a.C_zz), 1e-10);
  }
}

}  // namespace
}  // namespace skinfem
