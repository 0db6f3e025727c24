// Contact on the half of a mirror-symmetric skin (contact/contact_solver.hpp's MirrorView) against the full
// body solved on the half's mirrored mesh (mesh/mirror.hpp): the same elements, the whole zone's multipliers
// and a second condensation, so every result agrees to round-off of the two factorizations and LCP solves.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "skinfem/contact/contact_solver.hpp"
#include "skinfem/contact/holes/cover.hpp"
#include "skinfem/contact/holes/scan.hpp"
#include "skinfem/contact/holes/small_hole.hpp"
#include "skinfem/contact/holes/sweep.hpp"
#include "skinfem/contact/metrics.hpp"
#include "skinfem/mesh/build.hpp"
#include "skinfem/mesh/mirror.hpp"
#include "skinfem/scene/texture.hpp"

namespace skinfem::contact {
namespace {

// A plate on a small cap (apex at x = 0.5 on y = 0), 0.3 N, sliding along x, three sensors on y = 0.
Scene plate_on_cap() {
  Scene s;
  s.geometry.kind = GeometryKind::cap;
  s.geometry.cap = {20.0, 3.0, 0.5, 0.0, 6.0};
  s.material = {3.0, 0.5};
  s.sensors.positions = {{0.5, 0.0}, {-1.5, 0.0}, {2.0, 0.0}};
  s.sensors.disc_diameter = 0.2;
  s.mesh.h_min = 0.5, s.mesh.growth = 1.6, s.mesh.h_max = 2.0;
  s.mesh.refine_sensors = false;
  ContactLoad c;
  c.indenter = IndenterKind::plane;
  c.force = 0.3;
  c.zone_radius = 1.6;
  c.h = 0.35;
  c.mu = 0.5;
  c.static_ratio = 0.1;
  s.contact = c;
  return s;
}

struct Side {
  std::unique_ptr<ElasticModel> model;
  std::unique_ptr<Indenter> indenter;
  std::unique_ptr<CondensedContact> condensed;
};

// The sweep of the test below: its hole cuts the hats (contact/holes/cut.hpp), so its path is condensed too.
HoleSweep test_sweep() {
  HoleSweep sweep;
  sweep.from = {-0.8, 0.0}, sweep.to = {1.8, 0.0}, sweep.positions = 9, sweep.hole_diameter = 0.4;
  return sweep;
}

Side condensed_side(const Scene& s, const TetMesh& m) {
  Side x;
  x.model = std::make_unique<ElasticModel>(m, s.material, s.geometry.side, std::vector<Punch>{});
  x.indenter = std::make_unique<Indenter>(s, m);
  const auto zone = mortar_zone(m, contact_center(s), s.contact->zone_radius);
  const HoleSweep sw = test_sweep();
  const std::vector<int> faces = watch_path(m, zone, sw.from, sw.to, 0.5 * sw.hole_diameter);
  x.condensed = std::make_unique<CondensedContact>(
      condense(*x.model, zone, *x.indenter, SensorReadings(m, reading_sites(s.sensors), &x.model->solver()),
               {1, 0}, {}, faces));
  return x;
}

double rel(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return (a - b).cwiseAbs().maxCoeff() / std::max(b.cwiseAbs().maxCoeff(), 1e-300);
}

TEST(MirrorContact, HalfEqualsTheMirroredWholeInEveryFrictionModeWithHoles) {
  const Scene s = plate_on_cap();
  const TetMesh half = build_mesh(s, MeshPart::half_y);
  std::vector<int> source;
  const TetMesh whole = mirror_half(half, &source);
  const Side h = condensed_side(s, half), w = condensed_side(s, whole);
  const MirrorView view =
      mirror_view(whole, source, h.condensed->zone, contact_center(s), s.contact->zone_radius);
  ASSERT_EQ(view.zone.vertices, w.condensed->zone.vertices) << "the view's zone is the whole one";
  std::printf("half %d DOFs, %d multipliers; whole %d DOFs, %d multipliers\n", h.model->solver().free_dofs(),
              h.condensed->zone.size(), w.model->solver().free_dofs(), w.condensed->zone.size());
  EXPECT_LT(h.condensed->zone.size(), 0.6 * w.condensed->zone.size());

  const PlanarFaceIndex top(whole, kTop);
  const Vec2 centre = contact_center(s);
  double worst = 0;
  // Force control, depth control, and force control under a mixed friction law (Coulomb and a shear
  // strength, cut by the holes' exact discs).
  for (int config = 0; config < 3; ++config) {
    ContactLoad load = *s.contact;
    if (config == 1) load.force.reset(), load.depth = 0.02;
    if (config == 2) load.law = FrictionLaw::mixed, load.tau0 = 0.05;
    const ContactSolver full(*w.condensed, load), reduced(*h.condensed, load, &view);
    for (FrictionMode mode :
         {FrictionMode::none, FrictionMode::static_residual, FrictionMode::uncoupled, FrictionMode::coupled})
      // No hole, a hole on the axis, and one on y = 0 across the contact's edge.
      for (const std::vector<Hole>& holes : std::vector<std::vector<Hole>>{
               {}, {Hole{{0.5, 0.0}, 0.4}}, {Hole{{1.2, 0.0}, 0.5}, Hole{{-0.3, 0.0}, 0.3}}}) {
        const auto ex = excluded_by_holes(full.zone(), whole, holes);
        const Eigen::VectorXd cov = hole_cover(full.zone(), whole, holes);
        const ContactResult a = reduced.solve(mode, ex, {}, cov), b = full.solve(mode, ex, {}, cov);
        ASSERT_GT(b.force_N, 0);
        ASSERT_EQ(a.active, b.active) << to_string(mode) << ", " << holes.size() << " holes";
        const ContactMetrics ma = contact_metrics(reduced, whole, top, a, centre),
                             mb = contact_metrics(full, whole, top, b, centre);
        const double gap_scale = b.gap.cwiseAbs().maxCoeff();
        const double errors[] = {rel(a.lambda, b.lambda),
                                 rel(a.readings, b.readings),
                                 (a.gap - b.gap).cwiseAbs().maxCoeff() / gap_scale,
                                 std::abs(a.force_N / b.force_N - 1),
                                 std::abs(a.depth_mm / b.depth_mm - 1),
                                 std::abs(ma.contact_radius_mm / mb.contact_radius_mm - 1),
                                 std::abs(ma.pressure_centroid[0] - mb.pressure_centroid[0]),
                                 std::abs(ma.pressure_centroid[1])};
        for (double e : errors) worst = std::max(worst, e);
      }
    // The sweep through the contact, its hole cutting the hats and as a bulge, both through the whole view.
    HoleSweep sweep = test_sweep();
    const HoleDimples da(reduced, whole, top, s.material.E, s.material.nu),
        db(full, whole, top, s.material.E, s.material.nu);
    for (HoleModel model : {HoleModel::resolved, HoleModel::bulge}) {
      sweep.model = model;
      const SweepResult sa = hole_sweep(reduced, whole, sweep, FrictionMode::coupled, &da),
                        sb = hole_sweep(full, whole, sweep, FrictionMode::coupled, &db);
      ASSERT_GT(sb.varsigma.cwiseAbs().maxCoeff(), 0);
      worst = std::max(worst,
                       (sa.varsigma - sb.varsigma).cwiseAbs().maxCoeff() / sb.varsigma.cwiseAbs().maxCoeff());
    }
    const std::vector<Vec2> centers = hole_sweep(full, whole, sweep, FrictionMode::coupled, &db).centers;
    const Eigen::MatrixXd ha = small_hole_signals(reduced, FrictionMode::coupled, whole, top, centers, 0.1,
                                                  s.material.E, s.material.nu),
                          hb = small_hole_signals(full, FrictionMode::coupled, whole, top, centers, 0.1,
                                                  s.material.E, s.material.nu);
    ASSERT_GT(hb.cwiseAbs().maxCoeff(), 0);
    worst = std::max(worst, (ha - hb).cwiseAbs().maxCoeff() / hb.cwiseAbs().maxCoeff());
  }
  std::printf(
      "max |half − whole| over 4 modes × 3 hole sets × force and depth control and a mixed law, sweep, small "
      "holes: %.2e\n",
      worst);
  // Round-off of two direct factorizations (residual checked at 1e-10 relative) through the condensed
  // compliance and the LCP's principal solves (complementarity to ~1e-13).
  EXPECT_LT(worst, 1e-8);
}

// The skin `m` condensed watching the tracks of `texture` over `scan`.
Side texture_side(const Scene& s, const TetMesh& m, const std::vector<Hole>& texture, const Scan& scan) {
  Side x;
  x.model = std::make_unique<ElasticModel>(m, s.material, s.geometry.side, std::vector<Punch>{});
  x.indenter = std::make_unique<Indenter>(s, m);
  const auto zone = mortar_zone(m, contact_center(s), s.contact->zone_radius);
  std::vector<int> faces;
  for (const HoleTrack& k : hole_tracks(texture, {1, 0}, scan, contact_center(s), s.contact->zone_radius)) {
    const std::vector<int> f = watch_path(m, zone, k.from, k.to, k.radius);
    faces.insert(faces.end(), f.begin(), f.end());
  }
  std::sort(faces.begin(), faces.end());
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  x.condensed = std::make_unique<CondensedContact>(
      condense(*x.model, zone, *x.indenter, SensorReadings(m, reading_sites(s.sensors), &x.model->solver()),
               {1, 0}, {}, faces));
  return x;
}

std::vector<double> scan_u(const Scan& scan) {
  std::vector<double> u;
  for (int i = 0; i < scan.positions(); ++i) u.push_back(scan.u(i));
  return u;
}

// A texture off y = 0 but mirror-symmetric: a hole on the axis and a hole with its image. The half cuts the
// hole above y = 0 and mirrors it (contact/holes/scan.hpp): its scan is the mirrored whole's, and its
// superposition's terms are the axis hole alone and the pair together, each scanned on the whole.
TEST(MirrorContact, HalfScansAMirrorSymmetricTextureAsTheMirroredWhole) {
  Scene s = plate_on_cap();
  s.mesh.h_min = 0.7, s.contact->h = 0.5;  // coarser than the other tests': only the equality is asserted
  const TetMesh half = build_mesh(s, MeshPart::half_y);
  std::vector<int> source;
  const TetMesh whole = mirror_half(half, &source);
  const Hole axis{{-0.6, 0.0}, 0.3}, above{{0.4, 0.45}, 0.3}, below{{0.4, -0.45}, 0.3};
  const std::vector<Hole> texture{axis, above, below};
  const Scan scan{-1.2, 1.2, 0.4};
  const std::vector<double> u = scan_u(scan);
  const Side h = texture_side(s, half, texture, scan), w = texture_side(s, whole, texture, scan);
  const MirrorView view =
      mirror_view(whole, source, h.condensed->zone, contact_center(s), s.contact->zone_radius);
  const ContactSolver full(*w.condensed, *s.contact), reduced(*h.condensed, *s.contact, &view);
  ASSERT_TRUE(reduced.mirrored());
  ASSERT_FALSE(full.mirrored());
  double worst = 0;
  for (FrictionMode mode : {FrictionMode::static_residual, FrictionMode::coupled}) {
    const ScanResult a = texture_scan(reduced, texture, {1, 0}, u, mode),
                     b = texture_scan(full, texture, {1, 0}, u, mode);
    EXPECT_EQ(a.holes_in, b.holes_in) << "a hole above y = 0 counts with its image";
    EXPECT_EQ(*std::max_element(b.holes_in.begin(), b.holes_in.end()), 3);
    const double peak = b.varsigma.cwiseAbs().maxCoeff();
    ASSERT_GT(peak, 0);
    worst = std::max(worst, (a.varsigma - b.varsigma).cwiseAbs().maxCoeff() / peak);
    const Superposition sa = superposed_scan(reduced, texture, {1, 0}, u, mode);
    const Eigen::MatrixXd terms = texture_scan(full, {axis}, {1, 0}, u, mode).varsigma +
                                  texture_scan(full, {above, below}, {1, 0}, u, mode).varsigma;
    worst = std::max(worst, (sa.varsigma - terms).cwiseAbs().maxCoeff() / peak);
    EXPECT_GT(sa.mirror_pair_solves, 0);
    EXPECT_LT(sa.mirror_pair_solves, sa.solves);
    EXPECT_EQ(superposed_scan(full, texture, {1, 0}, u, mode).mirror_pair_solves, 0);
  }
  std::printf("mirror-symmetric texture: max |half − whole| %.2e of the peak\n", worst);
  EXPECT_LT(worst, 1e-8);  // as above: round-off of two factorizations and LCP solves
}

// A groove across the axis (a grating's) is its own mirror image: the half cuts its upper half once, and
// its scan is the mirrored whole's. Cut into two abutting grooves, images of each other, it scans as the
// whole groove on either skin: the cuts of disjoint rectangles add (B, area, gap0 integrate polynomials of
// degree 5 over each part, exactly, by the degree-5 rule).
TEST(MirrorContact, HalfScansAGrooveAcrossTheAxisAsTheMirroredWhole) {
  Scene s = plate_on_cap();
  s.mesh.h_min = 0.7, s.contact->h = 0.5;
  const TetMesh half = build_mesh(s, MeshPart::half_y);
  std::vector<int> source;
  const TetMesh whole = mirror_half(half, &source);
  Hole groove{{0.3, 0.0}, 0.4, 0, 0.5};
  groove.length = 3.6;  // across the zone (radius 1.6)
  Hole upper = groove, lower = groove;
  upper.length = lower.length = 1.8;
  upper.center[1] = 0.9, lower.center[1] = -0.9;
  const Scan scan{-2.0, 2.0, 0.4};
  const std::vector<double> u = scan_u(scan);
  const Side h = texture_side(s, half, {groove}, scan), w = texture_side(s, whole, {groove}, scan);
  const MirrorView view =
      mirror_view(whole, source, h.condensed->zone, contact_center(s), s.contact->zone_radius);
  const ContactSolver full(*w.condensed, *s.contact), reduced(*h.condensed, *s.contact, &view);
  double worst = 0;
  for (FrictionMode mode : {FrictionMode::static_residual, FrictionMode::coupled}) {
    const ScanResult b = texture_scan(full, {groove}, {1, 0}, u, mode);
    const double peak = b.varsigma.cwiseAbs().maxCoeff();
    ASSERT_GT(peak, 0);
    EXPECT_EQ(*std::max_element(b.holes_in.begin(), b.holes_in.end()), 1);
    for (const ScanResult& a : {texture_scan(reduced, {groove}, {1, 0}, u, mode),
                                texture_scan(full, {upper, lower}, {1, 0}, u, mode),
                                texture_scan(reduced, {upper, lower}, {1, 0}, u, mode)})
      worst = std::max(worst, (a.varsigma - b.varsigma).cwiseAbs().maxCoeff() / peak);
  }
  std::printf("groove across the axis: max |half − whole|, |two halves − one| %.2e of the peak\n", worst);
  EXPECT_LT(worst, 1e-8);  // as above: round-off of two factorizations and LCP solves
}

// Posts on y = 0 cut in half: the half's top keeps its own points on the cut, the base has the posts' ends
// there (mesh/surface.cpp), and the cut face is meshed from both. Its mirror is a valid whole whose contact,
// sweep and readings the half reproduces.
// Posts on membrane springs as well: the half's posts on the cut move in their symmetric modes (x, z, tilt
// about y) on half their springs; the whole's in all five, whose antisymmetric ones no symmetric load
// excites.
class MirrorPosts : public testing::TestWithParam<bool> {};

TEST_P(MirrorPosts, HalfWithPostsEqualsTheMirroredWhole) {
  Scene s = plate_on_cap();
  s.sensors.model = SensorModel::post;
  s.sensors.post = {0.2, 0.4};
  if (GetParam()) s.sensors.post.support = {8.0, 3.0, 0.05};
  const TetMesh half = build_mesh(s, MeshPart::half_y);
  std::vector<int> source;
  const TetMesh whole = mirror_half(half, &source);
  const Side h = condensed_side(s, half), w = condensed_side(s, whole);
  const MirrorView view =
      mirror_view(whole, source, h.condensed->zone, contact_center(s), s.contact->zone_radius);
  ASSERT_EQ(view.zone.vertices, w.condensed->zone.vertices);
  const ContactSolver full(*w.condensed, *s.contact), reduced(*h.condensed, *s.contact, &view);
  double worst = 0;
  for (FrictionMode mode : {FrictionMode::none, FrictionMode::coupled}) {
    const ContactResult a = reduced.solve(mode, {}, {}, {}), b = full.solve(mode, {}, {}, {});
    ASSERT_GT(b.force_N, 0);
    ASSERT_EQ(a.active, b.active) << to_string(mode);
    worst = std::max({worst, rel(a.lambda, b.lambda), rel(a.readings, b.readings)});
  }
  const PlanarFaceIndex top(whole, kTop);
  HoleSweep sweep = test_sweep();
  sweep.model = HoleModel::bulge;
  const HoleDimples da(reduced, whole, top, s.material.E, s.material.nu),
      db(full, whole, top, s.material.E, s.material.nu);
  const SweepResult sa = hole_sweep(reduced, whole, sweep, FrictionMode::coupled, &da),
                    sb = hole_sweep(full, whole, sweep, FrictionMode::coupled, &db);
  ASSERT_GT(sb.varsigma.cwiseAbs().maxCoeff(), 0);
  worst =
      std::max(worst, (sa.varsigma - sb.varsigma).cwiseAbs().maxCoeff() / sb.varsigma.cwiseAbs().maxCoeff());
  std::printf("posts: half %d DOFs, whole %d; max |half − whole| %.2e\n", h.model->solver().free_dofs(),
              w.model->solver().free_dofs(), worst);
  EXPECT_LT(worst, 1e-8);  // as above: round-off of two factorizations and LCP solves
}
INSTANTIATE_TEST_SUITE_P(MirrorContact, MirrorPosts, testing::Values(false, true),
                         [](const testing::TestParamInfo<bool>& p) {
                           return p.param ? "OnSprings" : "Held";
                         });

}  // namespace
}  // namespace skinfem::contact
