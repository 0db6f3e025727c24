// Meshing pipeline on caps and flat layers: exact volume and base area, markers, quality, grading.
#include <gtest/gtest.h>

#include <cmath>

#include "../common/convergence.hpp"
#include "skinfem/mesh/build.hpp"
#include "skinfem/mesh/p2_tet.hpp"
#include "skinfem/mesh/quality.hpp"
#include "skinfem/mesh/shape.hpp"
#include "skinfem/mesh/sizing.hpp"
#include "skinfem/mesh/surface.hpp"
#include "skinfem/mesh/surface_quadrature.hpp"
#include "skinfem/scene/load.hpp"

namespace skinfem {
namespace {

// A strongly curved cap (R = 20 mm) so that geometric errors are visible.
Scene small_cap(double scale) {
  Scene s;
  s.geometry.kind = GeometryKind::cap;
  s.geometry.cap = {20.0, 3.0, 0.5, 0.0, 6.0};
  s.sensors.positions = {{0.0, 0.0}};
  s.mesh.h_min = 0.4 * scale;
  s.mesh.h_max = 1.6 * scale;
  s.mesh.growth = 1.5;
  s.mesh.sensor_h = 0.1 * scale;  // the default (the disc radius) at scale 1; scaled, the meshes stay alike
  return s;
}

// Area of the base faces with the quadratic-triangle map (degree-5 face rule).
double base_area(const TetMesh& m) {
  double area = 0;
  for (int f = 0; f < m.faces.rows(); ++f)
    if (m.face_marker(f) == kBase)
      for (const auto& q : face_quadrature(m, f)) area += q.weight;
  return area;
}

TEST(MeshBuild, CapVolumeConvergesToTruncatedCapVolumeAtFourthOrder) {
  // Reference: V = π r_t²(h − R) + 2π/3 (R³ − (R² − r_t²)^{3/2}) (SkinShape::volume). With mid-edge
  // nodes on the exact sphere and cylinder the P2 geometry error is O(h⁴) (interpolation error O(h³)
  // integrated against a smooth surface, with first-order cancellation); straight tets give O(h²).
  std::vector<double> size, err_p2, err_p1;
  for (double scale : {2.0, 1.0, 0.5}) {
    Scene s = small_cap(scale);
    s.mesh.refine_sensors = false;  // the base then takes the top's triangulation: one family of meshes
    const MeshQuality q = assess_quality(build_mesh(s));
    const double exact = SkinShape(s.geometry).volume();
    size.push_back(s.mesh.h_max);
    err_p2.push_back(std::abs(q.volume_mm3 - exact) / exact);
    err_p1.push_back(std::abs(q.linear_volume_mm3 - exact) / exact);
  }
  auto order = [&](const std::vector<double>& err) { return testing::observed_order(size, err); };
  for (size_t i = 0; i < size.size(); ++i)
    std::printf("h_max %.2f: P2 volume error %.2e, straight-sided %.2e\n", size[i], err_p2[i], err_p1[i]);
  std::printf("observed order: P2 %.2f, straight-sided %.2f\n", order(err_p2), order(err_p1));
  EXPECT_GT(order(err_p2), 3.5);
  EXPECT_GT(order(err_p1), 1.7);
  for (size_t i = 0; i < size.size(); ++i) EXPECT_LT(err_p2[i], err_p1[i]);
}

TEST(MeshBuild, BaseAreaIsTheTruncationDisc) {
  // The base rim is a polygon whose mid-edge nodes lie on the circle: P2 area error O(Δθ⁴).
  const Scene s = small_cap(1.0);
  const TetMesh m = build_mesh(s);
  const double exact = M_PI * 6.0 * 6.0;
  const double dtheta = s.mesh.h_max / 6.0;
  EXPECT_NEAR(base_area(m), exact, exact * std::pow(dtheta, 4));
}

TEST(MeshBuild, EllipsoidalCapVolumeConvergesAtFourthOrder) {
  // Reference: SkinShape::volume, the ellipsoid's top integrated by Gauss × periodic trapezoid quadrature
  // (tests/mesh/test_shape.cpp checks it against the sphere's closed form). Mid-edge nodes on the exact
  // ellipsoid give O(h⁴) as on the sphere. The coarsest sphere level (h_max 3.2, two elements across the
  // cap's radius) is still pre-asymptotic here (local order 2.7), so the fit starts one level finer.
  std::vector<double> size, err_p2;
  for (double scale : {1.0, 0.7, 0.5, 0.35}) {
    Scene s = small_cap(scale);
    s.geometry.cap.R_y = 12.0;
    const MeshQuality q = assess_quality(build_mesh(s));
    const double exact = SkinShape(s.geometry).volume();
    size.push_back(s.mesh.h_max);
    err_p2.push_back(std::abs(q.volume_mm3 - exact) / exact);
    std::printf("h_max %.2f: P2 volume error %.2e\n", s.mesh.h_max, err_p2.back());
  }
  const double order = testing::observed_order(size, err_p2);
  std::printf("observed order %.2f\n", order);
  EXPECT_GT(order, 3.5);
}

TEST(MeshBuild, RidgedLayerMeshesUnfoldedAndItsVolumeConverges) {
  // Reference: SkinShape::volume, the ridges by their Bessel integral (tests/mesh/test_shape.cpp checks it
  // against brute-force quadrature). The ridged top is curved on the scale of its elements: TetGen keeps the
  // lifted footprint triangulation (no split points to snap), and the mid-edge nodes on the exact ridges
  // give the P2 geometry error O(h⁴) of a smooth surface.
  std::vector<double> size, err;
  for (double per_period : {5.0, 6.0, 8.0}) {
    Scene s;
    s.geometry.kind = GeometryKind::flat;
    s.geometry.flat = {1.0, 2.0};
    s.geometry.ridges.period = 0.4;
    s.geometry.ridges.height = 0.1;
    s.geometry.ridges.radius = 1.0;
    s.geometry.ridges.h = 0.4 / per_period;
    s.sensors.positions = {{0.0, 0.0}};
    s.mesh.h_min = 0.3;
    s.mesh.h_max = 0.6;
    s.mesh.growth = 1.5;
    const TetMesh m = build_mesh(s);
    const MeshQuality q = assess_quality(m);
    EXPECT_GT(q.min_jacobian_ratio, 0);
    const double exact = SkinShape(s.geometry).volume();
    size.push_back(s.geometry.ridges.h);
    err.push_back(std::abs(q.volume_mm3 - exact) / exact);
    std::printf("ridge h %.4f mm: %d nodes, %d straightened, P2 volume error %.2e\n", size.back(), q.nodes,
                m.straightened, err.back());
  }
  const double order = testing::observed_order(size, err);
  std::printf("observed order %.2f\n", order);
  EXPECT_GT(order, 3.0);
}

TEST(MeshBuild, AFoldedElementIsRefusedWithItsLocation) {
  // Node 4 of a P2 tet sits on edge (0, 1); moved to x0 − (x1 − x0) the map's tangent along that edge at
  // vertex 0 is −3x0 + 4x01 − x1 = −5(x1 − x0): reversed, so det J < 0 there (the element folds).
  TetMesh m = build_mesh(small_cap(1.0));
  EXPECT_NO_THROW(check_no_inverted_element(m));
  EXPECT_GT(assess_quality(m).min_jacobian_ratio, 0);
  const int t = m.num_tets() / 2;
  const Eigen::RowVector3d x0 = m.nodes.row(m.tets(t, 0)), x1 = m.nodes.row(m.tets(t, 1));
  ASSERT_EQ(p2::kEdge[0][0], 0);
  ASSERT_EQ(p2::kEdge[0][1], 1);
  m.nodes.row(m.tets(t, 4)) = x0 - (x1 - x0);
  EXPECT_LT(assess_quality(m).min_jacobian_ratio, 0);
  try {
    check_no_inverted_element(m);
    ADD_FAILURE() << "a folded element was accepted";
  } catch (const MeshError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("is inverted"), std::string::npos) << msg;
    EXPECT_NE(msg.find(" mm"), std::string::npos) << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
  }
}

TEST(MeshBuild, EveryBoundaryFaceIsMarkedAndLiesOnItsExactSurface) {
  const Scene s = small_cap(1.0);
  const TetMesh m = build_mesh(s);
  const SkinShape shape(s.geometry);
  int counts[8] = {};
  for (int f = 0; f < m.faces.rows(); ++f) {
    const int marker = m.face_marker(f);
    ASSERT_TRUE(marker == kBase || marker == kTop || marker == kSide) << "face " << f;
    ++counts[marker];
    for (int k = 0; k < 6; ++k) {
      const Eigen::Vector3d p = m.nodes.row(m.faces(f, k));
      if (marker == kBase) {
        EXPECT_NEAR(p.z(), 0.0, 1e-12);
      } else if (marker == kTop) {
        EXPECT_NEAR(p.z(), shape.top_z(p.x(), p.y()), 1e-12);
      } else {
        EXPECT_NEAR(std::hypot(p.x() - 0.5, p.y()), 6.0, 1e-12);
      }
    }
  }
  EXPECT_GT(counts[kBase], 0);
  EXPECT_GT(counts[kTop], 0);
  EXPECT_GT(counts[kSide], 0);
  // Every node of a marked face carries its marker; interior nodes carry none.
  for (int f = 0; f < m.faces.rows(); ++f)
    for (int k = 0; k < 6; ++k) EXPECT_TRUE(m.node_marker(m.faces(f, k)) & m.face_marker(f));
}

TEST(MeshBuild, QualityBoundsHoldAndNoElementIsInverted) {
  for (GeometryKind kind : {GeometryKind::cap, GeometryKind::flat}) {
    Scene s = small_cap(1.0);
    s.geometry.kind = kind;
    s.geometry.flat = {3.0, 6.0};
    const TetMesh m = build_mesh(s);
    const MeshQuality q = assess_quality(m);
    EXPECT_GE(q.min_dihedral_deg, 5.0);
    EXPECT_GT(q.min_jacobian_ratio, 0.5);  // curved elements stay close to their straight shape
    // TetGen's radius-edge bound is guaranteed away from the preserved surface (-Y).
    for (int t = 0; t < m.num_tets(); ++t) {
      bool touches_boundary = false;
      for (int k = 0; k < 4; ++k) touches_boundary |= m.node_marker(m.tets(t, k)) != 0;
      if (touches_boundary) continue;
      Eigen::Matrix3d A;
      Eigen::Vector3d b;
      const Eigen::Vector3d p0 = m.nodes.row(m.tets(t, 0));
      double shortest = 1e300;
      for (int i = 1; i < 4; ++i) {
        const Eigen::Vector3d d = m.nodes.row(m.tets(t, i)).transpose() - p0;
        A.row(i - 1) = 2 * d.transpose();
        b[i - 1] = d.squaredNorm();
      }
      for (const auto& e : p2::kEdge)
        shortest = std::min(shortest, (m.nodes.row(m.tets(t, e[0])) - m.nodes.row(m.tets(t, e[1]))).norm());
      ASSERT_LE(A.fullPivLu().solve(b).norm() / shortest, s.mesh.max_radius_edge * (1 + 1e-9)) << "tet " << t;
    }
  }
}

TEST(MeshBuild, ElementsAreSmallNearRegionsOfInterestAndLargeFarAway) {
  Scene s = small_cap(1.0);
  s.mesh.h_min = 0.2;
  s.mesh.h_max = 1.5;
  const TetMesh m = build_mesh(s);
  double near_max = 0, far_sum = 0;
  int far_n = 0;
  for (int t = 0; t < m.num_tets(); ++t) {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int k = 0; k < 4; ++k) c += m.nodes.row(m.tets(t, k)).transpose() / 4;
    const double r = std::hypot(c.x(), c.y());  // the sensor disc (radius 0.1) is at the origin, on the base
    if (r < 0.1 && c.z() < 0.2) near_max = std::max(near_max, tet_longest_edge(m, t));
    if (r > 4.0) far_sum += tet_longest_edge(m, t), ++far_n;
  }
  // The sizing field bounds the longest edge at the centroid by sensor_h + (g − 1)·distance (height < 0.2),
  // with (g − 1)·0.2 to spare as before for the faces, which the surface mesher sizes.
  EXPECT_LE(near_max, 0.1 + 0.5 * 0.2 + 0.5 * 0.2);
  EXPECT_GT(far_sum / far_n, 0.5 * 1.5);
}

