#include "skinfem/fem/fields.hpp"

#include <cmath>
#include <stdexcept>

#include "skinfem/mesh/p2_tet.hpp"
#include "skinfem/mesh/vtu.hpp"

namespace skinfem {

Eigen::Matrix3d element_stress(const TetMesh& m, const Lame& lame, const MixedSolution& x, int t,
                               const Eigen::Vector3d& xi, StressMeasure measure) {
  Eigen::Matrix<double, 10, 3> X, U;
  for (int a = 0; a < 10; ++a) {
    X.row(a) = m.nodes.row(m.tets(t, a));
    U.row(a) = x.u.segment<3>(3 * m.tets(t, a)).transpose();
  }
  const p2::Grad10 dref = p2::shape_gradient(xi);
  const Eigen::Matrix3d J = X.transpose() * dref;
  const Eigen::Matrix3d grad_u = U.transpose() * dref * J.inverse();  // ∂u_i/∂x_k
  const auto L = p2::barycentric(xi);
  double p = 0;
  for (int r = 0; r < 4; ++r) p += L[r] * x.p[m.tets(t, r)];
  if (measure == StressMeasure::neo_hookean) {
    const Eigen::Matrix3d F = Eigen::Matrix3d::Identity() + grad_u;
    return lame.mu * (F * F.transpose() - Eigen::Matrix3d::Identity()) / F.determinant() -
           p * Eigen::Matrix3d::Identity();
  }
  return lame.mu * (grad_u + grad_u.transpose()) - p * Eigen::Matrix3d::Identity();
}

Eigen::Matrix<double, Eigen::Dynamic, 9, Eigen::RowMajor> recover_stress(const TetMesh& m, const Lame& lame,
                                                                         const MixedSolution& x,
                                                                         StressMeasure measure) {
  static const double node_xi[10][3] = {{0, 0, 0},   {1, 0, 0},  {0, 1, 0},  {0, 0, 1},   {.5, 0, 0},
                                        {.5, .5, 0}, {0, .5, 0}, {0, 0, .5}, {.5, 0, .5}, {0, .5, .5}};
  Eigen::Matrix<double, Eigen::Dynamic, 9, Eigen::RowMajor> S =
      Eigen::Matrix<double, Eigen::Dynamic, 9, Eigen::RowMajor>::Zero(m.num_nodes(), 9);
  Eigen::VectorXd count = Eigen::VectorXd::Zero(m.num_nodes());
  for (int t = 0; t < m.num_tets(); ++t)
    for (int a = 0; a < 10; ++a) {
      const Eigen::Matrix3d s = element_stress(
          m, lame, x, t, Eigen::Vector3d(node_xi[a][0], node_xi[a][1], node_xi[a][2]), measure);
      S.row(m.tets(t, a)) += Eigen::Map<const Eigen::Matrix<double, 1, 9>>(s.data());
      count[m.tets(t, a)] += 1;
    }
  for (int i = 0; i < m.num_nodes(); ++i) S.row(i) /= count[i];
  return S;
}

Probe probe(const TetMesh& m, const PointLocator& locator, const Lame& lame, const MixedSolution& x,
            const Eigen::Vector3d& point) {
  const auto loc = locator.locate(point);
  if (!loc) throw std::out_of_range("probe point is outside the mesh");
  const p2::Vec10 N = p2::shape(loc->xi);
  Probe out;
  out.u.setZero();
  for (int a = 0; a < 10; ++a) out.u += N[a] * x.u.segment<3>(3 * m.tets(loc->tet, a));
  for (int r = 0; r < 4; ++r) out.p += loc->barycentric[r] * x.p[m.tets(loc->tet, r)];
  out.sigma = element_stress(m, lame, x, loc->tet, loc->xi);
  return out;
}

void write_fields_vtu(const std::string& path, const TetMesh& m, const Lame& lame, const MixedSolution& x,
                      StressMeasure measure) {
  DataArray u{"displacement_mm", 3, std::vector<double>(x.u.data(), x.u.data() + x.u.size())};
  DataArray p{"pressure_MPa", 1, std::vector<double>(m.num_nodes())};
  for (int i = 0; i < m.num_vertices; ++i) p.values[i] = x.p[i];
  for (int t = 0; t < m.num_tets(); ++t)  // P1 pressure at mid-edge nodes: mean of the edge's ends
    for (int e = 0; e < 6; ++e)
      p.values[m.tets(t, 4 + e)] = 0.5 * (x.p[m.tets(t, p2::kEdge[e][0])] + x.p[m.tets(t, p2::kEdge[e][1])]);
  const auto S = recover_stress(m, lame, x, measure);
  DataArray stress{"stress_MPa", 9, std::vector<double>(S.data(), S.data() + S.size())};
  DataArray vm{"von_mises_MPa", 1, std::vector<double>(m.num_tets())};
  for (int t = 0; t < m.num_tets(); ++t) {
    const Eigen::Matrix3d s = element_stress(m, lame, x, t, Eigen::Vector3d(0.25, 0.25, 0.25), measure);
    const Eigen::Matrix3d dev = s - s.trace() / 3 * Eigen::Matrix3d::Identity();
    vm.values[t] = std::sqrt(1.5 * dev.squaredNorm());
  }
  write_vtu(path, m, {u, p, stress}, {vm});
}

MixedSolution mirrored_solution(const TetMesh& whole, const std::vector<int>& source,
                                const MixedSolution& half) {
  MixedSolution x = half;
  x.u.resize(3 * whole.num_nodes());
  x.p.resize(whole.num_vertices);
  for (int i = 0; i < whole.num_nodes(); ++i) {
    const int s = source[i];
    x.u.segment<3>(3 * i) = half.u.segment<3>(3 * s);
    if (whole.nodes(i, 1) < 0) x.u[3 * i + 1] = -x.u[3 * i + 1];
    if (i < whole.num_vertices) x.p[i] = half.p[s];
  }
  return x;
}

}  // namespace skinfem
