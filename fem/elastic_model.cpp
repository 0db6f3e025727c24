#include "skinfem/fem/elastic_model.hpp"

#include <chrono>
#include <cmath>
#include <stdexcept>

#include "skinfem/fem/face_index.hpp"
#include "skinfem/mesh/surface_quadrature.hpp"

namespace skinfem {

std::vector<int> punch_nodes(const TetMesh& m, const Punch& punch) {
  // Corner nodes of the top inside the disc (the footprint mesh follows the punch circle), then the
  // mid-edge nodes of top edges between two of them: exactly the nodes of the polygonal contact area.
  const double r = 0.5 * punch.diameter * (1 + 1e-9);
  std::vector<bool> held(m.num_nodes(), false);
  for (int i = 0; i < m.num_vertices; ++i)
    held[i] = (m.node_marker(i) & kTop) && !(m.node_marker(i) & (kBase | kSide)) &&
              std::hypot(m.nodes(i, 0) - punch.center[0], m.nodes(i, 1) - punch.center[1]) <= r;
  for (int f = 0; f < m.faces.rows(); ++f)
    if (m.face_marker(f) == kTop)
      for (int e = 0; e < 3; ++e)
        if (held[m.faces(f, e)] && held[m.faces(f, (e + 1) % 3)]) held[m.faces(f, 3 + e)] = true;
  std::vector<int> nodes;
  for (int i = 0; i < m.num_nodes(); ++i)
    if (held[i]) nodes.push_back(i);
  if (nodes.empty())
    throw std::invalid_argument("punch at (" + std::to_string(punch.center[0]) + ", " +
                                std::to_string(punch.center[1]) +
                                ") holds no top node: refine the mesh there");
  return nodes;
}

ElasticModel::ElasticModel(const TetMesh& mesh, const Material& material, SideCondition side,
                           const std::vector<Punch>& punches, ModelOptions options)
    : mesh_(mesh), lame_(Lame::from(material.E, material.nu)) {
  const auto start = std::chrono::steady_clock::now();
  matrices_ = assemble_mixed(mesh, lame_);
  assemble_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const int n = mesh.num_nodes();
  fixed_.assign(3 * n, false);
  support_.assign(3 * n, false);
  const int held = kBase | kPost | (side == SideCondition::fixed ? kSide : 0);
  for (int i = 0; i < n; ++i)
    if (mesh.node_marker(i) & held)
      for (int c = 0; c < 3; ++c) fixed_[3 * i + c] = support_[3 * i + c] = true;
  // A half mesh's cut y = 0: the mirror-symmetric solution has u_y = 0 there and no shear across it. The
  // constraint takes no reaction of its own (support_ stays false): it is the other half's pull, not a
  // support.
  for (int i = 0; i < n; ++i)
    if (mesh.node_marker(i) & kSymmetry) fixed_[3 * i + 1] = true;
  for (const auto& p : punches) {
    punch_nodes_.push_back(punch_nodes(mesh, p));
    for (int i : punch_nodes_.back()) fixed_[3 * i + 2] = true;
  }
  top_index_ = std::make_unique<PlanarFaceIndex>(mesh, kTop);
  solver_ = std::make_unique<MixedSolver>(matrices_, lame_, fixed_, options.solver, options.tolerance,
                                          options.factor_progress, options.coupling);
}

LoadCaseResult ElasticModel::solve(const Eigen::VectorXd& f, const std::vector<Punch>& punches) const {
  if (punches.size() != punch_nodes_.size())
    throw std::invalid_argument("punch count differs from the model's");
  const int np = punches.size();
  // Linear in the punch depths: x = x_0 + Σ δ_k x_k, with x_0 the load alone (punches held at 0)
  // and x_k a unit depth of punch k. Force-driven punches fix δ through their reaction.
  auto punch_force = [&](const Eigen::VectorXd& r, int k) {
    double fz = 0;
    for (int i : punch_nodes_[k]) fz += r[3 * i + 2];
    return -fz;  // the punch pushes down on the skin: reaction −z is a positive pressing force
  };
  std::vector<MixedSolution> unit;
  std::vector<Eigen::VectorXd> unit_r;
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(3 * mesh_.num_nodes());
  for (int k = 0; k < np; ++k) {
    Eigen::VectorXd g = zero;
    for (int i : punch_nodes_[k]) g[3 * i + 2] = -1.0;
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
      for (int j = 0; j < np; ++j) M(k, j) = punch_force(unit_r[j], k);
      rhs[k] = punches[k].force.value_or(0.0) - punch_force(r, k);
    }
  }
  const Eigen::VectorXd delta = np ? Eigen::VectorXd(M.fullPivLu().solve(rhs)) : Eigen::VectorXd();
  for (int k = 0; k < np; ++k) {
    out.solution.u += delta[k] * unit[k].u;
    out.solution.p += delta[k] * unit[k].p;
    r += delta[k] * unit_r[k];
    out.solution.residual = std::max(out.solution.residual, unit[k].residual);
  }
  for (int k = 0; k < np; ++k) out.punches.push_back({punch_force(r, k), delta[k]});
  out.reactions = r;
  for (int d = 0; d < r.size(); ++d)
    if (!support_[d]) out.reactions[d] = 0;
  // External force on the skin: nodal loads plus punch reactions.
  for (int i = 0; i < mesh_.num_nodes(); ++i)
    for (int c = 0; c < 3; ++c) {
      const int d = 3 * i + c;
      out.applied_force_N[c] += (fixed_[d] && !support_[d]) ? r[d] : (support_[d] ? 0.0 : f[d]);
    }
  return out;
}

Eigen::VectorXd ElasticModel::patch_load(const TractionPatch& patch) const {
  // Face by face over the part of each top face inside the disc (projected on the base plane), so the load
  // is the consistent one of a uniform traction: a uniform pressure over a flat layer is then the hydrostatic
  // state's load exactly (issue 57: a rule over the disc whose points fell into whatever face held them read
  // 1.1 % high at a post 1 mm from a 20 mm patch's centre). Only the faces its edge cuts are refined; the
  // density is the force over the area found, so the total force is exact.
  const double a = 0.5 * patch.diameter;
  const Eigen::Vector2d centre(patch.center[0], patch.center[1]);
  const Eigen::Vector3d dir =
      Eigen::Vector3d(patch.direction[0], patch.direction[1], patch.direction[2]).normalized();
  Eigen::VectorXd F = Eigen::VectorXd::Zero(3 * mesh_.num_nodes());
  double area = 0;
  for (int f = 0; f < mesh_.faces.rows(); ++f) {
    if (mesh_.face_marker(f) != kTop) continue;
    // Summed per face first: fewer round-offs in the total.
    Eigen::Matrix<double, 6, 1> w = Eigen::Matrix<double, 6, 1>::Zero();
    for (const FacePoint& q : face_quadrature_in_disc(mesh_, f, centre, a, kPatchEdgeResolution * a))
      w += q.weight_xy * q.N;
    area += w.sum();
    for (int k = 0; k < 6; ++k) F.segment<3>(3 * mesh_.faces(f, k)) += w[k] * dir;
  }
  if (!(area > 0.5 * M_PI * a * a))
    throw std::out_of_range("traction patch at (" + std::to_string(centre.x()) + ", " +
                            std::to_string(centre.y()) + ") is off the top surface");
  return (patch.force / area) * F;
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
