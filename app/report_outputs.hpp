// What the report writes beyond its stages' own folders: the crosscheck's tables and the k sweep's.
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
// The sweep with the FE k of sensor #1 per mesh scale (mesh_rows) as one more axis; writes DIR/k_sweep.csv
// and sets its report.json entry (pipeline::k_paper_json).
void write_k_paper_answer(validation::KTargetAnswer& a, const std::vector<validation::KSweepPoint>& mesh_rows,
                          const std::string& dir, nlohmann::json& entry);

}  // namespace skinfem::app
