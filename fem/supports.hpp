// How the skin is held and loaded, apart from any law: the bonded base (and a fixed side), a half mesh's
// mirror plane, rigid flat punches, and the load vector of a traction patch. The linear model
// (fem/elastic_model.hpp) and the finite-strain solve (fem/newton.hpp) share them.
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "skinfem/mesh/tet_mesh.hpp"
#include "skinfem/scene/scene.hpp"

namespace skinfem {

struct Supports {
  std::vector<bool> fixed;    // 3N: every prescribed DOF (supports, mirror plane, punches' u_z)
  std::vector<bool> support;  // 3N: the base's and a fixed side's DOFs, whose reactions are reported
  std::vector<std::vector<int>> punch_nodes;  // per punch, the nodes it holds (punch_nodes below)
};

// The nodes a rigid flat punch holds: top corner nodes with (x, y) within its radius and the mid-edge
// nodes between them (the mesh follows the punch circle, so this is the inscribed polygon).
// The punch is frictionless: it prescribes u_z only (at ν = 0.5 a half-space does not couple normal
// and tangential contact, so friction would not change its pressure; see docs/theory.md §References).
std::vector<int> punch_nodes(const TetMesh& mesh, const Punch& punch);

// A half mesh's cut y = 0 holds u_y (the mirror-symmetric solution), with no reaction reported.
Supports skin_supports(const TetMesh& mesh, SideCondition side, const std::vector<Punch>& punches);

// From a solution's r (3N: internal force − f at the held DOFs, the force the skin puts on what holds it;
// free DOFs ignored) and its load f (3N), for either law:
// a punch's pressing force, −Σ r_z over its nodes (N; the skin pushes the punch up);
double punch_force(const std::vector<int>& punch_nodes, const Eigen::VectorXd& r);
// the supports' reactions alone (3N, zero elsewhere: the base's, which the sensors read);
Eigen::VectorXd support_reactions(const Supports& held, const Eigen::VectorXd& r);
// the external force on the skin (N): f but at supports, which take it, plus r at the other held DOFs
// (punches, a mirror plane): a load on a punch's node is part of what the punch holds.
Eigen::Vector3d applied_force(const Supports& held, const Eigen::VectorXd& r, const Eigen::VectorXd& f);

// Where a traction patch's edge cuts top faces, they are split down to pieces of this fraction of its radius.
inline constexpr double kPatchEdgeResolution = 1e-3;

// Load vector (3N, N) of a uniform traction patch on the top surface: total force `force` along `direction`,
// spread evenly over the disc (per unit area of its projection on the base plane), integrated face by face
// (mesh/surface_quadrature.hpp, face_quadrature_in_disc). A dead load: it keeps its direction and its
// reference area as the skin deforms. On a half mesh y ≥ 0 a patch centred on y = 0 gives half its force
// (the half's share of a symmetric load). Throws std::out_of_range when the disc is off the top surface.
Eigen::VectorXd patch_load(const TetMesh& mesh, const TractionPatch& patch);

}  // namespace skinfem
