#include "skinfem/fem/base_traction.hpp"

#include <Eigen/SparseCholesky>
#include <cmath>
#include <stdexcept>
#include <unordered_map>
#include <vector>

#include "skinfem/fem/face_index.hpp"
#include "skinfem/mesh/gauss_legendre.hpp"
#include "skinfem/mesh/surface_quadrature.hpp"

namespace skinfem {

namespace {
// Base faces for 2-D location plus a numbering of the base nodes.
struct BaseIndex {
  PlanarFaceIndex planar;
  std::vector<int> faces;
  std::unordered_map<int, int> local;  // mesh node → base node index
  std::vector<int> nodes;              // base node index → mesh node
  explicit BaseIndex(const TetMesh& m) : planar(m, kBase), faces(planar.faces()) {
    for (int f : faces)
      for (int k = 0; k < 6; ++k)
        if (local.emplace(m.faces(f, k), static_cast<int>(nodes.size())).second)
          nodes.push_back(m.faces(f, k));
  }
};

Eigen::SparseMatrix<double> base_mass(const TetMesh& m, const BaseIndex& idx) {
  std::vector<Eigen::Triplet<double>> t;
  for (int f : idx.faces)
    for (const auto& q : face_quadrature(m, f))
      for (int a = 0; a < 6; ++a)
        for (int b = 0; b < 6; ++b)
          t.emplace_back(idx.local.at(m.faces(f, a)), idx.local.at(m.faces(f, b)),
                         q.weight * q.N[a] * q.N[b]);
  Eigen::SparseMatrix<double> M(idx.nodes.size(), idx.nodes.size());
  M.setFromTriplets(t.begin(), t.end());
  return M;
}
}  // namespace

struct BaseTraction::Impl {
  const TetMesh& mesh;
  BaseIndex index;
  Eigen::MatrixX3d t;  // base node → traction
  Eigen::Vector3d total;
  Impl(const TetMesh& m) : mesh(m), index(m) {}
};

BaseTraction::BaseTraction(const TetMesh& mesh, const Eigen::VectorXd& reactions) : impl_(new Impl(mesh)) {
  auto& s = *impl_;
  const int nb = s.index.nodes.size();
  Eigen::MatrixX3d R(nb, 3);
  for (int i = 0; i < nb; ++i) R.row(i) = reactions.segment<3>(3 * s.index.nodes[i]).transpose();
  s.total = R.colwise().sum().transpose();
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> chol(base_mass(mesh, s.index));
  // The base mass matrix is SPD for any valid mesh; a failure means a degenerate base (zero-area faces).
  if (chol.info() != Eigen::Success)
    throw std::runtime_error(
        "base traction: the base's mass matrix cannot be factored (degenerate base faces)");
  s.t = chol.solve(R);
}

BaseTraction::~BaseTraction() = default;
BaseTraction::BaseTraction(BaseTraction&&) noexcept = default;

std::optional<Eigen::Vector3d> BaseTraction::traction(double x, double y) const {
  const auto& s = *impl_;
  double ps, pt;
  const int f = s.index.planar.find(x, y, ps, pt);
  if (f < 0) return std::nullopt;
  const auto N = triangle_shape(ps, pt);
  Eigen::Vector3d v = Eigen::Vector3d::Zero();
  for (int a = 0; a < 6; ++a) v += N[a] * s.t.row(s.index.local.at(s.mesh.faces(f, a))).transpose();
  if (s.index.planar.mirrored(y)) v.y() = -v.y();  // the symmetric field's value at (x, −y)
  return v;
}

SensorReading BaseTraction::reading_at(double x, double y) const {
  const auto t = traction(x, y);
  if (!t)
    throw std::out_of_range("point (" + std::to_string(x) + ", " + std::to_string(y) + ") is off the base");
  return {(*t)[2], -(*t)[0]};
}

PointValueDiscs point_value_discs(double h) {
  const double a1 = h / 40, a2 = 2 * a1, w1 = a2 * a2 / (a2 * a2 - a1 * a1);
  return {a1, w1, a2, 1 - w1};
}

std::vector<std::array<double, 3>> point_value_rule(double h) {
  const PointValueDiscs d = point_value_discs(h);
  std::vector<std::array<double, 3>> rule;
  for (const auto& p : uniform_disc_rule(d.a1, 12, 32)) rule.push_back({p[0], p[1], d.w1 * p[2]});
  for (const auto& p : uniform_disc_rule(d.a2, 12, 32)) rule.push_back({p[0], p[1], d.w2 * p[2]});
  return rule;
}

SensorReading BaseTraction::point_value(double x, double y, double thickness) const {
  SensorReading r;
  for (const auto& p : point_value_rule(thickness)) {
    const SensorReading v = reading_at(x + p[0], y + p[1]);
    r.sigma_z += p[2] * v.sigma_z;
    r.sigma_x += p[2] * v.sigma_x;
  }
  return r;
}

SensorReading BaseTraction::disc_mean(double x, double y, double diameter) const {
  SensorReading r;
  for (const auto& p : uniform_disc_rule(0.5 * diameter, 12, 32)) {
    const SensorReading v = reading_at(x + p[0], y + p[1]);
    r.sigma_z += p[2] * v.sigma_z;
    r.sigma_x += p[2] * v.sigma_x;
  }
  return r;
}

Eigen::Vector3d BaseTraction::total_force() const { return impl_->total; }

struct ReadingFunctionals::Impl {
  const TetMesh& mesh;
  BaseIndex index;
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> mass;
  explicit Impl(const TetMesh& m) : mesh(m), index(m), mass(base_mass(m, index)) {
    if (mass.info() != Eigen::Success)
      throw std::runtime_error(
          "reading functionals: the base's mass matrix cannot be factored (degenerate base faces)");
  }
};

ReadingFunctionals::ReadingFunctionals(const TetMesh& mesh) : impl_(new Impl(mesh)) {}
ReadingFunctionals::~ReadingFunctionals() = default;

Eigen::VectorXd ReadingFunctionals::operator()(double x, double y, double diameter, char component) const {
  // reading = Σ_q w_q N(x_q)ᵀ T, T = M⁻¹ R  ⇒  reading = (M⁻¹ Σ_q w_q N(x_q))ᵀ R.
  const auto& [mesh, index, mass] = *impl_;
  const auto pts = diameter > 0 ? uniform_disc_rule(0.5 * diameter, 12, 32)
                                : point_value_rule(meshed_thickness(mesh, x, y));
  Eigen::VectorXd w = Eigen::VectorXd::Zero(index.nodes.size());
  for (const auto& p : pts) {
    double s, t;
    const int f = index.planar.find(x + p[0], y + p[1], s, t);
    if (f < 0) throw std::out_of_range("sensor disc leaves the base");
    const auto N = triangle_shape(s, t);
    for (int a = 0; a < 6; ++a) w[index.local.at(mesh.faces(f, a))] += p[2] * N[a];
  }
  const Eigen::VectorXd c = mass.solve(w);
  Eigen::VectorXd out = Eigen::VectorXd::Zero(3 * mesh.num_nodes());
  const int k = component == 'z' ? 2 : 0;
  const double sign = component == 'z' ? 1.0 : -1.0;
  for (size_t i = 0; i < index.nodes.size(); ++i) out[3 * index.nodes[i] + k] = sign * c[i];
  return out;
}

Eigen::VectorXd disc_reading_functional(const TetMesh& mesh, double x, double y, double diameter,
                                        char component) {
  return ReadingFunctionals(mesh)(x, y, diameter, component);
}

}  // namespace skinfem