// The half y >= 0 of a mirror-symmetric skin is meshed as the whole one seen on that half: a region at
// y < 0 refines it where its mirror image lies (it was dropped: a region at y = −3 gave 10,581 nodes, its
// image at y = +3 182,872). The two fields are the same function on the half, so the meshes are identical.
TEST(MeshBuild, HalfMeshKeepsTheRefinementOfRegionsOnEitherSide) {
  const auto half_nodes = [](double region_y) {
    Scene s = small_cap(1.0);
    if (region_y != 0) s.mesh.regions = {{{0.5, region_y}, {0.5, region_y}, 0.5, 0.2}};
    return build_mesh(s, MeshPart::half_y).num_nodes();
  };
  const int none = half_nodes(0), above = half_nodes(2.5), below = half_nodes(-2.5);
  EXPECT_EQ(below, above);
  EXPECT_GT(below, 1.3 * none) << "the region below y = 0 did not refine the half (" << none << " nodes)";
}

// With posts on the cut, the half's cut is its own face (the base there is refined at each post's end). A
// cut point the rim's sizing put 4e-4 mm from a post's end once stayed there, beside elements of 0.1 mm: the
// half of candelier2011 with posts at scale 2 had 3.0× the tets of the whole's side y > 0, and its cut a
// 3.9e-4 mm edge. Both halves are meshed from the same sizing field; apart from the cut face, TetGen's
// points differ only by where refinement happens to put them (on the same scene's discs, 1.13×).
TEST(MeshBuild, HalfWithPostsOnTheCutHasTheWholesElements) {
  Scene s = load_scene(std::string(SKINFEM_SOURCE_DIR) + "/scenes/candelier2011.json");
  s.sensors.model = SensorModel::post;
  s = scaled_scene(s, 2.0);
  const TetMesh whole = build_mesh(s), half = build_mesh(s, MeshPart::half_y);
  int whole_side = 0;
  for (int e = 0; e < whole.num_tets(); ++e) {
    double y = 0;
    for (int k = 0; k < 4; ++k) y += whole.nodes(whole.tets(e, k), 1) / 4;
    whole_side += y > 0;
  }
  // The shortest edge of the cut face against the sizing field at its midpoint.
  const SizingField size(s, MeshPart::half_y);
  double shortest = 1e300;
  for (int f = 0; f < half.faces.rows(); ++f) {
    if (half.face_marker(f) != kSymmetry) continue;
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d a = half.nodes.row(half.faces(f, k)),
                            b = half.nodes.row(half.faces(f, (k + 1) % 3));
      const Eigen::Vector3d m = (a + b) / 2;
      shortest = std::min(shortest, (a - b).norm() / size.in_volume(m.x(), m.y(), m.z()));
    }
  }
  std::printf("half %d tets, whole %d (%d with y > 0); shortest cut edge %.3f of the size there\n",
              half.num_tets(), whole.num_tets(), whole_side, shortest);
  EXPECT_LT(half.num_tets(), 1.25 * whole_side);
  EXPECT_GT(shortest, 0.1);
}

