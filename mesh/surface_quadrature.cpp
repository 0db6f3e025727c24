#include "mesh/surface_quadrature.hpp"

#include <algorithm>
#include <cmath>

namespace skinfem {

Eigen::Matrix<double, 6, 1> triangle_shape(double s, double t) {
  const double l = 1 - s - t;
  Eigen::Matrix<double, 6, 1> n;
  n << l * (2 * l - 1), s * (2 * s - 1), t * (2 * t - 1), 4 * l * s, 4 * s * t, 4 * t * l;
  return n;
}

void triangle_shape_gradient(double s, double t, double ds[6], double dt[6]) {
  const double l = 1 - s - t;
  const double a[6] = {-(4 * l - 1), 4 * s - 1, 0, 4 * (l - s), 4 * t, -4 * t};
  const double b[6] = {-(4 * l - 1), 0, 4 * t - 1, -4 * s, 4 * s, 4 * (l - t)};
  std::copy(a, a + 6, ds);
  std::copy(b, b + 6, dt);
}

const std::array<TrianglePoint, 7>& triangle_rule_degree5() {
  // Centroid, and two orbits of three points.
  static constexpr double a1 = 0.059715871789770, b1 = 0.470142064105115, w1 = 0.132394152788506;
  static constexpr double a2 = 0.797426985353087, b2 = 0.101286507323456, w2 = 0.125939180544827;
  static const std::array<TrianglePoint, 7> rule{{{1.0 / 3, 1.0 / 3, 0.225},
                                                  {b1, b1, w1},
                                                  {a1, b1, w1},
                                                  {b1, a1, w1},
                                                  {b2, b2, w2},
                                                  {a2, b2, w2},
                                                  {b2, a2, w2}}};
  return rule;
}

std::vector<FacePoint> face_quadrature(const TetMesh& m, int f) {
  Eigen::Matrix<double, 6, 3> X;
  for (int a = 0; a < 6; ++a) X.row(a) = m.nodes.row(m.faces(f, a));
  std::vector<FacePoint> out;
  out.reserve(7);
  for (const auto& p : triangle_rule_degree5()) {
    const double s = p.s, t = p.t;
    double ds[6], dt[6];
    triangle_shape_gradient(s, t, ds, dt);
    Eigen::Vector3d xs = Eigen::Vector3d::Zero(), xt = Eigen::Vector3d::Zero();
    for (int a = 0; a < 6; ++a) {
      xs += ds[a] * X.row(a).transpose();
      xt += dt[a] * X.row(a).transpose();
    }
    const auto N = triangle_shape(s, t);
    const Eigen::Vector3d n = xs.cross(xt);
    out.push_back(
        {X.transpose() * N, N, n.normalized(), 0.5 * p.w * n.norm(), 0.5 * p.w * std::abs(n.z()), s, t});
  }
  return out;
}

}  // namespace skinfem
