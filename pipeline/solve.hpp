// `skinfem solve` as a stage: the scene's loads (punches, traction patches) on its skin bonded to the rigid
// base, Taylor–Hood P2–P1, one factorization and one solve; the figures of merit of the load case
// (validation/load_metrics.hpp) and every sensor's reading (fem/sensor_reading.hpp). Units: mm, N, MPa.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <vector>

#include "skinfem/fem/elastic_model.hpp"
#include "skinfem/fem/sensor_reading.hpp"
#include "skinfem/pipeline/clock.hpp"
#include "skinfem/validation/load_metrics.hpp"

namespace skinfem::pipeline {

struct SolveRun {
  std::unique_ptr<TetMesh> mesh;        // heap-held: model refers to it
  std::unique_ptr<ElasticModel> model;  // assembled and factored
  LoadCaseResult result;
  LoadMetrics metrics;
  Eigen::Vector3d base_force_N = Eigen::Vector3d::Zero();  // ∫ base traction
  std::vector<SensorReading> readings;                     // per sensor, MPa
  Timings wall;                                            // mesh, assemble, factor, solve
};

// Throws SceneError when the scene has no load, or beyond the resource guard (before meshing).
SolveRun solve_run(const Scene& scene, SolverKind solver);

}  // namespace skinfem::pipeline
