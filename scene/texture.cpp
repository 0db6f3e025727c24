#include "skinfem/scene/texture.hpp"

#include <algorithm>
#include <cmath>

#include "skinfem/scene/random.hpp"

namespace skinfem {

int Scan::positions() const { return static_cast<int>(std::floor((to - from) / step + 1e-9)) + 1; }

namespace {
// p − h's centre in the groove's frame: along its width (the sliding direction), along its length.
std::pair<double, double> groove_frame(const Hole& h, double x, double y) {
  const double dx = x - h.center[0], dy = y - h.center[1];
  return {dx * h.across[1] - dy * h.across[0], dx * h.across[0] + dy * h.across[1]};
}

}  // namespace

bool hole_contains(const Hole& h, double x, double y) {
  if (!h.groove()) return std::hypot(x - h.center[0], y - h.center[1]) < 0.5 * h.diameter;
  const auto [s, t] = groove_frame(h, x, y);
  return std::abs(s) < 0.5 * h.diameter && std::abs(t) < 0.5 * h.length;
}

double hole_radius(const Hole& h) {
  return h.groove() ? 0.5 * std::hypot(h.diameter, h.length) : 0.5 * h.diameter;
}

double rim_gap(const Hole& a, const Hole& b) {
  if (!a.groove() && !b.groove())
    return std::hypot(a.center[0] - b.center[0], a.center[1] - b.center[1]) - 0.5 * (a.diameter + b.diameter);
  if (!a.groove()) return rim_gap(b, a);
  if (!b.groove()) {
    const auto [s, t] = groove_frame(a, b.center[0], b.center[1]);
    const double ds = std::abs(s) - 0.5 * a.diameter, dt = std::abs(t) - 0.5 * a.length;
    // Outside the rectangle: its distance less the radius; inside: the depth to the nearest side, negative.
    return (ds > 0 || dt > 0 ? std::hypot(std::max(0.0, ds), std::max(0.0, dt)) : std::max(ds, dt)) -
           0.5 * b.diameter;
  }
  const auto [s, t] = groove_frame(a, b.center[0], b.center[1]);
  const double ds = std::abs(s) - 0.5 * (a.diameter + b.diameter),
               dt = std::abs(t) - 0.5 * (a.length + b.length);
  return ds > 0 || dt > 0 ? std::hypot(std::max(0.0, ds), std::max(0.0, dt)) : std::max(ds, dt);
}

bool holes_overlap(const Hole& a, const Hole& b) { return rim_gap(a, b) < 0; }

const char* hole_word(const Hole& h) { return h.groove() ? "groove" : "hole"; }

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
  if (const auto& g = t.grooves) {
    // Across the sliding direction d: their length along d's normal (−d_y, d_x).
    const Vec2& d = g->direction;
    const Vec2 across{-d[1], d[0]};
    for (int i = 0; i < g->count; ++i) {
      Hole h{
          {g->origin[0] + i * g->period * d[0], g->origin[1] + i * g->period * d[1]}, g->width, 0, g->depth};
      h.length = g->length;
      h.across = across;
      out.holes.push_back(h);
    }
  }
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
    // u = along puts the hole's centre (a groove's centre line) nearest c.
    const double along = (c[0] - hole.center[0]) * d[0] + (c[1] - hole.center[1]) * d[1];
    double half = 0, radius = 0;
    Vec2 start = hole.center;
    if (!hole.groove()) {
      const double r = reach + 0.5 * hole.diameter;
      const double across = std::abs((c[0] - hole.center[0]) * d[1] - (c[1] - hole.center[1]) * d[0]);
      if (across >= r) continue;
      half = std::sqrt(r * r - across * across), radius = 0.5 * hole.diameter;
    } else {
      // The groove's point along its length nearest c, q, e from it: the groove meets the disc while its
      // centre line is within the disc's chord at e plus half its width. Its part within the disc lies
      // within min(reach, length) of q along its length and half its width across.
      const double s = (c[0] - hole.center[0]) * hole.across[0] + (c[1] - hole.center[1]) * hole.across[1];
      const double q = std::clamp(s, -0.5 * hole.length, 0.5 * hole.length), e = std::abs(s - q);
      if (e >= reach) continue;
      half = 0.5 * hole.diameter + std::sqrt(reach * reach - e * e);
      radius = std::hypot(0.5 * hole.diameter, std::min(reach, hole.length));
      start = {hole.center[0] + q * hole.across[0], hole.center[1] + q * hole.across[1]};
    }
    const double u0 = std::max(scan.from, along - half), u1 = std::min(scan.to, along + half);
    if (u0 > u1) continue;
    HoleTrack t{
        {start[0] + u0 * d[0], start[1] + u0 * d[1]}, {start[0] + u1 * d[0], start[1] + u1 * d[1]}, radius};
    // A long groove sweeps the whole disc: the disc itself is then the smaller region to watch and refine.
    if (hole.groove() && M_PI * reach * reach < (2 * (u1 - u0) + M_PI * radius) * radius) t = {c, c, reach};
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