double size_top_z(const Scene& s, double x, double y) { return SkinShape(s.geometry).top_z(x, y); }

// Mean edge length of the faces with `marker` whose centroid (x, y) passes `keep`, mm (0 if none).
template <class Keep>
double mean_face_edge(const TetMesh& m, int marker, Keep keep) {
  double sum = 0;
  int n = 0;
  for (int f = 0; f < m.faces.rows(); ++f) {
    if (m.face_marker(f) != marker) continue;
    const Eigen::Vector3d a = m.nodes.row(m.faces(f, 0)), b = m.nodes.row(m.faces(f, 1)),
                          d = m.nodes.row(m.faces(f, 2));
    const Eigen::Vector3d g = (a + b + d) / 3;
    if (!keep(g.x(), g.y())) continue;
    sum += ((a - b).norm() + (b - d).norm() + (d - a).norm()) / 3, ++n;
  }
  return n ? sum / n : 0.0;
}

// A sensor disc (radius 0.1 at the origin) is a region at the base of size mesh.sensor_h (default: the disc
// radius), growing as h + (g − 1)·distance with the height counted.
TEST(MeshBuild, SensorDiscsRefineTheBaseAndGradeUpwards) {
  Scene s = small_cap(1.0);  // h_min 0.4, h_max 1.6, growth 1.5, sensor at the origin, disc diameter 0.2
  s.mesh.sensor_h = 0;       // the default
  const SizingField size(s);
  EXPECT_DOUBLE_EQ(sensor_mesh_size(s), 0.1);
  EXPECT_DOUBLE_EQ(size.on_base(0, 0), 0.1);
  EXPECT_NEAR(size.on_base(0.6, 0), 0.1 + 0.5 * 0.5, 1e-12);  // the column would give 0.4 + 0.5·0.5
  EXPECT_NEAR(size.in_volume(0, 0, 0.4), 0.1 + 0.5 * 0.4, 1e-12);
  EXPECT_NEAR(size.in_volume(0, 0, 1.0), 0.1 + 0.5 * 1.0, 1e-12);
  EXPECT_NEAR(size(0, 0), 0.1 + 0.5 * size_top_z(s, 0, 0), 1e-12);  // the top, about 3 mm above the disc

  auto mean_base_edge_on_disc = [](const TetMesh& m) {
    return mean_face_edge(m, kBase, [](double x, double y) { return std::hypot(x, y) <= 0.3; });
  };
  const double fine = mean_base_edge_on_disc(build_mesh(s));
  s.mesh.sensor_h = s.mesh.h_min;
  const SizingField coarser(s);
  EXPECT_DOUBLE_EQ(coarser.on_base(0, 0), 0.4);
  const double coarse = mean_base_edge_on_disc(build_mesh(s));
  std::printf("mean base edge within 0.3 mm of the disc centre: %.3f mm (sensor_h 0.1), %.3f mm (0.4)\n",
              fine, coarse);
  // Within 0.3 mm of the centre the bounds are 0.1…0.2 and 0.4…0.5 mm; edges sit at about 0.6–0.8 of them.
  EXPECT_LT(fine, 0.2);
  EXPECT_GT(coarse, 2 * fine);
}

