// Target edge length over the (x, y) plane, from the scene's regions of interest.
//
// Inside a region the size is its h (default mesh.h_min). Elements then grow geometrically by the
// growth rate g from one to the next; summing h₀, h₀g, h₀g², … shows that after a distance d the
// element size is h₀ + (g − 1)·d. So size(p) = min(h_max, min over regions of h_r + (g − 1)·dist(p, r)).
// Regions are extruded through the thickness: thin skins need the same size at every z.
#pragma once

#include <vector>

#include "scene/scene.hpp"

namespace skinfem {

class SizingField {
 public:
  // Regions: mesh.regions, the sensor discs (if mesh.refine_sensors), every punch and traction patch, and
  // with a contact: the candidate zone (disc of radius contact_zone_radius about contact_center) and every
  // hole disc, both of size contact_zone_h; the sweep path (every point within hole_diameter/2 + sweep.h of
  // the segment from → to) of size sweep.h, if sweep.h > 0.
  explicit SizingField(const Scene& scene);
  double operator()(double x, double y) const;  // mm
  double h_max() const { return h_max_; }

 private:
  std::vector<RegionOfInterest> regions_;
  double growth_, h_max_;
};

}  // namespace skinfem
