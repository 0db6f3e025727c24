// Shared fixtures for the fem suites: box meshes and a closed-form elastic field.
#pragma once

#include <cmath>
#include <vector>

#include "skinfem/fem/assembly.hpp"
#include "skinfem/mesh/build.hpp"

namespace skinfem::testing {

// Flat layer [−w, w]² × [0, h] meshed with a uniform target size.
inline TetMesh box_mesh(double h, double w, double size) {
  Scene s;
  s.geometry.kind = GeometryKind::flat;
  s.geometry.flat = {h, w};
  s.mesh.refine_sensors = false;
  s.mesh.h_min = s.mesh.h_max = size;
  return build_mesh(s);
}

// u = Σ A_m sin(k_m·x + φ_m), p given: a smooth field with closed-form derivatives.
// Equilibrium needs the body force f = −μ(Δu + ∇ div u) + ∇p.
struct PlaneWaves {
  std::vector<Eigen::Vector3d> A, k;
  std::vector<double> phase;
  // Pressure: p = P cos(q·x) when incompressible, else −λ div u.
  double P = 0;
  Eigen::Vector3d q = Eigen::Vector3d::Zero();
  double mu = 1, inv_lambda = 0;

  Eigen::Vector3d u(const Eigen::Vector3d& x) const {
    Eigen::Vector3d r = Eigen::Vector3d::Zero();
    for (size_t m = 0; m < A.size(); ++m) r += A[m] * std::sin(k[m].dot(x) + phase[m]);
    return r;
  }
  Eigen::Matrix3d grad_u(const Eigen::Vector3d& x) const {  // ∂u_i/∂x_j
    Eigen::Matrix3d g = Eigen::Matrix3d::Zero();
    for (size_t m = 0; m < A.size(); ++m) g += A[m] * k[m].transpose() * std::cos(k[m].dot(x) + phase[m]);
    return g;
  }
  double div_u(const Eigen::Vector3d& x) const { return grad_u(x).trace(); }
  double p(const Eigen::Vector3d& x) const {
    return inv_lambda == 0 ? P * std::cos(q.dot(x)) : -div_u(x) / inv_lambda;
  }
  Eigen::Vector3d grad_p(const Eigen::Vector3d& x) const {
    if (inv_lambda == 0) return -P * q * std::sin(q.dot(x));
    Eigen::Vector3d g = Eigen::Vector3d::Zero();  // −λ ∇ div u = λ Σ (A·k) k sin(·)
    for (size_t m = 0; m < A.size(); ++m) g += A[m].dot(k[m]) * k[m] * std::sin(k[m].dot(x) + phase[m]);
    return g / inv_lambda;
  }
  Eigen::Matrix3d sigma(const Eigen::Vector3d& x) const {
    const Eigen::Matrix3d g = grad_u(x);
    return mu * (g + g.transpose()) - p(x) * Eigen::Matrix3d::Identity();
  }
  Eigen::Vector3d body_force(const Eigen::Vector3d& x) const {
    Eigen::Vector3d lap = Eigen::Vector3d::Zero(), grad_div = Eigen::Vector3d::Zero();
    for (size_t m = 0; m < A.size(); ++m) {
      const double s = std::sin(k[m].dot(x) + phase[m]);
      lap -= k[m].squaredNorm() * A[m] * s;
      grad_div -= A[m].dot(k[m]) * k[m] * s;
    }
    return -mu * (lap + grad_div) + grad_p(x);
  }
};

}  // namespace skinfem::testing
