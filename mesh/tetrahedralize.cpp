#include "skinfem/mesh/tetrahedralize.hpp"

#include <tetgen.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <mutex>
#include <sstream>
#include <vector>

#include "skinfem/mesh/surface.hpp"

namespace skinfem {

namespace {
std::mutex tetgen_mutex;
const SizingField* active_size = nullptr;  // TetGen's size callback takes no user data

// Called by TetGen's quality refinement (-q) for every tetrahedron for every candidate tetrahedron: split it
// when its longest edge exceeds the target size at its centroid.
bool too_big(REAL* a, REAL* b, REAL* c, REAL* d, REAL*, REAL) {
  REAL* p[4] = {a, b, c, d};
  double longest2 = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) {
      double l2 = 0;
      for (int k = 0; k < 3; ++k) l2 += (p[i][k] - p[j][k]) * (p[i][k] - p[j][k]);
      longest2 = std::max(longest2, l2);
    }
  const double size = active_size->in_volume((a[0] + b[0] + c[0] + d[0]) / 4, (a[1] + b[1] + c[1] + d[1]) / 4,
                                             (a[2] + b[2] + c[2] + d[2]) / 4);
  return longest2 > size * size;
}

std::array<int, 3> sorted(int a, int b, int c) {
  std::array<int, 3> k{a, b, c};
  std::sort(k.begin(), k.end());
  return k;
}
}  // namespace

LinearTets tetrahedralize(const SurfaceMesh& surface, const SizingField& size, const MeshControls& controls,
                          FacetPolicy facets) {
  std::lock_guard<std::mutex> lock(tetgen_mutex);
  active_size = &size;

  tetgenio in, out;
  in.firstnumber = 0;
  in.numberofpoints = surface.vertices.rows();
  in.pointlist = new REAL[3 * in.numberofpoints];
  for (int i = 0; i < in.numberofpoints; ++i) {
    for (int k = 0; k < 3; ++k) in.pointlist[3 * i + k] = surface.vertices(i, k);
  }
  in.numberoffacets = surface.triangles.rows();
  in.facetlist = new tetgenio::facet[in.numberoffacets];
  in.facetmarkerlist = new int[in.numberoffacets];
  for (int f = 0; f < in.numberoffacets; ++f) {
    tetgenio::facet& facet = in.facetlist[f];
    tetgenio::init(&facet);
    facet.numberofpolygons = 1;
    facet.polygonlist = new tetgenio::polygon[1];
    tetgenio::init(&facet.polygonlist[0]);
    facet.polygonlist[0].numberofvertices = 3;
    facet.polygonlist[0].vertexlist = new int[3];
    for (int k = 0; k < 3; ++k) facet.polygonlist[0].vertexlist[k] = surface.triangles(f, k);
    in.facetmarkerlist[f] = surface.marker(f);
  }
  in.tetunsuitable = too_big;

  std::ostringstream sw;
  // TetGen merges coplanar triangles with equal markers into one facet and remeshes it; a region
  // that must keep its outline (a punch disc) carries the extra kKeepOutline bit in its marker.
  sw << "pq" << controls.max_radius_edge << "/" << controls.min_dihedral_deg << "Q";
  std::string switches = sw.str();
  std::vector<char> buf(switches.begin(), switches.end());
  buf.push_back('\0');
  tetgenbehavior behavior;
  if (!behavior.parse_commandline(buf.data())) throw MeshError("TetGen rejected the switches " + switches);
  if (facets != FacetPolicy::merge)
    behavior.facet_ang_tol = 179.9999;                         // merge only coplanar facets (within 2e-6 rad)
  if (facets == FacetPolicy::preserve) behavior.nobisect = 1;  // TetGen's -Y
  try {
    tetrahedralize(&behavior, &in, &out);
  } catch (int code) {
    active_size = nullptr;
    throw MeshError("TetGen failed with code " + std::to_string(code) + " (switches " + switches + ")");
  }
  active_size = nullptr;

  LinearTets r;
  const int base = out.firstnumber;
  r.points.resize(out.numberofpoints, 3);
  for (int i = 0; i < out.numberofpoints; ++i)
    for (int k = 0; k < 3; ++k) r.points(i, k) = out.pointlist[3 * i + k];
  r.tets.resize(out.numberoftetrahedra, 4);
  for (int t = 0; t < out.numberoftetrahedra; ++t) {
    for (int k = 0; k < 4; ++k) r.tets(t, k) = out.tetrahedronlist[t * out.numberofcorners + k] - base;
    const Eigen::Vector3d a = r.points.row(r.tets(t, 0)), b = r.points.row(r.tets(t, 1)),
                          c = r.points.row(r.tets(t, 2)), d = r.points.row(r.tets(t, 3));
    if ((b - a).cross(c - a).dot(d - a) < 0) std::swap(r.tets(t, 1), r.tets(t, 2));
  }

  // TetGen's boundary faces carry the facet markers; take orientation from the tet that owns each face.
  std::map<std::array<int, 3>, int> marker_of;
  for (int f = 0; f < out.numberoftrifaces; ++f) {
    const int* v = &out.trifacelist[3 * f];
    marker_of[sorted(v[0] - base, v[1] - base, v[2] - base)] = out.trifacemarkerlist[f] & ~kKeepOutline;
  }
  std::map<std::array<int, 3>, std::array<int, 4>> face_count;  // key → (count, a, b, c) outward
  static const int local[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};  // outward for det > 0
  for (int t = 0; t < r.tets.rows(); ++t)
    for (const auto& lf : local) {
      const int a = r.tets(t, lf[0]), b = r.tets(t, lf[1]), c = r.tets(t, lf[2]);
      auto& entry = face_count[sorted(a, b, c)];
      entry = {entry[0] + 1, a, b, c};
    }
  std::vector<std::array<int, 4>> faces;
  for (const auto& [key, entry] : face_count)
    if (entry[0] == 1) {
      auto it = marker_of.find(key);
      if (it == marker_of.end() || it->second == 0)
        throw MeshError("TetGen left a boundary face without a marker");
      faces.push_back({entry[1], entry[2], entry[3], it->second});
    }
  r.faces.resize(faces.size(), 3);
  r.face_marker.resize(faces.size());
  for (size_t f = 0; f < faces.size(); ++f) {
    r.faces.row(f) << faces[f][0], faces[f][1], faces[f][2];
    r.face_marker(f) = faces[f][3];
  }
  return r;
}

}  // namespace skinfem
