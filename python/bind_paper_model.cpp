// The paper's model, ingredient by ingredient (validation/paper_model.hpp).
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
#include "skinfem/contact/layer_hertz.hpp"
#include "skinfem/pipeline/sensor_greens.hpp"
#include "skinfem/validation/paper_model.hpp"

namespace skinfem::python {

void bind_paper_model(py::module_& m) {
  py::class_<PyKernel>(m, "Kernel",
                       "A Green tensor for the paper's convolution (validation/paper_model.hpp).")
      .def_readonly("what", &PyKernel::what);
  m.def(
      "halfspace_kernel",
      [](std::vector<double> thickness, double k) {
        require(std::isfinite(k) && k > 0, "k", k, "must be a finite rescaling factor > 0");
        if (thickness.empty()) throw SceneError("thickness_mm = []: must hold one thickness per sensor");
        for (double h : thickness)
          require(std::isfinite(h) && h > 0, "thickness_mm", h, "must be finite thicknesses > 0 (mm)");
        const int n = static_cast<int>(thickness.size());
        return PyKernel{validation::rescaled_halfspace_kernel(std::move(thickness), k),
                        "half-space Green tensor rescaled by k = " + std::to_string(k), n};
      },
      py::arg("thickness_mm"), py::arg("k") = 1.0,
      "k g_half(sqrt(k) offset) at each sensor's depth (thickness_mm per sensor); k = 1 is "
      "Boussinesq-Cerruti.");
  m.def(
      "layer_kernel",
      [](double h, double nu, double reach) {
        require(std::isfinite(h) && h > 0 && h <= 100, "h_mm", h, "must be a thickness in (0, 100] mm");
        require(nu >= 0 && nu <= 0.5, "nu", nu, "must be a Poisson's ratio in [0, 0.5]");
        // Tabulated every 0.01 mm up to reach, one Hankel transform each.
        require(std::isfinite(reach) && reach > 0 && reach <= 100, "reach_mm", reach,
                "must be the largest offset tabulated, in (0, 100] mm");
        return PyKernel{validation::layer_exact_kernel(h, nu, reach),
                        "exact bonded layer h = " + std::to_string(h) + " mm"};
      },
      py::arg("h_mm"), py::arg("nu") = 0.5, py::arg("reach_mm") = 20.0,
      "The exact bonded layer's point readings (Hankel transforms), the same for every sensor.");
  m.def(
      "fe_kernel",
      [](const pipeline::SensorGreens& g) {
        return PyKernel{
            [&g](int s, double ox, double oy) { return g.at(s, true, ox, oy, green::LayerLoad::point, 0); },
            "FE Green maps (" + g.path + " path), sensor-disc readings",
            static_cast<int>(g.thickness.size())};
      },
      py::arg("greens"), py::keep_alive<0, 1>(), "The FE maps of `greens` (disc readings) as a kernel.");
  py::class_<PyTractions>(m, "Tractions", "Interfacial tractions p_z, p_x (validation/paper_model.hpp).")
      .def_readonly("what", &PyTractions::what)
      .def_property_readonly("force_N", [](const PyTractions& t) { return t.t.force(); });
  m.def(
      "hertz_tractions",
      [](double force, double R, double E, double nu, std::array<double, 2> center, double ratio,
         double shear_kpa, double layer_h) {
        require(std::isfinite(force) && force > 0, "force_N", force, "must be a finite force > 0");
        require(std::isfinite(R) && R > 0, "radius_mm", R, "must be a finite radius > 0");
        require(std::isfinite(E) && E > 0, "E_MPa", E, "must be a finite Young's modulus > 0");
        require(nu >= 0 && nu <= 0.5, "nu", nu, "must be a Poisson's ratio in [0, 0.5]");
        require(std::isfinite(center[0]) && std::isfinite(center[1]), "center_mm",
                std::isfinite(center[0]) ? center[1] : center[0], "must be finite");
        require(std::isfinite(ratio), "ratio", ratio, "must be finite");
        require(std::isfinite(shear_kpa), "shear_kPa", shear_kpa, "must be finite");
        require(layer_h == 0 || (std::isfinite(layer_h) && layer_h > 0), "layer_h_mm", layer_h,
                "must be 0 (the half space) or a finite thickness > 0");
        if (layer_h > 0) {
          const contact::LayerHertzResult l = contact::layer_hertz_force(force, R, layer_h, E, nu);
          return PyTractions{validation::layer_hertz_tractions(l, center, ratio, 1e-3 * shear_kpa),
                             "exact bonded-layer Hertz pressure, a = " + std::to_string(l.a_mm) + " mm"};
        }
        const contact::HertzHalfspace h = contact::hertz_halfspace(force, R, E, nu);
        return PyTractions{validation::hertz_tractions(h, center, ratio, 1e-3 * shear_kpa),
                           "half-space Hertz pressure, a = " + std::to_string(h.a_mm) + " mm"};
      },
      py::arg("force_N"), py::arg("radius_mm"), py::arg("E_MPa"), py::arg("nu") = 0.5,
      py::arg("center_mm") = std::array<double, 2>{0, 0}, py::arg("ratio") = 0.0, py::arg("shear_kPa") = 0.0,
      py::arg("layer_h_mm") = 0.0,
      "A sphere's pressure: half-space Hertz, or the exact bonded layer of thickness layer_h_mm > 0; p_x = "
      "ratio p_z + shear_kPa where it presses.");
  m.def(
      "convolve",
      [](const PyTractions& t, const PyKernel& g, const Scene& scene) {
        require_kernel_fits(g, scene);
        const Eigen::VectorXd v = validation::convolve(t.t, g.g, scene.sensors);
        return kpa(v, {v.size() / 2, 2});
      },
      py::arg("tractions"), py::arg("kernel"), py::arg("scene"),
      "The paper's eq. (1): each sensor's (sigma_z, sigma_x), kPa (sensors x 2).");
  m.def(
      "first_order_hole",
      [](const PyTractions& t, const PyKernel& g, const Scene& scene,
         const std::vector<std::array<double, 2>>& centers, double area) {
        require_kernel_fits(g, scene);
        require(std::isfinite(area) && area > 0, "hole_area_mm2", area, "must be a finite area > 0");
        for (const auto& c : centers)
          require(std::isfinite(c[0]) && std::isfinite(c[1]), "centers_mm", std::isfinite(c[0]) ? c[1] : c[0],
                  "must be finite positions (mm)");
        return kpa_by_sensor(validation::first_order_hole(t.t, g.g, scene.sensors, centers, area));
      },
      py::arg("tractions"), py::arg("kernel"), py::arg("scene"), py::arg("centers_mm"),
      py::arg("hole_area_mm2"),
      "The paper's eqs. (2)-(3): varsigma at each hole centre, positions x sensors x (z, x), kPa.");
}

}  // namespace skinfem::python
