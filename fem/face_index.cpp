#include "skinfem/fem/face_index.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "skinfem/mesh/shape.hpp"
#include "skinfem/mesh/surface_quadrature.hpp"

namespace skinfem {

PlanarFaceIndex::PlanarFaceIndex(const TetMesh& m, int marker) : mesh_(m) {
  double xmin = 1e300, ymin = 1e300, xmax = -1e300, ymax = -1e300;
  std::vector<double> areas;
  for (int f = 0; f < m.faces.rows(); ++f) {
    if (m.face_marker(f) != marker) continue;
    faces_.push_back(f);
    for (int k = 0; k < 3; ++k) {
      const int n = m.faces(f, k);
      xmin = std::min(xmin, m.nodes(n, 0)), xmax = std::max(xmax, m.nodes(n, 0));
      ymin = std::min(ymin, m.nodes(n, 1)), ymax = std::max(ymax, m.nodes(n, 1));
    }
    const Eigen::Vector2d a = m.nodes.row(m.faces(f, 0)).head<2>(), b = m.nodes.row(m.faces(f, 1)).head<2>(),
                          c = m.nodes.row(m.faces(f, 2)).head<2>();
    Eigen::Matrix2d J;
    J << b - a, c - a;
    const Eigen::Matrix2d inv = J.inverse();
    corners_.push_back({a.x(), a.y(), inv(0, 0), inv(0, 1), inv(1, 0), inv(1, 1)});
    areas.push_back(0.5 * std::abs(J.determinant()));
  }
  if (faces_.empty()) throw std::invalid_argument("mesh has no faces with marker " + std::to_string(marker));
  // Twice the size of the finest tenth of the faces, so that a bucket in the fine zone holds a few faces;
  // no finer than 16 cells per face over the bounding box, which bounds the memory.
  std::vector<double> sorted = areas;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 10, sorted.end());
  const double fine_area = sorted[sorted.size() / 10];
  cell_ =
      std::max(2 * std::sqrt(fine_area), std::sqrt((xmax - xmin) * (ymax - ymin) / (16.0 * faces_.size())));
  x0_ = xmin - 1e-9, y0_ = ymin - 1e-9;
  nx_ = bin(xmax, x0_) + 2;
  ny_ = bin(ymax, y0_) + 2;
  buckets_.resize(static_cast<size_t>(nx_) * ny_);
  for (int e = 0; e < static_cast<int>(faces_.size()); ++e) {
    const int f = faces_[e];
    double fx0 = 1e300, fy0 = 1e300, fx1 = -1e300, fy1 = -1e300;
    for (int k = 0; k < 3; ++k) {
      const int n = m.faces(f, k);
      fx0 = std::min(fx0, m.nodes(n, 0)), fx1 = std::max(fx1, m.nodes(n, 0));
      fy0 = std::min(fy0, m.nodes(n, 1)), fy1 = std::max(fy1, m.nodes(n, 1));
    }
    for (int ix = bin(fx0, x0_); ix <= bin(fx1, x0_); ++ix)
      for (int iy = bin(fy0, y0_); iy <= bin(fy1, y0_); ++iy) buckets_[ix * ny_ + iy].push_back(e);
  }
}

int PlanarFaceIndex::find(double x, double y, double& s, double& t) const {
  if (mirrored(y)) y = -y;
  const int ix = bin(x, x0_), iy = bin(y, y0_);
  if (ix < 0 || iy < 0 || ix >= nx_ || iy >= ny_) return -1;
  int best = -1;
  double best_score = -1e300, bs = 0, bt = 0;
  for (int e : buckets_[ix * ny_ + iy]) {
    const Corner& c = corners_[e];
    const double dx = x - c.ax, dy = y - c.ay;
    const double st0 = c.i00 * dx + c.i01 * dy, st1 = c.i10 * dx + c.i11 * dy;
    const double score = std::min({st0, st1, 1 - st0 - st1});
    if (score > best_score) best_score = score, best = faces_[e], bs = st0, bt = st1;
    if (score > 1e-9) break;  // inside this face, so outside every other: the corner triangles do not overlap
  }
  if (best < 0 || best_score < -1e-9) return -1;
  s = bs, t = bt;
  return best;
}

double skin_thickness(const Geometry& geometry, const TetMesh& mesh, double x, double y) {
  const SkinShape shape(geometry);
  if (shape.exact()) {
    if (!shape.covers(x, y))
      throw std::out_of_range("no skin above (" + std::to_string(x) + ", " + std::to_string(y) +
                              "): the point is off the skin's footprint");
    return shape.mean_top_z(x, y);
  }
  return meshed_thickness(mesh, x, y);
}

double meshed_thickness(const TetMesh& mesh, double x, double y) {
  const PlanarFaceIndex top(mesh, kTop);
  double s, t;
  const int f = top.find(x, y, s, t);
  if (f < 0)
    throw std::out_of_range("no skin above (" + std::to_string(x) + ", " + std::to_string(y) +
                            "): the point is off the top surface");
  const auto N = triangle_shape(s, t);
  double z = 0;
  for (int k = 0; k < 6; ++k) z += N[k] * mesh.nodes(mesh.faces(f, k), 2);
  return z;
}

}  // namespace skinfem
