#include "skinfem/mesh/surface_quadrature.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

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

namespace {

using FaceNodes = Eigen::Matrix<double, 6, 3>;

FaceNodes face_nodes(const TetMesh& m, int f) {
  FaceNodes X;
  for (int a = 0; a < 6; ++a) X.row(a) = m.nodes.row(m.faces(f, a));
  return X;
}

// The rule on the sub-triangle (a, b, c) of the parameter triangle (each corner (s, t)); with a disc, only
// the points whose projection lies in it.
void add_rule(const FaceNodes& X, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
              const Eigen::Vector2d& c, const Eigen::Vector2d* centre, double radius,
              std::vector<FacePoint>& out) {
  const Eigen::Vector2d e1 = b - a, e2 = c - a;
  const double area = 0.5 * std::abs(e1.x() * e2.y() - e1.y() * e2.x());
  for (const auto& p : triangle_rule_degree5()) {
    const Eigen::Vector2d st = a + p.s * e1 + p.t * e2;
    const double s = st.x(), t = st.y();
    const auto N = triangle_shape(s, t);
    const Eigen::Vector3d x = X.transpose() * N;
    if (centre && (x.head<2>() - *centre).norm() > radius) continue;
    double ds[6], dt[6];
    triangle_shape_gradient(s, t, ds, dt);
    Eigen::Vector3d xs = Eigen::Vector3d::Zero(), xt = Eigen::Vector3d::Zero();
    for (int k = 0; k < 6; ++k) {
      xs += ds[k] * X.row(k).transpose();
      xt += dt[k] * X.row(k).transpose();
    }
    const Eigen::Vector3d n = xs.cross(xt);
    out.push_back({x, N, n.normalized(), area * p.w * n.norm(), area * p.w * std::abs(n.z()), s, t});
  }
}

Eigen::Vector2d projection(const FaceNodes& X, const Eigen::Vector2d& st) {
  return (X.transpose() * triangle_shape(st.x(), st.y())).head<2>();
}

// Distance from q to the straight triangle (p0, p1, p2), 0 inside it.
double distance_to_triangle(const Eigen::Vector2d& q, const Eigen::Vector2d p[3]) {
  const auto cross = [](const Eigen::Vector2d& u, const Eigen::Vector2d& v) {
    return u.x() * v.y() - u.y() * v.x();
  };
  double d = std::numeric_limits<double>::infinity();
  int sign = 0;
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector2d& u = p[i];
    const Eigen::Vector2d e = p[(i + 1) % 3] - u;
    const double side = cross(e, q - u);
    sign += side >= 0 ? 1 : -1;
    const double l = std::clamp((q - u).dot(e) / std::max(e.squaredNorm(), 1e-300), 0.0, 1.0);
    d = std::min(d, (u + l * e - q).norm());
  }
  return std::abs(sign) == 3 ? 0.0 : d;
}

void add_disc_part(const FaceNodes& X, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                   const Eigen::Vector2d& c, const Eigen::Vector2d& centre, double radius, double min_size,
                   std::vector<FacePoint>& out) {
  const Eigen::Vector2d p[3] = {projection(X, a), projection(X, b), projection(X, c)};
  int inside = 0;
  for (const auto& q : p) inside += (q - centre).norm() <= radius;
  // The disc is convex: with its corners inside, the (straight) piece is inside.
  if (inside == 3) return add_rule(X, a, b, c, nullptr, radius, out);
  if (distance_to_triangle(centre, p) > radius) return;
  const double size = std::max({(p[1] - p[0]).norm(), (p[2] - p[1]).norm(), (p[0] - p[2]).norm()});
  if (size <= min_size) return add_rule(X, a, b, c, &centre, radius, out);
  const Eigen::Vector2d ab = 0.5 * (a + b), bc = 0.5 * (b + c), ca = 0.5 * (c + a);
  add_disc_part(X, a, ab, ca, centre, radius, min_size, out);
  add_disc_part(X, ab, b, bc, centre, radius, min_size, out);
  add_disc_part(X, ca, bc, c, centre, radius, min_size, out);
  add_disc_part(X, ab, bc, ca, centre, radius, min_size, out);
}

}  // namespace

std::vector<FacePoint> face_quadrature(const TetMesh& m, int f) {
  std::vector<FacePoint> out;
  out.reserve(7);
  add_rule(face_nodes(m, f), {0, 0}, {1, 0}, {0, 1}, nullptr, 0, out);
  return out;
}

std::vector<FacePoint> face_quadrature_in_disc(const TetMesh& m, int f, const Eigen::Vector2d& centre,
                                               double radius, double min_size) {
  std::vector<FacePoint> out;
  add_disc_part(face_nodes(m, f), {0, 0}, {1, 0}, {0, 1}, centre, radius, min_size, out);
  return out;
}

}  // namespace skinfem
