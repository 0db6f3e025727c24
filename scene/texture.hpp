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

// A hole's shape: a disc, or a groove's rectangle (Hole::length > 0).
// Whether the point (x, y) (mm) lies inside the hole.
bool hole_contains(const Hole& h, double x, double y);
// The largest distance from the hole's centre to its rim (mm): a disc's radius, a groove's half diagonal.
double hole_radius(const Hole& h);
// The width of the plate between two holes' rims (mm), negative when they overlap. Grooves are taken
// parallel (a texture's are: all lie across the sliding direction).
double rim_gap(const Hole& a, const Hole& b);
// Whether two holes overlap (rim_gap < 0).
bool holes_overlap(const Hole& a, const Hole& b);
// "hole" or "groove", for messages.
const char* hole_word(const Hole& h);

// The hole `plate` at scan position u along the unit `direction`.
Hole hole_at(const Hole& plate, const Vec2& direction, double u);

// The part of a hole's track over the scan along which it overlaps the disc of radius `reach` about
// `centre`: what a zone of that radius sees of it, the region within `radius` of the segment from → to. A
// disc's track is its centre's segment and its radius; a groove's is the segment of its centre line's point
// nearest `centre` with a radius that holds the groove's part within the disc all along, or the disc itself
// (from = to = centre, radius = reach) when that is smaller.
struct HoleTrack {
  Vec2 from{0, 0}, to{0, 0};  // mm
  double radius = 0;          // mm
};
// One track per distinct segment and radius (a row's holes share one), holes that never come near left out.
std::vector<HoleTrack> hole_tracks(const std::vector<Hole>& holes, const Vec2& direction, const Scan& scan,
                                   const Vec2& centre, double reach);

}  // namespace skinfem
