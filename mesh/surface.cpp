#include "skinfem/mesh/surface.hpp"

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>
#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>

#include "skinfem/mesh/footprint.hpp"
#include "skinfem/mesh/self_intersection.hpp"

namespace skinfem {

namespace {
struct DoubleTraits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;  // the default is float
  using Normal = OpenMesh::Vec3d;
};
using OmMesh = OpenMesh::TriMesh_ArrayKernelT<DoubleTraits>;

// Returns an empty string when closed and manifold, else the reason.
std::string topology_problem(const OmMesh& m, size_t expected_faces) {
  if (m.n_faces() != expected_faces)
    return std::to_string(expected_faces - m.n_faces()) +
           " faces are non-manifold or inconsistently oriented";
  for (auto h : m.halfedges())
    if (m.is_boundary(h)) return "not watertight (open boundary edges)";
  for (auto v : m.vertices())
    if (!m.is_manifold(v)) return "non-manifold vertex";
  return "";
}

OmMesh to_openmesh(const SurfaceMesh& s, size_t& added) {
  OmMesh m;
  std::vector<OmMesh::VertexHandle> vh;
  for (int i = 0; i < s.vertices.rows(); ++i)
    vh.push_back(m.add_vertex({s.vertices(i, 0), s.vertices(i, 1), s.vertices(i, 2)}));
  added = 0;
  omlog().disable();
  omerr().disable();  // OpenMesh reports complex edges on stderr; we report them ourselves
  for (int t = 0; t < s.triangles.rows(); ++t)
    if (m.add_face(vh[s.triangles(t, 0)], vh[s.triangles(t, 1)], vh[s.triangles(t, 2)]).is_valid()) ++added;
  return m;
}

// Whether a footprint triangle lies inside one of the circles (its centroid does: the
// triangulation follows the circles, so no triangle straddles one).
bool inside_circle(const Footprint& fp, int a, int b, int c, const std::vector<Circle>& circles) {
  const double x = (fp.points(a, 0) + fp.points(b, 0) + fp.points(c, 0)) / 3;
  const double y = (fp.points(a, 1) + fp.points(b, 1) + fp.points(c, 1)) / 3;
  for (const auto& circle : circles)
    if (std::hypot(x - circle.centre[0], y - circle.centre[1]) < circle.radius) return true;
  return false;
}

// OBJ and OFF files may repeat a point for every face that uses it (STL readers merge them already): faces
// joined only through equal coordinates become neighbours.
void merge_duplicate_vertices(SurfaceMesh& s) {
  std::map<std::array<double, 3>, int> first;
  std::vector<int> to(s.vertices.rows());
  RowMatrixX3d kept(s.vertices.rows(), 3);
  int n = 0;
  for (int i = 0; i < s.vertices.rows(); ++i) {
    const auto [it, fresh] = first.try_emplace({s.vertices(i, 0), s.vertices(i, 1), s.vertices(i, 2)}, n);
    if (fresh) kept.row(n++) = s.vertices.row(i);
    to[i] = it->second;
  }
  s.vertices = kept.topRows(n);
  for (int t = 0; t < s.triangles.rows(); ++t)
    for (int k = 0; k < 3; ++k) s.triangles(t, k) = to[s.triangles(t, k)];
}

std::string point_words(const Eigen::Vector3d& p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.6g, %.6g, %.6g) mm", p.x(), p.y(), p.z());
  return buf;
}

// Turns every face the way of its neighbours (spreading across shared edges), so a surface written with
// mixed orientations still reads; check_watertight then requires the result to enclose positive volume.
// An edge of more than two faces, or a one-sided surface, is refused at its location.
void orient_faces(SurfaceMesh& s, const std::string& path) {
  const int nf = static_cast<int>(s.triangles.rows());
  std::map<std::pair<int, int>, std::vector<int>> faces_of;
  for (int t = 0; t < nf; ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = s.triangles(t, k), b = s.triangles(t, (k + 1) % 3);
      faces_of[{std::min(a, b), std::max(a, b)}].push_back(t);
    }
  const auto midpoint = [&](int a, int b) {
    return point_words(0.5 * (s.vertices.row(a) + s.vertices.row(b)).transpose());
  };
  for (const auto& [edge, faces] : faces_of)
    if (faces.size() > 2)
      throw MeshError(path + ": " + std::to_string(faces.size()) + " faces share the edge at " +
                      midpoint(edge.first, edge.second) + "; a manifold surface is required");
  // Whether face t runs a → b (true) or b → a (false).
  const auto runs = [&](int t, int a, int b) {
    for (int k = 0; k < 3; ++k)
      if (s.triangles(t, k) == a && s.triangles(t, (k + 1) % 3) == b) return true;
    return false;
  };
  std::vector<char> seen(nf, 0);
  for (int start = 0; start < nf; ++start) {
    if (seen[start]) continue;
    seen[start] = 1;
    std::vector<int> queue{start};
    while (!queue.empty()) {
      const int t = queue.back();
      queue.pop_back();
      for (int k = 0; k < 3; ++k) {
        const int a = s.triangles(t, k), b = s.triangles(t, (k + 1) % 3);
        for (int u : faces_of.at({std::min(a, b), std::max(a, b)})) {
          if (u == t) continue;
          if (runs(u, a, b)) {  // u must run b → a to agree with t
            if (seen[u])
              throw MeshError(path + ": the surface is one-sided (it cannot be oriented) at the edge " +
                              midpoint(a, b));
            std::swap(s.triangles(u, 1), s.triangles(u, 2));
          }
          if (!seen[u]) {
            seen[u] = 1;
            queue.push_back(u);
          }
        }
      }
    }
  }
}

}  // namespace

