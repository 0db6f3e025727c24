// The report's page, DIR/index.html: its headline numbers with their error bars, the levels behind them,
// the time per stage, k, the post design, the front-sensor answer, the hole budget, the crosscheck's tables,
// the figures scripts/figures.py drew (in the paper's order, captioned) and links to every file written.
#pragma once

#include <string>

#include "skinfem/pipeline/report.hpp"
#include "skinfem/scene/scene.hpp"

namespace skinfem::app {

using pipeline::ChainLevel;
using pipeline::ErrorBar;
using pipeline::HoleBudget;
using pipeline::ReportResult;

// Writes DIR/index.html (atomically). in: the report's run, with its seconds, peak and stage times the
// whole command's (the figures' included).
void write_index(const std::string& dir, const Scene& scene, const pipeline::ReportResult& in);

// Removes what an earlier report wrote in DIR (its files, figures/*.png, the defect frames), so that a
// report leaving a stage out (--fast, --no-error-bars, a scene without a contact) shows and links none of
// that stage's files from before. Only the report's own names go; anything else in DIR stays.
void remove_earlier_report(const std::string& dir);

// "value +- error", the value rounded to the error's second significant digit (the terminal's ASCII).
std::string with_error(double value, double error);

}  // namespace skinfem::app
