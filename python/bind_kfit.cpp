// k: the calibration protocol on FE (pipeline/kfit.hpp).
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
#include "skinfem/green/calibration.hpp"
#include "skinfem/pipeline/kfit.hpp"
#include "skinfem/pipeline/sensor_greens.hpp"

namespace skinfem::python {

void bind_kfit(py::module_& m) {
  py::class_<pipeline::KfitSensor>(m, "KfitSensor", "One sensor's k fits (pipeline/kfit.hpp).")
      .def_readonly("sensor", &pipeline::KfitSensor::sensor)
      .def_readonly("x_mm", &pipeline::KfitSensor::x_mm)
      .def_readonly("y_mm", &pipeline::KfitSensor::y_mm)
      .def_readonly("h_mm", &pipeline::KfitSensor::h_mm)
      .def_readonly("scan_half_width_mm", &pipeline::KfitSensor::scan_half_width_mm)
      .def_property_readonly("k_central", [](const pipeline::KfitSensor& k) { return k.fe.k_central; })
      .def_property_readonly("k_lsq_line", [](const pipeline::KfitSensor& k) { return k.fe.k_lsq_line; })
      .def_property_readonly("component_k",
                             [](const pipeline::KfitSensor& k) {
                               std::array<double, 4> v;
                               for (int c = 0; c < 4; ++c) v[c] = k.fe.components[c].k;
                               return per_component(v);
                             })
      .def_property_readonly(
          "peak_point_per_mm2",
          [](const pipeline::KfitSensor& k) { return per_component(k.peak_point_per_mm2); })
      .def_readonly("effective_thickness_mm", &pipeline::KfitSensor::effective_thickness_mm)
      .def_property_readonly("gains",
                             [](const pipeline::KfitSensor& k) {
                               py::dict d;  // per component: as given (sigma_z, sigma_x) or fitted
                               for (int c = 0; c < 4; ++c)
                                 d[green::component_name(green::kComponents[c])] = k.fe.components[c].gain;
                               return d;
                             })
      .def_property_readonly("paper_calibration",
                             [](const pipeline::KfitSensor& k) {
                               if (!k.paper_calibration) return py::object(py::none());
                               const auto& c = *k.paper_calibration;
                               py::dict d;
                               d["thickness_mm"] = c.thickness_mm;
                               d["scale_z"] = c.scale_z;
                               d["scale_x"] = c.scale_x;
                               d["rms_z_over_peak"] = c.rms_z_over_peak;
                               d["rms_x_over_peak"] = c.rms_x_over_peak;
                               return py::object(d);
                             })
      .def_property_readonly(
          "k_central_exact",
          [](const pipeline::KfitSensor& k) { return k.exact ? py::cast(k.exact->k_central) : py::none(); })
      .def_property_readonly(
          "k_lsq_line_exact",
          [](const pipeline::KfitSensor& k) { return k.exact ? py::cast(k.exact->k_lsq_line) : py::none(); })
      .def_property_readonly("disc_max_diff_over_peak", [](const pipeline::KfitSensor& k) {
        return k.exact ? py::object(per_component(k.disc_max_diff_over_peak)) : py::object(py::none());
      });
  py::class_<pipeline::KfitResult>(
      m, "KfitResult", "The k correction of every sensor; component arrays in (zz, zx, xz, xx) order.")
      .def_property_readonly(
          "load",
          [](const pipeline::KfitResult& r) { return r.load == green::LayerLoad::point ? "point" : "punch"; })
      .def_readonly("punch_diameter_mm", &pipeline::KfitResult::punch_diameter_mm)
      .def_readonly("sensors", &pipeline::KfitResult::sensors)
      .def_readonly("path", &pipeline::KfitResult::path)
      .def_readonly("path_model", &pipeline::KfitResult::path_model)
      .def_readonly("dofs", &pipeline::KfitResult::dofs)
      .def_readonly("adjoint_solves", &pipeline::KfitResult::adjoint_solves)
      .def_readonly("paper_k", &pipeline::KfitResult::paper_k)
      .def_readonly("paper_k_reproduced", &pipeline::KfitResult::paper_k_reproduced)
      .def_readonly("verdict", &pipeline::KfitResult::verdict)
      .def_readonly("explanation", &pipeline::KfitResult::explanation)
      .def_property_readonly("wall_s", [](const pipeline::KfitResult& r) { return json_object(r.wall); })
      .def_readonly("peak_rss_mb", &pipeline::KfitResult::peak_rss_mb);
  m.def("_kfit_json", [](const pipeline::KfitResult& r) { return pipeline::kfit_json(r).dump(); });
  m.def(
      "kfit",
      [](const Scene& scene, const std::string& load, const std::string& path) {
        const green::LayerLoad l = calibration_load_named(load);
        const pipeline::GreenPath p = pipeline::green_path_named(path);
        pipeline::require_linear(scene, "kfit");  // as the command line: k is the linear skin's
        py::gil_scoped_release free;
        return pipeline::kfit(scene, pipeline::green_path(scene, p), l);
      },
      py::arg("scene"), py::arg("load") = "punch", py::arg("path") = "auto",
      "The k correction of every sensor (what `skinfem kfit` computes): load 'punch' (the scene's "
      "calibration "
      "punch) or 'point'; path 'auto' (the meridian where the skin allows), '3d' or 'meridian'.");
}

}  // namespace skinfem::python
