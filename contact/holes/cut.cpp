#include "skinfem/contact/holes/cut.hpp"

#include <algorithm>
#include <cmath>

#include "skinfem/contact/holes/cover.hpp"
#include "skinfem/mesh/surface_quadrature.hpp"

namespace skinfem::contact {

namespace {
double distance_to_segment(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d d = b - a;
  const double L2 = d.squaredNorm();
  const double s = L2 > 0 ? std::clamp((p - a).dot(d) / L2, 0.0, 1.0) : 0.0;
  return (p - a - s * d).norm();
}
}  // namespace

std::vector<int> watch_path(const TetMesh& m, const MortarZone& zone, const Vec2& from, const Vec2& to,
                            double reach) {
  std::vector<int> faces;
  const Eigen::Vector2d a(from[0], from[1]), b(to[0], to[1]);
  reach *= 1 + 1e-3;  // the hole's polygon reaches 1.3e-5 beyond its circle (hole_cover.hpp)
  for (int f : zone.faces) {
    Eigen::Vector2d v[3];
    for (int k = 0; k < 3; ++k) v[k] = {m.nodes(m.faces(f, k), 0), m.nodes(m.faces(f, k), 1)};
    // The face is within reach if the segment passes within `reach` of the triangle: test the corners, the
    // segment's ends inside, and the edges against the segment by sampling both finely enough.
    double d = 1e300;
    for (int k = 0; k < 3; ++k) d = std::min(d, distance_to_segment(v[k], a, b));
    const double len = (b - a).norm(),
                 edge = std::max({(v[1] - v[0]).norm(), (v[2] - v[1]).norm(), (v[0] - v[2]).norm()});
    const int samples = 1 + static_cast<int>(std::ceil(len / std::max(1e-3, 0.25 * edge)));
    for (int s = 0; s <= samples && d > reach; ++s) {
      const Eigen::Vector2d p = a + (b - a) * (double(s) / samples);
      // Distance from p to the triangle: 0 inside, else to its edges.
      const auto cross = [](const Eigen::Vector2d& u, const Eigen::Vector2d& w) {
        return u.x() * w.y() - u.y() * w.x();
      };
      const double c0 = cross(v[1] - v[0], p - v[0]), c1 = cross(v[2] - v[1], p - v[1]),
                   c2 = cross(v[0] - v[2], p - v[2]);
      if ((c0 >= 0 && c1 >= 0 && c2 >= 0) || (c0 <= 0 && c1 <= 0 && c2 <= 0)) d = 0;
      for (int k = 0; k < 3; ++k) d = std::min(d, distance_to_segment(p, v[k], v[(k + 1) % 3]));
    }
    if (d <= reach) faces.push_back(f);
  }
  return faces;
}

HoleCut hole_cut(const PathCompliance& path, int n_c, const Hole& hole) {
  const Indenter& indenter = *path.indenter;
  HoleCut out;
  out.area = Eigen::VectorXd::Zero(n_c);
  out.gap0 = Eigen::VectorXd::Zero(n_c);
  std::vector<Eigen::Triplet<double>> t;
  const auto& rule = triangle_rule_degree5();
  for (const PathCompliance::Face& f : path.faces) {
    if (f.multiplier[0] < 0 && f.multiplier[1] < 0 && f.multiplier[2] < 0) continue;
    Eigen::Vector2d v[3];
    for (int k = 0; k < 3; ++k) v[k] = f.x[k].head<2>();
    const double det = (v[1] - v[0]).x() * (v[2] - v[0]).y() - (v[1] - v[0]).y() * (v[2] - v[0]).x();
    Eigen::Vector2d ccw[3] = {v[0], v[1], v[2]};
    if (det < 0) std::swap(ccw[1], ccw[2]);
    const std::vector<Eigen::Vector2d> poly = hole_in_triangle(hole, ccw);
    if (poly.size() < 3) continue;
    // (x, y) → face parameters through the straight corner triangle.
    Eigen::Matrix2d J;
    J.col(0) = v[1] - v[0];
    J.col(1) = v[2] - v[0];
    const Eigen::Matrix2d Jinv = J.inverse();
    Eigen::Matrix<double, 3, 6> local = Eigen::Matrix<double, 3, 6>::Zero();  // ∫_H ψ_a φ_b on this face
    for (size_t k = 1; k + 1 < poly.size(); ++k) {
      const Eigen::Vector2d p0 = poly[0], e1 = poly[k] - p0, e2 = poly[k + 1] - p0;
      const double sub = 0.5 * std::abs(e1.x() * e2.y() - e1.y() * e2.x());
      if (!(sub > 0)) continue;
      for (const TrianglePoint& q : rule) {
        const Eigen::Vector2d st = Jinv * (p0 + q.s * e1 + q.t * e2 - v[0]);
        const double s = st.x(), tt = st.y();
        // The curved face's (x, y) Jacobian over the straight one's: the same measure as MortarZone::D.
        double ds[6], dt[6];
        triangle_shape_gradient(s, tt, ds, dt);
        Eigen::Vector3d xs = Eigen::Vector3d::Zero(), xt = Eigen::Vector3d::Zero(),
                        x = Eigen::Vector3d::Zero();
        const auto N = triangle_shape(s, tt);
        for (int a = 0; a < 6; ++a) {
          xs += ds[a] * f.x[a];
          xt += dt[a] * f.x[a];
          x += N[a] * f.x[a];
        }
        const double w = q.w * sub * std::abs(xs.x() * xt.y() - xs.y() * xt.x()) / std::abs(det);
        const double psi[3] = {1 - s - tt, s, tt};
        const double gap = indenter.gap_at_rest(x);
        for (int a = 0; a < 3; ++a) {
          const int i = f.multiplier[a];
          if (i < 0) continue;
          out.area[i] += w * psi[a];
          out.gap0[i] += w * psi[a] * gap;
          local.row(a) += w * psi[a] * N.transpose();
        }
      }
    }
    for (int a = 0; a < 3; ++a)
      if (f.multiplier[a] >= 0)
        for (int b = 0; b < 6; ++b) t.emplace_back(f.multiplier[a], f.watched[b], local(a, b));
  }
  out.B.resize(n_c, static_cast<int>(path.nodes.size()));
  out.B.setFromTriplets(t.begin(), t.end());
  return out;
}

}  // namespace skinfem::contact
