// The hole's signals about the deformed sliding state (pipeline/finite_defect.hpp) against full finite-strain
// solves of the same hole: the sweep's signal is the tangent's answer to the hole's opening, taken at the
// material under the hole, so the full solve's change of the readings under a scaled opening s·o, divided by
// s, must tend to it as s → 0 with an error O(s). A wrong share of the opening on the half, a wrong material
// point or a wrong reading of the half's reactions would leave an error that does not vanish.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "../common/plate_on_cap.hpp"
#include "skinfem/contact/holes/dimple.hpp"
#include "skinfem/fem/face_index.hpp"
#include "skinfem/pipeline/finite_defect.hpp"

namespace skinfem::pipeline {
namespace {

// The shared cap (tests/common/plate_on_cap.hpp) on the neo-Hookean skin, sliding at μ = 1; a 0.5 mm hole on
// three positions across the apex; two sensors on the sliding line. Solved on its half.
Scene swept_cap() {
  Scene s = testing::plate_on_cap(6.0, 2.0);
  s.name = "swept_cap";
  s.material.model = MaterialModel::neo_hookean;
  s.sensors.positions = {{0.0, 0.0}, {1.0, 0.0}};
  s.contact->friction = FrictionMode::coupled;
  s.contact->sweep = HoleSweep{{-0.4, 0.0}, {0.4, 0.0}, 3, 0.5};
  s.contact->sweep->h = 0.5;
  return s;
}

Eigen::VectorXd readings_of(const FiniteContactRun& st, const SensorReadings& readings,
                            const contact::FiniteContactResult& f) {
  const Eigen::VectorXd reactions = support_reactions(st.held, f.internal_force - f.load);
  Eigen::VectorXd v(2 * readings.size());
  for (int k = 0; k < readings.size(); ++k) {
    const SensorReading x = readings.read(k, reactions);
    v[2 * k] = x.sigma_z, v[2 * k + 1] = x.sigma_x;
  }
  return v;
}

TEST(FiniteDefect, TheSweepsSignalIsTheFullSolvesAtFirstOrderInTheOpening) {
  const Scene scene = swept_cap();
  const FiniteDefectRun defect = finite_defect_run(scene, {FrictionMode::coupled});
  const FiniteDefectCase& run = defect.cases.at(0);
  const FiniteContactRun& st = run.state;
  ASSERT_TRUE(st.mirrored);
  EXPECT_LT(run.baseline_rel, 1e-9);
  // The hole at the middle position (the apex), its opening on the tangent as the sweep made it.
  const int i = 1;
  const double mu = Lame::from(scene.material.E, scene.material.nu).mu;
  const SensorReadings& readings = *st.sensor_sites;
  const contact::CondensedContact k = contact::tangent_contact(
      *st.solved, mu, st.held.fixed, st.solved_zone, *st.indenter, readings, st.load, st.solved_result);
  const contact::ContactSolver solver(k, *scene.contact, &*st.mirror);
  const PlanarFaceIndex top(*st.mesh, kTop);
  const contact::HoleDimples dimples(solver, *st.mesh, top, scene.material.E, scene.material.nu);
  const contact::HoleDimple hole = dimples(
      Hole{run.material_centres.at(i), scene.contact->sweep->hole_diameter}, run.sweep.baseline.lambda);
  const contact::ContactResult whole = solver.solve(FrictionMode::coupled, hole);
  const Eigen::VectorXd sweep_signal = run.sweep.varsigma.row(i).transpose();
  EXPECT_LT((whole.readings - run.sweep.baseline.readings - sweep_signal).norm(),
            1e-12 * sweep_signal.norm());

  const Eigen::VectorXd base = readings_of(st, readings, st.solved_result);
  std::vector<double> err;
  // Openings of ½, ¼ and ⅛ the hole's: at the full opening the set of hats in contact moves (the full solve's
  // change of the readings is then 12 % off the tangent's: the hole's own nonlinearity, printed).
  for (double s : {1.0, 0.5, 0.25, 0.125}) {
    contact::HoleDimple scaled = hole;
    scaled.opening *= s;
    const Eigen::VectorXd tangent =
        solver.solve(FrictionMode::coupled, scaled).readings - run.sweep.baseline.readings;
    contact::FiniteContactLoad load = st.load;
    load.opening = scaled.opening;
    const contact::FiniteContactResult f = contact::solve_finite_contact(
        *st.solved, mu, st.held.fixed, st.solved_zone, *st.indenter, load, {}, {}, &st.solved_result);
    const Eigen::VectorXd full = readings_of(st, readings, f) - base;
    const double gap = (full - tangent).norm() / tangent.norm();
    std::printf(
        "opening x %.3g: tangent %.4e, full %.4e kPa (largest |signal|), relative gap %.3e, %zu hats "
        "in contact (%zu without the hole)\n",
        s, 1e3 * tangent.cwiseAbs().maxCoeff(), 1e3 * full.cwiseAbs().maxCoeff(), gap, f.active.size(),
        st.solved_result.active.size());
    if (s < 1) err.push_back(gap);
  }
  ASSERT_EQ(err.size(), 3u);
  for (size_t j = 1; j < err.size(); ++j) EXPECT_NEAR(std::log2(err[j - 1] / err[j]), 1.0, 0.2) << err[j];
}

}  // namespace
}  // namespace skinfem::pipeline
