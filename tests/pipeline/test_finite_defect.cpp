// The hole's signals about the deformed sliding state (pipeline/finite_defect.hpp) against full finite-strain
// solves of the same hole: the sweep's signal is the tangent's answer to the hole's opening, taken at the
// material under the hole, so the full solve's change of the readings under a scaled opening s·o, divided by
// s, must tend to it as s → 0 with an error O(s). A wrong share of the opening on the half, a wrong material
// point or a wrong reading of the half's reactions would leave an error that does not vanish. Under Coulomb
// friction and under a shear strength.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "../common/plate_on_cap.hpp"
#include "skinfem/contact/holes/dimple.hpp"
#include "skinfem/fem/face_index.hpp"
#include "skinfem/pipeline/finite_defect.hpp"
#include "skinfem/scene/laws.hpp"

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

// The sweep's signal against the full solves' for the scene's law, at openings s·o of the hole's for each
// of `scales` (the last three compared: small enough that no hat enters or leaves the set).
void check_signal_at_first_order(const Scene& scene, const std::vector<double>& scales) {
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
  ContactLoad load0 = *scene.contact;
  if (kind(load0.law).shear_strength) load0.tau0 = st.tau0_MPa;  // the finite skin's, as the sweep's
  const contact::ContactSolver solver(k, load0, &*st.mirror);
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
  // Under Coulomb friction, openings of ½, ¼ and ⅛ the hole's: at the full opening the set of hats in
  // contact moves (the full solve's change of the readings is then 12 % off the tangent's: the hole's own
  // nonlinearity, printed).
  for (double s : scales) {
    contact::HoleDimple scaled = hole;
    scaled.opening *= s;
    // A shear strength's cut by the hole is a dead load, the tangent's by construction: the full solve
    // has the opening alone, and so does the tangent's answer here.
    scaled.covered.resize(0);
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
    err.push_back(gap);
  }
  err.erase(err.begin(), err.end() - 3);
  for (size_t j = 1; j < err.size(); ++j) EXPECT_NEAR(std::log2(err[j - 1] / err[j]), 1.0, 0.2) << err[j];
}

TEST(FiniteDefect, TheSweepsSignalIsTheFullSolvesAtFirstOrderInTheOpening) {
  check_signal_at_first_order(swept_cap(), {1.0, 0.5, 0.25, 0.125});
}

TEST(FiniteDefect, UnderAShearStrengthTheSweepsSignalIsTheFullSolvesAtFirstOrder) {
  // The same with τ0 = μF/A wherever the skin touches: the tangent's gaps hold the state's shear and its
  // touched set, so its hole-free contact is the finite one and its answer to the opening the derivative.
  Scene scene = swept_cap();
  scene.contact->law = FrictionLaw::shear_strength;
  // Half the hole's opening already lifts a hat, and under a shear strength a lifting hat drops its shear:
  // the openings compared are ¼, ⅛ and 1/16 of it.
  check_signal_at_first_order(scene, {0.5, 0.25, 0.125, 0.0625});
}

}  // namespace
}  // namespace skinfem::pipeline
