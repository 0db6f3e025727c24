// What the report writes beyond its stages' own folders: the crosscheck's tables and the k sweep's.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "skinfem/scene/scene.hpp"
#include "skinfem/validation/crosscheck.hpp"
#include "skinfem/validation/k_sweep.hpp"

namespace skinfem::app {

// DIR/readings.csv, defect.csv, pressure.csv and attribution.csv (stresses in kPa).
void write_crosscheck(const validation::Crosscheck& x, const Sensors& sensors, const std::string& dir);
// DIR/k_sweep.csv: the k sweep's points (parameter,value,k_central,k_lsq_line).
void write_k_sweep(const validation::KTargetAnswer& a, const std::string& dir);

}  // namespace skinfem::app
