#include "skinfem/contact/mortar.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "skinfem/mesh/surface_quadrature.hpp"

namespace skinfem::contact {

namespace {
// P1 hats of the corner triangle at face parameters (s, t), in face-node order 0, 1, 2.
Eigen::Vector3d hats(double s, double t) { return {1 - s - t, s, t}; }
}  // namespace

MortarZone mortar_zone(const TetMesh& m, const Vec2& center, double radius) {
  MortarZone z;
  std::vector<int> local(m.num_nodes(), -1);
  for (int i = 0; i < m.num_vertices; ++i)
    if ((m.node_marker(i) & kTop) && !(m.node_marker(i) & (kSide | kBase)) &&
        std::hypot(m.nodes(i, 0) - center[0], m.nodes(i, 1) - center[1]) <= radius) {
      local[i] = z.size();
      z.vertices.push_back(i);
    }
  if (z.vertices.empty())
    throw std::invalid_argument("contact zone of radius " + std::to_string(radius) +
                                " mm holds no top vertex: refine the mesh there");
  std::vector<Eigen::Triplet<double>> t;
  z.area = Eigen::VectorXd::Zero(z.size());
  for (int f = 0; f < m.faces.rows(); ++f) {
    if (m.face_marker(f) != kTop) continue;
    if (local[m.faces(f, 0)] < 0 && local[m.faces(f, 1)] < 0 && local[m.faces(f, 2)] < 0) continue;
    z.faces.push_back(f);
    for (const FacePoint& q : face_quadrature(m, f)) {
      const Eigen::Vector3d psi = hats(q.s, q.t);
      for (int a = 0; a < 3; ++a) {
        const int i = local[m.faces(f, a)];
        if (i < 0) continue;
        z.area[i] += q.weight_xy * psi[a];
        for (int b = 0; b < 6; ++b) t.emplace_back(i, m.faces(f, b), q.weight_xy * psi[a] * q.N[b]);
      }
    }
  }
  z.D.resize(z.size(), m.num_nodes());
  z.D.setFromTriplets(t.begin(), t.end());
  return z;
}

Eigen::VectorXd MortarZone::weighted(const TetMesh& m,
                                     const std::function<double(const Eigen::Vector3d&)>& f) const {
  std::vector<int> local(m.num_nodes(), -1);
  for (int i = 0; i < size(); ++i) local[vertices[i]] = i;
  Eigen::VectorXd out = Eigen::VectorXd::Zero(size());
  for (int face : faces)
    for (const FacePoint& q : face_quadrature(m, face)) {
      const Eigen::Vector3d psi = hats(q.s, q.t);
      const double v = f(q.x);
      for (int a = 0; a < 3; ++a)
        if (const int i = local[m.faces(face, a)]; i >= 0) out[i] += q.weight_xy * psi[a] * v;
    }
  return out;
}

MortarZone::SphereGaps MortarZone::sphere_gaps(const TetMesh& m, const Eigen::VectorXd& u,
                                               const Eigen::Vector3d& c, double R,
                                               const Eigen::VectorXd* lambda,
                                               const Eigen::Vector2d* sliding) const {
  std::vector<int> local(m.num_nodes(), -1);
  for (int i = 0; i < size(); ++i) local[vertices[i]] = i;
  SphereGaps out{Eigen::VectorXd::Zero(size()),
                 Eigen::VectorXd::Zero(size()),
                 Eigen::VectorXd::Zero(size()),
                 {},
                 {},
                 {}};
  std::vector<Eigen::Triplet<double>> t, tg, tt;
  const Eigen::Vector3d t3 =
      sliding ? Eigen::Vector3d(sliding->x(), sliding->y(), 0) : Eigen::Vector3d::Zero();
  for (int face : faces)
    for (const FacePoint& q : face_quadrature(m, face)) {
      const Eigen::Vector3d psi = hats(q.s, q.t);
      Eigen::Vector3d x = q.x;
      for (int b = 0; b < 6; ++b) x += q.N[b] * u.segment<3>(3 * m.faces(face, b));
      const double r = (x - c).norm();
      const Eigen::Vector3d n = (x - c) / r;
      if (lambda) {
        double p = 0;  // Σ λ_i ψ_i at the point
        for (int a = 0; a < 3; ++a)
          if (const int i = local[m.faces(face, a)]; i >= 0) p += (*lambda)[i] * psi[a];
        const Eigen::Matrix3d turn = q.weight_xy * p / r * (Eigen::Matrix3d::Identity() - n * n.transpose());
        if (p != 0)
          for (int a = 0; a < 6; ++a)
            for (int b = 0; b < 6; ++b)
              for (int k = 0; k < 3; ++k)
                for (int l = 0; l < 3; ++l)
                  tg.emplace_back(3 * m.faces(face, a) + k, 3 * m.faces(face, b) + l,
                                  q.N[a] * q.N[b] * turn(k, l));
      }
      for (int a = 0; a < 3; ++a) {
        const int i = local[m.faces(face, a)];
        if (i < 0) continue;
        const double w = q.weight_xy * psi[a];
        out.g[i] += w * (r - R);
        out.m[i] -= w * n.z();
        for (int b = 0; b < 6; ++b)
          for (int k = 0; k < 3; ++k) t.emplace_back(i, 3 * m.faces(face, b) + k, w * q.N[b] * n[k]);
        if (sliding) {
          const Eigen::Vector3d s = (t3 - t3.dot(n) * n).normalized();
          out.mt[i] -= w * s.z();
          for (int b = 0; b < 6; ++b)
            for (int k = 0; k < 3; ++k) tt.emplace_back(i, 3 * m.faces(face, b) + k, w * q.N[b] * s[k]);
        }
      }
    }
  out.Dn.resize(size(), 3 * m.num_nodes());
  out.Dn.setFromTriplets(t.begin(), t.end());
  if (sliding) {
    out.Dt.resize(size(), 3 * m.num_nodes());
    out.Dt.setFromTriplets(tt.begin(), tt.end());
  }
  if (lambda) {
    out.G.resize(3 * m.num_nodes(), 3 * m.num_nodes());
    out.G.setFromTriplets(tg.begin(), tg.end());
  }
  return out;
}

Eigen::VectorXd MortarZone::load(const Eigen::VectorXd& lambda, const Eigen::Vector2d& t_dir, double ratio,
                                 const Eigen::VectorXd& shear) const {
  const Eigen::VectorXd nodal = D.transpose() * lambda;  // ∫ p φ_j
  Eigen::VectorXd tangential = ratio * nodal;            // ∫ p_t φ_j
  if (shear.size()) tangential += D.transpose() * shear;
  Eigen::VectorXd f = Eigen::VectorXd::Zero(3 * nodal.size());
  for (int j = 0; j < nodal.size(); ++j) {
    f[3 * j] = t_dir.x() * tangential[j];
    f[3 * j + 1] = t_dir.y() * tangential[j];
    f[3 * j + 2] = -nodal[j];
  }
  return f;
}

}  // namespace skinfem::contact
