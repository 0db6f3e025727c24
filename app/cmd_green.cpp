// skinfem green — FE Green tensors of the scene's skin for every sensor, by reciprocity.
//
//   $ skinfem green scenes/candelier2011.json --out out/green
//   green candelier2011: 10 sensors × 4 components, 40 adjoint solves on 101342 DOFs (the half y >= 0:
//   mirror symmetry); 10.3 s (factor 5.8 s), peak 1113 MB
//
// A scene symmetric about y = 0 is solved on its half (pipeline/symmetry.hpp); the maps are written on the
// whole top. The scene's calibration load (a disc of calibration.punch_diameter with the rigid-punch profile,
// pressed normally or sheared along +x) is scanned along x through each sensor (y offset 0) at
// calibration.spacing over |offset| ≤ calibration.scan_half_width (default 4h), kept on the skin's footprint.
// Writes DIR/green.csv (sensor,component,offset_x_mm,offset_y_mm,g_point_per_mm2,g_disc_per_mm2, and
// g_exact_point_per_mm2, g_exact_disc_per_mm2 for flat layers: the exact layer values), DIR/green_maps.vtp
// (top surface; point data g_<ab>_sensorNN_per_mm2: the sensor-disc reading for a unit point force at that
// surface point) and DIR/summary.json (DOFs, adjoint solves, reciprocity check, timings, memory; on a cap
// solved in 3D, meridian_check: its sensor on the cap's axis against the meridian path,
// pipeline/sensor_greens.hpp). With --grid DX: DIR/kernel.h5 and DIR/kernel.vti, every sensor's four
// disc-reading components on a regular grid of spacing DX over the top's bounding box (green/kernel_grid.hpp;
// the README loads it with h5py).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "app/commands.hpp"
#include "app/common.hpp"
#include "app/stages.hpp"
#include "green/calibration.hpp"
#include "green/kernel_grid.hpp"
#include "mesh/mirror.hpp"
#include "mesh/shape.hpp"
#include "mesh/surface.hpp"
#include "mesh/vtu.hpp"
#include "pipeline/adjoint_setup.hpp"

