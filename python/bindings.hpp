// What the module's files share: its argument checks and conversions, and one binder per area (the
// skinfem Python module: python/module.cpp).
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <array>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "skinfem/green/layer_exact.hpp"
#include "skinfem/pipeline/sensor_greens.hpp"
#include "skinfem/scene/scene.hpp"
#include "skinfem/validation/crosscheck.hpp"
#include "skinfem/validation/paper_model.hpp"

namespace skinfem::python {

namespace py = pybind11;

// An argument outside its range: one line naming it, its value and what is allowed, raised as
// skinfem.SceneError (a ValueError), as the scene reader does for a file.
void require(bool ok, const char* name, double value, const std::string& allowed);
py::array_t<double> per_component(const std::array<double, 4>& v);
// MPa values (a contiguous vector) as a kPa array of `shape`, row-major.
py::array_t<double> kpa(const Eigen::VectorXd& v, std::vector<py::ssize_t> shape);
py::array_t<double> array_of(const std::vector<double>& v);
py::object json_object(const nlohmann::json& j);
green::LayerLoad calibration_load_named(const std::string& load);
// A positions × 2·sensors MPa matrix (σ_z of sensor k at column 2k) as positions × sensors × (z, x) kPa.
py::array_t<double> kpa_by_sensor(const Eigen::MatrixXd& v);
int case_index(const std::string& name);
// A crosscheck variant by name; `kind` says which list ("reading" or "signal") for the error.
size_t variant_named(const std::vector<validation::Variant>& variants, const std::string& name,
                     const char* kind);
std::vector<std::string> variant_names(const std::vector<validation::Variant>& variants);

// The paper model's Green-tensor ingredient (validation/paper_model.hpp), a Python object of its own.
struct PyKernel {
  validation::GreenKernel g;
  std::string what;
  int sensors = -1;  // the sensors it is built for (one per thickness, or the FE maps'); -1: any
};
// A kernel built for some sensors applied to another scene's would read past its tables.
void require_kernel_fits(const PyKernel& g, const Scene& scene);
// Its traction ingredient.
struct PyTractions {
  validation::Tractions t;
  std::string what;
};

// Scenes: build, read and validate them.
void bind_scene(py::module_& m);
// k: the calibration protocol on FE (pipeline/kfit.hpp).
void bind_kfit(py::module_& m);
// Contact: the 3D and meridian paths (pipeline/contact.hpp, pipeline/meridian_contact.hpp).
void bind_contact(py::module_& m);
// The hole sweep (pipeline/defect.hpp).
void bind_defect(py::module_& m);
// Sensor Green tensors and their maps (pipeline/sensor_greens.hpp, pipeline/green.hpp).
void bind_green(py::module_& m);
// The paper's model, ingredient by ingredient (validation/paper_model.hpp).
void bind_paper_model(py::module_& m);
// The paper's model against FE, assumption by assumption (validation/crosscheck.hpp).
void bind_crosscheck(py::module_& m);
// The main job (pipeline/report.hpp).
void bind_report(py::module_& m);

}  // namespace skinfem::python
