// Post sensors (scene.hpp's PostSensor): a rigid cylinder standing on the base, bonded to the skin, meshed as
// a cavity (mesh/surface.hpp) and read as the force on it over its cross-section (fem/sensor_reading.hpp).
// References: the exact cylinder (every P2 node of the wall and rim on it), the exact volume of the layer
// less the post, statics (the reactions of base and post balance the load), and Maxwell–Betti (the adjoint
// reading of a unit load equals the forward reading of the direct solve, a second method).
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <cstdio>

#include "../common/short_posts.hpp"
#include "skinfem/fem/elastic_model.hpp"
#include "skinfem/fem/sensor_reading.hpp"
#include "skinfem/green/fe_green.hpp"
#include "skinfem/mesh/build.hpp"
#include "skinfem/mesh/quality.hpp"
#include "skinfem/mesh/surface_quadrature.hpp"
#include "skinfem/scene/load.hpp"

namespace skinfem {
namespace {

constexpr double kH = 1.5, kHalfWidth = 3.0, kDiameter = 0.2, kHeight = 0.3;  // mm

Scene post_scene() {
  Scene s;
  s.geometry.kind = GeometryKind::flat;
  s.geometry.flat = {kH, kHalfWidth};
  s.sensors.positions = {{0, 0}, {-1.0, 0.5}};
  s.sensors.model = SensorModel::post;
  s.sensors.post = {kDiameter, kHeight};
  s.mesh.h_min = 0.3;
  s.mesh.h_max = 0.8;
  s.mesh.growth = 1.6;
  return s;
}

const TetMesh& post_mesh() {
  static const TetMesh m = build_mesh(post_scene());
  return m;
}

// The free-sided skin on that mesh, factored once for the tests that only solve on it (the suite runs as one
// process: tests/CMakeLists.txt, shared_fixture_suites).
const ElasticModel& free_model() {
  static const ElasticModel model(post_mesh(), post_scene().material, SideCondition::free,
                                  std::vector<Punch>{});
  return model;
}

TEST(PostSensor, TheCavityIsTheExactCylinder) {
  const TetMesh& m = post_mesh();
  const Scene s = post_scene();
  int wall_nodes = 0;
  for (int n = 0; n < m.num_nodes(); ++n) {
    if (!(m.node_marker(n) & kPost)) continue;
    double d = 1e300;
    for (const Vec2& c : s.sensors.positions)
      d = std::min(d, std::hypot(m.nodes(n, 0) - c[0], m.nodes(n, 1) - c[1]));
    const double z = m.nodes(n, 2);
    EXPECT_LE(z, kHeight + 1e-12);
    EXPECT_LE(d, 0.5 * kDiameter + 1e-12);
    if (z < kHeight - 1e-12) {  // on the wall (or its foot on the base): on the cylinder to round-off
      EXPECT_NEAR(d, 0.5 * kDiameter, 1e-12) << "node " << n;
      ++wall_nodes;
    }
  }
  EXPECT_GT(wall_nodes, 2 * 12);  // both posts, every wall node checked
  // The skin is the layer less both posts: the P2 wall's volume error is O(h⁴/R³) per element, far below
  // 1e-3 of a post's volume at these sizes.
  const double post_volume = M_PI * 0.25 * kDiameter * kDiameter * kHeight;
  EXPECT_NEAR(assess_quality(m).volume_mm3, 4 * kHalfWidth * kHalfWidth * kH - 2 * post_volume,
              1e-3 * post_volume);
  EXPECT_EQ(m.straightened, 0);
}

// On the half mesh a post on the cut has its top's diameter along y = 0, ending at the rim's exact ends.
// Points TetGen puts inside the top near the rim are not the rim's: moved onto the cylinder, one landed on
// an end and folded its element (the paper's skin with posts and its hole path meshed at 0.25 and 0.2 mm).
TEST(PostSensor, HalfPostTopsNearTheRimStayFlatAndUnfolded) {
  for (const char* h : {"0.25", "0.2"}) {
    const Scene s = parse_scene(std::string(R"({"name": "posts",
      "geometry": {"type": "cap", "R": 129.7, "h": 3.04, "apex": [0.5, 0.0], "truncation_radius": 18.0},
      "material": {"E": 3.0, "nu": 0.5},
      "sensors": {"line": {"start": [-4.5, 0.0], "step": [1.0, 0.0], "count": 10}, "model": "post"},
      "mesh": {"h_min": 0.25, "growth": 1.7, "h_max": 3.0,
               "regions": [{"from": [-4.5, 0.0], "to": [4.5, 0.0], "radius": 1.0, "h": 0.6}]},
      "contact": {"indenter": {"type": "plane"}, "force": 0.8, "zone_radius": 4.0, "h": 0.6,
                  "sweep": {"from": [-2.8, 0.0], "to": [3.8, 0.0], "hole_diameter": 0.5, "h": )") +
                                    h + "}}}",
                                "posts.json");
    TetMesh m;
    ASSERT_NO_THROW(m = build_mesh(s, MeshPart::half_y)) << "path h " << h;
    EXPECT_GT(assess_quality(m).min_jacobian_ratio, 0.0) << "path h " << h;
    // Every post node is on its wall (on the cylinder) or on its flat top, inside the rim.
    for (int n = 0; n < m.num_nodes(); ++n) {
      if (!(m.node_marker(n) & kPost)) continue;
      double d = 1e300;
      for (const Vec2& c : s.sensors.positions)
        d = std::min(d, std::hypot(m.nodes(n, 0) - c[0], m.nodes(n, 1) - c[1]));
      if (m.nodes(n, 2) < s.sensors.post.height - 1e-12)
        EXPECT_NEAR(d, 0.5 * s.sensors.post.diameter, 1e-12) << "node " << n;
      else
        EXPECT_LE(d, 0.5 * s.sensors.post.diameter + 1e-12) << "node " << n;
    }
  }
}

// TetGen's points on a post's wall are moved onto the cylinder; on the paper's layer with the post meshed at
// 0.025 mm one of them turned a sliver beside the wall inside out (an inverted linear element, which no P2
// straightening mends, and the scene did not mesh). Such points stay on their chords.
TEST(PostSensor, FinePostMeshesStayUnfolded) {
  const Scene s = parse_scene(R"({"name": "fine_post",
    "geometry": {"type": "flat", "h": 3.04, "half_width": 20.0, "side": "free"},
    "material": {"E": 3.0, "nu": 0.5},
    "sensors": {"positions": [[0.0, 0.0]], "model": "post"},
    "mesh": {"h_min": 0.2, "growth": 1.7, "h_max": 3.0, "sensor_h": 0.025,
             "regions": [{"from": [0.0, 0.0], "to": [0.0, 0.0], "radius": 1.0, "h": 0.6},
                         {"from": [-12.5, 0.0], "to": [12.5, 0.0], "radius": 0.5, "h": 1.0}]},
    "loads": {"punches": [{"center": [1.0, 0.0], "diameter": 0.5, "force": 1.0}]}})",
                              "fine_post.json");
  TetMesh m;
  ASSERT_NO_THROW(m = build_mesh(s));
  EXPECT_GT(assess_quality(m).min_jacobian_ratio, 0.0);
  // The wall's nodes on the cylinder, but for the few kept on their chords and the mid-edge nodes of their
  // edges (and of straightened elements): inside it by at most the sagitta of a chord a few elements long.
  int wall = 0, off = 0;
  double worst = 0;
  for (int n = 0; n < m.num_nodes(); ++n)
    if ((m.node_marker(n) & kPost) && m.nodes(n, 2) < 0.4 - 1e-12) {
      const double gap = 0.1 - std::hypot(m.nodes(n, 0), m.nodes(n, 1));
      ++wall;
      off += std::abs(gap) > 1e-12;
      worst = std::max(worst, gap);
      EXPECT_GT(gap, -1e-12) << "node " << n << " outside the post";
    }
  std::printf("%d of %d wall nodes off the cylinder, at most %.2e mm inside (straightened elements: %d)\n",
              off, wall, worst, m.straightened);
  EXPECT_LT(off, wall / 20);
  const double chord = 4 * 0.025;  // four elements of the post's size
  EXPECT_LT(worst, chord * chord / (8 * 0.1));
}

TEST(PostSensor, BaseAndPostsBalanceTheLoad) {
  const TetMesh& m = post_mesh();
  const ElasticModel& model = free_model();
  const TractionPatch patch{{0.6, 0.2}, 0.5, {0.3, 0.1, -1}, 1.0};
  const LoadCaseResult r = model.solve(model.patch_load(patch), {});
  // The force on the posts: every post node's tangential reaction, the normal one off the foot (where the
  // post meets the base, the normal reaction is the base's: fem/sensor_reading.hpp, Post::on_foot).
  Eigen::Vector3d total = Eigen::Vector3d::Zero(), on_posts = Eigen::Vector3d::Zero(), on_feet_z(0, 0, 0);
  for (int n = 0; n < m.num_nodes(); ++n) {
    total += r.reactions.segment<3>(3 * n);
    if (!(m.node_marker(n) & kPost)) continue;
    on_posts += r.reactions.segment<3>(3 * n);
    if (m.node_marker(n) & kBase)
      on_posts.z() -= r.reactions[3 * n + 2], on_feet_z.z() += r.reactions[3 * n + 2];
  }
  const Eigen::Vector3d applied(r.applied_force_N[0], r.applied_force_N[1], r.applied_force_N[2]);
  EXPECT_LT((total + applied).norm(), 1e-9 * applied.norm());
  // The posts carry a share of it, read by the seam as force over cross-section (σ_z = R_z / A, σ_x = −R_x /
  // A).
  const SensorReadings readings(m, reading_sites(post_scene().sensors));
  const double area = M_PI * 0.25 * kDiameter * kDiameter;
  Eigen::Vector3d read = Eigen::Vector3d::Zero();
  for (int k = 0; k < readings.size(); ++k) {
    const SensorReading v = readings.read(k, r.reactions);
    read += Eigen::Vector3d(-v.sigma_x * area, 0, v.sigma_z * area);
  }
  EXPECT_NEAR(read.x(), on_posts.x(), 1e-12 * on_posts.norm());
  EXPECT_NEAR(read.z(), on_posts.z(), 1e-12 * on_posts.norm());
  EXPECT_GT(on_posts.norm(), 1e-3 * applied.norm());           // the post is not a zero-force no-op
  EXPECT_GT(std::abs(on_feet_z.z()), 1e-3 * on_posts.norm());  // and the foot's share is not negligible
}

TEST(PostSensor, UniformPressureIsReadExactly) {
  // Reference: the hydrostatic state (issue 57, item 2). A uniform pressure q on the whole top of a layer
  // whose base and sides are held has the exact solution u = 0, p = q: it meets every boundary condition and
  // lies in the P2–P1 space, and on curved (isoparametric) elements Bᵀ1 is integrated exactly (cof(J)·∇φ is
  // of degree 3, the rule of degree 5). So the discrete solution is that state when the load vector is the
  // consistent one, and each post, whose top carries q and whose wall carries a pressure with no net force,
  // reads σ_z = q·A/(πr²), A its meshed cross-section, and σ_x = 0. A is the area inside the P2 circle of its
  // rim, which falls short of πr² by 8e-4 with 8 arcs (the post's mesh, 0.6 of its radius, gives more): the
  // bound on σ_z. A rule over the disc that dropped points into whatever faces held them read 1.1 % above q
  // at a post 1 mm from a 20 mm patch's centre.
  const TetMesh& m = post_mesh();
  const Scene s = post_scene();
  const ElasticModel model(m, s.material, SideCondition::fixed, std::vector<Punch>{});
  const double q = 0.01;  // MPa
  const double top_area = 4 * kHalfWidth * kHalfWidth;
  // The disc covers the square top; patch_load spreads the force over the part on the top.
  const TractionPatch patch{{0, 0}, 3 * kHalfWidth, {0, 0, -1}, q * top_area};
  const LoadCaseResult res = model.solve(model.patch_load(patch), {});
  double u_max = 0;
  for (int i = 0; i < res.solution.u.size(); ++i) u_max = std::max(u_max, std::abs(res.solution.u[i]));
  EXPECT_LT(u_max, 1e-9 * q * kH / (s.material.E / 3));  // the hydrostatic state, at round-off
  const SensorReadings readings(m, reading_sites(s.sensors));
  for (int k = 0; k < readings.size(); ++k) {
    const SensorReading v = readings.read(k, res.reactions);
    std::printf("post %d under %.3g MPa: sigma_z / q - 1 = %.2e, sigma_x / q = %.1e; max |u| %.1e mm\n",
                k + 1, q, v.sigma_z / q - 1, v.sigma_x / q, u_max);
    EXPECT_NEAR(v.sigma_z, q, 8e-4 * q);
    EXPECT_NEAR(v.sigma_x, 0, 1e-9 * q);
  }
}

TEST(PostSensor, AdjointReadingIsTheForwardOne) {
  // Maxwell–Betti on one mesh: the adjoint (the post displaced rigidly, the rest of the base held) gives the
  // reading of a unit point force anywhere on the top; the direct solve of that force gives it through the
  // reactions. Both sides are the same discrete system, so they agree to the solver's residual (1e-6 of the
  // peak is the issue's requirement, round-off is what the algebra allows).
  const TetMesh& m = post_mesh();
  const Scene s = post_scene();
  const ElasticModel& model = free_model();
  const green::FeGreen fe(model, s.sensors);
  const SensorReadings readings(m, reading_sites(s.sensors));
  double peak = 0, worst = 0;
  for (const auto& [x, y] : std::vector<std::pair<double, double>>{{0.5, 0}, {-0.3, 0.4}, {1.2, -0.8}}) {
    for (const Eigen::Vector3d& dir : {Eigen::Vector3d(0, 0, -1), Eigen::Vector3d(1, 0, 0)}) {
      const LoadCaseResult r = model.solve(model.point_load(x, y, dir), {});
      for (int k = 0; k < readings.size(); ++k) {
        const SensorReading direct = readings.read(k, r.reactions);
        const green::GreenSample g = fe.at(k, true, x - s.sensors.positions[k][0],
                                           y - s.sensors.positions[k][1], green::LayerLoad::point, 0);
        // g_zb: a force pressing into the skin (−z); g_xb: along +x.
        const double adj_z = dir.z() != 0 ? g.zz : g.xz, adj_x = dir.z() != 0 ? g.zx : g.xx;
        peak = std::max({peak, std::abs(direct.sigma_z), std::abs(direct.sigma_x)});
        worst = std::max({worst, std::abs(direct.sigma_z - adj_z), std::abs(direct.sigma_x - adj_x)});
      }
    }
  }
  EXPECT_LT(worst, 1e-6 * peak);
}

// Posts on membrane springs (fem/sensor_reading.hpp): the reading T·P₀ by the adjoint weights against the
// forward equilibrium found independently. Forward: the loaded skin with both posts displaced rigidly by
// each mode in turn gives the skin's stiffness against the posts' motions; the posts' equilibrium
// displacement U* solves (K + K_s) U = −P₀; a last direct solve with the posts at U* gives the force each
// post exerts on the skin, which the springs must balance (P + K_s U* = 0) and which the gauges read.
TEST(PostSensor, SpringReadingIsTheForwardEquilibrium) {
  const TetMesh& m = post_mesh();
  Scene s = post_scene();
  s.sensors.post.support = {8.0, 3.0, 0.05};  // N/mm, N/mm, N·mm/rad: of the order of the skin's own
  const ElasticModel& model = free_model();
  const SensorReadings springs(m, reading_sites(s.sensors), &model.solver());
  const Eigen::MatrixXd& K = springs.post_stiffness();
  ASSERT_EQ(K.rows(), 10);  // two posts, five rigid modes each
  std::printf(
      "skin stiffness against post 1's modes x, y, z, tilt x, tilt y: %.3g %.3g %.3g N/mm, %.3g %.3g N "
      "mm/rad\n",
      K(0, 0), K(1, 1), K(2, 2), K(3, 3), K(4, 4));
  // Maxwell–Betti: K is symmetric; it is positive definite (moving a post into the skin takes work).
  EXPECT_LT((K - K.transpose()).norm(), 1e-9 * K.norm());
  EXPECT_GT(
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(0.5 * (K + K.transpose())).eigenvalues().minCoeff(), 0);

  // The rigid modes on a post's nodes (the same as the seam's, built here from the mesh: the foot moves with
  // the post along the base and stays with the base along z).
  const int N = m.num_nodes();
  const auto mode = [&](int post, int j) {
    Eigen::VectorXd phi = Eigen::VectorXd::Zero(3 * N);
    const Vec2& c = s.sensors.positions[post];
    for (int n = 0; n < N; ++n) {
      if (!(m.node_marker(n) & kPost) || std::hypot(m.nodes(n, 0) - c[0], m.nodes(n, 1) - c[1]) > 0.1 + 1e-9)
        continue;
      const Eigen::Vector3d r(m.nodes(n, 0) - c[0], m.nodes(n, 1) - c[1], m.nodes(n, 2));
      const Eigen::Vector3d u =
          j < 3 ? Eigen::Vector3d::Unit(j).eval() : Eigen::Vector3d::Unit(j == 3 ? 0 : 1).cross(r).eval();
      phi.segment<3>(3 * n) = u;
      if (m.node_marker(n) & kBase) phi[3 * n + 2] = 0;
    }
    return phi;
  };
  std::vector<Eigen::VectorXd> phi;
  for (int post = 0; post < 2; ++post)
    for (int j = 0; j < 5; ++j) phi.push_back(mode(post, j));
  Eigen::VectorXd Ks(10);
  for (int i = 0; i < 10; ++i) Ks[i] = i % 5 == 2 ? 8.0 : i % 5 < 2 ? 3.0 : 0.05;

  const TractionPatch patch{{0.6, 0.2}, 0.5, {0.3, 0.1, -1}, 1.0};
  const Eigen::VectorXd f = model.patch_load(patch);
  const auto P = [&](const Eigen::VectorXd& U) {  // generalized forces of the posts on the skin
    Eigen::VectorXd u_fixed = Eigen::VectorXd::Zero(3 * N);
    for (int i = 0; i < 10; ++i) u_fixed += U[i] * phi[i];
    const MixedSolution x = model.solver().solve(f, u_fixed);
    const Eigen::VectorXd R = model.solver().reactions(x, f);
    Eigen::VectorXd out(10);
    for (int i = 0; i < 10; ++i) out[i] = phi[i].dot(R);
    return std::make_pair(out, R);
  };
  const auto [P0, R0] = P(Eigen::VectorXd::Zero(10));
  Eigen::MatrixXd K_forward(10, 10);
  for (int j = 0; j < 10; ++j) K_forward.col(j) = P(Eigen::VectorXd::Unit(10, j)).first - P0;
  const Eigen::VectorXd U = -(K_forward + Eigen::MatrixXd(Ks.asDiagonal())).lu().solve(P0);
  const Eigen::VectorXd P_star = P(U).first;
  EXPECT_LT((P_star + Ks.cwiseProduct(U)).norm(), 1e-9 * P0.norm()) << "the posts are not in equilibrium";

  // The seam's reading of the held posts' reactions is the forward reading at equilibrium.
  const SensorReadings rigid(m, reading_sites(post_scene().sensors));
  const double area = M_PI * 0.25 * kDiameter * kDiameter;
  for (int k = 0; k < 2; ++k) {
    const SensorReading adjoint = springs.read(k, R0), held = rigid.read(k, R0);
    const double forward_z = P_star[5 * k + 2] / area, forward_x = -P_star[5 * k] / area;
    std::printf("post %d: held sigma_z %.4f sigma_x %.4f, on springs %.4f %.4f (forward %.4f %.4f) kPa\n",
                k + 1, 1e3 * held.sigma_z, 1e3 * held.sigma_x, 1e3 * adjoint.sigma_z, 1e3 * adjoint.sigma_x,
                1e3 * forward_z, 1e3 * forward_x);
    EXPECT_NEAR(adjoint.sigma_z, forward_z, 1e-8 * std::abs(held.sigma_z));
    EXPECT_NEAR(adjoint.sigma_x, forward_x, 1e-8 * std::abs(held.sigma_x));
    // The springs are of the skin's stiffness: the reading changes by a fraction of itself, not by round-off.
    EXPECT_GT(std::abs(adjoint.sigma_z - held.sigma_z), 1e-2 * std::abs(held.sigma_z));
  }
  // Stiff springs are the held post: T = I − K (K + K_s)⁻¹ differs from I by about ‖K‖ / k.
  s.sensors.post.support = {1e9, 1e9, 1e9};
  const SensorReadings stiff(m, reading_sites(s.sensors), &model.solver());
  for (int k = 0; k < 2; ++k)
    EXPECT_NEAR(stiff.read(k, R0).sigma_z, rigid.read(k, R0).sigma_z,
                1e-6 * std::abs(rigid.read(k, R0).sigma_z));
}

// As its height t → 0 a post becomes the base under its outline, and its reading (force over cross-section)
// becomes the disc's (mean base traction over the same outline). The wall's share of the force scales with
// its area 2πr·t, so the gap closes at first order in t (σ_x: the drag of the skin's sideways displacement
// over the height; σ_z: the same order or faster). Meshes are scaled with t (post elements of size t, so
// every level resolves its own post alike); the gap is fitted over four heights (MFEM ConvergenceStudy
// style).
TEST(PostSensor, ShortPostsTendToTheDiscAtFirstOrderInHeight) {
  const auto reading = [](SensorModel model, double height) {
    Scene s = post_scene();
    s.sensors.positions = {{0, 0}};
    s.sensors.model = model;
    if (model == SensorModel::post)
      s.sensors.post = {kDiameter, height};
    else
      s.sensors.disc_diameter = kDiameter;
    s.mesh.sensor_h = std::min(0.05, height);
    const TetMesh m = build_mesh(s);
    const ElasticModel model_(m, s.material, SideCondition::free, std::vector<Punch>{});
    const TractionPatch patch{{0.6, 0.0}, 0.4, {0.3, 0, -1}, 1.0};
    const LoadCaseResult r = model_.solve(model_.patch_load(patch), {});
    return SensorReadings(m, reading_sites(s.sensors)).read(0, r.reactions);
  };
  const std::vector<double> heights = {0.2, 0.1, 0.05, 0.025};
  const SensorReading disc = reading(SensorModel::disc, heights.back());
  std::vector<double> gap_z, gap_x;
  for (double t : heights) {
    const SensorReading p = reading(SensorModel::post, t);
    gap_z.push_back(std::abs(p.sigma_z - disc.sigma_z));
    gap_x.push_back(std::abs(p.sigma_x - disc.sigma_x));
    std::printf("height %.3f mm: post sigma_z %.5f sigma_x %.5f MPa (disc %.5f, %.5f)\n", t, p.sigma_z,
                p.sigma_x, disc.sigma_z, disc.sigma_x);
  }
  testing::expect_gap_to_the_disc_closes(heights, gap_z, gap_x);
}

}  // namespace
}  // namespace skinfem
