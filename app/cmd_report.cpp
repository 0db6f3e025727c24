// skinfem report — the main job: the whole chain on one mesh and one factorization, and the paper's
// convolution model checked against it assumption by assumption (validation/crosscheck.hpp).
//
//   $ skinfem report scenes/candelier2011.json
//   report candelier2011: 95898 DOFs, one factorization for the chain and 2 coarser for the error bars;
//   25.9 s, peak 1185 MB
//
// The chain is pipeline::report_run's (pipeline/report.hpp); this command writes each stage's results as
// they become final (app/report_writer.hpp), and the figures are drawn by background processes as their
// inputs do.
//
// A scene mirror-symmetric about y = 0, contact included (pipeline/symmetry.hpp), is solved on its half y ≥ 0
// and every output is written for the whole skin (mesh.vtu, maps, pressure, fields).
//
// Stages, each writing its own folder under DIR (default out/<scene name>): mesh/ (mesh.vtu, boundary.vtu),
// green/ (green.csv, green_maps.vtp, post_design.csv: an isolated post against a disc at the skin's axis and
// a design sweep, pipeline/post_design.hpp), kfit/ (kfit.json, and k_sweep.csv: the exact layer's k as each
// reading of the calibration protocol changes, validation/k_sweep.hpp), and with a contact: contact/
// (pressure.vtp, fields.vtu, sensors.csv, modes.csv), defect/ (defect.csv, defect.pvd + frames/) and
// crosscheck/ (readings.csv, defect.csv, pressure.csv, attribution.csv with columns
// case,variant,sensor,component,amplitude_ratio,peak_shift_mm,shape_error). Then figures/*.png
// (scripts/figures.py, matplotlib) and DIR/report.json (the headline numbers with units, wall seconds per
// stage, peak memory) and DIR/index.html (figures, tables, links to every VTK file).
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "app/common.hpp"
#include "app/report_page.hpp"
#include "app/report_writer.hpp"
#include "skinfem/pipeline/chain_level.hpp"

namespace skinfem::app {

int run_report(const Scene& scene, const std::string& out_dir, const std::vector<double>& error_scales,
               bool fast) {
  const pipeline::ReportOptions options{error_scales, fast};
  pipeline::check_report(scene, options);
  check_output_dir(out_dir);
  remove_earlier_report(out_dir);
  ReportWriter writer(scene, out_dir, options);
  pipeline::ReportResult run = pipeline::report_run(scene, options, writer);
  return writer.finish(run);
}

}  // namespace skinfem::app
