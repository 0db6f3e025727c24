// Tractions on the bonded base from the reactions at its nodes (docs/theory.md §Base tractions):
// the nodal reactions R_i are spread into a P2 traction field t with the base's boundary mass
// matrix, ∫ t φ_i = R_i, so ∫ t dA = Σ R_i exactly balances the applied load.
// Sensor readings follow docs/theory.md §Conventions: σ_z = t_z (skin presses on the sensor), σ_x = −t_x
// (skin drags it toward +x), with t the traction the base exerts on the skin. Units: MPa, mm.
#pragma once

#include <Eigen/Dense>
#include <memory>
#include <optional>

#include "mesh/tet_mesh.hpp"

namespace skinfem {

struct SensorReading {
  double sigma_z = 0, sigma_x = 0;  // MPa
};

class BaseTraction {
 public:
  // reactions: 3N vector of nodal reactions (N), non-zero at base DOFs.
  BaseTraction(const TetMesh& mesh, const Eigen::VectorXd& reactions);
  ~BaseTraction();
  BaseTraction(BaseTraction&&) noexcept;

  // Traction the base exerts on the skin at (x, y, 0); nullopt outside the base.
  std::optional<Eigen::Vector3d> traction(double x, double y) const;
  SensorReading reading_at(double x, double y) const;  // point value (throws outside the base)
  // Mean over a disc of the given diameter (polar Gauss quadrature, 12 radii × 32 angles).
  SensorReading disc_mean(double x, double y, double diameter) const;
  // ∫ t dA over the whole base (N); equals the sum of the reactions.
  Eigen::Vector3d total_force() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Weights w (3N vector) such that the disc-mean reading component of the traction field built from
// reactions R is w·R (a linear functional: the adjoint load of reciprocity). component: 'z' or 'x';
// diameter 0 gives the point value at (x, y). The class factors the base mass matrix once for many
// sensors; the free function is the one-off form.
class ReadingFunctionals {
 public:
  explicit ReadingFunctionals(const TetMesh& mesh);  // keeps a reference to mesh
  explicit ReadingFunctionals(TetMesh&&) = delete;
  ~ReadingFunctionals();
  Eigen::VectorXd operator()(double x, double y, double diameter, char component) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

Eigen::VectorXd disc_reading_functional(const TetMesh& mesh, double x, double y, double diameter,
                                        char component);

}  // namespace skinfem
