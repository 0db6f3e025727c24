// What the report writes beyond its stages' own folders: the crosscheck's tables, report.json's entries
// for the front sensors, the k sweep and the error bars.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/report_page.hpp"
#include "skinfem/pipeline/chain_level.hpp"
#include "skinfem/scene/scene.hpp"
#include "skinfem/validation/crosscheck.hpp"
#include "skinfem/validation/k_sweep.hpp"

namespace skinfem::app {

// DIR/readings.csv, defect.csv, pressure.csv and attribution.csv (stresses in kPa).
void write_crosscheck(const validation::Crosscheck& x, const Sensors& sensors, const std::string& dir);
// report.json's front_sensors entry (validation::front_sensor_answer).
nlohmann::json front_sensor_json(const validation::FrontSensorAnswer& a);
// The exact layer's k as each reading of the calibration protocol changes about the scene's (thickness h at
// the headline sensor): which single change gives the paper's k (validation/k_sweep.hpp).
validation::KTargetAnswer k_paper_sweep(const Scene& scene, double h);
// The sweep with the FE k of sensor #1 per mesh scale (mesh_rows) as one more axis; writes DIR/k_sweep.csv
// and its report.json entry.
void write_k_paper_answer(validation::KTargetAnswer& a, const std::vector<validation::KSweepPoint>& mesh_rows,
                          const std::string& dir, nlohmann::json& entry);
// The chain's errors as the page shows them (units, what, how each was estimated); coarse_scales: the
// coarser levels' mesh scales, coarse to fine.
std::vector<ErrorBar> error_bars(const std::vector<pipeline::ChainError>& errors,
                                 const std::vector<double>& coarse_scales);
nlohmann::json error_bars_json(const std::vector<ErrorBar>& bars);

}  // namespace skinfem::app
