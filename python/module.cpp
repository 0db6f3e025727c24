// The skinfem Python module (imported as skinfem, python/skinfem/__init__.py): scenes and the pipeline's
// stages with typed results; numbers in the units their names give. Errors keep the command's one-line
// messages: SceneError and MeshError (ValueErrors) for bad input, SolverError (a RuntimeError) when a solve
// fails.
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>

#include "python/bindings.hpp"
#include "skinfem/fem/mixed_solver.hpp"
#include "skinfem/mesh/surface.hpp"
#include "skinfem/pipeline/progress.hpp"
#include "skinfem/scene/load.hpp"

using namespace skinfem;
using namespace skinfem::python;

PYBIND11_MODULE(_skinfem, m) {
  m.doc() = "skinfem's pipeline (see the package docstring)";
  m.attr("_skinfem_version") = SKINFEM_VERSION;
  // As the command's exit codes: bad input (2) is a ValueError, a failed solve (1) a RuntimeError.
  py::register_exception<SceneError>(m, "SceneError", PyExc_ValueError);
  py::register_exception<MeshError>(m, "MeshError", PyExc_ValueError);
  py::register_exception<SolverError>(m, "SolverError", PyExc_RuntimeError);

  m.def(
      "set_progress",
      [](std::function<void(const std::string&)> callback) {
        if (!callback) {
          pipeline::set_progress_sink(nullptr);
          return;
        }
        pipeline::set_progress_sink([callback](const std::string& message) {
          py::gil_scoped_acquire gil;
          callback(message);
        });
      },
      py::arg("callback"), "Progress lines of long stages go to callback(message); None: silent (default).");
  // The sink holds a Python callable: release it while the interpreter lives (atexit runs before
  // finalization), not in a static destructor after it, which would wait for the GIL forever.
  py::module_::import("atexit").attr("register")(
      py::cpp_function([]() { pipeline::set_progress_sink(nullptr); }));

  bind_scene(m);
  bind_kfit(m);
  bind_contact(m);
  bind_defect(m);
  bind_green(m);
  bind_paper_model(m);
  bind_crosscheck(m);
  bind_report(m);
}
