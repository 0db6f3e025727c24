#include "skinfem/fem/elastic_model.hpp"

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "skinfem/fem/face_index.hpp"
#include "skinfem/mesh/surface_quadrature.hpp"

namespace skinfem {

ElasticModel::ElasticModel(const TetMesh& mesh, const Material& material, SideCondition side,
                           const std::vector<Punch>& punches, ModelOptions options)
    : mesh_(mesh), lame_(Lame::from(material.E, material.nu)) {
  const auto start = std::chrono::steady_clock::now();
  matrices_ = assemble_mixed(mesh, lame_);
  assemble_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  held_ = skin_supports(mesh, side, punches);
  top_index_ = std::make_unique<PlanarFaceIndex>(mesh, kTop);
  solver_ = std::make_unique<MixedSolver>(matrices_, lame_, held_.fixed, options.solver, options.tolerance,
                                          options.factor_progress, options.coupling);
}

ElasticModel::ElasticModel(const TetMesh& mesh, MixedMatrices tangent, double mu, SideCondition side,
                           ModelOptions options)
    : mesh_(mesh), lame_{mu, 0.0}, matrices_(std::move(tangent)) {
  held_ = skin_supports(mesh, side, {});
  top_index_ = std::make_unique<PlanarFaceIndex>(mesh, kTop);
  solver_ = std::make_unique<MixedSolver>(matrices_, lame_, held_.fixed, options.solver, options.tolerance,
                                          options.factor_progress, options.coupling);
}

LoadCaseResult ElasticModel::solve(const Eigen::VectorXd& f, const std::vector<Punch>& punches) const {
  if (punches.size() != held_.punch_nodes.size())
    throw std::invalid_argument("punch count differs from the model's");
  const int np = punches.size();
  // Linear in the punch depths: x = x_0 + Σ δ_k x_k, with x_0 the load alone (punches held at 0)
  // and x_k a unit depth of punch k. Force-driven punches fix δ through their reaction.
  auto force = [&](const Eigen::VectorXd& r, int k) { return punch_force(held_.punch_nodes[k], r); };
  std::vector<MixedSolution> unit;
  std::vector<Eigen::VectorXd> unit_r;
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(3 * mesh_.num_nodes());
  for (int k = 0; k < np; ++k) {
    Eigen::VectorXd g = zero;
    for (int i : held_.punch_nodes[k]) g[3 * i + 2] = -1.0;
    unit.push_back(solver_->solve(zero, g));
    unit_r.push_back(solver_->reactions(unit.back(), {}));
  }
  LoadCaseResult out;
  out.solution = solver_->solve(f);
  Eigen::VectorXd r = solver_->reactions(out.solution, f);
  // δ: displacement-driven rows fix δ_k; force-driven rows ask punch_force(r_0 + Σ δ_j r_j) = F_k.
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(np, np);
  Eigen::VectorXd rhs(np);
  for (int k = 0; k < np; ++k) {
    if (punches[k].displacement) {
      M(k, k) = 1;
      rhs[k] = *punches[k].displacement;
    } else {
      for (int j = 0; j < np; ++j) M(k, j) = force(unit_r[j], k);
      rhs[k] = punches[k].force.value_or(0.0) - force(r, k);
    }
  }
  const Eigen::VectorXd delta = np ? Eigen::VectorXd(M.fullPivLu().solve(rhs)) : Eigen::VectorXd();
  for (int k = 0; k < np; ++k) {
    out.solution.u += delta[k] * unit[k].u;
    out.solution.p += delta[k] * unit[k].p;
    r += delta[k] * unit_r[k];
    out.solution.residual = std::max(out.solution.residual, unit[k].residual);
  }
  for (int k = 0; k < np; ++k) out.punches.push_back({force(r, k), delta[k]});
  out.reactions = support_reactions(held_, r);
  const Eigen::Vector3d applied = applied_force(held_, r, f);
  for (int c = 0; c < 3; ++c) out.applied_force_N[c] = applied[c];
  return out;
}

Eigen::VectorXd ElasticModel::patch_load(const TractionPatch& patch) const {
  return skinfem::patch_load(mesh_, patch);
}

Eigen::VectorXd ElasticModel::point_load(double x, double y, const Eigen::Vector3d& force) const {
  Eigen::VectorXd F = Eigen::VectorXd::Zero(3 * mesh_.num_nodes());
  add_point_load(F, x, y, force);
  return F;
}

void ElasticModel::add_point_load(Eigen::VectorXd& F, double x, double y,
                                  const Eigen::Vector3d& force) const {
  double s, t;
  const int f = top_index_->find(x, y, s, t);
  if (f < 0)
    throw std::out_of_range("load point (" + std::to_string(x) + ", " + std::to_string(y) +
                            ") is off the top surface");
  const auto N = triangle_shape(s, t);
  for (int k = 0; k < 6; ++k) F.segment<3>(3 * mesh_.faces(f, k)) += N[k] * force;
}

}  // namespace skinfem
