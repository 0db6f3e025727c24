#include "skinfem/scene/texture.hpp"

#include <algorithm>
#include <cmath>

#include "skinfem/scene/random.hpp"

namespace skinfem {

int Scan::positions() const { return static_cast<int>(std::floor((to - from) / step + 1e-9)) + 1; }

bool holes_overlap(const Hole& a, const Hole& b) {
  return std::hypot(a.center[0] - b.center[0], a.center[1] - b.center[1]) < 0.5 * (a.diameter + b.diameter);
}

Hole hole_at(const Hole& plate, const Vec2& direction, double u) {
  Hole h = plate;
  h.center = {plate.center[0] + u * direction[0], plate.center[1] + u * direction[1]};
  return h;
}

TextureHoles texture_holes(const Texture& t) {
  TextureHoles out;
  out.holes = t.listed;
  if (const auto& l = t.lattice)
    for (int j = 0; j < l->ny; ++j)
      for (int i = 0; i < l->nx; ++i)
        out.holes.push_back(Hole{
            {l->origin[0] + i * l->period[0], l->origin[1] + j * l->period[1]}, l->diameter, 0, l->depth});
  if (const auto& r = t.random) {
    const double area = std::abs((r->to[0] - r->from[0]) * (r->to[1] - r->from[1]));
    const long wanted = r->mirror ? 2 * std::lround(0.5 * r->density * area) : std::lround(r->density * area);
    const double y_top = std::max(r->from[1], r->to[1]);
    SplitMix64 rng{r->seed};
    // Give up after 20,000 rejections in a row: the rectangle is full (each draw checks every hole placed,
    // so the bound keeps a hopeless density to about a second).
    long placed = 0, draws = 0, rejected = 0;
    while (placed < wanted && rejected < 20000) {
      ++draws;
      Hole h;
      h.center = {rng.uniform(r->from[0], r->to[0]),
                  r->mirror ? rng.uniform(0.0, y_top) : rng.uniform(r->from[1], r->to[1])};
      h.diameter = rng.uniform(r->diameter_min, r->diameter_max);
      h.depth = r->depth;
      Hole image = h;
      image.center[1] = -h.center[1];
      bool free = !r->mirror || !holes_overlap(h, image);
      for (const Hole& o : out.holes)
        free = free && !holes_overlap(h, o) && !(r->mirror && holes_overlap(image, o));
      if (!free) {
        ++rejected;
        continue;
      }
      rejected = 0;
      out.holes.push_back(h);
      ++placed;
      if (r->mirror) out.holes.push_back(image), ++placed;
    }
    if (placed < wanted)
      out.error = "placed " + std::to_string(placed) + " of its " + std::to_string(wanted) +
                  " holes without overlapping another in " + std::to_string(draws) + " draws";
  }
  return out;
}

std::vector<HoleTrack> hole_tracks(const std::vector<Hole>& holes, const Vec2& d, const Scan& scan,
                                   const Vec2& c, double reach) {
  std::vector<HoleTrack> out;
  for (const Hole& hole : holes) {
    const double r = reach + 0.5 * hole.diameter;
    const double along = (c[0] - hole.center[0]) * d[0] + (c[1] - hole.center[1]) * d[1];
    const double across = std::abs((c[0] - hole.center[0]) * d[1] - (c[1] - hole.center[1]) * d[0]);
    if (across >= r) continue;
    const double half = std::sqrt(r * r - across * across);
    const double u0 = std::max(scan.from, along - half), u1 = std::min(scan.to, along + half);
    if (u0 > u1) continue;
    const HoleTrack t{hole_at(hole, d, u0).center, hole_at(hole, d, u1).center, 0.5 * hole.diameter};
    const auto same = [&t](const HoleTrack& o) {
      return o.radius == t.radius && std::hypot(o.from[0] - t.from[0], o.from[1] - t.from[1]) +
                                             std::hypot(o.to[0] - t.to[0], o.to[1] - t.to[1]) <
                                         1e-9;
    };
    if (std::none_of(out.begin(), out.end(), same)) out.push_back(t);
  }
  return out;
}

}  // namespace skinfem
