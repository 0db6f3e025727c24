// The paper's model against FE, assumption by assumption (validation/crosscheck.hpp).
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
#include "skinfem/pipeline/adjoint_setup.hpp"
#include "skinfem/pipeline/contact.hpp"
#include "skinfem/pipeline/contact_setup.hpp"
#include "skinfem/pipeline/crosscheck.hpp"
#include "skinfem/pipeline/defect.hpp"
#include "skinfem/pipeline/kfit.hpp"
#include "skinfem/pipeline/sensor_greens.hpp"
#include "skinfem/pipeline/skin_setup.hpp"
#include "skinfem/pipeline/symmetry.hpp"

namespace skinfem::python {

void bind_crosscheck(py::module_& m) {
  py::class_<validation::Crosscheck>(
      m, "Crosscheck",
      "The paper's model against FE, one assumption swapped in per variant (validation/crosscheck.hpp).")
      .def_property_readonly(
          "reading_variants",
          [](const validation::Crosscheck& x) { return variant_names(x.reading_variants); })
      .def_property_readonly("signal_variants",
                             [](const validation::Crosscheck& x) { return variant_names(x.signal_variants); })
      .def_property_readonly("u_mm", [](const validation::Crosscheck& x) { return array_of(x.u); })
      .def(
          "readings_kPa",
          [](const validation::Crosscheck& x, const std::string& variant, const std::string& name) {
            const size_t v = variant_named(x.reading_variants, variant, "reading");
            const Eigen::VectorXd& r = x.readings[v][case_index(name)];
            return kpa(r, {r.size() / 2, 2});
          },
          py::arg("variant"), py::arg("case"), "sensors x (sigma_z, sigma_x), kPa")
      .def(
          "varsigma_kPa",
          [](const validation::Crosscheck& x, const std::string& variant, const std::string& name) {
            return kpa_by_sensor(
                x.signals[variant_named(x.signal_variants, variant, "signal")][case_index(name)]);
          },
          py::arg("variant"), py::arg("case"), "positions x sensors x (z, x), kPa")
      .def(
          "amplitude_ratio",
          [](const validation::Crosscheck& x, const std::string& variant, const std::string& name) {
            const auto& ms = x.metrics[variant_named(x.signal_variants, variant, "signal")][case_index(name)];
            py::array_t<double> a({static_cast<py::ssize_t>(ms.size()), py::ssize_t{2}});
            for (size_t k = 0; k < ms.size(); ++k)
              for (int b = 0; b < 2; ++b) a.mutable_at(k, b) = ms[k][b].amplitude_ratio;
            return a;
          },
          py::arg("variant"), py::arg("case"), "max|varsigma| of the variant over FE's, sensors x (z, x)");
  m.def(
      "crosscheck",
      [](const Scene& scene) {
        pipeline::require_sweep(scene);
        py::gil_scoped_release free;
        auto skin = pipeline::skin_setup(scene, pipeline::contact_mesh_part(scene));
        auto adjoints = pipeline::adjoint_setup(scene, skin);
        const pipeline::KfitResult k =
            pipeline::kfit(scene, pipeline::sensor_greens(scene, *adjoints), green::LayerLoad::punch);
        std::shared_ptr<const pipeline::ContactSetup> contact = pipeline::contact_setup(scene, skin);
        const double force = scene.contact->force.value_or(
            pipeline::contact_run(scene, contact, scene.contact->friction).result().force_N);
        const pipeline::DefectRun defect =
            pipeline::defect_run(scene, contact, {}, pipeline::DefectFrames::every);
        return pipeline::crosscheck_run(scene, *adjoints, *contact, defect, force,
                                        k.sensors.at(0).fe.k_lsq_line);
      },
      py::arg("scene"),
      "The paper's model against FE, one assumption at a time, on one skin (the crosscheck of `skinfem "
      "report`).");
}

}  // namespace skinfem::python