double signed_volume(const SurfaceMesh& s) {
  double v = 0;
  for (int t = 0; t < s.triangles.rows(); ++t) {
    const Eigen::Vector3d a = s.vertices.row(s.triangles(t, 0)), b = s.vertices.row(s.triangles(t, 1)),
                          c = s.vertices.row(s.triangles(t, 2));
    v += a.dot(b.cross(c)) / 6.0;
  }
  return v;
}

void check_watertight(const SurfaceMesh& surface, const std::string& what) {
  size_t added = 0;
  const OmMesh m = to_openmesh(surface, added);
  if (auto problem = topology_problem(m, surface.triangles.rows()); !problem.empty())
    throw MeshError(what + ": surface is " + problem + "; a closed manifold surface is required");
  if (signed_volume(surface) <= 0)
    throw MeshError(what + ": surface encloses no volume or is inward oriented");
}

namespace {
// The footprint of the top or the base face; the outer rim goes back onto the truncation circle.
Footprint face_footprint(const SkinShape& shape, const std::vector<Vec2>& loop, const Size2d& size,
                         const std::vector<Circle>& circles, bool half) {
  Footprint fp = mesh_footprint(loop, size, circles, half);
  // Refinement splits boundary chords at their midpoints; put those vertices back on the circle (not those
  // on a half mesh's straight cut: all there have y = 0 exactly).
  if (shape.kind() == GeometryKind::cap) {
    for (int b : fp.boundary) {
      if (fp.points(b, 1) == 0.0) continue;
      const Vec3 p = shape.on_side({fp.points(b, 0), fp.points(b, 1), 0.0});
      fp.points.row(b) << p[0], p[1];
    }
  }
  return fp;
}

// Whether the base footprint's rim is the top's, point for point (to round-off); if so, rotates its
// boundary list to start where the top's does and copies the top's rim coordinates.
bool align_rim(Footprint& base, const Footprint& top) {
  const size_t n = top.boundary.size();
  if (base.boundary.size() != n) return false;
  auto same = [&](int b, int t) { return (base.points.row(b) - top.points.row(t)).norm() < 1e-9; };
  size_t shift = n;
  for (size_t k = 0; k < n && shift == n; ++k)
    if (same(base.boundary[k], top.boundary[0])) shift = k;
  if (shift == n) return false;
  std::rotate(base.boundary.begin(), base.boundary.begin() + shift, base.boundary.end());
  for (size_t k = 0; k < n; ++k)
    if (!same(base.boundary[k], top.boundary[k])) return false;
  for (size_t k = 0; k < n; ++k) base.points.row(base.boundary[k]) = top.points.row(top.boundary[k]);
  return true;
}

// The same on a half whose cut the two faces need not share (it is the symmetry face, meshed from whatever
// points either has there, close_cut): every top rim point has its base point (inside the cut, where the
// base drops points beside a post's end, it may have none: −1), and the base has no rim point off the cut
// that the top lacks. Returns the base vertex of each top boundary position (empty if not).
std::vector<int> align_rim_off_cut(Footprint& base, const Footprint& top) {
  std::map<std::pair<double, double>, int> at;
  for (int b : base.boundary) at[{base.points(b, 0), base.points(b, 1)}] = b;
  const auto find = [&](double x, double y) {
    auto it = at.lower_bound({x - 1e-9, -1e300});
    for (; it != at.end() && it->first.first <= x + 1e-9; ++it)
      if (std::abs(it->first.second - y) < 1e-9) return it->second;
    return -1;
  };
  std::vector<int> match;
  std::vector<char> used(base.points.rows(), 0);
  const size_t n = top.boundary.size();
  const auto on_cut = [&](size_t k) { return top.points(top.boundary[k % n], 1) == 0.0; };
  for (size_t k = 0; k < n; ++k) {
    const int b = find(top.points(top.boundary[k], 0), top.points(top.boundary[k], 1));
    if (b < 0 && !(on_cut(k) && on_cut(k + 1) && on_cut(k + n - 1))) return {};
    match.push_back(b);
    if (b >= 0) used[b] = 1;
  }
  for (int b : base.boundary)
    if (!used[b] && base.points(b, 1) != 0.0) return {};
  for (size_t k = 0; k < n; ++k)
    if (match[k] >= 0) base.points.row(match[k]) = top.points.row(top.boundary[k]);
  return match;
}
}  // namespace

