#include "skinfem/mesh/size_estimate.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "skinfem/mesh/shape.hpp"
#include "skinfem/mesh/sizing.hpp"
#include "skinfem/mesh/surface.hpp"

namespace skinfem {

namespace {
constexpr double kTetsPerCube = 43.3;  // c⁻¹: elements per h³ of volume (fitted below)
constexpr double kThinCap = 2.5;       // κ: the element size a thin skin allows, in thicknesses
constexpr int kDepthIntervals = 24;    // midpoint rule through the thickness, on intervals that grow
constexpr double kDepthRatio = 1.35;   // by this ratio down from the top (the first is t/1800 thick)

struct Integrator {
  const SizingField& size;
  const SkinShape& shape;
  double cx, cy, radius;  // a cap's footprint: the disc of `radius` about (cx, cy); radius 0 for a flat layer
  std::vector<Circle> posts;  // post sensors: cavities up to post_height, no skin there
  double post_height = 0;
  double stop, tets = 0;

  double thickness(double x, double y) const {
    if (radius > 0 && std::hypot(x - cx, y - cy) > radius) return 0;
    return shape.top_z(x, y);
  }
  // The skin's bottom above (x, y): a post's top inside its outline, else the base.
  double bottom(double x, double y) const {
    for (const Circle& c : posts)
      if (std::hypot(x - c.centre[0], y - c.centre[1]) < c.radius) return post_height;
    return 0;
  }

  // Elements per mm² of footprint above (x, y): ∫₀ᵗ dz / (c h_eff³), by the midpoint rule on intervals that
  // grow geometrically down from the top: a region refined on the top (a contact zone, ridges) grades with
  // depth, so its elements crowd into a layer far thinner than the skin, which evenly spaced points miss.
  double column(double x, double y) const {
    const double t = thickness(x, y), skin = t - bottom(x, y);
    if (!(t > 0) || !(skin > 0)) return 0;
    std::array<double, kDepthIntervals> z, h;
    for (int k = 0; k < kDepthIntervals; ++k)
      z[k] = t - 0.5 * (skin * depth_fraction(k) + skin * depth_fraction(k + 1));
    size.in_column(x, y, z.data(), kDepthIntervals, h.data());
    double sum = 0;
    for (int k = 0; k < kDepthIntervals; ++k) {
      const double d0 = skin * depth_fraction(k), d1 = skin * depth_fraction(k + 1);
      const double hk = std::min(h[k], kThinCap * t);
      sum += kTetsPerCube / (hk * hk * hk) * (d1 - d0);
    }
    return sum;
  }
  // The smallest size in the column above (x, y).
  double min_size(double x, double y) const {
    const double t = thickness(x, y);
    if (!(t > 0)) return 0;
    std::array<double, kDepthIntervals> z, h;
    for (int k = 0; k < kDepthIntervals; ++k)
      z[k] = t * (1 - 0.5 * (depth_fraction(k) + depth_fraction(k + 1)));
    size.in_column(x, y, z.data(), kDepthIntervals, h.data());
    double m = size.h_max();
    for (int k = 0; k < kDepthIntervals; ++k) m = std::min(m, h[k]);
    return std::min(m, kThinCap * t);
  }
  // Interval k of the column spans depths t·[f(k), f(k+1)]: geometric growth by kDepthRatio from the top.
  // Tabulated once: the estimate asks for them millions of times.
  static double depth_fraction(int k) {
    static const std::array<double, kDepthIntervals + 1> f = [] {
      std::array<double, kDepthIntervals + 1> out{};
      for (int i = 0; i <= kDepthIntervals; ++i)
        out[i] = (std::pow(kDepthRatio, i) - 1) / (std::pow(kDepthRatio, kDepthIntervals) - 1);
      return out;
    }();
    return f[k];
  }

  // Adaptive midpoint rule on the square cell of centre (x, y) and half-side r: split while the sizes at
  // its centre and corners differ by more than 30 % and the cell is wider than twice the smallest size.
  void cell(double x, double y, double r, int depth) {
    if (tets > stop) return;
    const std::array<std::array<double, 2>, 5> p{
        {{x, y}, {x - r, y - r}, {x + r, y - r}, {x - r, y + r}, {x + r, y + r}}};
    double lo = 1e300, hi = 0;
    for (const auto& q : p) {
      const double h = min_size(q[0], q[1]);
      if (h > 0) lo = std::min(lo, h), hi = std::max(hi, h);
    }
    if (depth < 40 && hi > 0 && (hi > 1.3 * lo || lo == 1e300) && 2 * r > 2 * lo) {
      for (int i : {-1, 1})
        for (int j : {-1, 1}) cell(x + 0.5 * r * i, y + 0.5 * r * j, 0.5 * r, depth + 1);
      return;
    }
    // 2×2 Gauss points: the footprint's edge cuts some cells, which the zero columns outside account for.
    const double g = r / std::sqrt(3.0);
    double sum = 0;
    for (int i : {-1, 1})
      for (int j : {-1, 1}) sum += column(x + g * i, y + g * j);
    tets += sum * r * r;
  }
};
}  // namespace

MeshEstimate estimate_mesh(const Scene& scene, double stop_tets, MeshPart part) {
  MeshEstimate e;
  const SkinShape shape(scene.geometry);
  if (!shape.exact()) return e;
  const SizingField size(scene, part);
  const bool half = part == MeshPart::half_y;
  const Geometry& g = scene.geometry;
  const bool cap = g.kind == GeometryKind::cap;
  const double r = cap ? g.cap.truncation_radius : g.flat.half_width;
  const double cx = cap ? g.cap.apex_x : 0, cy = cap ? g.cap.apex_y : 0;
  Integrator in{size, shape, cx, cy, cap ? r : 0, post_circles(scene), scene.sensors.post.height, stop_tets};
  // Start from a grid of cells no wider than h_max, so no feature is missed between samples; on a half, an
  // even count whose upper rows are the half y >= cy.
  const int n = half ? 2 * std::max(1, static_cast<int>(std::ceil(r / size.h_max())))
                     : std::max(1, static_cast<int>(std::ceil(2 * r / size.h_max())));
  const double w = r / n;
  for (int i = 0; i < n; ++i)
    for (int j = half ? n / 2 : 0; j < n; ++j)
      in.cell(cx - r + (2 * i + 1) * w, cy - r + (2 * j + 1) * w, w, 0);
  e.tets = in.tets;
  e.dofs = kDofsPerTet * in.tets;
  e.known = true;
  return e;
}

double fewest_tets(double volume_mm3, double h_max) {
  return 6 * std::sqrt(2.0) * volume_mm3 / std::pow(h_max, 3);
}

}  // namespace skinfem
