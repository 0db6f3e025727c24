// Finite-element Green tensors of any scene by reciprocity (Maxwell–Betti; docs/theory.md §Reciprocity).
//
// A sensor reading is a linear functional J = w·R of the base reactions R. With the base held, the
// reactions are R = K_bF x_F for the free unknowns x_F = K_FF⁻¹ f_F, so J = y·f with
// y = K_FF⁻¹ K_Fb w: the displacement field obtained by imposing the base displacement −w under no load.
// One such adjoint solve per sensor and reading component gives that sensor's response to a unit force
// anywhere on the top surface: g_ab(X − sensor) = ±y_a(X). Loads spread over a disc integrate y
// against their traction profile.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "skinfem/fem/elastic_model.hpp"
#include "skinfem/fem/face_index.hpp"
#include "skinfem/green/halfspace.hpp"
#include "skinfem/green/layer_exact.hpp"

namespace skinfem::green {

// Quadrature of a unit load spread over a disc of radius a with the profile of LayerLoad:
// point (a ignored), punch (rigid-punch half-space profile 1/(2πa√(a² − r²)), also for the bonded
// tangential punch, Johnson §7.1) or uniform (1/(πa²)). Points (dx, dy, weight), weights sum to 1.
// nr × nt points (radial Gauss × uniform angles).
std::vector<std::array<double, 3>> load_quadrature(LayerLoad load, double radius, int nr = 12, int nt = 32);
// The default rule, computed once per thread while (load, radius) repeat: scans ask for it at every offset.
const std::vector<std::array<double, 3>>& load_rule(LayerLoad load, double radius);

class FeGreen {
 public:
  // One adjoint solve per sensor, reading component (z, x) and reading kind (point value at the
  // sensor centre, mean over its disc): 4 per sensor on the model's factorization, all in one block solve.
  // The model must carry no punch constraints.
  // Keeps a reference to model, which must outlive it (a temporary model does not compile).
  FeGreen(const ElasticModel& model, const Sensors& sensors,
          const std::function<void(const std::string&)>& progress = {});
  FeGreen(ElasticModel&&, const Sensors&, const std::function<void(const std::string&)>& = {}) = delete;

  // g_ab (1/mm²) of sensor `sensor` for a unit load centred at offset (ox, oy) from it, spread as
  // `load` over radius `radius`. disc: the sensor's disc mean, else its centre value.
  GreenSample at(int sensor, bool disc, double ox, double oy, LayerLoad load, double radius) const;
  // The disc reading of `sensor` for a unit point force at the top point above (x, y) (mm, absolute); false,
  // g untouched, when no top face lies above (x, y).
  bool disc_map_at(int sensor, double x, double y, GreenSample& g) const;

  // The adjoint displacement (3N) of sensor, reading component b ∈ {'z','x'}, point/disc: top-surface
  // nodal values give the point-load Green map there.
  const Eigen::VectorXd& adjoint(int sensor, char reading, bool disc) const;
  int adjoint_solves() const { return static_cast<int>(adjoint_.size()); }
  // The block solve's checked relative residual (fem/mixed_solver.hpp, solve_block).
  double max_adjoint_residual() const { return max_residual_; }

 private:
  Eigen::Vector3d displacement_at_top(const Eigen::VectorXd& y, double x, double yy) const;
  const ElasticModel& model_;
  Sensors sensors_;
  PlanarFaceIndex top_;
  std::vector<Eigen::VectorXd> adjoint_;  // index 4·sensor + 2·disc + (reading == 'x')
  double max_residual_ = 0;
};

}  // namespace skinfem::green
