// The report's page, DIR/index.html: its headline numbers with their error bars, the levels behind them,
// the time per stage, k, the post design, the front-sensor answer, the hole budget, the crosscheck's tables,
// the figures scripts/figures.py drew (in the paper's order, captioned) and links to every file written.
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "skinfem/pipeline/chain_level.hpp"
#include "skinfem/pipeline/clock.hpp"
#include "skinfem/pipeline/hole_budget.hpp"
#include "skinfem/pipeline/post_design.hpp"
#include "skinfem/scene/scene.hpp"
#include "skinfem/validation/crosscheck.hpp"

namespace skinfem::app {

using pipeline::ChainLevel;
using pipeline::HoleBudget;
using pipeline::Timings;

using pipeline::ErrorBar;

// What index.html shows, as the stages returned it.
struct IndexInput {
  int dofs = 0;
  double wall_total_s = 0, peak_rss_mb = 0;
  const Timings* wall = nullptr;         // the report's own seconds per stage
  const Timings* wall_beside = nullptr;  // seconds of the stages run on another thread beside them
  std::string kfit_verdict, k_paper_answer;
  std::optional<validation::FrontSensorAnswer> front;
  std::optional<HoleBudget> budget;
  std::vector<ErrorBar> error_bars;                 // empty without error bars
  const std::vector<ChainLevel>* levels = nullptr;  // the error bars' levels, coarse to fine
  std::map<std::string, double> exponents;          // time ∝ DOFs^e per stage
  const validation::Crosscheck* x = nullptr;
  const pipeline::PostDesign* post = nullptr;  // what a post changes, when the skin has an axis
  std::string post_answer;
  std::string left_out;  // what a --fast report left out; empty otherwise
};

// Writes DIR/index.html (atomically).
void write_index(const std::string& dir, const Scene& scene, const IndexInput& in);

// "value +- error", the value rounded to the error's second significant digit (the terminal's ASCII).
std::string with_error(double value, double error);

}  // namespace skinfem::app
