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
// docs/kernels.md loads it with h5py). The computation and summary.json are pipeline/green.hpp's; this file
// writes and prints them.
#include <algorithm>
#include <cstdio>
#include <sstream>

#include "app/commands.hpp"
#include "app/common.hpp"
#include "app/stages.hpp"
#include "skinfem/mesh/vtu.hpp"
#include "skinfem/pipeline/green.hpp"

namespace skinfem::app {

void write_green(const Scene& scene, const SensorGreens& greens, const GreenRun& run,
                 const nlohmann::json& summary, const std::string& out_dir, std::string* lines) {
  std::ostringstream csv;
  csv.precision(10);
  csv << "sensor,component,offset_x_mm,offset_y_mm,g_point_per_mm2,g_disc_per_mm2"
      << (run.flat ? ",g_exact_point_per_mm2,g_exact_disc_per_mm2" : "")
      << "\n";  // ridged: the smooth layer's
  for (const GreenScan& scan : run.scans)
    for (auto c : green::kComponents)
      for (size_t i = 0; i < scan.profile.offset_x.size(); ++i) {
        csv << scan.sensor << "," << green::component_name(c) << "," << scan.profile.offset_x[i] << ",0,"
            << green::component(scan.profile.point[i], c) << "," << green::component(scan.profile.disc[i], c);
        if (run.flat)
          csv << "," << green::component(scan.exact_point[i], c) << ","
              << green::component(scan.exact_disc[i], c);
        csv << "\n";
      }
  std::vector<DataArray> maps;
  for (size_t s = 0; s < run.maps.size(); ++s)
    for (int c = 0; c < 4; ++c) {
      char name[64];
      std::snprintf(name, sizeof name, "g_%s_sensor%02zu_per_mm2",
                    green::component_name(green::kComponents[c]), s + 1);
      maps.push_back({name, 1, run.maps[s][c]});
    }
  prepare_output_dir(out_dir);
  write_text_atomic(out_dir + "/green.csv", csv.str());
  write_surface_vtp(out_dir + "/green_maps.vtp", *run.top, kTop, maps);
  if (run.grid) {
    green::write_kernel_h5(out_dir + "/kernel.h5", *run.grid, scene.name);
    green::write_kernel_vti(out_dir + "/kernel.vti", *run.grid);
  }
  write_json(out_dir + "/summary.json", summary);
  say(lines,
      "green %s: %zu sensors × 4 components, %s path (%s): %d adjoint solves on %d DOFs; %.1f s (factor "
      "%.1f s), peak %.0f MB\n",
      scene.name.c_str(), scene.sensors.positions.size(), greens.path.c_str(), greens.model.c_str(),
      greens.adjoint_solves, greens.dofs, run.wall.total(), run.wall.at("factor"), peak_rss_mb());
  if (run.reciprocity_rel)
    say(lines, "  reciprocity check (direct solve vs adjoint, sensor 1, offset 1 mm): %.1e relative\n",
        *run.reciprocity_rel);
  if (run.meridian_check) say(lines, "  %s\n", meridian_check_line(*run.meridian_check).c_str());
  if (run.flat && !run.ridged && !run.post) {
    double worst = 0;
    for (const GreenScan& scan : run.scans)
      for (double e : *scan.disc_max_diff_over_peak) worst = std::max(worst, e);
    const bool preloaded = scene.material.model == MaterialModel::neo_hookean && !scene.loads.patches.empty();
    say(lines, "  disc readings against the exact %slayer: max |difference| / peak %.1e\n",
        preloaded ? "(linear, unloaded) " : "", worst);
  }
  if (run.grid) {
    const green::KernelGrid& grid = *run.grid;
    say(lines, "  kernel grid: %zu × %zu points at %g mm over x [%g, %g], y [%g, %g] mm (%ld on the skin)\n",
        grid.x.size(), grid.y.size(), grid.dx, grid.x.front(), grid.x.back(), grid.y.front(), grid.y.back(),
        static_cast<long>(std::count(grid.on_skin.begin(), grid.on_skin.end(), 1)));
  }
  say(lines, "  wrote %s/green.csv, green_maps.vtp, %ssummary.json\n", out_dir.c_str(),
      run.grid ? "kernel.h5, kernel.vti, " : "");
}

int run_green(const Scene& scene, const std::string& out_dir, double grid_dx, GreenPath path) {
  check_output_dir(out_dir);
  if (grid_dx > 0) check_kernel_grid(scene, grid_dx);
  const SensorGreens greens = green_path(scene, path);
  const GreenRun run = green_run(scene, greens, greens.adjoints.get(), grid_dx);
  write_green(scene, greens, run, green_json(scene, greens, run, grid_dx), out_dir);
  return 0;
}

}  // namespace skinfem::app