namespace {
// Whether a punch's outline crosses a post's, or nearly touches it (inside or out).
bool outlines_cross(const std::vector<Circle>& punches, const std::vector<Circle>& posts,
                    const SizingField& size) {
  for (const Circle& p : posts)
    for (const Circle& c : punches) {
      const double d = std::hypot(c.centre[0] - p.centre[0], c.centre[1] - p.centre[1]);
      // Circles this close (a tenth of the mesh size) leave CGAL's refinement slivers between them.
      const double near = 0.1 * size(p.centre[0], p.centre[1]);
      if (d < c.radius + p.radius + near && d > std::abs(c.radius - p.radius) - near) return true;
    }
  return false;
}
}  // namespace

std::vector<Circle> post_circles(const Scene& scene) {
  std::vector<Circle> posts;
  if (scene.sensors.model == SensorModel::post)
    for (const Vec2& p : scene.sensors.positions) posts.push_back({p, 0.5 * scene.sensors.post.diameter});
  return posts;
}

namespace {
// Each post turns the base inside its outline into a cavity: the base triangles inside are removed, and the
// post's wall (layers of the outline's points up to `height`) and its flat top take their place, marked
// kPost. The skin lies outside the cylinder and above the top, so their outward normals point into the post.
// On a half mesh a post centred on the cut is a half: its outline is the upper arc, its wall is open at the
// cut and its top is closed by the diameter there (close_cut then meshes the cut around it).
void add_posts(SurfaceMesh& s, const std::vector<Circle>& posts, double height, const SizingField& size,
               bool half) {
  std::vector<std::array<int, 3>> tris;
  std::vector<int> markers;
  for (int t = 0; t < s.triangles.rows(); ++t) {
    if (s.marker(t) == kBase) {
      double cx = 0, cy = 0;
      for (int k = 0; k < 3; ++k)
        cx += s.vertices(s.triangles(t, k), 0) / 3, cy += s.vertices(s.triangles(t, k), 1) / 3;
      bool inside = false;
      for (const Circle& c : posts)
        inside = inside || std::hypot(cx - c.centre[0], cy - c.centre[1]) < c.radius;
      if (inside) continue;
    }
    tris.push_back({s.triangles(t, 0), s.triangles(t, 1), s.triangles(t, 2)});
    markers.push_back(s.marker(t));
  }
  std::vector<Eigen::RowVector3d> added;
  const int nv0 = s.vertices.rows();
  for (const Circle& c : posts) {
    // The outline's points on the base, by angle (counter-clockwise seen from above; on a half, from 0 to π:
    // the cut's −0.0 is read as +0.0).
    const bool open = half && c.centre[1] == 0.0;
    std::vector<std::pair<double, int>> ring;
    for (int v = 0; v < nv0; ++v) {
      if (s.vertices(v, 2) != 0.0) continue;
      const double dx = s.vertices(v, 0) - c.centre[0], dy = s.vertices(v, 1) - c.centre[1];
      if (std::abs(std::hypot(dx, dy) - c.radius) < 1e-9 * (1 + c.radius))
        ring.push_back({std::atan2(dy == 0.0 ? 0.0 : dy, dx), v});
    }
    if (ring.size() < 3) throw MeshError("a post's outline was not kept on the base");
    std::sort(ring.begin(), ring.end());
    const int n = static_cast<int>(ring.size());
    double wall_size = 1e300;
    for (const auto& [angle, v] : ring)
      wall_size = std::min(wall_size, size.in_volume(s.vertices(v, 0), s.vertices(v, 1), 0.5 * height));
    const int layers = std::max(1, static_cast<int>(std::ceil(height / wall_size - 1e-9)));
    // vertex of ring position k on wall layer j (0: the base's, layers: the top's)
    std::vector<std::vector<int>> id(layers + 1, std::vector<int>(n));
    for (int k = 0; k < n; ++k) id[0][k] = ring[k].second;
    for (int j = 1; j <= layers; ++j)
      for (int k = 0; k < n; ++k) {
        const int v = ring[k].second;
        id[j][k] = nv0 + static_cast<int>(added.size());
        added.push_back({s.vertices(v, 0), s.vertices(v, 1), height * j / layers});
      }
    for (int j = 0; j < layers; ++j)
      for (int k = 0; k < (open ? n - 1 : n); ++k) {
        const int p0 = id[j][k], p1 = id[j][(k + 1) % n], p2 = id[j + 1][(k + 1) % n], p3 = id[j + 1][k];
        tris.push_back({p0, p2, p1});  // counter-clockwise ring × up points out of the post: reversed
        markers.push_back(kPost);
        tris.push_back({p0, p3, p2});
        markers.push_back(kPost);
      }
    std::vector<Vec2> loop;
    for (int k = 0; k < n; ++k)
      loop.push_back({s.vertices(ring[k].second, 0), s.vertices(ring[k].second, 1)});
    const RowMatrixX3i top = triangulate_polygon(loop);
    for (int t = 0; t < top.rows(); ++t) {
      tris.push_back({id[layers][top(t, 0)], id[layers][top(t, 2)], id[layers][top(t, 1)]});  // normal −z
      markers.push_back(kPost);
    }
  }
  // Base points inside an outline belong to no face any more: drop them (TetGen would mesh them as points).
  RowMatrixX3d all(nv0 + added.size(), 3);
  all.topRows(nv0) = s.vertices;
  for (size_t i = 0; i < added.size(); ++i) all.row(nv0 + i) = added[i];
  std::vector<int> to(all.rows(), -1);
  for (const auto& t : tris)
    for (int v : t) to[v] = 0;
  int n = 0;
  s.vertices.resize(all.rows(), 3);
  for (int v = 0; v < all.rows(); ++v)
    if (to[v] == 0) s.vertices.row(n) = all.row(v), to[v] = n++;
  s.vertices.conservativeResize(n, 3);
  s.triangles.resize(tris.size(), 3);
  s.marker.resize(tris.size());
  for (size_t t = 0; t < tris.size(); ++t) {
    s.triangles.row(t) << to[tris[t][0]], to[tris[t][1]], to[tris[t][2]];
    s.marker(t) = markers[t];
  }
}
// Appends the triangulation of a polygon of existing vertices in (x, z), counter-clockwise (an outward normal
// −y), as faces of the cut y = 0 from face f on, dropping any rows past f; returns the new face count.
int add_cut_polygon(SurfaceMesh& s, int f, const std::vector<int>& poly) {
  std::vector<Vec2> xz;
  for (int v : poly) xz.push_back({s.vertices(v, 0), s.vertices(v, 2)});
  const RowMatrixX3i tris = triangulate_polygon(xz);
  s.triangles.conservativeResize(f + tris.rows(), 3);
  s.marker.conservativeResize(f + tris.rows());
  for (int t = 0; t < tris.rows(); ++t) {
    s.triangles.row(f + t) << poly[tris(t, 0)], poly[tris(t, 1)], poly[tris(t, 2)];
    s.marker(f + t) = kSymmetry;
  }
  return f + static_cast<int>(tris.rows());
}

// Keeps only the vertices that the first f faces use, renumbered in their order.
void drop_unused_vertices(SurfaceMesh& s, int f) {
  std::vector<int> to(s.vertices.rows(), -1);
  int n = 0;
  for (int t = 0; t < f; ++t)
    for (int c = 0; c < 3; ++c)
      if (to[s.triangles(t, c)] < 0) to[s.triangles(t, c)] = 0;
  RowMatrixX3d kept(s.vertices.rows(), 3);
  for (int v = 0; v < s.vertices.rows(); ++v)
    if (to[v] == 0) kept.row(n) = s.vertices.row(v), to[v] = n++;
  s.vertices = kept.topRows(n);
  for (int t = 0; t < f; ++t)
    for (int c = 0; c < 3; ++c) s.triangles(t, c) = to[s.triangles(t, c)];
}

// The cut y = 0 of a half mesh with posts on it: whatever the other faces leave open there (base and top
// along the cut, the side band's ends, each post's wall ends and the diameter of its top) is one polygon in
// (x, z), meshed with no point added. triangulate_polygon's triangles are counter-clockwise in (x, z): an
// outward normal −y.
void close_cut(SurfaceMesh& s) {
  std::map<std::pair<int, int>, int> uses;
  for (int t = 0; t < s.triangles.rows(); ++t)
    for (int e = 0; e < 3; ++e) {
      const int a = s.triangles(t, e), b = s.triangles(t, (e + 1) % 3);
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  std::map<int, int> next;
  for (int t = 0; t < s.triangles.rows(); ++t)
    for (int e = 0; e < 3; ++e) {
      const int a = s.triangles(t, e), b = s.triangles(t, (e + 1) % 3);
      if (uses[{std::min(a, b), std::max(a, b)}] != 1) continue;
      if (s.vertices(a, 1) != 0.0 || s.vertices(b, 1) != 0.0)
        throw MeshError("a half mesh's surface is open off its cut y = 0");
      next[b] = a;
    }
  if (next.empty()) throw MeshError("a half mesh's cut y = 0 has no open edges");
  std::vector<int> poly{next.begin()->first};
  while (poly.size() <= next.size()) {
    const int v = next.at(poly.back());
    if (v == poly.front()) break;
    poly.push_back(v);
  }
  if (poly.size() != next.size()) throw MeshError("a half mesh's cut y = 0 is not one polygon");
  add_cut_polygon(s, static_cast<int>(s.triangles.rows()), poly);
}
// The top's and the base's triangulations in the plane, their rims matched point for point (the side band
// joins them). The base gets its own, coarser triangulation when contact regions grade with depth. The side
// band needs both rims to be the same points; refinement splits rim chords differently on each face, so each
// face is remeshed on the other's rim until they agree (else the base takes the top's triangulation).
struct Faces {
  Footprint top, base;  // base: its own triangulation, or a copy of the top's
  // A half with posts whose base has its own triangulation: the base vertex of each top boundary position;
  // empty otherwise (the base's boundary positions are the top's).
  std::vector<int> base_of_top;
};
Faces matched_faces(const SkinShape& shape, const std::vector<Vec2>& loop, const SizingField& size,
                    const std::vector<Circle>& circles, const std::vector<Circle>& posts, bool half) {
  const Size2d top_size = [&](double x, double y) { return size(x, y); };
  std::vector<Circle> outlines = circles;
  outlines.insert(outlines.end(), posts.begin(), posts.end());
  auto rim_of = [](const Footprint& fp) {
    std::vector<Vec2> rim;
    for (int b : fp.boundary) rim.push_back({fp.points(b, 0), fp.points(b, 1)});
    return rim;
  };
  // A punch's outline that crosses or nearly touches a post's cannot share one triangulation with it: the
  // crossing points lie on neither circle, so the post's ring on the base is lost (and tangent circles
  // leave CGAL slivers). Then each face gets its own, the top with the punches, the base with the posts.
  const bool crossing = outlines_cross(circles, posts, size);
  const bool own_faces = size.graded_in_depth() || crossing;
  const std::vector<Circle>& base_outlines = crossing ? posts : outlines;
  // Posts are the base's: the top follows their outlines only when it lends the base its triangulation
  // (else each would stamp a small circle of faces, and of contact multipliers, on the top above it).
  const std::vector<Circle>& top_outlines = own_faces ? circles : outlines;
  Footprint top = face_footprint(shape, loop, top_size, top_outlines, half);
  std::optional<Footprint> own_base;
  // On a half with posts the base's cut is refined at the posts' ends; the top keeps its own cut points.
  const bool own_cuts = half && !posts.empty();
  std::vector<int> base_of_top;
  // The base's rim with the top's own points on the cut instead of the base's.
  const auto rim_with_top_cut = [&](const Footprint& own, const Footprint& t) {
    std::vector<std::pair<double, double>> cut;
    for (int b : t.boundary)
      if (t.points(b, 1) == 0.0) cut.push_back({t.points(b, 0), 0.0});
    std::vector<Vec2> rim;
    for (const Vec2& p : rim_of(own))
      if (p[1] != 0.0 || std::find(cut.begin(), cut.end(), std::pair{p[0], 0.0}) != cut.end())
        rim.push_back(p);
    return rim;
  };
  // A crossing has no shared triangulation to fall back on: it is given more rounds to agree.
  const int rounds = crossing ? 12 : 4;
  for (int round = 0; own_faces && round < rounds && !own_base; ++round) {
    Footprint own = face_footprint(
        shape, rim_of(top), [&](double x, double y) { return size.on_base(x, y); }, base_outlines, half);
    if (own_cuts ? !(base_of_top = align_rim_off_cut(own, top)).empty() : align_rim(own, top))
      own_base = std::move(own);
    else if (own_cuts)
      top = face_footprint(shape, rim_with_top_cut(own, top), top_size, top_outlines, half);
    else
      top = face_footprint(shape, rim_of(own), top_size, top_outlines, half);
  }
  if (!own_base && crossing)
    throw MeshError(
        "a punch's outline crosses a post's and the base and top could not be given matching "
        "rims; move the punch off the post's outline");
  if (!own_base && top_outlines.size() != outlines.size())
    top = face_footprint(shape, rim_of(top), top_size, outlines, half);
  Footprint base = own_base ? std::move(*own_base) : top;
  return {std::move(top), std::move(base), std::move(base_of_top)};
}
}  // namespace

SurfaceMesh layer_surface(const Scene& scene, const SizingField& size, MeshPart part) {
  const Geometry& geometry = scene.geometry;
  const SkinShape shape(geometry);
  const bool half = part == MeshPart::half_y;
  const Vec2 centre =
      geometry.kind == GeometryKind::cap ? Vec2{geometry.cap.apex_x, geometry.cap.apex_y} : Vec2{0, 0};
  if (half && centre[1] != 0.0) throw MeshError("a half mesh (y >= 0) needs the skin's axis on y = 0");
  const Size2d top_size = [&](double x, double y) { return size(x, y); };
  const double rim =
      geometry.kind == GeometryKind::cap ? geometry.cap.truncation_radius : geometry.flat.half_width;
  const auto loop =
      geometry.kind == GeometryKind::cap
          ? (half ? half_circle_loop(centre, rim, top_size) : circle_loop(centre, rim, top_size))
          : (half ? half_square_loop(rim, top_size) : square_loop(rim, top_size));
  // A half mesh keeps only the punch outlines wholly inside it: the commands that mesh a half (green, kfit)
  // load no punch.
  std::vector<Circle> circles;
  for (const auto& p : scene.loads.punches)
    if (!half || p.center[1] - 0.5 * p.diameter > 0) circles.push_back({p.center, 0.5 * p.diameter});
  // Post sensors: the base follows their outlines, and each becomes a cavity in the skin (add_posts).
  const std::vector<Circle> posts = post_circles(scene);
  for (const Circle& c : posts)
    if (half && c.centre[1] != 0.0) throw MeshError("a half mesh cuts only posts centred on y = 0");
  const Faces faces = matched_faces(shape, loop, size, circles, posts, half);
  const Footprint &top = faces.top, &base = faces.base;
  const int nvb = base.points.rows(), nvt = top.points.rows(), nb = static_cast<int>(top.boundary.size());

  // Side band: as many layers as the rim's sizing asks for, at least one.
  double rim_size = 0, rim_height = 0;
  for (int b : top.boundary) {
    rim_size += size(top.points(b, 0), top.points(b, 1)) / nb;
    rim_height = std::max(rim_height, shape.top_z(top.points(b, 0), top.points(b, 1)));
  }
  const int layers = std::max(1, static_cast<int>(std::ceil(rim_height / rim_size - 1e-9)));

  SurfaceMesh s;
  s.vertices.resize(nvb + nvt + (layers - 1) * nb, 3);
  for (int i = 0; i < nvb; ++i) s.vertices.row(i) << base.points(i, 0), base.points(i, 1), 0.0;
  for (int i = 0; i < nvt; ++i) {
    const double x = top.points(i, 0), y = top.points(i, 1);
    s.vertices.row(nvb + i) << x, y, shape.top_z(x, y);
  }
  // vertex of boundary position k on side layer j (0 = base, layers = top)
  auto side_vertex = [&](int k, int j) {
    if (j == 0) return faces.base_of_top.empty() ? base.boundary[k % nb] : faces.base_of_top[k % nb];
    if (j == layers) return nvb + top.boundary[k % nb];
    return nvb + nvt + (j - 1) * nb + k % nb;
  };
  for (int j = 1; j < layers; ++j)
    for (int k = 0; k < nb; ++k) {
      const int b = top.boundary[k];
      const double x = top.points(b, 0), y = top.points(b, 1);
      s.vertices.row(side_vertex(k, j)) << x, y, shape.top_z(x, y) * j / layers;
    }

  const int ntb = base.triangles.rows(), ntt = top.triangles.rows();
  s.triangles.resize(ntb + ntt + 2 * nb * layers, 3);
  s.marker.resize(s.triangles.rows());
  int f = 0;
  // Interleaved base/top as long as both have triangles: the order TetGen saw before the base had its own.
  for (int t = 0; t < std::max(ntb, ntt); ++t) {
    if (t < ntb) {
      const int a = base.triangles(t, 0), b = base.triangles(t, 1), c = base.triangles(t, 2);
      s.triangles.row(f) << a, c, b;  // base: outward normal −z
      s.marker(f++) = kBase;
    }
    if (t < ntt) {
      const int a = top.triangles(t, 0), b = top.triangles(t, 1), c = top.triangles(t, 2);
      s.triangles.row(f) << nvb + a, nvb + b, nvb + c;
      s.marker(f++) = kTop | (inside_circle(top, a, b, c, circles) ? kKeepOutline : 0);
    }
  }
  const auto on_cut = [&](int k) { return half && top.points(top.boundary[k % nb], 1) == 0.0; };
  for (int k = 0; k < nb; ++k) {
    if (on_cut(k) && on_cut(k + 1)) continue;  // the cut is the symmetry face, below
    for (int j = 0; j < layers; ++j) {         // counter-clockwise rim × up = outward
      const int p0 = side_vertex(k, j), p1 = side_vertex(k + 1, j), p2 = side_vertex(k + 1, j + 1),
                p3 = side_vertex(k, j + 1);
      s.triangles.row(f) << p0, p1, p2;
      s.marker(f++) = kSide;
      s.triangles.row(f) << p0, p2, p3;
      s.marker(f++) = kSide;
    }
  }
  if (half && posts.empty()) {
    // The cut y = 0 as one polygon in (x, z): base points by increasing x, up the side at the far end, top
    // points back, down the side at the near end. Counter-clockwise in (x, z) is an outward normal −y.
    std::vector<int> cut;  // boundary positions on the cut, by increasing x
    for (int k = 0; k < nb; ++k)
      if (on_cut(k)) cut.push_back(k);
    std::sort(cut.begin(), cut.end(),
              [&](int a, int b) { return top.points(top.boundary[a], 0) < top.points(top.boundary[b], 0); });
    std::vector<int> poly;
    for (int k : cut) poly.push_back(side_vertex(k, 0));
    for (int j = 1; j < layers; ++j) poly.push_back(side_vertex(cut.back(), j));
    for (auto it = cut.rbegin(); it != cut.rend(); ++it) poly.push_back(side_vertex(*it, layers));
    for (int j = layers - 1; j >= 1; --j) poly.push_back(side_vertex(cut.front(), j));
    f = add_cut_polygon(s, f, poly);
    drop_unused_vertices(s, f);  // side-band points above the cut's inner points belong to no face
  }
  s.triangles.conservativeResize(f, 3);
  s.marker.conservativeResize(f);
  if (!posts.empty()) {
    add_posts(s, posts, scene.sensors.post.height, size, half);
    if (half) close_cut(s);
  }
  check_watertight(s, "generated layer surface");
  return s;
}

namespace {
// What OpenMesh reads without a word: headers that declare more than the file holds (it allocates what an
// OFF header declares: 2e9 vertices ended in std::bad_alloc; a binary STL of the wrong length reads as "no
// faces") and coordinates that are not finite.
void check_before_reading(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  const double bytes = static_cast<double>(std::filesystem::file_size(path));
  std::ifstream in(path, std::ios::binary);
  char count_text[64];
  std::string word;
  if (ext == ".off") in >> word;
  if (word == "OFF") {  // OpenMesh's variants (COFF, NOFF, …) put other counts there: theirs to check
    double nv = -1, nf = -1;
    while (in >> std::ws && in.peek() == '#') in.ignore(1 << 20, '\n');
    in >> nv >> nf;
    if (!in || nv < 0 || nf < 0) throw MeshError(path + ": the OFF header has no vertex and face counts");
    // Each vertex takes at least 6 characters ("0 0 0\n"), each triangle 8 ("3 0 1 2\n").
    if (6 * nv + 8 * nf > bytes) {
      std::snprintf(count_text, sizeof count_text, "%.0f vertices and %.0f faces", nv, nf);
      throw MeshError(path + ": the OFF header declares " + count_text + ", more than its " +
                      std::to_string(static_cast<long long>(bytes)) + " bytes can hold");
    }
  }
  std::string head(512, '\0');
  in.clear();
  in.seekg(0);
  in.read(head.data(), head.size());
  head.resize(in.gcount());
  const bool ascii_stl =
      ext == ".stl" && head.rfind("solid", 0) == 0 && head.find("facet") != std::string::npos;
  if (ascii_stl || ext == ".obj" || ext == ".off") {
    // OpenMesh reads "nan" and "inf" without a word: the surface then came apart as "not watertight".
    in.clear();
    in.seekg(0);
    std::string line;
    for (int n = 1; std::getline(in, line); ++n) {
      std::istringstream words(line);
      std::string first;
      words >> first;
      // The lines that hold coordinates: "vertex x y z" (STL), "v x y z" (OBJ), every line after the header
      // but comments (OFF).
      const bool coordinates = ascii_stl       ? first == "vertex"
                               : ext == ".obj" ? first == "v"
                                               : n > 1 && !first.empty() && first[0] != '#';
      if (!coordinates) continue;
      if (ext == ".off") words.clear(), words.seekg(0);
      for (std::string w; words >> w;) {
        std::transform(w.begin(), w.end(), w.begin(), [](unsigned char c) { return std::tolower(c); });
        const std::size_t start = w[0] == '-' || w[0] == '+' ? 1 : 0;
        if (w.compare(start, 3, "nan") == 0 || w.compare(start, 3, "inf") == 0)
          throw MeshError(path + ": line " + std::to_string(n) + " holds \"" + w +
                          "\": every coordinate must be a finite number (mm)");
      }
    }
    return;
  }
  if (ext == ".stl" && bytes >= 84) {
    uint32_t n = 0;
    std::memcpy(&n, head.data() + 80, 4);
    if (84.0 + 50.0 * n != bytes) {
      std::snprintf(count_text, sizeof count_text, "%u faces, 84 + 50 × %u = %.0f bytes", n, n,
                    84.0 + 50.0 * n);
      throw MeshError(path + ": a binary STL declaring " + count_text + "; the file has " +
                      std::to_string(static_cast<long long>(bytes)));
    }
  }
}
}  // namespace

bool over_top(const SurfaceMesh& s, const Vec2& p) {
  for (int t = 0; t < s.triangles.rows(); ++t) {
    if ((s.marker(t) & ~kKeepOutline) != kTop) continue;
    double w[3];
    for (int k = 0; k < 3; ++k) {
      const auto a = s.vertices.row(s.triangles(t, (k + 1) % 3)),
                 b = s.vertices.row(s.triangles(t, (k + 2) % 3));
      w[k] = (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
    }
    if ((w[0] >= 0 && w[1] >= 0 && w[2] >= 0) || (w[0] <= 0 && w[1] <= 0 && w[2] <= 0)) return true;
  }
  return false;
}

SurfaceMesh import_surface(const std::string& path) {
  if (!std::filesystem::exists(path)) throw MeshError(path + ": no such file");
  check_before_reading(path);
  OmMesh m;
  omlog().disable();
  omerr().disable();
  OpenMesh::IO::Options opt;
  if (!OpenMesh::IO::read_mesh(m, path, opt)) throw MeshError(path + ": cannot be read as STL/OBJ/OFF");
  if (m.n_faces() == 0) throw MeshError(path + ": surface has no faces");

  SurfaceMesh s;
  s.vertices.resize(m.n_vertices(), 3);
  for (auto v : m.vertices()) {
    const auto p = m.point(v);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) {
      char at[128];
      std::snprintf(at, sizeof at, "vertex %d is (%g, %g, %g)", v.idx(), p[0], p[1], p[2]);
      throw MeshError(path + ": " + at + "; every coordinate must be a finite number (mm)");
    }
    s.vertices.row(v.idx()) << p[0], p[1], p[2];
  }
  s.triangles.resize(m.n_faces(), 3);
  for (auto f : m.faces()) {
    int i = 0;
    for (auto v : m.fv_range(f)) s.triangles(f.idx(), i++) = v.idx();
  }
  merge_duplicate_vertices(s);
  orient_faces(s, path);
  if (signed_volume(s) < 0) s.triangles.col(1).swap(s.triangles.col(2));  // consistently inward: turn out
  // Faces the reader dropped (complex edges) leave open edges, which this check reports.
  check_watertight(s, path);
  if (const auto x = first_self_intersection(s))
    throw MeshError(path + ": surface intersects itself near (" + std::to_string((*x)[0]) + ", " +
                    std::to_string((*x)[1]) + ", " + std::to_string((*x)[2]) +
                    ") mm; a closed surface that does not cross itself is required");

  const double diameter = (s.vertices.colwise().maxCoeff() - s.vertices.colwise().minCoeff()).norm();
  const double tol = 1e-9 * diameter;
  s.marker.resize(s.triangles.rows());
  int base_faces = 0;
  for (int t = 0; t < s.triangles.rows(); ++t) {
    const Eigen::Vector3d a = s.vertices.row(s.triangles(t, 0)), b = s.vertices.row(s.triangles(t, 1)),
                          c = s.vertices.row(s.triangles(t, 2));
    const Eigen::Vector3d n = (b - a).cross(c - a).normalized();
    const bool on_base = std::abs(a.z()) < tol && std::abs(b.z()) < tol && std::abs(c.z()) < tol && n.z() < 0;
    s.marker(t) = on_base ? kBase : (std::abs(n.z()) < 1e-6 ? kSide : kTop);
    base_faces += on_base;
  }
  if (s.vertices.col(2).minCoeff() < -tol)
    throw MeshError(path + ": surface reaches below the base plane z = 0");
  if (base_faces == 0) throw MeshError(path + ": no face lies on the base plane z = 0");
  return s;
}

}  // namespace skinfem
