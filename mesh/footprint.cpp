#include "skinfem/mesh/footprint.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_criteria_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>
#include <map>
#include <stdexcept>

namespace skinfem {

namespace {
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Delaunay_mesh_vertex_base_2<K>;
using Fb = CGAL::Delaunay_mesh_face_base_2<K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using CDT = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;

// CGAL's Delaunay_mesh_size_criteria_2 with a size bound that varies in space: a face is
// imperatively bad when its longest edge exceeds the sizing field at its centroid.
class GradedCriteria : public virtual CGAL::Delaunay_mesh_criteria_2<CDT> {
 public:
  using Base = CGAL::Delaunay_mesh_criteria_2<CDT>;
  struct Quality : std::pair<double, double> {  // (squared min sine, edge length / size)
    Quality() = default;
    Quality(double sine, double size) : std::pair<double, double>(sine, size) {}
    double sine() const { return first; }
    double size() const { return second; }
    bool operator<(const Quality& q) const {
      if (size() > 1) return q.size() > 1 ? size() > q.size() : true;
      if (q.size() > 1) return false;
      return sine() < q.sine();
    }
  };
  class Is_bad : public Base::Is_bad {
   public:
    Is_bad(double aspect, const Size2d* size) : Base::Is_bad(aspect, K()), size_(size) {}
    CGAL::Mesh_2::Face_badness operator()(const Quality q) const {
      if (q.size() > 1) return CGAL::Mesh_2::IMPERATIVELY_BAD;
      return q.sine() < this->B ? CGAL::Mesh_2::BAD : CGAL::Mesh_2::NOT_BAD;
    }
    CGAL::Mesh_2::Face_badness operator()(const CDT::Face_handle& fh, Quality& q) const {
      const auto& a = fh->vertex(0)->point();
      const auto& b = fh->vertex(1)->point();
      const auto& c = fh->vertex(2)->point();
      double l[3] = {CGAL::squared_distance(b, c), CGAL::squared_distance(c, a),
                     CGAL::squared_distance(a, b)};
      std::sort(l, l + 3);
      const double cx = (a.x() + b.x() + c.x()) / 3, cy = (a.y() + b.y() + c.y()) / 3;
      const double target = (*size_)(cx, cy);
      q.second = std::sqrt(l[2]) / target;
      if (q.size() > 1) {
        q.first = 1;
        return CGAL::Mesh_2::IMPERATIVELY_BAD;
      }
      const double area2 = 2 * CGAL::area(a, b, c);
      q.first = area2 * area2 / (l[2] * l[1]);
      return q.sine() < this->B ? CGAL::Mesh_2::BAD : CGAL::Mesh_2::NOT_BAD;
    }

   private:
    const Size2d* size_;
  };
  explicit GradedCriteria(const Size2d& size) : Base(0.125), size_(&size) {}  // min angle ≈ 20.7°
  Is_bad is_bad_object() const { return Is_bad(this->bound(), size_); }

 private:
  const Size2d* size_;
};

// Points along a → b, spaced by the sizing field, then stretched to end exactly at b (b excluded).
void append_graded_edge(const Vec2& a, const Vec2& b, const Size2d& size, std::vector<Vec2>& out) {
  const double len = std::hypot(b[0] - a[0], b[1] - a[1]);
  std::vector<double> s{0.0};
  while (s.back() < len) {
    const double t = s.back() / len;
    s.push_back(s.back() + size(a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])));
  }
  const double stretch = len / s.back();
  for (size_t i = 0; i + 1 < s.size(); ++i) {
    const double t = s[i] * stretch / len;
    out.push_back({a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])});
  }
}
}  // namespace

std::vector<Vec2> circle_loop(const Vec2& centre, double radius, const Size2d& size) {
  std::vector<double> theta{0.0};
  while (theta.back() < 2 * M_PI) {
    const double t = theta.back();
    theta.push_back(t + size(centre[0] + radius * std::cos(t), centre[1] + radius * std::sin(t)) / radius);
  }
  size_t n = theta.size() - 1;
  if (n < 8) {  // a polygon coarser than an octagon would misrepresent the disc
    n = 8;
    for (size_t i = 0; i <= n; ++i) theta.push_back(2 * M_PI * i / n);
    theta.erase(theta.begin(), theta.end() - (n + 1));
  }
  const double stretch = 2 * M_PI / theta.back();
  std::vector<Vec2> loop;
  for (size_t i = 0; i < n; ++i) {
    const double t = theta[i] * stretch;
    loop.push_back({centre[0] + radius * std::cos(t), centre[1] + radius * std::sin(t)});
  }
  return loop;
}

