// The main job (pipeline/report.hpp) as `skinfem report` runs it, without its files: report.json's content.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "python/bindings.hpp"
#include "skinfem/pipeline/report.hpp"
#include "skinfem/scene/commands.hpp"

namespace skinfem::python {

namespace {
// The command's default levels (its --error-scales), from the command table.
std::vector<double> default_error_scales() {
  for (const OptionSpec& o : command_named("report").options)
    if (o.name == "error_scales") {
      std::vector<double> out;
      std::stringstream text(o.default_value);
      for (std::string item; std::getline(text, item, ',');) out.push_back(std::stod(item));
      return out;
    }
  return {};
}
}  // namespace

void bind_report(py::module_& m) {
  m.def(
      "report",
      [](const Scene& scene, std::optional<std::vector<double>> error_scales, bool fast) {
        pipeline::ReportOptions options;
        options.fast = fast;
        // Given levels go to the library, which refuses them with fast; the default only without fast.
        if (error_scales)
          options.error_scales = *error_scales;
        else if (!fast)
          options.error_scales = default_error_scales();
        pipeline::ReportSink keep_only;  // no files: the result is the report
        pipeline::ReportResult r;
        {
          py::gil_scoped_release free;
          r = pipeline::report_run(scene, options, keep_only);
        }
        r.json["wall_total_s"] = r.seconds;
        r.json["peak_rss_mb"] = r.peak_rss_mb;
        return json_object(r.json);
      },
      py::arg("scene"), py::arg("error_scales") = py::none(), py::arg("fast") = false,
      "The main job (what `skinfem report` computes) as report.json's dict, no files written: the whole "
      "chain "
      "on one mesh and one factorization, the paper's model checked against it, error bars from the coarser "
      "levels error_scales (mesh sizes x s, s > 1; default the command's; [] none) and the post design. "
      "fast=True: no error bars, hole budget, post design, k sweep or effective-thickness fits.");
}

}  // namespace skinfem::python