namespace skinfem::app {

namespace {

// Bounding box (x_lo, x_hi, y_lo, y_hi; mm) of the skin's footprint, from the scene alone (no meshing).
std::array<double, 4> footprint_box(const Scene& scene) {
  const Geometry& g = scene.geometry;
  if (g.kind == GeometryKind::flat)
    return {-g.flat.half_width, g.flat.half_width, -g.flat.half_width, g.flat.half_width};
  if (g.kind == GeometryKind::cap)
    return {g.cap.apex_x - g.cap.truncation_radius, g.cap.apex_x + g.cap.truncation_radius,
            g.cap.apex_y - g.cap.truncation_radius, g.cap.apex_y + g.cap.truncation_radius};
  const SurfaceMesh surface = import_surface(g.surface.path);
  const Eigen::RowVector3d lo = surface.vertices.colwise().minCoeff(),
                           hi = surface.vertices.colwise().maxCoeff();
  return {lo(0), hi(0), lo(1), hi(1)};
}

// The kernel grid is held in memory (4 components per sensor) and written twice: bounded at 1e6 points and
// 2.5e7 values (200 MB).
void check_kernel_grid(const Scene& scene, double dx) {
  const auto box = footprint_box(scene);
  const double points = (std::floor((box[1] - box[0]) / dx) + 1) * (std::floor((box[3] - box[2]) / dx) + 1);
  const double values = 4.0 * points * static_cast<double>(scene.sensors.positions.size());
  if (points > 1e6 || values > 2.5e7) {
    char line[256];
    std::snprintf(
        line, sizeof line,
        "--grid = %g: the kernel grid over the %.4g × %.4g mm footprint would have %.3g points (%.3g "
        "values for %zu sensors); allowed at most 1e6 points and 2.5e7 values: use a larger --grid",
        dx, box[1] - box[0], box[3] - box[2], points, values, scene.sensors.positions.size());
    throw SceneError(line);
  }
}

// The top of an axisymmetric skin as a polar P2 surface about (cx, cy) out to `radius`, for the meridian
// path's maps: rings growing geometrically from the centre, 72 angles.
TetMesh polar_top(const Scene& scene, double cx, double cy, double radius) {
  const SkinShape shape(scene.geometry);
  constexpr int n = 60, m = 72;   // rings, angles
  const auto ring = [&](int i) {  // i in 0 … 2n: vertex rings at even i, mid-edge rings at odd i
    const auto r = [&](int k) { return radius * std::expm1(3.0 * k / n) / std::expm1(3.0); };
    return i % 2 == 0 ? r(i / 2) : 0.5 * (r(i / 2) + r(i / 2 + 1));
  };
  TetMesh t;
  const auto id = [&](int i, int j) { return i == 0 ? 0 : 1 + (i - 1) * 2 * m + (j % (2 * m)); };
  t.nodes.resize(1 + 2 * n * 2 * m, 3);
  for (int i = 0; i <= 2 * n; ++i)
    for (int j = 0; j < (i == 0 ? 1 : 2 * m); ++j) {
      const double r = ring(i), th = M_PI * j / m, x = cx + r * std::cos(th), y = cy + r * std::sin(th);
      t.nodes.row(id(i, j)) << x, y, shape.top_z(x, y);
    }
  std::vector<std::array<int, 6>> faces;
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < m; ++b) {
      const int i = 2 * a, j = 2 * b;
      if (a == 0) {
        faces.push_back({id(0, 0), id(2, j), id(2, j + 2), id(1, j), id(2, j + 1), id(1, j + 2)});
        continue;
      }
      faces.push_back(
          {id(i, j), id(i + 2, j), id(i + 2, j + 2), id(i + 1, j), id(i + 2, j + 1), id(i + 1, j + 1)});
      faces.push_back(
          {id(i, j), id(i + 2, j + 2), id(i, j + 2), id(i + 1, j + 1), id(i + 1, j + 2), id(i, j + 1)});
    }
  t.faces.resize(faces.size(), 6);
  for (size_t f = 0; f < faces.size(); ++f)
    for (int k = 0; k < 6; ++k) t.faces(f, k) = faces[f][k];
  t.face_marker = Eigen::VectorXi::Constant(faces.size(), kTop);
  t.node_marker = Eigen::VectorXi::Constant(t.nodes.rows(), kTop);
  return t;
}

}  // namespace

