// skinfem green — FE Green tensors of the scene's skin for every sensor, by reciprocity.
//
//   $ skinfem green scenes/candelier2011.json --out out/green
//   green candelier2011: 10 sensors × 4 components, 40 adjoint solves on 101342 DOFs (the half y >= 0:
//   mirror symmetry); 10.3 s (factor 5.8 s), peak 1113 MB
//
// A scene symmetric about y = 0 is solved on its half (app/symmetry.hpp); the maps are written on the whole
// top. The scene's calibration load (a disc of calibration.punch_diameter with the rigid-punch profile,
// pressed normally or sheared along +x) is scanned along x through each sensor (y offset 0) at
// calibration.spacing over |offset| ≤ calibration.scan_half_width (default 4h), kept on the skin's footprint.
// Writes DIR/green.csv (sensor,component,offset_x_mm,offset_y_mm,g_point_per_mm2,g_disc_per_mm2, and
// g_exact_point_per_mm2, g_exact_disc_per_mm2 for flat layers: the exact layer values), DIR/green_maps.vtp
// (top surface; point data g_<ab>_sensorNN_per_mm2: the sensor-disc reading for a unit point force at that
// surface point) and DIR/summary.json (DOFs, adjoint solves, reciprocity check, timings, memory).
// With --grid DX: DIR/kernel.h5 and DIR/kernel.vti, every sensor's four disc-reading components on a regular
// grid of spacing DX over the top's bounding box (green/kernel_grid.hpp; the README loads it with h5py).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "app/adjoint_setup.hpp"
#include "app/commands.hpp"
#include "app/common.hpp"
#include "app/stages.hpp"
#include "green/calibration.hpp"
#include "green/kernel_grid.hpp"
#include "mesh/mirror.hpp"
#include "mesh/surface.hpp"
#include "mesh/vtu.hpp"

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

}  // namespace

