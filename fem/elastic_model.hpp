// One skin ready for many loads: mesh + material + constraints (bonded base, optional fixed side,
// rigid punches) assembled and factored once. Loads are traction patches, nodal forces and
// punches driven by force or by displacement.
#pragma once

#include <memory>
#include <vector>

#include "skinfem/fem/assembly.hpp"
#include "skinfem/fem/base_traction.hpp"
#include "skinfem/fem/face_index.hpp"
#include "skinfem/fem/mixed_solver.hpp"
#include "skinfem/fem/supports.hpp"
#include "skinfem/scene/scene.hpp"

namespace skinfem {

struct ModelOptions {
  SolverKind solver = SolverKind::direct_ldlt;
  double tolerance = 1e-10;
  FactorProgress factor_progress;  // hears from a long factorization (fem/factor_progress.hpp); may be empty
  // Columns whose products the factorization gives at once (MixedSolver::Coupling); read during
  // construction only.
  const MixedSolver::Coupling* coupling = nullptr;
};

struct PunchResult {
  double force_N = 0;          // pressing force (positive when pushing into the skin)
  double displacement_mm = 0;  // indentation depth (positive downward)
};

struct LoadCaseResult {
  MixedSolution solution;
  Eigen::VectorXd reactions;  // 3N, at base (and side, if fixed) DOFs; punch reactions excluded
  std::vector<PunchResult> punches;
  double applied_force_N[3] = {0, 0, 0};  // total external force on the skin (punch + patches)
};

class ElasticModel {
 public:
  // punches: their nodes become constrained (u_z); pass the scene's punches (may be empty).
  // The model keeps a reference to mesh, which must outlive it (a temporary mesh does not compile).
  ElasticModel(const TetMesh& mesh, const Material& material, SideCondition side,
               const std::vector<Punch>& punches, ModelOptions options = {});
  ElasticModel(TetMesh&&, const Material&, SideCondition, const std::vector<Punch>&,
               ModelOptions = {}) = delete;
  // The incompressible neo-Hookean skin linearized about a deformed state: `tangent` is its tangent there
  // (fem/finite_strain.hpp's assemble_finite_strain at (u, p)), mu its shear modulus (MPa). Solves give the
  // increments of (u, p) for load increments: the sensitivity under that preload. No punches.
  ElasticModel(const TetMesh& mesh, MixedMatrices tangent, double mu, SideCondition side,
               ModelOptions options = {});
  ElasticModel(TetMesh&&, MixedMatrices, double, SideCondition, ModelOptions = {}) = delete;

  const TetMesh& mesh() const { return mesh_; }
  const MixedMatrices& matrices() const { return matrices_; }
  const MixedSolver& solver() const { return *solver_; }
  // MixedSolver::release_factorization: for a model whose solves are done.
  void release_factorization() { solver_->release_factorization(); }
  const Lame& lame() const { return lame_; }
  double assemble_seconds() const { return assemble_seconds_; }

  // Solve with an external load vector f (3N) plus the model's punches, each driven by its force or
  // displacement as given in `punches` (same order as at construction).
  LoadCaseResult solve(const Eigen::VectorXd& f, const std::vector<Punch>& punches) const;

  // fem/supports.hpp's patch_load on the model's mesh.
  Eigen::VectorXd patch_load(const TractionPatch& patch) const;
  // Load vector of a point force at the top-surface point above (x, y): f = N(x) F. Throws off the top.
  Eigen::VectorXd point_load(double x, double y, const Eigen::Vector3d& force) const;

  // Adds the point load above (x, y) to F, without allocating.
  void add_point_load(Eigen::VectorXd& F, double x, double y, const Eigen::Vector3d& force) const;

  // Base-constrained DOF flags (3N) and punch constraint groups.
  const std::vector<bool>& fixed() const { return held_.fixed; }
  const std::vector<std::vector<int>>& punch_groups() const { return held_.punch_nodes; }

 private:
  const TetMesh& mesh_;
  Lame lame_;
  MixedMatrices matrices_;
  Supports held_;
  std::unique_ptr<MixedSolver> solver_;
  std::unique_ptr<PlanarFaceIndex> top_index_;
  double assemble_seconds_ = 0;
};

}  // namespace skinfem
