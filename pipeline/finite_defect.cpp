#include "skinfem/pipeline/finite_defect.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "skinfem/contact/holes/dimple.hpp"
#include "skinfem/fem/face_index.hpp"
#include "skinfem/mesh/surface_quadrature.hpp"
#include "skinfem/pipeline/defect.hpp"
#include "skinfem/pipeline/progress.hpp"
#include "skinfem/pipeline/resources.hpp"
#include "skinfem/pipeline/scene_json.hpp"
#include "skinfem/validation/hole_budget.hpp"

namespace skinfem::pipeline {

namespace {

// The reference point X under the spatial point c on the top: X + u_h(X) = c, u_h the top's horizontal
// displacement, by fixed-point iteration (a contraction while |∇u_h| < 1).
Vec2 material_point(const TetMesh& mesh, const PlanarFaceIndex& top, const Eigen::VectorXd& u,
                    const Vec2& c) {
  Vec2 X = c;
  for (int it = 0; it < 50; ++it) {
    double s = 0, t = 0;
    const int f = top.find(X[0], X[1], s, t);
    if (f < 0) return X;  // off the top: no material there to move
    const Eigen::Matrix<double, 6, 1> N = triangle_shape(s, t);
    double ux = 0, uy = 0;
    for (int k = 0; k < 6; ++k) {
      const int n = mesh.faces(f, k);
      ux += N[k] * u[3 * n];
      uy += N[k] * u[3 * n + 1];
    }
    const Vec2 next{c[0] - ux, c[1] - uy};
    const double step = std::hypot(next[0] - X[0], next[1] - X[1]);
    X = next;
    if (step < 1e-12) break;
  }
  return X;
}

}  // namespace

FiniteDefectRun finite_defect_run(const Scene& scene) {
  require_sweep(scene);
  check_finite_contact(scene, FrictionMode::coupled);
  const HoleSweep& sweep = *scene.contact->sweep;
  if (sweep.model != HoleModel::bulge)
    throw SceneError(
        scene.source_path +
        ": contact.sweep.hole_model = \"resolved\": with material.model \"neo_hookean\" the hole "
        "is the bulge (\"bulge\"), a small change about the deformed state");
  FiniteDefectRun run;
  run.state = finite_contact_run(scene, FrictionMode::coupled);
  const FiniteContactRun& st = run.state;
  run.wall = st.wall;

  Stopwatch clock;
  progress("the contact condensed on the tangent at the deformed sliding state");
  const double mu = Lame::from(scene.material.E, scene.material.nu).mu;
  const contact::CondensedContact tangent =
      contact::tangent_contact(*st.solved, mu, st.held.fixed, st.solved_zone, *st.indenter, *st.sensor_sites,
                               st.load, st.solved_result);
  const contact::ContactSolver solver(tangent, *scene.contact, st.mirror ? &*st.mirror : nullptr);
  run.wall["tangent"] = clock.seconds();

  clock = Stopwatch();
  const PlanarFaceIndex top(*st.mesh, kTop);
  const contact::HoleDimples dimples(solver, *st.mesh, top, scene.material.E, scene.material.nu);
  const Eigen::VectorXd& u = st.result.solution.u;
  run.sliding = contact::hole_sweep(
      solver, *st.mesh, sweep, FrictionMode::coupled, &dimples,
      [&](int i, const contact::ContactResult&) {
        if ((i + 1) % 50 == 0 || i + 1 == sweep.positions)
          progress("sweep sliding: " + std::to_string(i + 1) + "/" + std::to_string(sweep.positions) +
                   " positions");
      },
      nullptr,
      [&](const Vec2& c) {
        const Vec2 X = material_point(*st.mesh, top, u, c);
        run.material_centres.push_back(X);
        return X;
      });
  run.wall["sweep_sliding"] = clock.seconds();
  const Eigen::VectorXd& lam = run.sliding.baseline.lambda;
  run.baseline_rel = (lam - st.result.lambda).cwiseAbs().maxCoeff() / st.result.lambda.maxCoeff();
  const Eigen::MatrixXd& v = run.sliding.varsigma;
  for (int col = 0; col < v.cols(); ++col)
    if (const double r = validation::roughness(v.col(col)); r > run.max_roughness)
      run.max_roughness = r, run.max_roughness_column = col;
  return run;
}

nlohmann::json finite_defect_json(const Scene& scene, const FiniteDefectRun& run) {
  const HoleSweep& sweep = *scene.contact->sweep;
  const contact::SweepResult& res = run.sliding;
  nlohmann::json c;
  c["friction"] = to_string(FrictionMode::coupled);
  c["ratio"] = scene.contact->mu;
  c["seconds"] = res.seconds;
  c["ms_per_position"] = 1e3 * res.seconds / sweep.positions;
  c["max_complementarity"] = res.max_complementarity;
  c["max_roughness"] = run.max_roughness;
  c["max_roughness_curve"] = "#" + std::to_string(run.max_roughness_column / 2 + 1) +
                             (run.max_roughness_column % 2 ? " varsigma_x" : " varsigma_z");
  c["sensors"] = sweep_peaks_json(res);
  double shift = 0;
  for (size_t i = 0; i < run.material_centres.size(); ++i)
    shift = std::max(shift, std::hypot(res.centers[i][0] - run.material_centres[i][0],
                                       res.centers[i][1] - run.material_centres[i][1]));
  nlohmann::json summary;
  summary["cases"]["sliding"] = c;
  summary["scene"] = scene_json(scene);
  summary["material_model"] = "neo_hookean";
  summary["friction_law"] = to_string(scene.contact->law);
  summary["left_out"] = "the static case (its state at rest needs a finite solve of its own), error bars";
  summary["positions"] = sweep.positions;
  summary["hole_diameter_mm"] = sweep.hole_diameter;
  summary["hole_model"] = "bulge";
  summary["from_mm"] = {sweep.from[0], sweep.from[1]};
  summary["to_mm"] = {sweep.to[0], sweep.to[1]};
  summary["largest_material_shift_mm"] = shift;
  summary["tangent_baseline_rel"] = run.baseline_rel;
  summary["state"] = finite_contact_json(scene, run.state);
  summary["dofs"] = run.state.dofs;
  summary["wall_s"] = run.wall;
  summary["wall_total_s"] = run.wall.total();
  summary["peak_rss_mb"] = peak_rss_mb();
  return summary;
}

}  // namespace skinfem::pipeline
