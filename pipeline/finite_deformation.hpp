// The report's "Does finite deformation matter at the paper's load?" for a scene whose material.model is
// neo_hookean: its static and sliding states in finite strain and the hole sweeps about them
// (pipeline/finite_defect.hpp), beside the report's linear ones on the same mesh: the contact zone in the
// material frame (contact/metrics.hpp, as the linear contact is measured) and in the spatial one, the
// sensors' readings and the hole-signal amplitudes; and the shear-strength hypothesis on the finite skin.
// The hole budget's finite rows are pipeline/hole_budget.hpp's add_finite_row on these runs. Units: mm, N,
// MPa (kPa and µm in the JSON, as its keys say).
#pragma once

#include <Eigen/Dense>
#include <array>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "skinfem/contact/metrics.hpp"
#include "skinfem/pipeline/defect.hpp"
#include "skinfem/pipeline/finite_defect.hpp"
#include "skinfem/pipeline/hole_budget.hpp"

namespace skinfem::pipeline {

struct FiniteDeformation {
  FiniteDefectRun run;  // cases static, sliding
  // The same cases on the linear skin: the report's defect sweeps' hole-free contacts, their metrics and
  // signals (positions × 2·sensors, MPa).
  std::array<contact::ContactResult, 2> linear;
  std::array<contact::ContactMetrics, 2> linear_metrics;
  std::array<Eigen::MatrixXd, 2> linear_signals;
  bool same_mesh = false;  // the linear and finite skins have the same nodes (the comparison is kinematics')
  // The contact zone against the tangential load from 0 to μF: the finite path's converged states
  // (run.path), and the linear coupled contact at kLinearPathPoints ratios from 0 to μ (material frame).
  std::vector<FinitePathPoint> linear_path;
  // Unless the scene's law is already it: the budget's shear-strength hypothesis (τ0 = μF/A wherever the
  // skin touches, validation::friction_hypotheses) on the finite skin, static then sliding, on `shear_scene`;
  // or why Newton could not carry it.
  std::optional<FiniteDefectRun> shear;
  std::optional<Scene> shear_scene;
  std::string shear_failed;
};
// The sliding case's stations on the finite path (pipeline/finite_defect.hpp's sliding_stations): with the
// frictionless and static states, five points from 0 to μF for two more finite solves.
constexpr int kSlidingStations = 3;
constexpr int kLinearPathPoints = 31;

// scene: material.model neo_hookean (check_finite_contact's rules, a bulge sweep); linear: the report's
// defect run of the same scene on the linear skin, static then sliding. shear_strength: also the
// shear-strength hypothesis (FiniteDeformation::shear), unless the scene's law is already it.
FiniteDeformation finite_deformation(const Scene& scene, const DefectRun& linear, bool shear_strength = true);

// report.json's finite_deformation entry: per case the contact (linear, finite, relative change), the
// spatial frame's zone and shift, readings and hole amplitudes per sensor; the zone along the tangential
// load (`path`: finite in both frames, linear); costs, and `answer`, one paragraph from these numbers and,
// with a budget holding the finite row, its facts.
nlohmann::json finite_deformation_json(const Scene& scene, const FiniteDeformation& f,
                                       const HoleBudget* budget);

}  // namespace skinfem::pipeline
