// What a contact solve says about the contact: its size, peak pressures and how sliding moves them.
#pragma once

#include "skinfem/contact/contact_solver.hpp"
#include "skinfem/fem/face_index.hpp"

namespace skinfem::contact {

struct ContactMetrics {
  // Sub-element contact radius: p² fitted by α + βr² + γr⁴ over the active vertices in the outer 40 % of
  // the contact (r about the pressure centroid), then its root; exact for Hertz (p² ∝ a² − r²) and
  // following the square-root vanishing of any smooth contact at its edge. Through an exponential interface
  // (no edge, a tail) the fit covers λ ≥ 5 % of the peak: the loaded part's hard-contact edge.
  double contact_radius_mm = 0;
  // sqrt(A/π), A = Σ ∫ψ_i over the vertices inside the outer boundary (active, or inactive but enclosed:
  // holes and their lifted rims): a mesh-resolution estimate of the same radius.
  double equivalent_radius_mm = 0;
  double p0_MPa = 0;        // pressure at the first-touch point (P1 interpolation); 0 when p0_in_hole
  bool p0_in_hole = false;  // the first-touch point lies in a hole: the indenter is absent there
  double p_max_MPa = 0;
  Vec2 pressure_centroid{0, 0};  // ∫p x dA / ∫p dA, mm
  Vec2 zone_centroid{0, 0};      // centroid of the active vertices' hats, mm
  double front_back_peak_ratio =
      1;  // max p ahead of the first-touch point (along the sliding direction) / max p behind
  double front_edge_mm = 0,
         back_edge_mm = 0;  // farthest active vertex ahead / behind along the sliding direction
};

// mesh, top: the mesh of solver.zone() (the whole one under a mirror view). holes: where the indenter is
// absent (r solved with them). With holes the contact radius is the outer boundary's (the boundary between
// the contact and the inactive vertices connected to the zone's rim, so that a hole's own rim, lifted or
// not, is never taken for the edge): the edge fit is made about the centroid of the area that boundary
// encloses and leaves out the vertices within a hole diameter of a hole's centre, whose pressure the rim
// reloads.
ContactMetrics contact_metrics(const ContactSolver& solver, const TetMesh& mesh, const PlanarFaceIndex& top,
                               const ContactResult& r, const Vec2& center,
                               const std::vector<Hole>& holes = {});

// The edge of a contact from its outer pressures p (MPa) at radii (mm) about its centre: p^q (q = 2 for a
// hard contact's √(a − r) edge, 1 through a linear interface) fitted by α + βr² + γr⁴ over r ≥ 0.6 max r,
// the fit's root nearest the last radius, and the fit's rms residual in p. radius 0: fewer than 6 such
// points or no positive root.
struct EdgeFit {
  double radius = 0, rms = 0;
};
EdgeFit edge_fit(const std::vector<double>& radii, const std::vector<double>& p, int q);
// edge_fit's radius at q = 2, or `fallback`.
double edge_fit_radius(const std::vector<double>& radii, const std::vector<double>& p, double fallback);

}  // namespace skinfem::contact