// With a contact, the candidate zone (about the apex for a plate on a cap) gets contact.h, a hole its h (or
// contact.h), and the sweep path (radius hole_diameter/2 + sweep.h about the segment) gets sweep.h; the size
// grows as h + (g − 1)·distance.
TEST(MeshBuild, ContactZoneAndSweepPathAreRegionsOfInterest) {
  Scene s = small_cap(1.0);  // apex (0.5, 0), h_min 0.4, h_max 1.6, growth 1.5
  s.mesh.refine_sensors = false;
  s.sensors.positions = {{-4.0, 0.0}};  // away from the probes below
  ContactLoad c;
  c.indenter = IndenterKind::plane;
  c.force = 0.8;
  c.zone_radius = 1.0;
  c.h = 0.3;
  c.sweep = HoleSweep{{-2, 2}, {2, 2}, 11, 0.5, 0.2};           // region radius 0.25 + 0.2 = 0.45 about y = 2
  c.holes = {Hole{{-2, -2}, 0.4, 0.1}, Hole{{2, -2}, 0.4, 0}};  // its own size; the zone's
  s.contact = c;
  const SizingField size(s);
  EXPECT_DOUBLE_EQ(size(0.5, 0), 0.3);                 // the zone's centre, the apex
  EXPECT_DOUBLE_EQ(size(1.4, 0), 0.3);                 // inside the zone
  EXPECT_DOUBLE_EQ(size(2.5, 0), 0.3 + 0.5 * 1.0);     // 1 mm outside it
  EXPECT_DOUBLE_EQ(size(-1.5, 2.4), 0.2);              // on the sweep path
  EXPECT_NEAR(size(0, 1.5), 0.2 + 0.5 * 0.05, 1e-12);  // 0.05 mm outside it
  EXPECT_DOUBLE_EQ(size(-5, -5), 1.6);                 // far: h_max
  EXPECT_DOUBLE_EQ(size(-2, -2), 0.1);                 // a hole with its own size
  EXPECT_DOUBLE_EQ(size(2.1, -2), 0.3);                // a hole with the zone's
  // Contact regions sit at the top: below it the distance counts the depth (the top is at z = 3 on the apex).
  EXPECT_NEAR(size.in_volume(0.5, 0, 2.0), 0.3 + 0.5 * 1.0, 1e-12);
  EXPECT_NEAR(size.in_volume(2.5, 0, size_top_z(s, 2.5, 0) - 1.0), 0.3 + 0.5 * std::sqrt(2.0), 1e-12);
  EXPECT_DOUBLE_EQ(size.on_base(0.5, 0), 1.6);   // 0.3 + 0.5·3 = 1.8 exceeds h_max
  EXPECT_DOUBLE_EQ(size.on_base(-4.0, 0), 0.3);  // a sensor: the contact's size is carried down to it

  c.sweep->h = 0;  // no refinement along the path; the zone's size then grows to it
  c.h = 0;         // the zone takes mesh.h_min
  s.contact = c;
  const SizingField coarse(s);
  EXPECT_DOUBLE_EQ(coarse(0.5, 0), 0.4);
  EXPECT_NEAR(coarse(0.5, 2.4), 0.4 + 0.5 * 1.4, 1e-12);
}

