// Scenes: build, read and validate them.
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
#include "skinfem/mesh/sizing.hpp"
#include "skinfem/scene/load.hpp"
#include "skinfem/validation/k_sweep.hpp"

namespace skinfem::python {

void bind_scene(py::module_& m) {
  py::class_<Scene>(m, "Scene", "A validated scene (mm, N, MPa); build one with skinfem.scene(...).")
      .def_readonly("name", &Scene::name)
      .def_readonly("source_path", &Scene::source_path)
      .def_property_readonly("E_MPa", [](const Scene& s) { return s.material.E; })
      .def_property_readonly("nu", [](const Scene& s) { return s.material.nu; })
      .def_property_readonly("nominal_thickness_mm", [](const Scene& s) { return nominal_thickness(s); })
      .def_property_readonly("sensor_positions_mm",
                             [](const Scene& s) {
                               py::array_t<double> a({static_cast<py::ssize_t>(s.sensors.positions.size()),
                                                      static_cast<py::ssize_t>(2)});
                               auto v = a.mutable_unchecked<2>();
                               for (size_t i = 0; i < s.sensors.positions.size(); ++i)
                                 for (int k = 0; k < 2; ++k) v(i, k) = s.sensors.positions[i][k];
                               return a;
                             })
      .def_property_readonly("has_contact", [](const Scene& s) { return s.contact.has_value(); })
      .def_property(
          "max_dofs", [](const Scene& s) { return s.limits.max_dofs; },
          [](Scene& s, double n) {
            require(std::isfinite(n) && n >= 0, "max_dofs", n, "must be a finite number >= 0 (0: no limit)");
            s.limits.max_dofs = n;
          },
          "Refuse a mesh estimated or built above this many DOFs, as the command line's --max-dofs does "
          "(0, the default: the available memory only).")
      .def(
          "scaled",
          [](const Scene& scene, double s, bool cap_holes) {
            require(std::isfinite(s) && s > 0, "s", s, "must be a finite mesh scale > 0");
            return scaled_scene(scene, s, cap_holes);
          },
          py::arg("s"), py::arg("cap_holes") = false,
          "The scene with every mesh size scaled by s (the family every study's levels come from).")
      .def("__repr__",
           [](const Scene& s) { return "<skinfem.Scene '" + s.name + "' from " + s.source_path + ">"; });
  m.def(
      "k_sweep",
      [](double h, double nu, double punch_diameter) {
        require(std::isfinite(h) && h > 0 && h <= 100, "h", h, "must be a thickness in (0, 100] mm");
        require(nu >= 0 && nu <= 0.5, "nu", nu, "must be a Poisson's ratio in [0, 0.5]");
        require(std::isfinite(punch_diameter) && punch_diameter > 0 && punch_diameter <= 10 * h,
                "punch_diameter", punch_diameter,
                "must be a calibration punch in (0, 10 h] mm (wider, it no longer probes the layer's Green "
                "tensor)");
        validation::KProtocol base;
        base.h = h, base.nu = nu, base.punch_diameter = punch_diameter;
        py::list rows;
        for (const auto& p : validation::k_sweep(base))
          rows.append(py::dict(py::arg("parameter") = p.parameter, py::arg("value") = p.value,
                               py::arg("k_central") = p.k_central, py::arg("k_lsq_line") = p.k_lsq_line));
        return rows;
      },
      py::arg("h"), py::arg("nu"), py::arg("punch_diameter"),
      "The report's k sweep (kfit/k_sweep.csv): both k criteria of the exact bonded layer as each reading of "
      "the calibration protocol varies alone about this base (point sensors, a rigid punch).");
  m.def("load_scene", &load_scene, py::arg("path"), "Reads and validates a scene file.");
  m.def("parse_scene", &parse_scene, py::arg("json_text"), py::arg("source_path"),
        "Validates a scene given as JSON text; source_path names it in messages and anchors relative paths.");
}

}  // namespace skinfem::python
