// Output of a chain study (`study --chain`, the report's error bars): its table, its figure data and its
// summary lines.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "skinfem/pipeline/chain_level.hpp"

namespace skinfem::app {

// Prints each quantity's order and errors and each stage's time-vs-DOFs exponent (from study,
// pipeline::chain_study_json's), writes DIR/chain_study.csv (stage,level,dofs,seconds,error; the Pareto plot
// of scripts/figures.py) and DIR/chain_study.json (study).
void write_chain_study(const std::vector<pipeline::ChainLevel>& levels, const nlohmann::json& study,
                       const std::string& out_dir);

}  // namespace skinfem::app
