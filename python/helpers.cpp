#include <cstdio>

#include "python/bindings.hpp"
#include "skinfem/fem/sensor_reading.hpp"
#include "skinfem/scene/load.hpp"

namespace skinfem::python {

// An argument outside its range: one line naming it, its value and what is allowed, raised as
// skinfem.SceneError (a ValueError), as the scene reader does for a file.
void require(bool ok, const char* name, double value, const std::string& allowed) {
  if (ok) return;
  char v[32];
  std::snprintf(v, sizeof v, "%g", value);
  throw SceneError(std::string(name) + " = " + v + ": " + allowed);
}

py::array_t<double> per_component(const std::array<double, 4>& v) {
  py::array_t<double> a(4);
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

// MPa values (a contiguous vector) as a kPa array of `shape`, row-major.
py::array_t<double> kpa(const Eigen::VectorXd& v, std::vector<py::ssize_t> shape) {
  py::array_t<double> a(std::move(shape));
  for (Eigen::Index i = 0; i < v.size(); ++i) a.mutable_data()[i] = 1e3 * v[i];
  return a;
}

py::array_t<double> array_of(const std::vector<double>& v) {
  py::array_t<double> a(static_cast<py::ssize_t>(v.size()));
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

py::object json_object(const nlohmann::json& j) {
  return py::module_::import("json").attr("loads")(j.dump());
}

green::LayerLoad calibration_load_named(const std::string& load) {
  if (load == "punch") return green::LayerLoad::punch;
  if (load == "point") return green::LayerLoad::point;
  throw SceneError("load: '" + load + "' is not one of punch, point");
}

// A positions × 2·sensors MPa matrix (σ_z of sensor k at column 2k) as positions × sensors × (z, x) kPa.
py::array_t<double> kpa_by_sensor(const Eigen::MatrixXd& v) {
  const py::ssize_t n = v.rows(), ns = v.cols() / 2;
  py::array_t<double> a({n, ns, py::ssize_t{2}});
  auto w = a.mutable_unchecked<3>();
  for (py::ssize_t i = 0; i < n; ++i)
    for (py::ssize_t k = 0; k < ns; ++k)
      for (int c = 0; c < 2; ++c) w(i, k, c) = 1e3 * v(i, 2 * k + c);
  return a;
}

int case_index(const std::string& name) {
  if (name == "static") return 0;
  if (name == "sliding") return 1;
  throw SceneError("case: '" + name + "' is not one of static, sliding");
}

// A crosscheck variant by name; `kind` says which list ("reading" or "signal") for the error.
size_t variant_named(const std::vector<validation::Variant>& variants, const std::string& name,
                     const char* kind) {
  for (size_t v = 0; v < variants.size(); ++v)
    if (variants[v].name == name) return v;
  throw SceneError("variant: '" + name + "' is not one of this crosscheck's " + kind + " variants");
}

std::vector<std::string> variant_names(const std::vector<validation::Variant>& variants) {
  std::vector<std::string> names;
  for (const auto& v : variants) names.push_back(v.name);
  return names;
}

// A kernel built for some sensors applied to another scene's would read past its tables.
void require_kernel_fits(const PyKernel& g, const Scene& scene) {
  const int n = static_cast<int>(reading_sites(scene.sensors).size());
  if (g.sensors >= 0 && g.sensors != n)
    throw SceneError("kernel: built for " + std::to_string(g.sensors) + " sensor(s) (" + g.what +
                     "), the scene '" + scene.name + "' has " + std::to_string(n));
}

}  // namespace skinfem::python
