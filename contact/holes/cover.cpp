#include "skinfem/contact/holes/cover.hpp"

#include <algorithm>
#include <cmath>

#include "skinfem/scene/texture.hpp"

namespace skinfem::contact {

namespace {

using Poly = std::vector<Eigen::Vector2d>;

// Sutherland–Hodgman: the part of `poly` on the left of the directed edge a → b.
Poly clip(const Poly& poly, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const auto side = [&](const Eigen::Vector2d& p) {
    return (b.x() - a.x()) * (p.y() - a.y()) - (b.y() - a.y()) * (p.x() - a.x());
  };
  Poly out;
  for (size_t i = 0; i < poly.size(); ++i) {
    const Eigen::Vector2d& p = poly[i];
    const Eigen::Vector2d& q = poly[(i + 1) % poly.size()];
    const double sp = side(p), sq = side(q);
    if (sp >= 0) out.push_back(p);
    if ((sp >= 0) != (sq >= 0)) out.push_back(p + (q - p) * (sp / (sp - sq)));
  }
  return out;
}

// Area and centroid of a simple polygon (counter-clockwise).
double area_centroid(const Poly& poly, Eigen::Vector2d& centroid) {
  double a = 0;
  Eigen::Vector2d c = Eigen::Vector2d::Zero();
  for (size_t i = 0; i < poly.size(); ++i) {
    const Eigen::Vector2d& p = poly[i];
    const Eigen::Vector2d& q = poly[(i + 1) % poly.size()];
    const double cross = p.x() * q.y() - q.x() * p.y();
    a += cross;
    c += (p + q) * cross;
  }
  if (a != 0) centroid = c / (3 * a);
  return a / 2;
}

}  // namespace

std::vector<Eigen::Vector2d> hole_in_triangle(const Hole& h, const Eigen::Vector2d v[3]) {
  // The regular polygon with the circle's area: circumradius r·sqrt(2π / (k sin(2π/k))).
  static const double grow = std::sqrt(2 * M_PI / (kHoleSides * std::sin(2 * M_PI / kHoleSides)));
  const double r = h.groove() ? hole_radius(h) : 0.5 * h.diameter * grow;
  const Eigen::Vector2d lo = v[0].cwiseMin(v[1]).cwiseMin(v[2]), hi = v[0].cwiseMax(v[1]).cwiseMax(v[2]);
  if (h.center[0] + r < lo.x() || h.center[0] - r > hi.x() || h.center[1] + r < lo.y() ||
      h.center[1] - r > hi.y())
    return {};
  Poly disc;
  const Eigen::Vector2d c(h.center[0], h.center[1]);
  if (h.groove()) {
    // Counter-clockwise: ±half width along the sliding direction s, ±half length along `across` t.
    const Eigen::Vector2d t(h.across[0], h.across[1]), s(t.y(), -t.x());
    const double a = 0.5 * h.diameter, b = 0.5 * h.length;
    disc = {c - a * s - b * t, c + a * s - b * t, c + a * s + b * t, c - a * s + b * t};
  } else {
    disc.resize(kHoleSides);
    for (int k = 0; k < kHoleSides; ++k) {
      const double phi = 2 * M_PI * k / kHoleSides;
      disc[k] = c + r * Eigen::Vector2d(std::cos(phi), std::sin(phi));
    }
  }
  for (int e = 0; e < 3 && !disc.empty(); ++e) disc = clip(disc, v[e], v[(e + 1) % 3]);
  return disc.size() >= 3 ? disc : Poly{};
}

Eigen::VectorXd hole_cover(const MortarZone& zone, const TetMesh& m, const std::vector<Hole>& holes) {
  const int n = zone.size();
  Eigen::VectorXd covered = Eigen::VectorXd::Zero(n), area = Eigen::VectorXd::Zero(n);
  if (holes.empty() || n == 0) return covered;
  std::vector<int> local(m.num_vertices, -1);
  for (int i = 0; i < n; ++i) local[zone.vertices[i]] = i;
  for (int f : zone.faces) {
    Eigen::Vector2d v[3];
    for (int a = 0; a < 3; ++a) v[a] = {m.nodes(m.faces(f, a), 0), m.nodes(m.faces(f, a), 1)};
    double t_area = 0.5 * ((v[1] - v[0]).x() * (v[2] - v[0]).y() - (v[1] - v[0]).y() * (v[2] - v[0]).x());
    if (t_area < 0) std::swap(v[1], v[2]);  // counter-clockwise seen from above
    int order[3] = {m.faces(f, 0), m.faces(f, 1), m.faces(f, 2)};
    if (t_area < 0) std::swap(order[1], order[2]);
    t_area = std::abs(t_area);
    for (int a = 0; a < 3; ++a)
      if (const int i = local[order[a]]; i >= 0) area[i] += t_area / 3;
    for (const Hole& h : holes) {
      const Poly disc = hole_in_triangle(h, v);
      if (disc.size() < 3) continue;
      Eigen::Vector2d c;
      const double a_cut = area_centroid(disc, c);
      if (!(a_cut > 0)) continue;
      // ∫ over the cut of each linear hat = the cut's area × the hat at its centroid.
      const double d = 2 * t_area;
      const double l1 = ((v[2] - v[1]).x() * (c - v[1]).y() - (v[2] - v[1]).y() * (c - v[1]).x()) / d;
      const double l2 = ((v[0] - v[2]).x() * (c - v[2]).y() - (v[0] - v[2]).y() * (c - v[2]).x()) / d;
      const double bary[3] = {l1, l2, 1 - l1 - l2};
      for (int a = 0; a < 3; ++a)
        if (const int i = local[order[a]]; i >= 0) covered[i] += a_cut * bary[a];
    }
  }
  for (int i = 0; i < n; ++i) covered[i] = area[i] > 0 ? std::clamp(covered[i] / area[i], 0.0, 1.0) : 0.0;
  return covered;
}

}  // namespace skinfem::contact
