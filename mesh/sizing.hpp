// Target edge length in the skin, from the scene's regions of interest.
//
// Inside a region the size is its h (default mesh.h_min). Elements then grow geometrically by the
// growth rate g from one to the next; summing h₀, h₀g, h₀g², … shows that after a distance d the
// element size is h₀ + (g − 1)·d. So size = min(h_max, min over regions of h_r + (g − 1)·dist(p, r)).
// Three kinds of region:
//  - through the thickness (mesh.regions, punches, traction patches; sensor discs of imported surfaces):
//    dist is the horizontal distance, the same at every z — a thin skin's Green maps need it at every depth;
//  - at the top (the contact zone, holes, the hole's path): dist also counts the depth below the top
//    surface, so the mesh coarsens towards the base. Contact needs its resolution where the pressure
//    acts; sensors read it through the layer, smoothed over ~h;
//  - at the base (each sensor disc at mesh.sensor_h): dist also counts the height above the base (above a
//    post's top: the whole post, up to its singular top rim, is meshed at sensor_h). A disc
//    reading is the mean traction over the disc, whose edge the reading's adjoint sees as a dislocation
//    edge. candelier2011's axis sensor, against the meridian solution: an h_min = 0.25 mm column over the
//    0.1 mm disc radius had 101k DOFs and disc-map errors 1.4–1.8e-3 of the peak; the disc at 0.1 mm on the
//    base with the column kept, 119k and 0.5–0.7e-3; the disc alone (this), 89k and 0.8–1.1e-3.
//  Imported surfaces have no exact top, so there top regions are extruded like the others.
#pragma once

#include <optional>
#include <vector>

#include "skinfem/mesh/shape.hpp"
#include "skinfem/mesh/tet_mesh.hpp"
#include "skinfem/scene/scene.hpp"

namespace skinfem {

// mesh.sensor_h, or its default min(h_min, disc radius) (h_min for point sensors), mm.
double sensor_mesh_size(const Scene& scene);

// The scene with every mesh size scaled by s: h_min, h_max, the sensor discs, regions, the contact zone,
// holes and the hole path, and the grading growth − 1 (at distance d the target is h + (g − 1)d, so the
// grading scales too). Every study's levels are this one family (`study`, `study --chain`, the
// report's error bars). cap_holes: the mesh over each hole at most its diameter, for a coarse level whose
// hole the scaled mesh cannot see.
Scene scaled_scene(const Scene& base, double s, bool cap_holes = false);

class SizingField {
 public:
  // Through regions: mesh.regions, every punch and traction patch. Top regions, with a contact: the candidate
  // zone (disc of radius contact_zone_radius about contact_center) of size contact_zone_h, every hole disc of
  // its own h (default contact_zone_h); the sweep path (every point within hole_diameter/2 + sweep.h of the
  // segment from → to) of size sweep.h, if sweep.h > 0; and then every sensor disc becomes a through region
  // of size contact_zone_h (at most). Base regions (if mesh.refine_sensors): the sensor discs at
  // sensor_mesh_size; on imported surfaces, through regions of size h_min instead.
  // part half_y: the field of the whole skin seen on the half y >= 0, every region mirrored into it (a
  // region at y < 0 refines the half where its mirror image lies), so the mirrored half has the whole's
  // refinement on both sides.
  explicit SizingField(const Scene& scene, MeshPart part = MeshPart::whole);
  double operator()(double x, double y) const { return at(x, y, 0.0); }  // on the top surface, mm
  double on_base(double x, double y) const;                              // on the base z = 0, mm
  double in_volume(double x, double y, double z) const;                  // at a point of the skin, mm
  // in_volume(x, y, z[k]) for k < n into out[k], bit for bit, with the horizontal distances computed once
  // for the column: the mesh size estimate samples each column at 24 depths.
  void in_column(double x, double y, const double* z, int n, double* out) const;
  double h_max() const { return h_max_; }
  bool graded_in_depth() const { return shape_.has_value() && (!top_.empty() || !base_.empty()); }

 private:
  double at(double x, double y, double depth) const;  // depth below the top surface, mm
  std::vector<RegionOfInterest> through_, top_, base_;
  double growth_, h_max_;
  double post_height_ = 0;          // mm: base regions of post sensors count the height above the posts' tops
  std::optional<SkinShape> shape_;  // generated skins only
};

}  // namespace skinfem
