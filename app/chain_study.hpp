// Output of a chain study (`study --chain`, the report's error bars): its table, its figure data and its
// summary lines.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "skinfem/pipeline/chain_level.hpp"

namespace skinfem::app {

// Prints each quantity's order and errors and each stage's time-vs-DOFs exponent, writes
// DIR/chain_study.csv (stage,level,dofs,seconds,error; the Pareto plot of scripts/figures.py) and
// DIR/chain_study.json (levels, extrapolation, time_vs_dofs_exponent), and returns the latter.
nlohmann::json write_chain_study(const Scene& scene, const std::vector<pipeline::ChainLevel>& levels,
                                 const std::string& out_dir);

}  // namespace skinfem::app
