// Green kernels sampled on a regular grid over the skin's top, for simulators that convolve pressure maps
// with them (the paper's model, docs/theory.md §Conventions), and their export to HDF5 and VTK image data.
#pragma once

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "skinfem/green/fe_green.hpp"

namespace skinfem::green {

// Grid lines over [lo, hi] at spacing dx, centred in the interval (so a symmetric interval keeps 0).
std::vector<double> grid_lines(double lo, double hi, double dx);

struct KernelGrid {
  std::vector<double> x, y;  // nx and ny grid lines, mm, base-plane coordinates (not offsets)
  double dx = 0;             // mm, spacing in x and y
  // ny×nx, row-major (index j·nx + i for the point (x_i, y_j)): 1 where the point lies on the top.
  std::vector<unsigned char> on_skin;
  std::vector<Vec2> sensors;  // mm, sensor centres; the kernel's offset is (x_i, y_j) − sensor
  double disc_diameter = 0;   // mm, each value is the mean reading over this disc
  // values[s][c][j·nx + i]: g_c (1/mm², MPa per N) of sensor s for a unit point force at (x_i, y_j) on the
  // top, c in kComponents order (zz, zx, xz, xx); 0 where the point is off the skin.
  std::vector<std::array<std::vector<double>, 4>> values;
};

// A sensor's disc reading for a unit point force at the top point above (x, y) (mm, absolute); false when no
// skin lies there (FeGreen::disc_map_at).
using DiscMap = std::function<bool(int sensor, double x, double y, GreenSample& g)>;

// Samples every sensor's disc-reading Green maps at the grid points over the box [x_lo, x_hi] × [y_lo, y_hi]
// (mm) that lie on the skin's top.
KernelGrid kernel_grid(const DiscMap& map, const Sensors& sensors, double x_lo, double x_hi, double y_lo,
                       double y_hi, double dx);

// One HDF5 file: datasets x_mm (nx), y_mm (ny), on_skin (ny×nx, uint8), sensorNN/g_<ab>_per_mm2 (ny×nx),
// attributes for units, the sign convention, the offset rule, each sensor's position and the disc diameter.
// Written to a temporary name and renamed; object timestamps are off, so equal grids give equal bytes.
void write_kernel_h5(const std::string& path, const KernelGrid& grid, const std::string& scene_name);
// The same arrays as VTK image data (point data g_<ab>_sensorNN_per_mm2 and on_skin) on the plane z = 0.
void write_kernel_vti(const std::string& path, const KernelGrid& grid);

}  // namespace skinfem::green