// The contact zone refines the top face only: the base under it gets its own, coarser triangulation, and
// the sensor discs (through the thickness) still refine the base.
TEST(MeshBuild, ContactRefinementGradesWithDepth) {
  Scene s = small_cap(1.0);
  ContactLoad c;
  c.indenter = IndenterKind::plane;
  c.force = 0.8;
  c.zone_radius = 2.0;
  c.h = 0.25;
  s.contact = c;
  const TetMesh m = build_mesh(s);
  auto mean_edge = [&](int marker) {
    return mean_face_edge(m, marker, [](double x, double y) {
      return std::hypot(x - 0.5, y) <= 1.5 && std::hypot(x, y) >= 0.6;
    });
  };
  // Sizes bound the longest edge: top ≤ 0.25; base, 3 mm below, 0.25 + 0.5·3 (or the sensor disc's 0.4 +
  // 0.5·d, at least 0.65 in this ring). Means sit at about 0.6–0.8 of the bound.
  EXPECT_LT(mean_edge(kTop), 0.25);
  EXPECT_GT(mean_edge(kBase), 2 * mean_edge(kTop));
}

// Top and base are triangulated separately under a contact and must meet on the same rim: for every zone
// size the surface is closed (else TetGen is never reached) and the volume exact (a flat layer).
TEST(MeshBuild, TopAndBaseRimsAgreeForEveryContactSize) {
  Scene s = load_scene(std::string(SKINFEM_SOURCE_DIR) + "/tests/mesh/data/hertz_layer.json");
  for (double h : {0.8, 0.6, 0.5, 0.4}) {
    s.contact->h = h;
    const MeshQuality q = assess_quality(build_mesh(s));
    EXPECT_NEAR(q.volume_mm3, 30.0 * 30.0 * 3.04, 1e-9 * q.volume_mm3) << "contact.h " << h;
  }
}

