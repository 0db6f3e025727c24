// The paper's linear model of the sensor (§III eq. (1), §IV eqs. (2)–(3)), each ingredient swappable:
//   σ_b(x_i) = ∬ [p_z(x) g_zb(x − x_i) + p_x(x) g_xb(x − x_i)] dx dy,                      b ∈ {z, x}
//   ς_b(u)  ≈ −[p_x(u) g_xb(u − x_i) + p_z(u) g_zb(u − x_i)] S_d        (first-order hole of area S_d)
// Pressure: half-space Hertz, the exact bonded layer (contact/layer_hertz.hpp) or FE contact; friction:
// p_x = ratio·p_z (none, static c, μ uncoupled, or the FE's coupled pressure with μ), plus a shear strength
// where the skin touches (contact::FrictionLaw); Green tensor: the
// half-space rescaled by any k, the exact layer, or the FE reciprocity maps of each sensor.
//
// Conventions, the same everywhere in skinfem (green/halfspace.hpp): g_ab(offset) is reading b of a sensor
// for a unit force along a applied at offset = force position − sensor position; a force "along z" presses
// into the skin; p_z > 0 presses, p_x > 0 drags the skin toward +x; σ_z > 0 when the skin presses on the
// sensor, σ_x > 0 when it drags the sensor toward +x. Readings vectors hold sensor k's σ_z at 2k and σ_x at
// 2k + 1 (MPa), as contact::ContactResult::readings. Units: mm, N, MPa.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <functional>
#include <vector>

#include "skinfem/contact/condensed.hpp"
#include "skinfem/contact/layer_hertz.hpp"
#include "skinfem/green/fe_green.hpp"
#include "skinfem/green/layer_exact.hpp"

namespace skinfem::validation {

// g_ab of sensor `sensor` for a unit point force at offset (ox, oy), 1/mm².
using GreenKernel = std::function<green::GreenSample(int sensor, double ox, double oy)>;

// the rescaled (docs/theory.md §Conventions) half-space, k·g_half(√k offset) at the depth of each sensor
// (thickness[sensor], mm).
GreenKernel rescaled_halfspace_kernel(std::vector<double> thickness, double k);
// The exact bonded layer (point values at the base), the same for every sensor; tabulated along the two
// axes every `step` mm out to `reach` and interpolated linearly (relative error ≲ (step/h)²/8).
GreenKernel layer_exact_kernel(double h, double nu, double reach, double step = 0.01);
// The FE Green maps (reciprocity): the sensor-disc mean reading for a point force on the skin's top.
GreenKernel fe_kernel(const green::FeGreen& fe);

// Interfacial tractions: pressure p_z and p_x = ratio·p_z + shear (a shear strength where the pressure
// acts), as pointwise functions and as quadrature points (x, y, weight·p_z, weight·p_x) covering the
// contact, weights in mm² (projection on the (x, y) plane).
struct Tractions {
  std::function<double(double, double)> pressure;    // p_z, MPa
  std::function<double(double, double)> tangential;  // p_x, MPa
  std::vector<std::array<double, 4>> points;
  double force() const;  // Σ weight·p_z, N
};

// An axisymmetric pressure p(r) on the disc r < a about `center`: polar Gauss rule with r = a sin θ (exact
// for the square-root edge of Hertz-like pressures), n_theta × n_phi points.
// shear: MPa, uniform on the disc.
Tractions axisymmetric_tractions(std::function<double(double)> p_of_r, const Vec2& center, double a,
                                 double ratio, double shear = 0, int n_theta = 48, int n_phi = 96);
// The two analytic pressures of a sphere on the skin as tractions (friction as above): half-space Hertz,
// p0 √(1 − r²/a²), and the exact bonded layer's (contact/layer_hertz.hpp).
Tractions hertz_tractions(const contact::HertzHalfspace& hertz, const Vec2& center, double ratio,
                          double shear = 0);
Tractions layer_hertz_tractions(const contact::LayerHertzResult& layer, const Vec2& center, double ratio,
                                double shear = 0);
// The FE contact pressure Σ λ_i ψ_i on the mortar zone (contact/mortar.hpp) and its traction
// ratio·p + Σ shear_i ψ_i (shear: empty or nodal, contact::ContactResult::shear), 7 points per top face.
Tractions fe_tractions(const contact::MortarZone& zone, const TetMesh& mesh, const Eigen::VectorXd& lambda,
                       double ratio, const Eigen::VectorXd& shear = {});

// σ_z and σ_x of every sensor (2·sensors, MPa) by the convolution of eq. (1).
Eigen::VectorXd convolve(const Tractions& t, const GreenKernel& g, const Sensors& sensors);

// convolve(fe_tractions(zone, mesh, λ, ratio, shear), g, sensors) for many λ on one zone (a hole sweep's
// frames): the kernel evaluated once at the zone's quadrature points, then the same sums in the same order,
// so the same numbers to the last bit. zone and mesh must outlive it.
class FeConvolution {
 public:
  FeConvolution(const contact::MortarZone& zone, const TetMesh& mesh, const GreenKernel& g,
                const Sensors& sensors);
  Eigen::VectorXd operator()(const Eigen::VectorXd& lambda, double ratio,
                             const Eigen::VectorXd& shear = {}) const;

 private:
  struct Point {
    int face;
    double s, t, weight_xy;
  };
  const contact::MortarZone& zone_;
  const TetMesh& mesh_;
  int sensors_ = 0;
  std::vector<Point> points_;          // fe_tractions's, in its order
  std::vector<green::GreenSample> g_;  // sensors × points, sensor-major
};
// ς of every sensor for the hole centred at each of `centers` (positions × 2·sensors, MPa), eqs. (2)–(3).
Eigen::MatrixXd first_order_hole(const Tractions& t, const GreenKernel& g, const Sensors& sensors,
                                 const std::vector<Vec2>& centers, double hole_area);

}  // namespace skinfem::validation