std::vector<Vec2> square_loop(double w, const Size2d& size) {
  const Vec2 corners[4] = {{-w, -w}, {w, -w}, {w, w}, {-w, w}};
  std::vector<Vec2> loop;
  for (int i = 0; i < 4; ++i) append_graded_edge(corners[i], corners[(i + 1) % 4], size, loop);
  return loop;
}

std::vector<Vec2> half_circle_loop(const Vec2& centre, double radius, const Size2d& size) {
  std::vector<double> theta{0.0};
  while (theta.back() < M_PI) {
    const double t = theta.back();
    theta.push_back(t + size(centre[0] + radius * std::cos(t), centre[1] + radius * std::sin(t)) / radius);
  }
  const size_t n = std::max<size_t>(theta.size() - 1, 4);  // no coarser than half an octagon
  std::vector<Vec2> loop{{centre[0] + radius, centre[1]}};
  for (size_t i = 1; i < n; ++i) {
    const double t = n == theta.size() - 1 ? theta[i] * M_PI / theta.back() : M_PI * i / n;
    loop.push_back({centre[0] + radius * std::cos(t), centre[1] + radius * std::sin(t)});
  }
  // The cut, from (−radius, 0) (included) to (+radius, 0) (the loop's start, excluded).
  append_graded_edge({centre[0] - radius, centre[1]}, {centre[0] + radius, centre[1]}, size, loop);
  return loop;
}

std::vector<Vec2> half_square_loop(double w, const Size2d& size) {
  const Vec2 corners[4] = {{-w, 0}, {w, 0}, {w, w}, {-w, w}};
  std::vector<Vec2> loop;
  for (int i = 0; i < 4; ++i) append_graded_edge(corners[i], corners[(i + 1) % 4], size, loop);
  return loop;
}

RowMatrixX3i triangulate_polygon(const std::vector<Vec2>& loop) {
  CDT cdt;
  std::map<CDT::Vertex_handle, int> index;
  std::vector<CDT::Vertex_handle> vh;
  for (size_t i = 0; i < loop.size(); ++i) {
    vh.push_back(cdt.insert(K::Point_2(loop[i][0], loop[i][1])));
    index[vh.back()] = static_cast<int>(i);
  }
  if (index.size() != loop.size()) throw std::runtime_error("triangulate_polygon: repeated points");
  for (size_t i = 0; i < vh.size(); ++i) cdt.insert_constraint(vh[i], vh[(i + 1) % vh.size()]);
  if (cdt.number_of_vertices() != loop.size())
    throw std::runtime_error("triangulate_polygon: the polygon's edges cross");
  // Inside = reached from the infinite faces across an odd number of constrained edges (flood fill).
  std::map<CDT::Face_handle, int> depth;
  std::vector<CDT::Face_handle> frontier{cdt.infinite_face()};
  depth[cdt.infinite_face()] = 0;
  for (size_t k = 0; k < frontier.size(); ++k) {
    const auto f = frontier[k];
    for (int e = 0; e < 3; ++e) {
      const auto g = f->neighbor(e);
      if (depth.count(g)) continue;
      depth[g] = depth[f] + (cdt.is_constrained({f, e}) ? 1 : 0);
      frontier.push_back(g);
    }
  }
  std::vector<std::array<int, 3>> tris;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if (depth.at(f) % 2 == 1)
      tris.push_back({index.at(f->vertex(0)), index.at(f->vertex(1)), index.at(f->vertex(2))});
  RowMatrixX3i out(tris.size(), 3);
  for (size_t i = 0; i < tris.size(); ++i) out.row(i) << tris[i][0], tris[i][1], tris[i][2];
  return out;
}

