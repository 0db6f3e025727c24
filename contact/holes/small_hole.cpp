#include "skinfem/contact/holes/small_hole.hpp"

#include <Eigen/LU>
#include <cmath>

#include "skinfem/scene/laws.hpp"

namespace skinfem::contact {

Eigen::MatrixXd small_hole_signals(const ContactSolver& solver, FrictionMode mode, const TetMesh& mesh,
                                   const PlanarFaceIndex& top, const std::vector<Vec2>& centers,
                                   double hole_diameter, double E, double nu) {
  // K and the reading rows live on the solved problem (the half under a mirror view); the pressure, the
  // hats and the hole centres on the whole zone and `mesh`.
  const CondensedContact& c = solver.condensed();
  const MortarZone& z = solver.zone();
  const ContactResult r = solver.solve(mode);
  const double solved_ratio = kind(mode).coupled ? r.ratio : 0.0;
  const std::vector<int> A = solver.solved_set(r.active);
  const int na = static_cast<int>(A.size()), nr = static_cast<int>(c.S_p.rows());
  // Force control borders the active block with the force row and the unknown approach δ.
  const bool force = solver.force_controlled();
  const int n = na + (force ? 1 : 0);
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n), rhs = Eigen::MatrixXd::Zero(n, nr);
  for (int a = 0; a < na; ++a) {
    for (int b = 0; b < na; ++b)
      K(a, b) = c.C_zz(A[a], A[b]) + (solved_ratio != 0 ? solved_ratio * c.C_zt(A[a], A[b]) : 0.0);
    if (force) {
      K(a, na) = -c.zone.area[A[a]];
      K(na, a) = c.zone.area[A[a]];
    }
    rhs.row(a) = c.S_p.col(A[a]).transpose() + r.ratio * c.S_t.col(A[a]).transpose();
  }
  const Eigen::MatrixXd W = K.transpose().partialPivLu().solve(rhs);  // n × readings

  std::vector<int> solved_slot(c.zone.size(), -1), whole_index(mesh.num_nodes(), -1);
  for (int a = 0; a < na; ++a) solved_slot[A[a]] = a;
  std::vector<double> pressure(mesh.num_nodes(), 0.0);
  for (int i = 0; i < z.size(); ++i) {
    pressure[z.vertices[i]] = r.lambda[i];
    whole_index[z.vertices[i]] = i;
  }
  // A shear strength τ is missing over the hole too: the nodal shear drops by S_d ψ_i(u) τ / ∫ψ_i (the
  // hole's area lumped on the hats, contact/holes/cover.hpp), read directly through S_t and, where it acts
  // while the pressure is solved, through the gaps it opens, C_zt Δτ, on the kept zone.
  const bool shear = r.tau != 0;
  const bool shear_acting = shear && kind(mode).coupled;
  const double S_d = M_PI * 0.25 * hole_diameter * hole_diameter;
  Eigen::VectorXd drop = Eigen::VectorXd::Zero(z.size());
  const double eps = 0.5 * hole_diameter;
  const double volume_per_pressure = 8 * (1 - nu * nu) * eps * eps * eps / (3 * E);
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(centers.size(), nr);
  for (size_t i = 0; i < centers.size(); ++i) {
    double s = 0, t = 0;
    const int f = top.find(centers[i][0], centers[i][1], s, t);
    if (f < 0) continue;
    const double psi[3] = {1 - s - t, s, t};
    double p = 0;
    for (int k = 0; k < 3; ++k) p += psi[k] * pressure[mesh.faces(f, k)];
    const double V = volume_per_pressure * p;
    for (int k = 0; k < 3; ++k) {
      const int w = whole_index[mesh.faces(f, k)];
      if (w < 0) continue;
      if (const int a = solved_slot[solver.solved_index(w)]; a >= 0)
        out.row(i) -= solver.opening_share() * V * psi[k] * W.row(a);
    }
    if (!shear) continue;
    drop.setZero();
    for (int k = 0; k < 3; ++k)
      if (const int w = whole_index[mesh.faces(f, k)]; w >= 0)
        drop[w] = S_d * psi[k] * r.shear[w] / z.area[w];
    const Eigen::VectorXd d = solver.solved_lambda(drop);
    out.row(i) -= (c.S_t * d).transpose();
    if (shear_acting) {
      const Eigen::VectorXd dq = c.C_zt * d;
      for (int a = 0; a < na; ++a) out.row(i) += dq[A[a]] * W.row(a);
    }
  }
  return out;
}

}  // namespace skinfem::contact
