// Contact of a rigid indenter centred on the axis of a body of revolution (a flat layer, a spherical cap
// about its apex), solved on the skin's meridian: the 3D contact (contact/condensed.hpp, contact/lcp.hpp)
// restricted to what the scene needs.
//
// Frictionless, the pressure, the gaps and the zone are axisymmetric: mode 0 (green/meridian.hpp). The
// multipliers are the nodal pressures λ_i of hats ψ_i(r) at the top's vertices (linear in each top edge's
// parameter, as contact/mortar.hpp's are in a face's), integrals over the projection on the base plane,
// dA = 2πr dr; the compliance C_ij = −∫ψ_i u_z of multiplier j's pressure comes from one mode-0 solve per
// multiplier, and the complementarity problem is contact/lcp.hpp's, exact. The uncoupled mode (the paper's
// assumption) adds p_t = μ p along +x after the pressure is solved: a mode-1 load, one more solve. Both are
// exact restrictions of the 3D problem. The static and coupled modes are not: the tangential traction's
// normal displacement varies as cos θ, so their contact zone is not a disc and their pressure not a mode-0
// field; they need the 3D path.
//
// Readings: each sensor's disc mean of the forward solution's base traction (fem/base_traction.hpp in 3D),
// t = t0(ρ) + t1(ρ, θ) from the modes' base traces, for sensors anywhere on the base.
//
// The contact edge. The pressure vanishes like √(a − r), which hats of size c resolve only to about √(c/a)
// of p0 at the edge. So the solve runs twice: on radial cells of `zone_cell` across the zone, then, with the
// edge a₁ found by the first (metrics.hpp's edge fit), on cells graded down to `edge_cell` at a₁. Units: mm,
// N, MPa.
#pragma once

#include <Eigen/Dense>
#include <functional>
#include <stdexcept>
#include <vector>

#include "skinfem/fem/sensor_reading.hpp"
#include "skinfem/green/meridian.hpp"

namespace skinfem::contact {

struct MeridianContactSkin {
  std::function<double(double)> top;  // z of the skin's top at radius r
  double radius = 0;                  // the meridian's extent
  double h = 0;                       // thickness on the axis
  SideCondition side = SideCondition::free;
  double E = 0, nu = 0.5;  // MPa, –
  // MPa/mm; > 0: a linear interface in series (scene.hpp, InterfaceLaw::linear), its closure p/K adding
  // λ_i ∫ψ_i / K to every weighted gap (C + diag(area/K), as contact/contact_solver.hpp); 0: hard.
  double interface_K = 0;
};

// Radial cells: zone_cell across the zone, edge_cell at the contact edge (second pass), growing by `growth`
// per cell away from it and beyond the zone up to max_cell. Across the thickness: top_cell at the top (the
// edge's field varies as fast across as along), base_cell at the base (the readings), growing by `growth`
// up to layer_cell. mm.
struct MeridianContactSizes {
  double zone_cell = 0, edge_cell = 0, growth = 1.1, max_cell = 0;
  double top_cell = 0, base_cell = 0, layer_cell = 0;
  // For a zone of radius R on a skin of thickness h: zone_cell R/30, edge_cell R/30000, top_cell R/1100,
  // growth 1.2, max_cell 4h/3, base_cell h/36, layer_cell h/12 (tests/contact/test_meridian_contact.cpp:
  // the exact layer's a, p0, δ within 5e-4 and its pressure within 1 % of p0 on scenes/hertz_layer.json);
  // `scale` > 1 multiplies every size by it and the growth's excess by it.
  static MeridianContactSizes for_zone(double zone_radius, double h, double scale = 1);
};

struct MeridianContactResult {
  std::vector<double> r;         // n_c multiplier radii, mm
  Eigen::VectorXd lambda;        // n_c nodal pressures, MPa
  Eigen::VectorXd gap;           // n_c weighted gaps ∫ψ_i gap dA, mm³
  double depth_mm = 0;           // rigid approach from first touch
  double force_N = 0;            // ∫ p dA
  double contact_radius_mm = 0;  // the edge fit (metrics.hpp)
  double p0_MPa = 0;             // λ on the axis
  Eigen::VectorXd readings;      // 2·sensors, MPa: σ_z of sensor k at 2k, σ_x at 2k + 1, frictionless
  // The same for the traction p_t = p along the sliding direction alone (ratio 1; empty when not asked): the
  // uncoupled mode's readings at ratio μ are readings + μ·readings_per_ratio.
  Eigen::VectorXd readings_per_ratio;
  double complementarity = 0, min_lambda = 0, min_gap = 0;
  int pivots = 0;
  // The pressure at radius r (mm) as the multipliers' hats carry it: linear between neighbouring r_i, 0
  // beyond the last; MPa.
  double pressure_at(double r) const;
  int dofs = 0;         // mode 0's free unknowns (mode 1's added with a sliding direction)
  int multipliers = 0;  // the second pass's
  struct Cost {
    double mesh_s = 0, assemble_s = 0, factor_s = 0, condense_s = 0, lcp_s = 0, readings_s = 0;
  } cost;  // both passes
};

// The contact reaches the zone's outermost multiplier: the zone may be cutting it short.
struct ZoneTooSmall : std::runtime_error {
  explicit ZoneTooSmall(double last_multiplier_mm);
  double last_multiplier_mm;
};

// The indenter pressed with force_N > 0 (force control) or, when force_N is 0, to depth_mm > 0 (depth
// control). direction: the sliding direction in the base plane for readings_per_ratio, or zero (none).
struct MeridianContactLoad {
  double force_N = 0, depth_mm = 0;
  Eigen::Vector2d direction{0, 0};
};

// gap0(r): the indenter's height above the undeformed top at radius r before loading (≥ 0, 0 at first touch
// on the axis). sites: disc sensors (posts are refused: std::invalid_argument), centres relative to the
// axis. zone_radius: the multipliers' extent (the side's vertex never carries one). Throws ZoneTooSmall, and
// what contact/lcp.hpp throws.
MeridianContactResult meridian_contact(const MeridianContactSkin& skin, double zone_radius,
                                       const std::function<double(double)>& gap0,
                                       const MeridianContactLoad& load, const std::vector<ReadingSite>& sites,
                                       const MeridianContactSizes& sizes);

}  // namespace skinfem::contact
