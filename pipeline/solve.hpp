// `skinfem solve` as a stage: the scene's loads (punches, traction patches) on its skin bonded to the rigid
// base, Taylor–Hood P2–P1; the figures of merit of the load case (validation/load_metrics.hpp) and every
// sensor's reading (fem/sensor_reading.hpp). The linear skin: one factorization and one solve. The
// neo-Hookean skin (material.model): Newton with load steps (fem/newton.hpp); patches are dead loads,
// punches are driven by their displacement, and the sensors read the base's reaction (the internal force at
// its held DOFs) over their reference discs: the base does not move. Units: mm, N, MPa.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <vector>

#include "skinfem/fem/elastic_model.hpp"
#include "skinfem/fem/newton.hpp"
#include "skinfem/fem/sensor_reading.hpp"
#include "skinfem/pipeline/clock.hpp"
#include "skinfem/validation/load_metrics.hpp"

namespace skinfem::pipeline {

struct SolveRun {
  std::unique_ptr<TetMesh> mesh;        // heap-held: model refers to it
  std::unique_ptr<ElasticModel> model;  // the linear skin, assembled and factored; null for neo_hookean
  Lame lame;                            // the law's moduli (neo_hookean: μ = E/3)
  int dofs = 0;                         // free displacement DOFs + pressure DOFs
  // The solution; its reactions at the base's (and a fixed side's) DOFs, the punches' forces and depths.
  LoadCaseResult result;
  // neo_hookean: the converged load steps with their Newton residuals, and the steps halved and retried.
  std::vector<NewtonStep> newton_steps;
  int rejected_steps = 0;
  LoadMetrics metrics;
  Eigen::Vector3d base_force_N = Eigen::Vector3d::Zero();  // ∫ base traction
  std::vector<SensorReading> readings;                     // per sensor, MPa
  Timings wall;                                            // mesh, assemble, factor, solve
};

// Throws SceneError when the scene has no load, or beyond the resource guard (before meshing); for
// neo_hookean, when a punch is driven by force or a post stands on springs (not modelled at finite strain),
// and SolverError when Newton cannot carry the load (the load factor reached).
SolveRun solve_run(const Scene& scene, SolverKind solver);

}  // namespace skinfem::pipeline
