#include "skinfem/mesh/build.hpp"

#include <cmath>
#include <cstdio>
#include <map>

#include "skinfem/mesh/p2_tet.hpp"
#include "skinfem/mesh/quality.hpp"
#include "skinfem/mesh/shape.hpp"
#include "skinfem/mesh/size_estimate.hpp"
#include "skinfem/mesh/surface.hpp"
#include "skinfem/mesh/tetrahedralize.hpp"

namespace skinfem {

namespace {
// Puts p on the vertical cylinder over c, keeping its height.
void onto_cylinder(const Circle& c, Eigen::Vector3d& p) {
  const double dx = p.x() - c.centre[0], dy = p.y() - c.centre[1], d = std::hypot(dx, dy);
  if (d > 0) p.x() = c.centre[0] + c.radius * dx / d, p.y() = c.centre[1] + c.radius * dy / d;
}

// The post whose wall (or rim) holds both ends of an edge, or null: an edge across the post's top does not.
const Circle* cylinder_of(const std::vector<Circle>& posts, const Eigen::Vector3d& a,
                          const Eigen::Vector3d& b) {
  for (const Circle& c : posts) {
    const auto on = [&](const Eigen::Vector3d& p) {
      return std::abs(std::hypot(p.x() - c.centre[0], p.y() - c.centre[1]) - c.radius) < 1e-6 * c.radius;
    };
    if (on(a) && on(b)) return &c;
  }
  return nullptr;
}
}  // namespace

TetMesh make_quadratic(const RowMatrixX3d& points,
                       const Eigen::Matrix<int, Eigen::Dynamic, 4, Eigen::RowMajor>& tets,
                       const RowMatrixX3i& faces, const Eigen::VectorXi& face_marker,
                       const Geometry& geometry, const std::vector<Circle>& posts) {
  const SkinShape shape(geometry);
  const int nv = points.rows();
  auto key = [](int a, int b) { return a < b ? std::pair{a, b} : std::pair{b, a}; };

  // Which boundary parts each boundary edge lies on decides where its mid-node goes.
  std::map<std::pair<int, int>, int> edge_marker;
  for (int f = 0; f < faces.rows(); ++f)
    for (int e = 0; e < 3; ++e) edge_marker[key(faces(f, e), faces(f, (e + 1) % 3))] |= face_marker(f);

  TetMesh m;
  m.num_vertices = nv;
  std::map<std::pair<int, int>, int> mid;
  std::vector<Eigen::Vector3d> extra;
  auto mid_node = [&](int a, int b) {
    auto [it, fresh] = mid.emplace(key(a, b), nv + static_cast<int>(extra.size()));
    if (fresh) {
      Eigen::Vector3d p = 0.5 * (points.row(a) + points.row(b)).transpose();
      auto em = edge_marker.find(key(a, b));
      const int marker = em == edge_marker.end() ? 0 : em->second;
      if (shape.exact()) {
        if (marker & kSide) {
          const Vec3 q = shape.on_side({p.x(), p.y(), p.z()});
          p << q[0], q[1], q[2];
        }
        if (marker & kTop) p.z() = shape.top_z(p.x(), p.y());
      }
      if (marker & kPost)
        if (const Circle* c = cylinder_of(posts, points.row(a), points.row(b))) onto_cylinder(*c, p);
      extra.push_back(p);
    }
    return it->second;
  };
  m.tets.resize(tets.rows(), 10);
  for (int t = 0; t < tets.rows(); ++t) {
    for (int k = 0; k < 4; ++k) m.tets(t, k) = tets(t, k);
    for (int e = 0; e < 6; ++e)
      m.tets(t, 4 + e) = mid_node(tets(t, p2::kEdge[e][0]), tets(t, p2::kEdge[e][1]));
  }
  m.nodes.resize(nv + extra.size(), 3);
  m.nodes.topRows(nv) = points;
  for (size_t i = 0; i < extra.size(); ++i) m.nodes.row(nv + i) = extra[i];

  m.faces.resize(faces.rows(), 6);
  m.face_marker = face_marker;
  m.node_marker = Eigen::VectorXi::Zero(m.nodes.rows());
  for (int f = 0; f < faces.rows(); ++f) {
    for (int e = 0; e < 3; ++e) {
      m.faces(f, e) = faces(f, e);
      m.faces(f, 3 + e) = mid.at(key(faces(f, e), faces(f, (e + 1) % 3)));
    }
    for (int k = 0; k < 6; ++k) m.node_marker(m.faces(f, k)) |= face_marker(f);
  }
  return m;
}

namespace {
// Boundary points TetGen added lie on the flat input triangles: move them onto the exact cap or
// cylinder (by at most the sagitta of a boundary triangle, L²/8R).
// Returns the wall points moved, with where they were.
std::vector<std::pair<int, Eigen::RowVector3d>> snap_to_surface(LinearTets& lin, const SkinShape& shape,
                                                                const std::vector<Circle>& posts,
                                                                double post_height) {
  std::vector<std::pair<int, Eigen::RowVector3d>> moved;
  Eigen::VectorXi marker = Eigen::VectorXi::Zero(lin.points.rows());
  // Points on a post's wall (its rim included): on a post face that is not the flat top. A point inside the
  // top near the rim is not one, however close: moved onto the cylinder it could land on a rim point (on
  // the cut of a half post, TetGen's points along the top's diameter end at the rim's exact ends).
  std::vector<char> on_wall(lin.points.rows(), 0);
  for (int f = 0; f < lin.faces.rows(); ++f) {
    for (int k = 0; k < 3; ++k) marker(lin.faces(f, k)) |= lin.face_marker(f);
    if (!(lin.face_marker(f) & kPost)) continue;
    double lo = 1e300, hi = -1e300;
    for (int k = 0; k < 3; ++k)
      lo = std::min(lo, lin.points(lin.faces(f, k), 2)), hi = std::max(hi, lin.points(lin.faces(f, k), 2));
    if (hi - lo > 1e-9 * post_height)
      for (int k = 0; k < 3; ++k) on_wall[lin.faces(f, k)] = 1;
  }
  for (int i = 0; i < lin.points.rows(); ++i) {
    if (marker(i) & kSide) {
      const Vec3 q = shape.on_side({lin.points(i, 0), lin.points(i, 1), lin.points(i, 2)});
      lin.points.row(i) << q[0], q[1], q[2];
    }
    if (marker(i) & kSymmetry) lin.points(i, 1) = 0;  // TetGen's points on the cut, to round-off
    if (marker(i) & kTop) lin.points(i, 2) = shape.top_z(lin.points(i, 0), lin.points(i, 1));
    // TetGen's points on a post's wall or rim lie on the flat chords: onto the cylinder (not those inside its
    // top, which is flat).
    if (on_wall[i])
      for (const Circle& c : posts) {
        Eigen::Vector3d p = lin.points.row(i).transpose();
        if (std::hypot(p.x() - c.centre[0], p.y() - c.centre[1]) < 1.5 * c.radius) {
          moved.push_back({i, lin.points.row(i)});
          onto_cylinder(c, p);
          lin.points.row(i) = p.transpose();
        }
      }
  }
  return moved;
}

// A wall point moved onto the cylinder by its chord's sagitta can turn a flat (sliver) tetrahedron beside
// the wall inside out, which straightening its P2 edges cannot mend: such points go back onto their chords
// (off the cylinder by at most the sagitta L²/8R, as are the mid-edge nodes of their edges, which
// make_quadratic leaves straight).
void unsnap_inverting(LinearTets& lin, const std::vector<std::pair<int, Eigen::RowVector3d>>& moved) {
  if (moved.empty()) return;
  std::map<int, Eigen::RowVector3d> from(moved.begin(), moved.end());
  const auto volume = [&](int t) {
    const Eigen::RowVector3d a = lin.points.row(lin.tets(t, 0));
    return (lin.points.row(lin.tets(t, 1)) - a)
        .cross(lin.points.row(lin.tets(t, 2)) - a)
        .dot(lin.points.row(lin.tets(t, 3)) - a);
  };
  for (int pass = 0; pass < 4; ++pass) {
    int restored = 0;
    for (int t = 0; t < lin.tets.rows(); ++t) {
      if (volume(t) > 0) continue;
      for (int k = 0; k < 4; ++k)
        if (auto it = from.find(lin.tets(t, k)); it != from.end()) {
          lin.points.row(it->first) = it->second;
          from.erase(it);
          ++restored;
        }
    }
    if (restored == 0) return;
  }
}
}  // namespace

void straighten_folded_elements(TetMesh& m) {
  // A pass can fold a neighbour that shares a straightened edge; a few passes settle it (a linear tet with
  // all edges straight is its own straight-sided tet, which TetGen made valid).
  for (int pass = 0; pass < 4; ++pass) {
    int changed = 0;
    for (int t = 0; t < m.num_tets(); ++t) {
      if (!folded(m, t)) continue;
      for (int e = 0; e < 6; ++e)
        m.nodes.row(m.tets(t, 4 + e)) =
            0.5 * (m.nodes.row(m.tets(t, p2::kEdge[e][0])) + m.nodes.row(m.tets(t, p2::kEdge[e][1])));
      ++changed;
    }
    m.straightened += changed;
    if (changed == 0) return;
  }
}

TetMesh build_mesh(const Scene& scene, MeshPart part, double max_tets) {
  const SizingField size(scene, part);
  const bool generated = scene.geometry.kind != GeometryKind::surface;
  if (!generated && part != MeshPart::whole) throw MeshError("an imported skin is meshed whole");
  const SurfaceMesh surface =
      generated ? layer_surface(scene, size, part) : import_surface(scene.geometry.surface.path);
  if (!generated && scene.contact && !over_top(surface, contact_center(scene))) {
    const Vec2 c = contact_center(scene);
    const Eigen::RowVector3d lo = surface.vertices.colwise().minCoeff(),
                             hi = surface.vertices.colwise().maxCoeff();
    char line[512];
    std::snprintf(
        line, sizeof line,
        "contact.indenter.center = (%g, %g): not above the imported skin's top (%s spans x %g to %g, "
        "y %g to %g mm); the indenter must press on the skin",
        c[0], c[1], scene.geometry.surface.path.c_str(), lo[0], hi[0], lo[1], hi[1]);
    throw MeshError(line);
  }
  if (!generated && max_tets > 0) {
    const double volume = signed_volume(surface), fewest = fewest_tets(volume, scene.mesh.h_max);
    if (fewest > max_tets) {
      char line[512];
      std::snprintf(
          line, sizeof line,
          "%s: the surface encloses %.3g mm³, at least %.3g tetrahedra at mesh.h_max = %g mm, above "
          "the %.3g this machine's memory (or --max-dofs) allows; coordinates are read as mm: "
          "scale the surface, or raise mesh.h_max",
          scene.geometry.surface.path.c_str(), volume, fewest, scene.mesh.h_max, max_tets);
      throw MeshError(line);
    }
  }
  const FacetPolicy facets = !generated                        ? FacetPolicy::keep
                             : scene.geometry.ridges.present() ? FacetPolicy::preserve
                                                               : FacetPolicy::merge;
  LinearTets lin = tetrahedralize(surface, size, scene.mesh, facets);
  const std::vector<Circle> posts = post_circles(scene);
  if (generated)
    unsnap_inverting(lin, snap_to_surface(lin, SkinShape(scene.geometry), posts, scene.sensors.post.height));
  TetMesh mesh = make_quadratic(lin.points, lin.tets, lin.faces, lin.face_marker, scene.geometry, posts);
  mesh.part = part;
  straighten_folded_elements(mesh);
  check_no_inverted_element(mesh);
  return mesh;
}

}  // namespace skinfem
