// Sensor Green tensors and their maps (pipeline/sensor_greens.hpp, pipeline/green.hpp).
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
#include "skinfem/green/kernel_grid.hpp"
#include "skinfem/pipeline/green.hpp"
#include "skinfem/pipeline/sensor_greens.hpp"

namespace skinfem::python {

void bind_green(py::module_& m) {
  py::class_<pipeline::SensorGreens>(
      m, "Greens", py::dynamic_attr(),
      "Every sensor's Green maps, 3D or meridian (pipeline/sensor_greens.hpp).")
      .def_readonly("path", &pipeline::SensorGreens::path)
      .def_readonly("model", &pipeline::SensorGreens::model)
      .def_readonly("dofs", &pipeline::SensorGreens::dofs)
      .def_readonly("adjoint_solves", &pipeline::SensorGreens::adjoint_solves)
      .def_property_readonly(
          "thickness_mm", [](const pipeline::SensorGreens& g) { return array_of(g.thickness); },
          "skin thickness above each sensor, mm")
      .def(
          "g_per_mm2",
          [](const pipeline::SensorGreens& g, int sensor, py::array_t<double, py::array::forcecast> ox,
             py::array_t<double, py::array::forcecast> oy, bool disc, const std::string& load,
             double radius) {
            if (sensor < 0 || sensor >= static_cast<int>(g.thickness.size()))
              throw SceneError("sensor: " + std::to_string(sensor) + " is not a sensor index (0 to " +
                               std::to_string(g.thickness.size() - 1) + ")");
            if (ox.size() != oy.size()) throw SceneError("offsets: x and y differ in length");
            const green::LayerLoad l =
                load == "point" ? green::LayerLoad::point : calibration_load_named(load);
            py::array_t<double> out({ox.size(), py::ssize_t{4}});
            auto w = out.mutable_unchecked<2>();
            const double *x = ox.data(), *y = oy.data();
            for (py::ssize_t i = 0; i < ox.size(); ++i) {
              const green::GreenSample v = g.at(sensor, disc, x[i], y[i], l, radius);
              w(i, 0) = v.zz, w(i, 1) = v.zx, w(i, 2) = v.xz, w(i, 3) = v.xx;
            }
            return out;
          },
          py::arg("sensor"), py::arg("offset_x_mm"), py::arg("offset_y_mm"), py::arg("disc") = true,
          py::arg("load") = "point", py::arg("radius_mm") = 0.0,
          "g (1/mm^2) of sensor (0-based) for a unit load centred at each offset from it, columns zz, zx, "
          "xz, "
          "xx (reading b of a force along a: g_ab); disc: the sensor's disc mean, else its centre value; "
          "load "
          "'point' or 'punch' of radius_mm.")
      .def("_kernel_grid", [](const pipeline::SensorGreens& g, const Scene& scene, double dx,
                              std::optional<std::array<double, 4>> box) {
        if (!(dx > 0)) throw SceneError("dx_mm: " + std::to_string(dx) + " must be > 0");
        if (!box) {
          pipeline::check_kernel_grid(scene, dx);
          box = pipeline::footprint_box(scene);
        }
        const auto& b = *box;
        const green::KernelGrid k = green::kernel_grid(g.disc_map, scene.sensors, b[0], b[1], b[2], b[3], dx);
        const py::ssize_t nx = k.x.size(), ny = k.y.size(), ns = k.values.size();
        py::array_t<double> x(nx), y(ny), values({ns, py::ssize_t{4}, ny, nx});
        py::array_t<bool> on({ny, nx});
        std::copy(k.x.begin(), k.x.end(), x.mutable_data());
        std::copy(k.y.begin(), k.y.end(), y.mutable_data());
        for (py::ssize_t i = 0; i < nx * ny; ++i) on.mutable_data()[i] = k.on_skin[i];
        for (py::ssize_t s = 0; s < ns; ++s)
          for (int c = 0; c < 4; ++c)
            std::copy(k.values[s][c].begin(), k.values[s][c].end(),
                      values.mutable_data() + (s * 4 + c) * nx * ny);
        py::dict d;
        d["x_mm"] = x, d["y_mm"] = y, d["on_skin"] = on, d["g_per_mm2"] = values;
        return d;
      });
  m.def(
      "greens",
      [](const Scene& scene, const std::string& path) {
        const pipeline::GreenPath p = pipeline::green_path_named(path);
        py::gil_scoped_release free;
        return pipeline::green_path(scene, p);
      },
      py::arg("scene"), py::arg("path") = "auto",
      "Every sensor's Green maps (what `skinfem green` computes): path 'auto' (the meridian where the skin "
      "allows), '3d' or 'meridian'.");
}

}  // namespace skinfem::python
