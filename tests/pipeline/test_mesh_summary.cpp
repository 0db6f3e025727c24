// What `mesh` and the report say of a skin's mesh (pipeline/mesh_summary.hpp). References: the exact volume
// of the shape in closed form (a box (2w)²h; a spherical cap cut by a cylinder,
// π(h − R)r² + (2π/3)(R³ − (R² − r²)^{3/2}); a post's cavity πd²/4·t per sensor), computed here, not by
// SkinShape; mirror symmetry (a half mesh mirrored holds twice the half's volume); and mesh_json's numbers
// against the typed MeshSummary and MeshQuality they are built from.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "skinfem/mesh/build.hpp"
#include "skinfem/mesh/mirror.hpp"
#include "skinfem/pipeline/mesh_summary.hpp"
#include "skinfem/pipeline/scene_json.hpp"

namespace skinfem::pipeline {
namespace {

constexpr double kRoundOff = 1e-12;  // relative: sums of a few thousand tet volumes in double precision

// A small flat layer, coarse: its faces are planes, so every tet (straight or P2) tiles it exactly.
Scene flat_scene() {
  Scene s;
  s.name = "flat";
  s.geometry.kind = GeometryKind::flat;
  s.geometry.flat = {2.0, 4.0};  // h, half_width (mm)
  s.sensors.positions = {{0, 0}, {1.5, 0}};
  s.mesh.h_min = 0.5;
  s.mesh.growth = 1.7;
  s.mesh.h_max = 1.5;
  return s;
}

// A spherical cap cut by the cylinder of radius r_t about its apex, inside its rim.
Scene cap_scene() {
  Scene s;
  s.name = "cap";
  s.geometry.kind = GeometryKind::cap;
  s.geometry.cap.R = 40;
  s.geometry.cap.h = 2;
  s.geometry.cap.truncation_radius = 5;
  s.sensors.positions = {{0, 0}};
  s.mesh.h_min = 0.6;
  s.mesh.growth = 1.7;
  s.mesh.h_max = 1.5;
  return s;
}

double cap_volume(double R, double h, double r) {
  return M_PI * (h - R) * r * r + 2 * M_PI / 3 * (R * R * R - std::pow(R * R - r * r, 1.5));
}

TEST(MeshSummary, AFlatLayersExactVolumeIsTheBoxAndItsMeshTilesItExactly) {
  const Scene s = flat_scene();
  const TetMesh mesh = build_mesh(s);
  const MeshSummary sum = mesh_summary(s, mesh, 0.25);
  const double box = 8.0 * 8.0 * 2.0;
  ASSERT_TRUE(sum.exact_volume_mm3.has_value());
  EXPECT_NEAR(*sum.exact_volume_mm3, box, kRoundOff * box);
  EXPECT_NEAR(sum.quality.volume_mm3, box, kRoundOff * box);
  EXPECT_NEAR(sum.quality.linear_volume_mm3, box, kRoundOff * box);
  // The typed counts are the mesh's own.
  EXPECT_EQ(sum.quality.nodes, mesh.num_nodes());
  EXPECT_EQ(sum.quality.elements, mesh.num_tets());
  EXPECT_EQ(sum.straightened, mesh.straightened);
  EXPECT_EQ(sum.seconds, 0.25);
}

TEST(MeshSummary, PostCavitiesAreTakenFromTheExactVolume) {
  Scene s = flat_scene();
  s.sensors.model = SensorModel::post;
  s.sensors.post.diameter = 0.3;
  s.sensors.post.height = 0.5;
  const double cavity = M_PI * 0.25 * 0.3 * 0.3 * 0.5;
  const double exact = 8.0 * 8.0 * 2.0 - 2 * cavity;  // two sensors
  const MeshSummary sum = mesh_summary(s, build_mesh(s), 0);
  ASSERT_TRUE(sum.exact_volume_mm3.has_value());
  EXPECT_NEAR(*sum.exact_volume_mm3, exact, kRoundOff * exact);
  // The box is exact, so the mesh's error is the cavities'. Each is a cylinder inscribed by at least 6
  // straight sides (its edges ≤ its radius: the sensor's size, mesh.sensor_h), whose area deficit is at most
  // 1 − 6 sin(π/3)/(2π) of the disc's; its P2 sides, mid-edge nodes on the cylinder, come closer still.
  const double hexagon_deficit = 1 - 6 * std::sin(M_PI / 3) / (2 * M_PI);
  std::printf("posts: mesh %.9f, exact %.9f, cavities %.6f mm3\n", sum.quality.volume_mm3, exact, 2 * cavity);
  EXPECT_LT(std::abs(sum.quality.volume_mm3 - exact), hexagon_deficit * 2 * cavity);
  EXPECT_LT(sum.quality.volume_mm3, 8.0 * 8.0 * 2.0 - cavity);
}

TEST(MeshSummary, ACapsExactVolumeIsTheClosedFormAndItsP2MeshComesCloserThanItsStraightOne) {
  const Scene s = cap_scene();
  const double exact = cap_volume(40, 2, 5);
  const TetMesh mesh = build_mesh(s);
  const MeshSummary sum = mesh_summary(s, mesh, 0);
  ASSERT_TRUE(sum.exact_volume_mm3.has_value());
  EXPECT_NEAR(*sum.exact_volume_mm3, exact, kRoundOff * exact);
  // Straight-sided tets inscribe the curved top and side: each facet of edge e ≤ max_edge_mm lies about
  // e²/(8ρ) (a chord's sagitta) inside the surface of curvature radius ρ (top: R = 40, side: r_t = 5); the
  // straight deficit is at most twice the sum of sagitta × area (2: a facet's circumradius exceeds e/2).
  const double e = sum.quality.max_edge_mm;
  const double top_area = M_PI * 25, side_area = 2 * M_PI * 5 * 2;
  const double bound = 2 * (e * e / (8 * 40) * top_area + e * e / (8 * 5) * side_area);
  std::printf("cap: P2 %.9f, straight %.9f, exact %.9f, bound %.4f mm3\n", sum.quality.volume_mm3,
              sum.quality.linear_volume_mm3, exact, bound);
  EXPECT_LT(sum.quality.linear_volume_mm3, exact);
  EXPECT_GT(sum.quality.linear_volume_mm3, exact - bound);
  // Mid-edge nodes on the surfaces make the geometric error one order higher in e/ρ: at most the straight
  // deficit times h_max / r_t (the smaller radius of curvature).
  EXPECT_LT(std::abs(sum.quality.volume_mm3 - exact),
            s.mesh.h_max / 5 * (exact - sum.quality.linear_volume_mm3));
}

TEST(MeshSummary, AMirroredHalfHoldsTwiceTheHalfAndTheWholeExactVolume) {
  const Scene s = flat_scene();
  const TetMesh half = build_mesh(s, MeshPart::half_y);
  const TetMesh whole = mirror_half(half);
  const MeshSummary h = mesh_summary(s, half, 0), w = mesh_summary(s, whole, 0);
  EXPECT_EQ(w.quality.elements, 2 * h.quality.elements);
  EXPECT_NEAR(w.quality.volume_mm3, 2 * h.quality.volume_mm3, kRoundOff * w.quality.volume_mm3);
  EXPECT_NEAR(w.quality.volume_mm3, *w.exact_volume_mm3, kRoundOff * w.quality.volume_mm3);
  // Mirroring copies shapes: the quality figures of the whole are the half's.
  EXPECT_EQ(w.quality.min_dihedral_deg, h.quality.min_dihedral_deg);
  EXPECT_EQ(w.quality.max_dihedral_deg, h.quality.max_dihedral_deg);
  EXPECT_EQ(w.quality.max_edge_mm, h.quality.max_edge_mm);
}

TEST(MeshSummary, AnImportedSurfaceHasNoExactVolume) {
  Scene s = flat_scene();
  s.geometry.kind = GeometryKind::surface;
  s.geometry.surface.path = std::string(SKINFEM_SOURCE_DIR) + "/scenes/dome.stl";
  const TetMesh mesh = build_mesh(flat_scene());  // any mesh: the exact volume comes from the scene alone
  const MeshSummary sum = mesh_summary(s, mesh, 0);
  EXPECT_FALSE(sum.exact_volume_mm3.has_value());
  const nlohmann::json j = mesh_json(s, sum);
  EXPECT_FALSE(j.contains("exact_volume_mm3"));
  EXPECT_FALSE(j.contains("volume_rel_error"));
  EXPECT_EQ(j.at("volume_mm3").get<double>(), sum.quality.volume_mm3);
}

TEST(MeshSummary, TheJsonSaysTheTypedSummary) {
  const Scene s = cap_scene();
  const MeshSummary sum = mesh_summary(s, build_mesh(s), 1.5);
  const nlohmann::json j = mesh_json(s, sum);
  const MeshQuality& q = sum.quality;
  EXPECT_EQ(j.at("nodes").get<int>(), q.nodes);
  EXPECT_EQ(j.at("vertices").get<int>(), q.vertices);
  EXPECT_EQ(j.at("elements").get<int>(), q.elements);
  EXPECT_EQ(j.at("boundary_faces").get<int>(), q.boundary_faces);
  EXPECT_EQ(j.at("min_dihedral_deg").get<double>(), q.min_dihedral_deg);
  EXPECT_EQ(j.at("max_dihedral_deg").get<double>(), q.max_dihedral_deg);
  EXPECT_EQ(j.at("max_radius_edge").get<double>(), q.max_radius_edge);
  EXPECT_EQ(j.at("min_edge_mm").get<double>(), q.min_edge_mm);
  EXPECT_EQ(j.at("max_edge_mm").get<double>(), q.max_edge_mm);
  EXPECT_EQ(j.at("min_jacobian_ratio").get<double>(), q.min_jacobian_ratio);
  EXPECT_EQ(j.at("volume_mm3").get<double>(), q.volume_mm3);
  EXPECT_EQ(j.at("exact_volume_mm3").get<double>(), *sum.exact_volume_mm3);
  EXPECT_NEAR(j.at("volume_rel_error").get<double>(), q.volume_mm3 / *sum.exact_volume_mm3 - 1, kRoundOff);
  EXPECT_EQ(j.at("straightened_elements").get<int>(), sum.straightened);
  EXPECT_EQ(j.at("wall_s").get<double>(), 1.5);
  EXPECT_EQ(j.at("scene"), scene_json(s));
  EXPECT_GT(j.at("peak_rss_mb").get<double>(), 0);
}

}  // namespace
}  // namespace skinfem::pipeline