nlohmann::json green_stage(const Scene& scene, const AdjointSetup& setup, const std::string& out_dir,
                           double grid_dx) {
  using green::GreenSample;
  using green::LayerLoad;
  const double radius = 0.5 * scene.calibration.punch_diameter;
  Stopwatch clock;
  const TetMesh& mesh = setup.mesh;
  const ElasticModel& model = *setup.model;
  const green::FeGreen& fe = *setup.fe;
  nlohmann::json wall = setup.wall;

  // Reciprocity check: a direct solve with a point force at 1 mm from sensor 1 against the adjoint value. On
  // a half mesh the force lies on the cut, where the half carries half of it.
  clock = Stopwatch();
  const auto& s0 = scene.sensors.positions[0];
  const bool half = is_half_y(mesh);
  const LoadCaseResult direct =
      model.solve(model.point_load(s0[0] + 1.0, s0[1], {0, 0, half ? -0.5 : -1.0}), {});
  const SensorReading direct_reading =
      BaseTraction(mesh, direct.reactions).disc_mean(s0[0], s0[1], scene.sensors.disc_diameter);
  const GreenSample adjoint_value = fe.at(0, true, 1.0, 0.0, LayerLoad::point, 0);
  const double reciprocity_rel =
      std::abs(direct_reading.sigma_z - adjoint_value.zz) / std::abs(direct_reading.sigma_z);
  wall["reciprocity_check"] = clock.seconds();

  clock = Stopwatch();

  const bool flat = scene.geometry.kind == GeometryKind::flat;
  std::ostringstream csv;
  csv.precision(10);
  csv << "sensor,component,offset_x_mm,offset_y_mm,g_point_per_mm2,g_disc_per_mm2"
      << (flat ? ",g_exact_point_per_mm2,g_exact_disc_per_mm2" : "") << "\n";  // ridged: the smooth layer's
  nlohmann::json per_sensor = nlohmann::json::array();
  const int ns = static_cast<int>(scene.sensors.positions.size());
  for (int s = 0; s < ns; ++s) {
    progress_step("green: calibration scans", s, ns, clock.seconds());
    const auto& pos = scene.sensors.positions[s];
    const double h = thickness_at(scene, mesh, pos);
    const auto prof = green::scan_profile(fe, s, LayerLoad::punch, radius,
                                          scan_half_width(scene, &mesh, h, pos), scene.calibration.spacing);
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
    per_sensor.push_back(js);
  }
  wall["profiles"] = clock.seconds();

  // Maps: the disc reading of each sensor for a unit point force at every top-surface node; a half mesh's
  // maps are written on the whole top, each node's value that of the node it mirrors (g is even in y).
  std::vector<int> source;
  const TetMesh whole = half ? mirror_half(mesh, &source) : TetMesh{};
  const TetMesh& shown = half ? whole : mesh;
  std::vector<DataArray> maps;
  for (size_t s = 0; s < scene.sensors.positions.size(); ++s)
    for (auto c : green::kComponents) {
      const char force = green::component_name(c)[0], reading = green::component_name(c)[1];
      const Eigen::VectorXd& y = fe.adjoint(s, reading, true);
      char name[64];
      std::snprintf(name, sizeof name, "g_%s_sensor%02zu_per_mm2", green::component_name(c), s + 1);
      DataArray a{name, 1, std::vector<double>(shown.num_nodes(), 0.0)};
      for (int j = 0; j < shown.num_nodes(); ++j) {
        const int i = half ? source[j] : j;
        a.values[j] = force == 'z' ? -y[3 * i + 2] : y[3 * i];
      }
      maps.push_back(std::move(a));
    }
  green::KernelGrid grid;
  if (grid_dx > 0) {
    clock = Stopwatch();
    const auto box = footprint_box(scene);
    grid = green::kernel_grid(fe, scene.sensors, box[0], box[1], box[2], box[3], grid_dx);
    wall["kernel_grid"] = clock.seconds();
  }
  prepare_output_dir(out_dir);
  write_text_atomic(out_dir + "/green.csv", csv.str());
  write_surface_vtp(out_dir + "/green_maps.vtp", shown, kTop, maps);
  if (grid_dx > 0) {
    green::write_kernel_h5(out_dir + "/kernel.h5", grid, scene.name);
    green::write_kernel_vti(out_dir + "/kernel.vti", grid);
  }
  nlohmann::json summary = {
      {"scene", scene_json(scene)},
      {"dofs", model.solver().free_dofs()},
      {"mesh_part", half ? "half y >= 0 (mirror symmetry about y = 0)" : "whole"},
      {"sensors", per_sensor},
      {"adjoint_solves", fe.adjoint_solves()},
      {"max_adjoint_residual", fe.max_adjoint_residual()},
      {"reciprocity_check_rel", reciprocity_rel},
      {"load_model", "rigid-punch half-space profile F/(2πa√(a²−r²)), normal and tangential"},
      {"punch_diameter_mm", scene.calibration.punch_diameter},
      {"wall_s", wall},
      {"wall_total_s", total_seconds(wall)},
      {"peak_rss_mb", peak_rss_mb()}};
  if (grid_dx > 0)
    summary["kernel_grid"] = {{"spacing_mm", grid_dx},
                              {"nx", grid.x.size()},
                              {"ny", grid.y.size()},
                              {"x_range_mm", {grid.x.front(), grid.x.back()}},
                              {"y_range_mm", {grid.y.front(), grid.y.back()}},
                              {"points_on_skin", std::count(grid.on_skin.begin(), grid.on_skin.end(), 1)}};
  write_json(out_dir + "/summary.json", summary);
  std::printf(
      "green %s: %zu sensors × 4 components, %d adjoint solves on %d DOFs%s; %.1f s (factor %.1f s), peak "
      "%.0f "
      "MB\n",
      scene.name.c_str(), scene.sensors.positions.size(), fe.adjoint_solves(), model.solver().free_dofs(),
      half ? " (the half y >= 0: mirror symmetry)" : "", total_seconds(wall), wall["factor"].get<double>(),
      peak_rss_mb());
  std::printf("  reciprocity check (direct solve vs adjoint, sensor 1, offset 1 mm): %.1e relative\n",
              reciprocity_rel);
  if (grid_dx > 0)
    std::printf("  kernel grid: %zu × %zu points at %g mm over x [%g, %g], y [%g, %g] mm (%ld on the skin)\n",
                grid.x.size(), grid.y.size(), grid_dx, grid.x.front(), grid.x.back(), grid.y.front(),
                grid.y.back(), static_cast<long>(std::count(grid.on_skin.begin(), grid.on_skin.end(), 1)));
  std::printf("  wrote %s/green.csv, green_maps.vtp, %ssummary.json\n", out_dir.c_str(),
              grid_dx > 0 ? "kernel.h5, kernel.vti, " : "");
  return summary;
}

int run_green(const Scene& scene, const std::string& out_dir, double grid_dx) {
  check_output_dir(out_dir);
  if (grid_dx > 0) check_kernel_grid(scene, grid_dx);
  green_stage(scene, *adjoint_setup(scene), out_dir, grid_dx);
  return 0;
}

}  // namespace skinfem::app
