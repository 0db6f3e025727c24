// A textured plate's holes (contact.texture, scene/scene.hpp) expanded from its patterns, and where they are
// at a scan position.
#pragma once

#include <string>
#include <vector>

#include "skinfem/scene/scene.hpp"

namespace skinfem {

// The texture's holes, or the reason they cannot be placed (the random holes do not fit at that density).
struct TextureHoles {
  std::vector<Hole> holes;
  std::string error;  // empty on success
};
TextureHoles texture_holes(const Texture& texture);

// Whether two discs overlap (closer than the sum of their radii).
bool holes_overlap(const Hole& a, const Hole& b);

// The hole `plate` at scan position u along the unit `direction`.
Hole hole_at(const Hole& plate, const Vec2& direction, double u);

// The part of a hole's track (its centre's segment over the scan) along which it comes within `reach` of
// `centre` (its centre within reach + its radius): what a zone of radius `reach` about `centre` sees of it.
struct HoleTrack {
  Vec2 from{0, 0}, to{0, 0};  // mm, the centre's segment
  double radius = 0;          // mm, the hole's
};
// One track per distinct segment and radius (a row's holes share one), holes that never come near left out.
std::vector<HoleTrack> hole_tracks(const std::vector<Hole>& holes, const Vec2& direction, const Scan& scan,
                                   const Vec2& centre, double reach);

}  // namespace skinfem
