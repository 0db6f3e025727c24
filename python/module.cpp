// The skinfem Python module (imported as skinfem, python/skinfem/__init__.py): scenes and the pipeline's
// stages with typed results; numbers in the units their names give. Errors keep the command's one-line
// messages: SceneError and MeshError (ValueErrors) for bad input, SolverError (a RuntimeError) when a solve
// fails.
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

#include "contact/layer_hertz.hpp"
#include "fem/mixed_solver.hpp"
#include "green/kernel_grid.hpp"
#include "mesh/sizing.hpp"
#include "mesh/surface.hpp"
#include "pipeline/adjoint_setup.hpp"
#include "pipeline/contact.hpp"
#include "pipeline/crosscheck.hpp"
#include "pipeline/defect.hpp"
#include "pipeline/green.hpp"
#include "pipeline/kfit.hpp"
#include "pipeline/meridian_contact.hpp"
#include "pipeline/progress.hpp"
#include "pipeline/sensor_greens.hpp"
#include "pipeline/symmetry.hpp"
#include "scene/load.hpp"
#include "validation/k_sweep.hpp"
#include "validation/paper_model.hpp"

namespace py = pybind11;
using namespace skinfem;

namespace {

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

// The paper model's Green-tensor ingredient (validation/paper_model.hpp), a Python object of its own.
struct PyKernel {
  validation::GreenKernel g;
  std::string what;
  int sensors = -1;  // the sensors it is built for (one per thickness, or the FE maps'); -1: any
};

// A kernel built for some sensors applied to another scene's would read past its tables.
void require_kernel_fits(const PyKernel& g, const Scene& scene) {
  const int n = static_cast<int>(reading_sites(scene.sensors).size());
  if (g.sensors >= 0 && g.sensors != n)
    throw SceneError("kernel: built for " + std::to_string(g.sensors) + " sensor(s) (" + g.what +
                     "), the scene '" + scene.name + "' has " + std::to_string(n));
}

// Its traction ingredient.
struct PyTractions {
  validation::Tractions t;
  std::string what;
};

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
  // The sink holds a Python callable: release it while the interpreter lives (atexit runs before
  // finalization), not in a static destructor after it, which would wait for the GIL forever.
  py::module_::import("atexit").attr("register")(
      py::cpp_function([]() { pipeline::set_progress_sink(nullptr); }));

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
      .def_property_readonly(
          "friction", [](const pipeline::MeridianContactRun& r) { return contact::to_string(r.chosen); })
      .def_property_readonly("left_out",
                             [](const pipeline::MeridianContactRun& r) {
                               std::vector<std::string> v;
                               for (FrictionMode m : r.left_out) v.push_back(contact::to_string(m));
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
        if (pipeline::contact_on_meridian(scene, chosen, green_path_named(path), &why)) {
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
        const pipeline::GreenPath p = green_path_named(path);
        py::gil_scoped_release free;
        return pipeline::green_path(scene, p);
      },
      py::arg("scene"), py::arg("path") = "auto",
      "Every sensor's Green maps (what `skinfem green` computes): path 'auto' (the meridian where the skin "
      "allows), '3d' or 'meridian'.");

  // The paper's model, ingredient by ingredient (validation/paper_model.hpp).
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
