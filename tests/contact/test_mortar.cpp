// The mortar contact operator on P2 faces (contact/mortar.hpp): exact areas and moments, the consistent
// load of a uniform pressure, and why P2 vertices need the linear multipliers.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "skinfem/contact/mortar.hpp"
#include "skinfem/fem/assembly.hpp"
#include "skinfem/mesh/build.hpp"
#include "skinfem/mesh/surface_quadrature.hpp"

namespace skinfem::contact {
namespace {

// Cap (R = 20 mm, h = 3 mm, apex at the origin) cut at 6 mm: curved quadratic top faces.
const TetMesh& cap() {
  static const TetMesh m = [] {
    Scene s;
    s.geometry.kind = GeometryKind::cap;
    s.geometry.cap = {20.0, 3.0, 0.0, 0.0, 6.0};
    s.sensors.positions = {{0, 0}};
    s.mesh.h_min = 0.3;
    s.mesh.h_max = 1.0;
    s.mesh.growth = 1.5;
    return build_mesh(s);
  }();
  return m;
}

// Inside the zone the hats sum to 1: Σ ∫ψ_i lies between the projected area of the faces with every corner in
// the zone and that of all faces touching it; with the disc about the apex, Σ ∫ψ_i x is the moment of a
// nearly symmetric patch.
TEST(Mortar, HatsPartitionTheProjectedTop) {
  const TetMesh& m = cap();
  const MortarZone z = mortar_zone(m, {0, 0}, 4.0);
  std::vector<char> in(m.num_nodes(), 0);
  for (int v : z.vertices) in[v] = 1;
  double inner = 0, outer = 0;
  for (int f : z.faces)
    for (const FacePoint& q : face_quadrature(m, f)) {
      outer += q.weight_xy;
      if (in[m.faces(f, 0)] && in[m.faces(f, 1)] && in[m.faces(f, 2)]) inner += q.weight_xy;
    }
  EXPECT_GT(z.area.sum(), inner);
  EXPECT_LT(z.area.sum(), outer);
  EXPECT_TRUE((z.area.array() > 0).all());
}

// A uniform multiplier field λ = 1 loads each P2 node with ∫φ_j dx dy, the consistent load of a unit
// vertical pressure (compared with fem's traction_load on the projected normal component). That load is
// zero (or negative) at vertices on straight faces; the mortar constraint never asks a vertex to carry it.
TEST(Mortar, UniformPressureGivesTheConsistentP2Load) {
  const TetMesh& m = cap();
  const MortarZone z = mortar_zone(m, {0, 0}, 4.0);
  const Eigen::VectorXd f = z.load(Eigen::VectorXd::Ones(z.size()), Eigen::Vector2d(1, 0), 0.0);
  // traction −e_z per unit projected area = −e_z·|n_z| per unit true area on the top.
  const Eigen::VectorXd g = traction_load(m, kTop, [](const Eigen::Vector3d&, const Eigen::Vector3d& n) {
    return Eigen::Vector3d(0, 0, -std::abs(n.z()));
  });
  // Equal at nodes whose faces all lie inside the zone (elements are at most 1 mm: |xy| < 2 suffices).
  for (int j = 0; j < m.num_nodes(); ++j)
    if ((m.node_marker(j) & kTop) && std::hypot(m.nodes(j, 0), m.nodes(j, 1)) < 2.0) {
      EXPECT_NEAR(f[3 * j + 2], g[3 * j + 2], 1e-12 * g.cwiseAbs().maxCoeff()) << j;
    }
  int vertices_with_no_load = 0;
  for (int i = 0; i < m.num_vertices; ++i)
    if ((m.node_marker(i) & kTop) && f[3 * i + 2] > -1e-6 * z.area.maxCoeff()) ++vertices_with_no_load;
  EXPECT_GT(vertices_with_no_load, 0) << "P2 vertices carry no share of a uniform pressure";
  // Friction traction: ratio·p along the sliding direction.
  const Eigen::VectorXd ft = z.load(Eigen::VectorXd::Ones(z.size()), Eigen::Vector2d(0, 1), 0.5);
  double fy = 0, fz = 0;
  for (int j = 0; j < m.num_nodes(); ++j) fy += ft[3 * j + 1], fz += ft[3 * j + 2];
  EXPECT_NEAR(fy, -0.5 * fz, 1e-12 * std::abs(fz));
}

TEST(Mortar, ZoneHoldsOnlyTopVerticesWithinItsRadius) {
  const TetMesh& m = cap();
  const MortarZone z = mortar_zone(m, {1.0, 0.5}, 2.0);
  for (int v : z.vertices) {
    EXPECT_LT(v, m.num_vertices);
    EXPECT_TRUE(m.node_marker(v) & kTop);
    EXPECT_LE(std::hypot(m.nodes(v, 0) - 1.0, m.nodes(v, 1) - 0.5), 2.0);
  }
  EXPECT_THROW(mortar_zone(m, {1.0, 0.5}, 1e-6), std::invalid_argument);
}

}  // namespace
}  // namespace skinfem::contact
