// Output of a chain study (`study --chain`, the report's error bars): its table, its figure data and its
// summary lines.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "skinfem/pipeline/chain_level.hpp"

namespace skinfem::app {

// Writes DIR/chain_study.csv (stage,level,dofs,seconds,error; the Pareto plot of scripts/figures.py) and
// DIR/chain_study.json (study, pipeline::chain_study_json's). print_table: also print each quantity's order
// and errors and each stage's time-vs-DOFs exponent (`study --chain`; the report prints its error bars in
// its own words).
void write_chain_study(const std::vector<pipeline::ChainLevel>& levels, const nlohmann::json& study,
                       const std::string& out_dir, bool print_table);

}  // namespace skinfem::app
