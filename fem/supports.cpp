#include "skinfem/fem/supports.hpp"

#include <cmath>
#include <stdexcept>

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

Supports skin_supports(const TetMesh& mesh, SideCondition side, const std::vector<Punch>& punches) {
  const int n = mesh.num_nodes();
  Supports s;
  s.fixed.assign(3 * n, false);
  s.support.assign(3 * n, false);
  const int held = kBase | kPost | (side == SideCondition::fixed ? kSide : 0);
  for (int i = 0; i < n; ++i)
    if (mesh.node_marker(i) & held)
      for (int c = 0; c < 3; ++c) s.fixed[3 * i + c] = s.support[3 * i + c] = true;
  // A half mesh's cut y = 0: the mirror-symmetric solution has u_y = 0 there and no shear across it. The
  // constraint takes no reaction of its own: it is the other half's pull, not a support.
  for (int i = 0; i < n; ++i)
    if (mesh.node_marker(i) & kSymmetry) s.fixed[3 * i + 1] = true;
  for (const auto& p : punches) {
    s.punch_nodes.push_back(punch_nodes(mesh, p));
    for (int i : s.punch_nodes.back()) s.fixed[3 * i + 2] = true;
  }
  return s;
}

double punch_force(const std::vector<int>& punch_nodes, const Eigen::VectorXd& r) {
  double fz = 0;
  for (int i : punch_nodes) fz += r[3 * i + 2];
  return -fz;
}

Eigen::VectorXd support_reactions(const Supports& held, const Eigen::VectorXd& r) {
  Eigen::VectorXd out = r;
  for (int d = 0; d < r.size(); ++d)
    if (!held.support[d]) out[d] = 0;
  return out;
}

Eigen::Vector3d applied_force(const Supports& held, const Eigen::VectorXd& r, const Eigen::VectorXd& f) {
  Eigen::Vector3d a = Eigen::Vector3d::Zero();
  for (int d = 0; d < r.size(); ++d)
    if (!held.support[d]) a[d % 3] += f[d] + (held.fixed[d] ? r[d] : 0.0);
  return a;
}

Eigen::VectorXd patch_load(const TetMesh& mesh, const TractionPatch& patch) {
  // Face by face over the part of each top face inside the disc (projected on the base plane), so the load
  // is the consistent one of a uniform traction: a uniform pressure over a flat layer is then the hydrostatic
  // state's load exactly (issue 57: a rule over the disc whose points fell into whatever face held them read
  // 1.1 % high at a post 1 mm from a 20 mm patch's centre). Only the faces its edge cuts are refined; the
  // density is the force over the area found, so the total force is exact.
  const double a = 0.5 * patch.diameter;
  const Eigen::Vector2d centre(patch.center[0], patch.center[1]);
  const Eigen::Vector3d dir =
      Eigen::Vector3d(patch.direction[0], patch.direction[1], patch.direction[2]).normalized();
  Eigen::VectorXd F = Eigen::VectorXd::Zero(3 * mesh.num_nodes());
  double area = 0;
  for (int f = 0; f < mesh.faces.rows(); ++f) {
    if (mesh.face_marker(f) != kTop) continue;
    // Summed per face first: fewer round-offs in the total.
    Eigen::Matrix<double, 6, 1> w = Eigen::Matrix<double, 6, 1>::Zero();
    for (const FacePoint& q : face_quadrature_in_disc(mesh, f, centre, a, kPatchEdgeResolution * a))
      w += q.weight_xy * q.N;
    area += w.sum();
    for (int k = 0; k < 6; ++k) F.segment<3>(3 * mesh.faces(f, k)) += w[k] * dir;
  }
  // A half mesh y ≥ 0 carries half of a patch centred on its cut (the mirror image carries the rest).
  const double share = is_half_y(mesh) && centre.y() == 0 ? 0.5 : 1.0;
  if (!(area > 0.5 * share * M_PI * a * a))
    throw std::out_of_range("traction patch at (" + std::to_string(centre.x()) + ", " +
                            std::to_string(centre.y()) + ") is off the top surface");
  return (share * patch.force / area) * F;
}

}  // namespace skinfem