TEST(MeshBuild, FlatLayerVolumeIsExact) {
  Scene s = small_cap(1.0);
  s.geometry.kind = GeometryKind::flat;
  s.geometry.flat = {2.0, 4.0};
  const MeshQuality q = assess_quality(build_mesh(s));
  EXPECT_NEAR(q.volume_mm3, 8.0 * 8.0 * 2.0, 1e-10);
  EXPECT_NEAR(q.min_jacobian_ratio, 1.0, 1e-12);  // no curved face: every element is affine
}

}  // namespace
}  // namespace skinfem

namespace skinfem {
namespace {

// A punch whose outline crosses or touches a post's (issue 57: a punch 0.15–0.35 mm from a post's axis
// failed with "surface is not watertight" or crashed in CGAL: the crossing points lay on neither circle, so
// the post's ring on the base was lost). The top then follows the punches and the base the posts, each on
// its own triangulation: the skin's volume is the box's less the post's cylinder, and no top face
// straddles the punch's edge. The volume's bound, relative to the cylinder's: its P2 wall on an octagon at
// worst, θ⁴/480 = 7.8e-4 (θ = 2π/8), plus one element near the wall straightened (its arc segment,
// θ³/(12π) = 1.3e-2).
TEST(MeshBuild, APunchOverAPostsOutlineMeshes) {
  for (double d : {0.15, 0.2, 0.25, 0.3, 0.35}) {
    Scene s = small_cap(1.0);
    s.geometry.kind = GeometryKind::flat;
    s.geometry.flat = {3.0, 6.0};
    s.sensors.model = SensorModel::post;
    s.sensors.post.diameter = 0.2;
    s.sensors.post.height = 0.4;
    s.loads.punches = {Punch{{d, 0.0}, 0.5, 1.0, std::nullopt}};
    const TetMesh m = build_mesh(s);
    const double post = M_PI * 0.1 * 0.1 * 0.4, theta = M_PI / 4;
    EXPECT_NEAR(assess_quality(m).volume_mm3, 12.0 * 12.0 * 3.0 - post,
                post * (std::pow(theta, 4) / 480 + std::pow(theta, 3) / (12 * M_PI)))
        << "punch at " << d;
    int straddling = 0;
    for (int f = 0; f < m.faces.rows(); ++f) {
      if (m.face_marker(f) != kTop) continue;
      bool in = false, out = false;
      for (int k = 0; k < 3; ++k) {
        const double r = std::hypot(m.nodes(m.faces(f, k), 0) - d, m.nodes(m.faces(f, k), 1));
        in |= r < 0.25 * (1 - 1e-9);
        out |= r > 0.25 * (1 + 1e-9);
      }
      straddling += in && out;
    }
    EXPECT_EQ(straddling, 0) << "punch at " << d;
  }
}

TEST(MeshBuild, TopFacesFollowThePunchEdge) {
  // A rigid punch holds exactly its disc only if no top face straddles the punch circle: every
  // face has its corners all within or all outside (corners on the circle count as both).
  for (GeometryKind kind : {GeometryKind::flat, GeometryKind::cap}) {
    Scene s = small_cap(1.0);
    s.geometry.kind = kind;
    s.geometry.flat = {3.0, 6.0};
    s.loads.punches = {Punch{{0.7, -0.3}, 0.5, 1.0, std::nullopt}};
    const TetMesh m = build_mesh(s);
    int straddling = 0, inside = 0;
    for (int f = 0; f < m.faces.rows(); ++f) {
      if (m.face_marker(f) != kTop) continue;
      bool in = false, out = false;
      for (int k = 0; k < 3; ++k) {
        const double r = std::hypot(m.nodes(m.faces(f, k), 0) - 0.7, m.nodes(m.faces(f, k), 1) + 0.3);
        in |= r < 0.25 * (1 - 1e-9);
        out |= r > 0.25 * (1 + 1e-9);
      }
      straddling += in && out;
      inside += in && !out;
    }
    EXPECT_EQ(straddling, 0);
    EXPECT_GT(inside, 0);
  }
}

}  // namespace
}  // namespace skinfem
