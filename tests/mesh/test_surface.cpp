// Imported closed surfaces: meshed like generated ones; open or broken ones rejected with a clear error.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "skinfem/mesh/build.hpp"
#include "skinfem/mesh/quality.hpp"
#include "skinfem/mesh/surface.hpp"

namespace skinfem {
namespace {

// A box [−2, 2]² × [0, 1] as ASCII STL, outward facets; `skip` drops one facet to open it.
std::string write_box_stl(const std::string& name, int skip = -1) {
  const double v[8][3] = {{-2, -2, 0}, {2, -2, 0}, {2, 2, 0}, {-2, 2, 0},
                          {-2, -2, 1}, {2, -2, 1}, {2, 2, 1}, {-2, 2, 1}};
  const int f[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                        {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
  std::filesystem::create_directories(SKINFEM_TEST_TMP);
  const std::string path = std::string(SKINFEM_TEST_TMP) + "/" + name;
  std::ofstream out(path);
  out << "solid box\n";
  for (int t = 0; t < 12; ++t) {
    if (t == skip) continue;
    out << " facet normal 0 0 0\n  outer loop\n";
    for (int k = 0; k < 3; ++k)
      out << "   vertex " << v[f[t][k]][0] << " " << v[f[t][k]][1] << " " << v[f[t][k]][2] << "\n";
    out << "  endloop\n endfacet\n";
  }
  out << "endsolid box\n";
  return path;
}

TEST(ImportedSurface, ClosedStlIsMeshedWithBaseTopAndSideMarkers) {
  Scene s;
  s.geometry.kind = GeometryKind::surface;
  s.geometry.surface.path = write_box_stl("box.stl");
  s.sensors.positions = {{0.0, 0.0}};
  s.mesh.h_min = 0.3;
  s.mesh.h_max = 0.8;
  const TetMesh m = build_mesh(s);
  const MeshQuality q = assess_quality(m);
  EXPECT_NEAR(q.volume_mm3, 16.0, 1e-10);  // flat faces: the volume is exact
  double base = 0;
  bool seen[8] = {};
  for (int f = 0; f < m.faces.rows(); ++f) {
    seen[m.face_marker(f)] = true;
    const Eigen::Vector3d a = m.nodes.row(m.faces(f, 0)), b = m.nodes.row(m.faces(f, 1)),
                          c = m.nodes.row(m.faces(f, 2));
    const Eigen::Vector3d n = (b - a).cross(c - a);
    if (m.face_marker(f) == kBase) {
      base += 0.5 * n.norm();
      EXPECT_LT(n.z(), 0);  // outward = downward
    }
    if (m.face_marker(f) == kTop) {
      EXPECT_GT(n.z(), 0);
    }
  }
  EXPECT_TRUE(seen[kBase] && seen[kTop] && seen[kSide]);
  EXPECT_NEAR(base, 16.0, 1e-10);
  EXPECT_GE(q.min_dihedral_deg, 5.0);
  EXPECT_LE(q.max_edge_mm, 0.8 * 1.8);  // interior tets obey the size; boundary edges are split by TetGen
}

TEST(ImportedSurface, OpenStlIsRejectedAsNotWatertight) {
  const std::string path = write_box_stl("open_box.stl", 4);
  try {
    import_surface(path);
    FAIL() << "an open surface was accepted";
  } catch (const MeshError& e) {
    EXPECT_NE(std::string(e.what()).find("not watertight"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("open_box.stl"), std::string::npos) << e.what();
  }
}

TEST(ImportedSurface, MissingFileAndSurfaceWithoutBaseAreRejected) {
  EXPECT_THROW(import_surface(std::string(SKINFEM_TEST_TMP) + "/nope.stl"), MeshError);
  // the same box lifted off z = 0 has no base face
  const std::string path = write_box_stl("lifted.stl");
  std::ifstream in(path);
  const std::string text((std::istreambuf_iterator<char>(in)), {});
  // Every vertex's z, the last number of its line (0 or 1), raised by 10: a "1" put before it.
  std::string lifted;
  for (size_t i = 0; i < text.size(); ++i) {
    const bool z = i + 2 < text.size() && text[i] == ' ' && (text[i + 1] == '0' || text[i + 1] == '1') &&
                   text[i + 2] == '\n';
    lifted += z ? std::string(" 1") : std::string(1, text[i]);
  }
  std::ofstream(path) << lifted;
  try {
    import_surface(path);
    FAIL() << "a surface without base was accepted";
  } catch (const MeshError& e) {
    EXPECT_NE(std::string(e.what()).find("base plane"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace skinfem
