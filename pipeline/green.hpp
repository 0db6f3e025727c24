// `skinfem green` as a stage: every sensor's Green tensor from its Green maps (pipeline/sensor_greens.hpp,
// the 3D or the meridian path) scanned with the scene's calibration load, the maps at every top-surface
// node, and optionally on a regular grid (green/kernel_grid.hpp). Checks: on the 3D path a direct solve
// against the adjoint value (reciprocity); on flat scenes each scan against the exact layer; on a cap
// solved in 3D, its axis sensor against the meridian path. Units: mm, N, MPa; g in 1/mm².
#pragma once

#include <array>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "skinfem/green/calibration.hpp"
#include "skinfem/green/kernel_grid.hpp"
#include "skinfem/pipeline/adjoint_setup.hpp"
#include "skinfem/pipeline/clock.hpp"
#include "skinfem/pipeline/sensor_greens.hpp"

namespace skinfem::pipeline {

struct GreenScan {
  int sensor = 0;  // 1-based
  double h_mm = 0;
  green::ScanProfile profile;  // the calibration punch along x through the sensor: centre value, disc mean
  // Flat scenes: the exact (on a ridged layer, the smooth) layer's values on the same offsets, and the
  // largest difference of the disc readings over the peak per component (zz, zx, xz, xx).
  std::vector<green::GreenSample> exact_point, exact_disc;
  std::optional<std::array<double, 4>> disc_max_diff_over_peak;
};

struct GreenRun {
  std::vector<GreenScan> scans;
  bool flat = false, ridged = false;
  bool post = false;  // post sensors: the exact layer's readings are a disc's, what the post differs from
  std::optional<double> reciprocity_rel;  // the 3D path: |direct − adjoint| / |direct|, sensor 1, 1 mm
  std::string mesh_part;                  // the 3D path: "whole" or the half's description
  std::optional<MeridianCheck> meridian_check;  // the axis sensor of a cap solved in 3D
  // The maps: the disc reading of each sensor for a unit point force at every node of `top` (the 3D mesh's
  // top written whole; on the meridian path a polar surface over the footprint): maps[sensor][component].
  std::shared_ptr<const TetMesh> top;
  std::vector<std::array<std::vector<double>, 4>> maps;
  std::optional<green::KernelGrid> grid;
  Timings wall;  // the Green path's stages, reciprocity_check, profiles, kernel_grid
};

// Bounding box (x_lo, x_hi, y_lo, y_hi; mm) of the skin's footprint, from the scene alone (no meshing).
std::array<double, 4> footprint_box(const Scene& scene);
// The kernel grid is held in memory (4 components per sensor) and written twice: bounded at 1e6 points and
// 2.5e7 values (200 MB). Throws SceneError naming --grid otherwise.
void check_kernel_grid(const Scene& scene, double dx);

// setup: the 3D path's adjoints (reciprocity check, maps on the mesh), or null for the meridian path.
// grid_dx > 0: also the kernel on that grid over the footprint. axis_scan: the meridian check's scan, made
// before (a fast report's, beside its factorization); used when it is of the axis sensor's scan.
GreenRun green_run(const Scene& scene, const SensorGreens& greens, const AdjointSetup* setup,
                   double grid_dx = 0, const MeridianScan* axis_scan = nullptr);
// summary.json of `skinfem green`.
nlohmann::json green_json(const Scene& scene, const SensorGreens& greens, const GreenRun& run,
                          double grid_dx);

}  // namespace skinfem::pipeline