nlohmann::json green_stage(const Scene& scene, const SensorGreens& greens, const AdjointSetup* setup,
                           const std::string& out_dir, double grid_dx) {
  using green::GreenSample;
  using green::LayerLoad;
  const double radius = 0.5 * scene.calibration.punch_diameter;
  Stopwatch clock;
  nlohmann::json wall = greens.wall;

  // The 3D path's reciprocity check: a direct solve with a point force at 1 mm from sensor 1 against the
  // adjoint value. On a half mesh the force lies on the cut, where the half carries half of it.
  double reciprocity_rel = 0;
  const bool half = setup && is_half_y(setup->mesh);
  if (setup) {
    clock = Stopwatch();
    const auto& s0 = scene.sensors.positions[0];
    const ElasticModel& model = *setup->model;
    const LoadCaseResult direct =
        model.solve(model.point_load(s0[0] + 1.0, s0[1], {0, 0, half ? -0.5 : -1.0}), {});
    const SensorReading direct_reading =
        BaseTraction(setup->mesh, direct.reactions).disc_mean(s0[0], s0[1], scene.sensors.disc_diameter);
    const GreenSample adjoint_value = greens.at(0, true, 1.0, 0.0, LayerLoad::point, 0);
    reciprocity_rel = std::abs(direct_reading.sigma_z - adjoint_value.zz) / std::abs(direct_reading.sigma_z);
    wall["reciprocity_check"] = clock.seconds();
  }

  clock = Stopwatch();
  const bool flat = scene.geometry.kind == GeometryKind::flat;
  std::ostringstream csv;
  csv.precision(10);
  csv << "sensor,component,offset_x_mm,offset_y_mm,g_point_per_mm2,g_disc_per_mm2"
      << (flat ? ",g_exact_point_per_mm2,g_exact_disc_per_mm2" : "") << "\n";  // ridged: the smooth layer's
  nlohmann::json per_sensor = nlohmann::json::array();
  const int ns = static_cast<int>(scene.sensors.positions.size());
  const int axis = axis_sensor(scene, greens);
  nlohmann::json check;
  for (int s = 0; s < ns; ++s) {
    progress_step("green: calibration scans", s, ns, clock.seconds());
    const double h = greens.thickness[s];
    const auto prof = green::scan_profile(greens.of(s), LayerLoad::punch, radius, greens.scan_half_width[s],
                                          scene.calibration.spacing);
    std::vector<GreenSample> exact, exact_disc;
    if (flat) {
      const green::LayerGreen layer(h, scene.material.nu, LayerLoad::punch, radius);
      exact = green::exact_profile(layer, prof.offset_x);
      exact_disc = green::exact_profile(layer, prof.offset_x, scene.sensors.disc_diameter);
    }
    for (auto c : green::kComponents)
      for (size_t i = 0; i < prof.offset_x.size(); ++i) {
        csv << s + 1 << "," << green::component_name(c) << "," << prof.offset_x[i] << ",0,"
            << green::component(prof.point[i], c) << "," << green::component(prof.disc[i], c);
        if (flat) csv << "," << green::component(exact[i], c) << "," << green::component(exact_disc[i], c);
        csv << "\n";
      }
    nlohmann::json js = {{"sensor", s + 1}, {"h_mm", h}, {"scan_half_width_mm", prof.offset_x.back()}};
    if (flat) {
      const auto err = green::max_error_over_peak(prof.disc, exact_disc);
      for (size_t c = 0; c < 4; ++c)
        js[scene.geometry.ridges.present()
               ? "disc_vs_smooth_max_diff_over_peak"
               : "fe_vs_exact_max_err_over_peak"][green::component_name(green::kComponents[c])] = err[c];
    }
    if (s == axis) {
      check = meridian_check(scene, s, prof, LayerLoad::punch, radius, h);
      js["meridian_check"] = check;
    }
    per_sensor.push_back(js);
  }
  wall["profiles"] = clock.seconds();

  // Maps: the disc reading of each sensor for a unit point force at every top-surface node. 3D: the mesh's
  // top (a half mesh's written whole, each node's value that of the node it mirrors: g is even in y); the
  // meridian: a polar surface over the footprint.
  std::vector<int> source;
  TetMesh shown;
  if (!setup) {
    const Geometry& g = scene.geometry;
    shown = flat ? polar_top(scene, 0, 0, g.flat.half_width)
                 : polar_top(scene, g.cap.apex_x, g.cap.apex_y, g.cap.truncation_radius);
  } else if (half) {
    shown = mirror_half(setup->mesh, &source);
  }
  const TetMesh& top = setup && !half ? setup->mesh : shown;
  std::vector<DataArray> maps;
  for (size_t s = 0; s < scene.sensors.positions.size(); ++s) {
    std::vector<GreenSample> at_node(top.num_nodes());
    for (int j = 0; j < top.num_nodes(); ++j) {
      if (setup) {  // nodal values of the adjoints, as FeGreen::disc_map_at reads them
        const Eigen::VectorXd &yz = setup->fe->adjoint(s, 'z', true), &yx = setup->fe->adjoint(s, 'x', true);
        const int i = half ? source[j] : j;
        at_node[j] = {-yz[3 * i + 2], -yx[3 * i + 2], yz[3 * i], yx[3 * i]};
      } else {
        greens.disc_map(static_cast<int>(s), top.nodes(j, 0), top.nodes(j, 1), at_node[j]);
      }
    }
    for (auto c : green::kComponents) {
      char name[64];
      std::snprintf(name, sizeof name, "g_%s_sensor%02zu_per_mm2", green::component_name(c), s + 1);
      DataArray a{name, 1, std::vector<double>(top.num_nodes(), 0.0)};
      for (int j = 0; j < top.num_nodes(); ++j) a.values[j] = green::component(at_node[j], c);
      maps.push_back(std::move(a));
    }
  }
  green::KernelGrid grid;
  if (grid_dx > 0) {
    clock = Stopwatch();
    const auto box = footprint_box(scene);
    grid = green::kernel_grid(greens.disc_map, scene.sensors, box[0], box[1], box[2], box[3], grid_dx);
    wall["kernel_grid"] = clock.seconds();
  }
  prepare_output_dir(out_dir);
  write_text_atomic(out_dir + "/green.csv", csv.str());
  write_surface_vtp(out_dir + "/green_maps.vtp", top, kTop, maps);
  if (grid_dx > 0) {
    green::write_kernel_h5(out_dir + "/kernel.h5", grid, scene.name);
    green::write_kernel_vti(out_dir + "/kernel.vti", grid);
  }
  nlohmann::json summary = {
      {"scene", scene_json(scene)},
      {"path", greens.path},
      {"path_model", greens.model},
      {"dofs", greens.dofs},
      {"sensors", per_sensor},
      {"adjoint_solves", greens.adjoint_solves},
      {"load_model", "rigid-punch half-space profile F/(2πa√(a²−r²)), normal and tangential"},
      {"punch_diameter_mm", scene.calibration.punch_diameter},
      {"wall_s", wall},
      {"wall_total_s", total_seconds(wall)},
      {"peak_rss_mb", peak_rss_mb()}};
  if (setup) {
    summary["mesh_part"] = half ? "half y >= 0 (mirror symmetry about y = 0)" : "whole";
    summary["max_adjoint_residual"] = greens.max_adjoint_residual;
    summary["reciprocity_check_rel"] = reciprocity_rel;
  }
  if (!check.is_null()) summary["meridian_check"] = check;
  if (grid_dx > 0)
    summary["kernel_grid"] = {{"spacing_mm", grid_dx},
                              {"nx", grid.x.size()},
                              {"ny", grid.y.size()},
                              {"x_range_mm", {grid.x.front(), grid.x.back()}},
                              {"y_range_mm", {grid.y.front(), grid.y.back()}},
                              {"points_on_skin", std::count(grid.on_skin.begin(), grid.on_skin.end(), 1)}};
  write_json(out_dir + "/summary.json", summary);
  std::printf(
      "green %s: %zu sensors × 4 components, %s path (%s): %d adjoint solves on %d DOFs; %.1f s (factor "
      "%.1f s), peak %.0f MB\n",
      scene.name.c_str(), scene.sensors.positions.size(), greens.path.c_str(), greens.model.c_str(),
      greens.adjoint_solves, greens.dofs, total_seconds(wall), wall["factor"].get<double>(), peak_rss_mb());
  if (setup)
    std::printf("  reciprocity check (direct solve vs adjoint, sensor 1, offset 1 mm): %.1e relative\n",
                reciprocity_rel);
  if (!check.is_null()) std::printf("  %s\n", meridian_check_line(check).c_str());
  if (flat && !scene.geometry.ridges.present()) {
    double worst = 0;
    for (const auto& js : per_sensor)
      for (const auto& e : js.at("fe_vs_exact_max_err_over_peak")) worst = std::max(worst, e.get<double>());
    std::printf("  disc readings against the exact layer: max |difference| / peak %.1e\n", worst);
  }
  if (grid_dx > 0)
    std::printf("  kernel grid: %zu × %zu points at %g mm over x [%g, %g], y [%g, %g] mm (%ld on the skin)\n",
                grid.x.size(), grid.y.size(), grid_dx, grid.x.front(), grid.x.back(), grid.y.front(),
                grid.y.back(), static_cast<long>(std::count(grid.on_skin.begin(), grid.on_skin.end(), 1)));
  std::printf("  wrote %s/green.csv, green_maps.vtp, %ssummary.json\n", out_dir.c_str(),
              grid_dx > 0 ? "kernel.h5, kernel.vti, " : "");
  return summary;
}

int run_green(const Scene& scene, const std::string& out_dir, double grid_dx, GreenPath path) {
  check_output_dir(out_dir);
  if (grid_dx > 0) check_kernel_grid(scene, grid_dx);
  const SensorGreens greens = green_path(scene, path);
  green_stage(scene, greens, greens.adjoints.get(), out_dir, grid_dx);
  return 0;
}

}  // namespace skinfem::app
