// The hole sweep (pipeline/defect.hpp).
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "python/bindings.hpp"
#include "skinfem/pipeline/chain_level.hpp"
#include "skinfem/pipeline/contact_setup.hpp"
#include "skinfem/pipeline/defect.hpp"

namespace skinfem::python {

void bind_defect(py::module_& m) {
  py::class_<pipeline::DefectRun>(
      m, "DefectRun", py::dynamic_attr(),
      "A hole swept through the contact, static and sliding (pipeline/defect.hpp).")
      .def_readonly("cases", &pipeline::DefectRun::cases)
      .def_property_readonly(
          "u_mm",
          [](const pipeline::DefectRun& r) {
            const auto& c = r.sweeps.at(0).centers;
            py::array_t<double> a(static_cast<py::ssize_t>(c.size()));
            for (size_t i = 0; i < c.size(); ++i) a.mutable_data()[i] = c[i][0];
            return a;
          },
          "the hole centre's x at each position, mm")
      .def(
          "varsigma_kPa",
          [](const pipeline::DefectRun& r, const std::string& name) {
            for (size_t ci = 0; ci < r.cases.size(); ++ci)
              if (r.cases[ci] == name) return kpa_by_sensor(r.sweeps[ci].varsigma);
            throw SceneError("case: '" + name + "' is not one of static, sliding");
          },
          py::arg("case"), "ς of case 'static' or 'sliding': positions × sensors × (z, x), kPa")
      .def_property_readonly("wall_s", [](const pipeline::DefectRun& r) { return json_object(r.wall); });
  m.def("_defect_json", [](const pipeline::DefectRun& r, const Scene& scene) {
    return pipeline::defect_json(scene, r).dump();
  });
  m.def(
      "_defect",
      [](const Scene& scene, const std::vector<double>& error_scales) {
        pipeline::check_error_scales(error_scales);
        pipeline::require_sweep(scene);  // before the set-up
        py::gil_scoped_release free;
        std::vector<pipeline::ChainLevel> coarse = pipeline::largest_sliding_levels(scene, error_scales);
        return pipeline::defect_run(scene, pipeline::contact_setup(scene), std::move(coarse));
      },
      py::arg("scene"), py::arg("error_scales"));
}

}  // namespace skinfem::python