Footprint mesh_footprint(const std::vector<Vec2>& loop, const Size2d& size,
                         const std::vector<Circle>& circles, bool cut_at_y0) {
  CDT cdt;
  auto insert_loop = [&](const std::vector<Vec2>& pts) {
    std::vector<CDT::Vertex_handle> vh;
    for (const auto& p : pts) vh.push_back(cdt.insert(K::Point_2(p[0], p[1])));
    for (size_t i = 0; i < vh.size(); ++i) cdt.insert_constraint(vh[i], vh[(i + 1) % vh.size()]);
  };
  if (!cut_at_y0) {
    insert_loop(loop);
  } else {
    // A circle centred on the cut ends on it: the loop's points inside the cut (not its ends) within half
    // the local size of a circle's end, or between its ends, go, else an edge a thousandth of that size can
    // remain there (the scaled candelier2011's cut had a point 4e-4 mm from a post's end, and the half 3×
    // the whole's tets per side).
    std::vector<Vec2> kept;
    const size_t n = loop.size();
    for (size_t i = 0; i < n; ++i) {
      const Vec2& p = loop[i];
      const bool inner = p[1] == 0.0 && loop[(i + 1) % n][1] == 0.0 && loop[(i + n - 1) % n][1] == 0.0;
      bool near_end = false;
      for (const auto& c : circles)
        near_end = near_end ||
                   (c.centre[1] == 0.0 && std::abs(p[0] - c.centre[0]) < c.radius + 0.5 * size(p[0], 0.0));
      if (!(inner && near_end)) kept.push_back(p);
    }
    insert_loop(kept);
  }
  for (const auto& c : circles) {
    if (!(cut_at_y0 && c.centre[1] == 0.0)) {
      insert_loop(circle_loop(c.centre, c.radius, size));
      continue;
    }
    // The upper arc as an open polyline: half_circle_loop's points above the cut, between its exact ends.
    std::vector<CDT::Vertex_handle> arc{cdt.insert(K::Point_2(c.centre[0] + c.radius, 0.0))};
    for (const Vec2& p : half_circle_loop(c.centre, c.radius, size))
      if (p[1] > 0) arc.push_back(cdt.insert(K::Point_2(p[0], p[1])));
    arc.push_back(cdt.insert(K::Point_2(c.centre[0] - c.radius, 0.0)));
    for (size_t i = 0; i + 1 < arc.size(); ++i) cdt.insert_constraint(arc[i], arc[i + 1]);
  }
  CGAL::refine_Delaunay_mesh_2(cdt, GradedCriteria(size));
  // Refinement splits constrained chords at their midpoints: put interior-circle vertices back on
  // their circle (the outer loop is the caller's to project).
  for (auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e) {
    if (!cdt.is_constrained(*e) || circles.empty()) continue;
    for (int k : {cdt.cw(e->second), cdt.ccw(e->second)}) {
      auto v = e->first->vertex(k);
      const double x = v->point().x(), y = v->point().y();
      if (cut_at_y0 && y == 0.0) continue;  // on the cut: a circle's end there is exact already
      const Circle* nearest = nullptr;
      double gap = 1e300;
      for (const auto& c : circles) {
        const double g = std::abs(std::hypot(x - c.centre[0], y - c.centre[1]) - c.radius);
        if (g < gap) gap = g, nearest = &c;
      }
      if (gap > 0.25 * size(x, y)) continue;  // a vertex of the outer loop
      const double r = std::hypot(x - nearest->centre[0], y - nearest->centre[1]);
      if (r > 0)
        v->set_point(K::Point_2(nearest->centre[0] + nearest->radius * (x - nearest->centre[0]) / r,
                                nearest->centre[1] + nearest->radius * (y - nearest->centre[1]) / r));
    }
  }

  Footprint fp;
  std::map<CDT::Vertex_handle, int> index;
  std::vector<Vec2> pts;
  auto id = [&](CDT::Vertex_handle v) {
    auto [it, fresh] = index.emplace(v, static_cast<int>(pts.size()));
    if (fresh) pts.push_back({v->point().x(), v->point().y()});
    return it->second;
  };
  std::vector<std::array<int, 3>> tris;
  std::map<int, int> next_on_boundary;  // boundary edge a → b, counter-clockwise
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!f->is_in_domain()) continue;
    tris.push_back({id(f->vertex(0)), id(f->vertex(1)), id(f->vertex(2))});
    for (int e = 0; e < 3; ++e)
      if (cdt.is_infinite(f->neighbor(e)) || !f->neighbor(e)->is_in_domain())
        next_on_boundary[id(f->vertex(cdt.ccw(e)))] = id(f->vertex(cdt.cw(e)));
  }
  fp.points.resize(pts.size(), 2);
  for (size_t i = 0; i < pts.size(); ++i) fp.points.row(i) << pts[i][0], pts[i][1];
  fp.triangles.resize(tris.size(), 3);
  for (size_t i = 0; i < tris.size(); ++i) fp.triangles.row(i) << tris[i][0], tris[i][1], tris[i][2];
  if (next_on_boundary.empty()) throw std::runtime_error("footprint meshing produced no boundary");
  int v = next_on_boundary.begin()->first;
  do {
    fp.boundary.push_back(v);
    v = next_on_boundary.at(v);
  } while (v != fp.boundary.front() && fp.boundary.size() <= next_on_boundary.size());
  if (fp.boundary.size() != next_on_boundary.size())
    throw std::runtime_error("footprint boundary is not a single loop");
  return fp;
}

}  // namespace skinfem
