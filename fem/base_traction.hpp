// Tractions on the bonded base from the reactions at its nodes (docs/theory.md §Base tractions):
// the nodal reactions R_i are spread into a P2 traction field t with the base's boundary mass
// matrix, ∫ t φ_i = R_i, so ∫ t dA = Σ R_i exactly balances the applied load.
// Sensor readings follow docs/theory.md §Conventions: σ_z = t_z (skin presses on the sensor), σ_x = −t_x
// (skin drags it toward +x), with t the traction the base exerts on the skin. Units: MPa, mm.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "skinfem/mesh/tet_mesh.hpp"

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
  SensorReading reading_at(double x, double y) const;  // the field's value there (throws outside the base)
  // A sensor's point value at (x, y) under a skin `thickness` thick: point_value_rule's limit of disc means,
  // what ReadingFunctionals reads for diameter 0.
  SensorReading point_value(double x, double y, double thickness) const;
  // Mean over a disc of the given diameter (polar Gauss quadrature, 12 radii × 32 angles).
  SensorReading disc_mean(double x, double y, double diameter) const;
  // ∫ t dA over the whole base (N); equals the sum of the reactions.
  Eigen::Vector3d total_force() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The quadrature (dx, dy, weight) of a sensor's point value as the limit of disc means, for a skin h thick:
// a smooth trace's disc mean of radius a is t(0) + ∇²t(0) a²/8 + O(a⁴), so t(0) = (a2² m(a1) − a1² m(a2)) /
// (a2² − a1²) + O(a1² a2²), with a1 = h/40, a2 = h/20 (green/meridian.cpp: the same on the meridian). The
// traction's own value at a point, an L2 projection's, converges more slowly than its means.
struct PointValueDiscs {
  double a1, w1, a2, w2;  // radii (mm) and weights: t(0) ≈ w1·m(a1) + w2·m(a2)
};
PointValueDiscs point_value_discs(double h);
std::vector<std::array<double, 3>> point_value_rule(double h);

// Weights w (3N vector) such that the disc-mean reading component of the traction field built from
// reactions R is w·R (a linear functional: the adjoint load of reciprocity). component: 'z' or 'x';
// diameter 0 gives the point value at (x, y) (point_value_rule, with the meshed skin's thickness there). The
// class factors the base mass matrix once for many sensors; the free function is the one-off form.
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
