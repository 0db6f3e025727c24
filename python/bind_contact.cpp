// Contact: the 3D and meridian paths (pipeline/contact.hpp, pipeline/meridian_contact.hpp).
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
#include "skinfem/contact/contact_solver.hpp"
#include "skinfem/pipeline/contact.hpp"
#include "skinfem/pipeline/contact_setup.hpp"
#include "skinfem/pipeline/meridian_contact.hpp"

namespace skinfem::python {

void bind_contact(py::module_& m) {
  py::class_<pipeline::ContactRun>(
      m, "ContactRun", py::dynamic_attr(),
      "The indenter on the skin in every friction mode; attributes are the chosen "
      "mode's (pipeline/contact.hpp).")
      .def_property_readonly("friction", [](const pipeline::ContactRun& r) { return to_string(r.chosen); })
      .def_property_readonly("force_N", [](const pipeline::ContactRun& r) { return r.result().force_N; })
      .def_property_readonly("tangential_force_N",
                             [](const pipeline::ContactRun& r) { return r.result().tangential_force_N; })
      .def_property_readonly("indentation_um",
                             [](const pipeline::ContactRun& r) { return 1e3 * r.result().depth_mm; })
      .def_property_readonly("contact_radius_mm",
                             [](const pipeline::ContactRun& r) { return r.metric().contact_radius_mm; })
      .def_property_readonly("p0_kPa",
                             [](const pipeline::ContactRun& r) -> std::optional<double> {
                               if (r.metric().p0_in_hole) return std::nullopt;  // no indenter there
                               return 1e3 * r.metric().p0_MPa;
                             })
      .def_property_readonly("max_penetration_um",
                             [](const pipeline::ContactRun& r) { return 1e3 * r.max_penetration_mm; })
      .def_property_readonly(
          "readings_kPa",
          [](const pipeline::ContactRun& r) {
            const Eigen::VectorXd& v = r.result().readings;  // σ_z of sensor k at 2k, σ_x at 2k + 1
            return kpa(v, {v.size() / 2, 2});
          },
          "sensors × (sigma_z, sigma_x), kPa")
      .def_property_readonly(
          "pressure_kPa",
          [](const pipeline::ContactRun& r) { return kpa(r.result().lambda, {r.result().lambda.size()}); },
          "nodal pressure of each contact multiplier, kPa")
      .def_property_readonly(
          "multiplier_xy_mm",
          [](const pipeline::ContactRun& r) {
            const auto& zone = r.setup->solver->zone();
            const TetMesh& mesh = r.setup->mesh();
            py::array_t<double> a({static_cast<py::ssize_t>(zone.size()), py::ssize_t{2}});
            auto v = a.mutable_unchecked<2>();
            for (int i = 0; i < zone.size(); ++i)
              for (int k = 0; k < 2; ++k) v(i, k) = mesh.nodes(zone.vertices[i], k);
            return a;
          },
          "(x, y) of each multiplier's vertex, mm")
      .def_property_readonly(
          "dofs", [](const pipeline::ContactRun& r) { return r.setup->model->solver().free_dofs(); })
      .def_property_readonly("wall_s", [](const pipeline::ContactRun& r) { return json_object(r.wall); });
  m.def("_contact_json", [](const pipeline::ContactRun& r, const Scene& scene) {
    return pipeline::contact_json(scene, r).dump();
  });
  py::class_<pipeline::MeridianContactRun>(
      m, "MeridianContactRun", py::dynamic_attr(),
      "The indenter on the axis of a body of revolution, on its meridian, in the modes exact there; "
      "attributes are the chosen mode's (pipeline/meridian_contact.hpp).")
      .def_property_readonly("friction",
                             [](const pipeline::MeridianContactRun& r) { return to_string(r.chosen); })
      .def_property_readonly("left_out",
                             [](const pipeline::MeridianContactRun& r) {
                               std::vector<std::string> v;
                               for (FrictionMode m : r.left_out) v.push_back(to_string(m));
                               return v;
                             })
      .def_property_readonly("force_N",
                             [](const pipeline::MeridianContactRun& r) { return r.solved.force_N; })
      .def_property_readonly(
          "tangential_force_N",
          [](const pipeline::MeridianContactRun& r) { return r.modes.at(r.chosen).ratio * r.solved.force_N; })
      .def_property_readonly("indentation_um",
                             [](const pipeline::MeridianContactRun& r) { return 1e3 * r.solved.depth_mm; })
      .def_property_readonly("contact_radius_mm",
                             [](const pipeline::MeridianContactRun& r) { return r.solved.contact_radius_mm; })
      .def_property_readonly("p0_kPa",
                             [](const pipeline::MeridianContactRun& r) { return 1e3 * r.solved.p0_MPa; })
      .def_property_readonly(
          "readings_kPa",
          [](const pipeline::MeridianContactRun& r) {
            const Eigen::VectorXd& v = r.modes.at(r.chosen).readings;
            return kpa(v, {v.size() / 2, 2});
          },
          "sensors × (sigma_z, sigma_x), kPa")
      .def_property_readonly(
          "pressure_kPa",
          [](const pipeline::MeridianContactRun& r) {
            return kpa(r.solved.lambda, {r.solved.lambda.size()});
          },
          "nodal pressure of each contact multiplier, kPa")
      .def_property_readonly(
          "multiplier_r_mm",
          [](const pipeline::MeridianContactRun& r) {
            return py::array_t<double>(static_cast<py::ssize_t>(r.solved.r.size()), r.solved.r.data());
          },
          "each multiplier's distance from the axis, mm")
      .def_property_readonly("dofs", [](const pipeline::MeridianContactRun& r) { return r.solved.dofs; })
      .def_property_readonly("wall_s",
                             [](const pipeline::MeridianContactRun& r) { return json_object(r.wall); });
  m.def("_meridian_contact_json", [](const pipeline::MeridianContactRun& r, const Scene& scene) {
    return pipeline::meridian_contact_json(scene, r).dump();
  });
  m.def(
      "_contact",
      [](const Scene& scene, const std::string& friction, const std::string& path) -> py::object {
        const FrictionMode chosen = pipeline::friction_mode_named(scene, friction);
        std::string why;
        if (pipeline::contact_on_meridian(scene, chosen, pipeline::green_path_named(path), &why)) {
          py::gil_scoped_release free;
          auto run = pipeline::meridian_contact_run(scene, chosen);
          py::gil_scoped_acquire held;
          return py::cast(std::move(run));
        }
        py::gil_scoped_release free;
        auto run = pipeline::contact_run(
            scene, pipeline::contact_setup(scene, nullptr, pipeline::HolePath::none), chosen);
        run.not_meridian = why;
        py::gil_scoped_acquire held;
        return py::cast(std::move(run));
      },
      py::arg("scene"), py::arg("friction") = "", py::arg("path") = "auto");
}

}  // namespace skinfem::python
