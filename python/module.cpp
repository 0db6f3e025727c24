// The skinfem Python module (imported as skinfem, python/skinfem/__init__.py): scenes and the pipeline's
// stages with typed results; numbers in the units their names give. Errors keep the command's one-line
// messages: SceneError and MeshError (ValueErrors) for bad input, SolverError (a RuntimeError) when a solve
// fails.
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <array>
#include <string>
#include <vector>

#include "fem/mixed_solver.hpp"
#include "mesh/sizing.hpp"
#include "mesh/surface.hpp"
#include "pipeline/contact.hpp"
#include "pipeline/defect.hpp"
#include "pipeline/kfit.hpp"
#include "pipeline/progress.hpp"
#include "pipeline/sensor_greens.hpp"
#include "scene/load.hpp"

namespace py = pybind11;
using namespace skinfem;

namespace {

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

py::object json_object(const nlohmann::json& j) {
  return py::module_::import("json").attr("loads")(j.dump());
}

pipeline::GreenPath green_path_named(const std::string& path) {
  if (path == "auto") return pipeline::GreenPath::automatic;
  if (path == "3d") return pipeline::GreenPath::full3d;
  if (path == "meridian") return pipeline::GreenPath::meridian;
  throw SceneError("path: '" + path + "' is not one of auto, 3d, meridian");
}

green::LayerLoad calibration_load_named(const std::string& load) {
  if (load == "punch") return green::LayerLoad::punch;
  if (load == "point") return green::LayerLoad::point;
  throw SceneError("load: '" + load + "' is not one of punch, point");
}

}  // namespace

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
      .def("scaled", &scaled_scene, py::arg("s"), py::arg("cap_holes") = false,
           "The scene with every mesh size scaled by s (the family every study's levels come from).")
      .def("__repr__",
           [](const Scene& s) { return "<skinfem.Scene '" + s.name + "' from " + s.source_path + ">"; });
  m.def("load_scene", &load_scene, py::arg("path"), "Reads and validates a scene file.");
  m.def("parse_scene", &parse_scene, py::arg("json_text"), py::arg("source_path"),
        "Validates a scene given as JSON text; source_path names it in messages and anchors relative paths.");

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
        const pipeline::GreenPath p = green_path_named(path);
        py::gil_scoped_release free;
        return pipeline::kfit(scene, pipeline::green_path(scene, p), l);
      },
      py::arg("scene"), py::arg("load") = "punch", py::arg("path") = "auto",
      "The k correction of every sensor (what `skinfem kfit` computes): load 'punch' (the scene's "
      "calibration "
      "punch) or 'point'; path 'auto' (the meridian where the skin allows), '3d' or 'meridian'.");
  py::class_<pipeline::ContactRun>(
      m, "ContactRun", py::dynamic_attr(),
      "The indenter on the skin in every friction mode; attributes are the chosen "
      "mode's (pipeline/contact.hpp).")
      .def_property_readonly("friction",
                             [](const pipeline::ContactRun& r) { return contact::to_string(r.chosen); })
      .def_property_readonly("force_N", [](const pipeline::ContactRun& r) { return r.result().force_N; })
      .def_property_readonly("tangential_force_N",
                             [](const pipeline::ContactRun& r) { return r.result().tangential_force_N; })
      .def_property_readonly("indentation_um",
                             [](const pipeline::ContactRun& r) { return 1e3 * r.result().depth_mm; })
      .def_property_readonly("contact_radius_mm",
                             [](const pipeline::ContactRun& r) { return r.metric().contact_radius_mm; })
      .def_property_readonly("p0_kPa", [](const pipeline::ContactRun& r) { return 1e3 * r.metric().p0_MPa; })
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
  m.def(
      "_contact",
      [](const Scene& scene, const std::string& friction) {
        const FrictionMode chosen = pipeline::friction_mode_named(scene, friction);
        py::gil_scoped_release free;
        return pipeline::contact_run(scene, pipeline::contact_setup(scene, nullptr, false), chosen);
      },
      py::arg("scene"), py::arg("friction") = "");
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
              if (r.cases[ci] == name) {
                const Eigen::MatrixXd& v = r.sweeps[ci].varsigma;
                const py::ssize_t n = v.rows(), ns = v.cols() / 2;
                py::array_t<double> a({n, ns, py::ssize_t{2}});
                auto w = a.mutable_unchecked<3>();
                for (py::ssize_t i = 0; i < n; ++i)
                  for (py::ssize_t k = 0; k < ns; ++k)
                    for (int c = 0; c < 2; ++c) w(i, k, c) = 1e3 * v(i, 2 * k + c);
                return a;
              }
            throw SceneError("case: '" + name + "' is not one of static, sliding");
          },
          py::arg("case"), "ς of case 'static' or 'sliding': positions × sensors × (z, x), kPa")
      .def_property_readonly("wall_s", [](const pipeline::DefectRun& r) { return json_object(r.wall); });
  m.def("_defect_json", [](const pipeline::DefectRun& r, const Scene& scene) {
    return pipeline::defect_json(scene, r).dump();
  });
  m.def(
      "_defect",
      [](const Scene& scene) {
        pipeline::require_sweep(scene);  // before the set-up
        py::gil_scoped_release free;
        return pipeline::defect_run(scene, pipeline::contact_setup(scene));
      },
      py::arg("scene"));
}
