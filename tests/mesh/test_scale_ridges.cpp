// scale_ridges: the same-mesh control of a ridge study. Reference: SkinShape::volume of the skin with ridges
// f times as high (ridges by their cosine series and Bessel integrals, checked against brute force in
// test_shape.cpp), the P2 volume's error bounded by the ridged mesh's own (test_build.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "skinfem/mesh/build.hpp"
#include "skinfem/mesh/quality.hpp"
#include "skinfem/mesh/scale_ridges.hpp"
#include "skinfem/mesh/shape.hpp"

namespace skinfem {
namespace {

Scene ridged(GeometryKind kind, RidgeProfile profile) {
  Scene s;
  s.geometry.kind = kind;
  s.geometry.flat = {1.0, 2.0};
  s.geometry.cap = {20.0, 1.0, 0.0, 0.0, 2.0};
  s.geometry.ridges.period = 0.4;
  s.geometry.ridges.height = 0.1;
  s.geometry.ridges.radius = 1.0;
  s.geometry.ridges.angle_deg = 20;
  s.geometry.ridges.profile = profile;
  s.geometry.ridges.edge_width = 0.1;
  s.geometry.ridges.h = profile == RidgeProfile::rectangular ? 0.1 / 3 : 0.05;
  s.sensors.positions = {{0.0, 0.0}};
  s.mesh.h_min = 0.3;
  s.mesh.h_max = 0.6;
  s.mesh.growth = 1.5;
  return s;
}

TEST(ScaleRidges, GivesTheLowerRidgesOnTheSameElements) {
  for (GeometryKind kind : {GeometryKind::flat, GeometryKind::cap})
    for (RidgeProfile profile : {RidgeProfile::sinusoidal, RidgeProfile::rectangular}) {
      SCOPED_TRACE(std::string(kind == GeometryKind::flat ? "flat" : "cap") +
                   (profile == RidgeProfile::sinusoidal ? " sinusoidal" : " rectangular"));
      const Scene s = ridged(kind, profile);
      const TetMesh m = build_mesh(s);
      const MeshQuality q = assess_quality(m);
      const double v_ridged = SkinShape(s.geometry).volume();
      EXPECT_GT(q.min_jacobian_ratio, 0);
      // The rectangular walls are C¹ only; 2e-5 bounds both profiles' P2 volume error at this size.
      const double tol = 2e-5 * v_ridged;
      EXPECT_NEAR(q.volume_mm3, v_ridged, tol);
      std::printf("%d elements straightened by meshing, volume error %.1e\n", m.straightened,
                  q.volume_mm3 / v_ridged - 1);

      // Rectangular walls: meshed unfolded (above), but the shift folds their thin elements; sinusoidal only.
      if (profile == RidgeProfile::rectangular) continue;
      for (double f : {0.5, 0.02}) {
        SCOPED_TRACE("f " + std::to_string(f));
        const TetMesh c = scale_ridges(m, s.geometry, f);
        EXPECT_EQ(c.tets, m.tets);
        EXPECT_EQ(c.faces, m.faces);
        Geometry lower = s.geometry;
        lower.ridges.height *= f;
        const SkinShape shape(lower);
        // Top vertices move onto the lower ridges (mid-edge nodes may sit on a straightened element's chord;
        // the volume bounds them); the base and the nodes deeper than a period stay.
        double top_off = 0;
        const SkinShape ridged_shape(s.geometry);
        for (int i = 0; i < c.num_nodes(); ++i) {
          const double x = c.nodes(i, 0), y = c.nodes(i, 1);
          if ((c.node_marker(i) & kBase) || m.nodes(i, 2) < ridged_shape.top_z(x, y) - 0.4) {
            EXPECT_EQ(c.nodes(i, 2), m.nodes(i, 2));
          }
          if (i < c.num_vertices && (c.node_marker(i) & kTop) && !(c.node_marker(i) & kSide))
            top_off = std::max(top_off, std::abs(c.nodes(i, 2) - shape.top_z(x, y)));
        }
        EXPECT_LT(top_off, 1e-14);
        const MeshQuality qc = assess_quality(c);
        EXPECT_GT(qc.min_jacobian_ratio, 0);
        EXPECT_NEAR(qc.volume_mm3, shape.volume(), tol);
        std::printf("f %.2f: %d elements straightened (%d by meshing), volume error %.1e\n", f,
                    c.straightened, m.straightened, qc.volume_mm3 / shape.volume() - 1);
      }
    }
}

}  // namespace
}  // namespace skinfem
