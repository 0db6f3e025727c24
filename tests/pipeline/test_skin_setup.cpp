// The shared meshed and factored skin (pipeline/skin_setup.hpp). References: a second path that builds the
// same problem, `solve` (pipeline/solve.hpp: its own mesh, model and forward readings) — a patch solved on
// the shared skin's factorization must give solve's readings and base force to round-off, with the scene's
// material and side condition; the mesh it was handed (factored_skin keeps it, and a half stays a half whose
// mirror holds the whole's volume); the border hook called once, on that mesh; a sensor off the skin refused.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "skinfem/fem/base_traction.hpp"
#include "skinfem/mesh/build.hpp"
#include "skinfem/mesh/mirror.hpp"
#include "skinfem/mesh/quality.hpp"
#include "skinfem/pipeline/skin_setup.hpp"
#include "skinfem/pipeline/solve.hpp"

namespace skinfem::pipeline {
namespace {

constexpr double kRoundOff = 1e-9;  // relative to the largest reading: two direct solves of one system

Scene layer() {
  Scene s;
  s.name = "skin_layer";
  s.geometry.kind = GeometryKind::flat;
  s.geometry.flat = {1.5, 4.0};
  s.sensors.positions = {{0, 0}, {1, 0}};
  s.mesh.h_min = 0.7;
  s.mesh.growth = 1.7;
  s.mesh.h_max = 1.5;
  s.mesh.sensor_h = 0.7;
  return s;
}

TEST(SkinSetup, ItsFactorizationSolvesTheScenesProblemAsSolveDoes) {
  Scene s = layer();
  s.material = {2.0, 0.45};  // neither default: the skin must take the scene's
  s.geometry.side = SideCondition::fixed;
  const TractionPatch p{{0.4, 0.3}, 0.8, {0.6, 0, -0.8}, 0.5};
  s.loads.patches = {p};  // meshes both skins alike (a patch refines the mesh under it)
  const std::shared_ptr<Skin> skin = skin_setup(s);
  const LoadCaseResult r = skin->model->solve(skin->model->patch_load(p), {});
  const SensorReadings readings(skin->mesh, reading_sites(s.sensors));

  const SolveRun reference = solve_run(s, SolverKind::direct_ldlt);
  ASSERT_EQ(skin->mesh.num_nodes(), reference.mesh->num_nodes());
  EXPECT_EQ(skin->model->solver().free_dofs(), reference.model->solver().free_dofs());
  double scale = 0;
  for (const SensorReading& q : reference.readings)
    scale = std::max({scale, std::abs(q.sigma_z), std::abs(q.sigma_x)});
  ASSERT_GT(scale, 0);
  for (int k = 0; k < readings.size(); ++k) {
    const SensorReading q = readings.read(k, r.reactions);
    EXPECT_NEAR(q.sigma_z, reference.readings[k].sigma_z, kRoundOff * scale);
    EXPECT_NEAR(q.sigma_x, reference.readings[k].sigma_x, kRoundOff * scale);
  }
  const Eigen::Vector3d base = BaseTraction(skin->mesh, r.reactions).total_force();
  EXPECT_LT((base - reference.base_force_N).norm(), kRoundOff * p.force);
  for (const char* stage : {"mesh", "assemble", "factor"}) EXPECT_TRUE(skin->wall.contains(stage)) << stage;
}

TEST(SkinSetup, AFactoredSkinKeepsTheMeshItWasGiven) {
  const Scene s = layer();
  TetMesh mesh = build_mesh(s);
  const int nodes = mesh.num_nodes(), tets = mesh.num_tets();
  int calls = 0, seen_nodes = -1;
  const Border border = [&](const TetMesh& m) -> const MixedSolver::Coupling* {
    ++calls;
    seen_nodes = m.num_nodes();
    return nullptr;  // no columns: a plain factorization
  };
  const std::shared_ptr<Skin> skin = factored_skin(s, std::move(mesh), 0.125, border);
  EXPECT_EQ(skin->mesh.num_nodes(), nodes);
  EXPECT_EQ(skin->mesh.num_tets(), tets);
  EXPECT_EQ(calls, 1);
  EXPECT_EQ(seen_nodes, nodes);
  EXPECT_EQ(skin->wall.at("mesh"), 0.125);
  EXPECT_EQ(&skin->model->mesh(), &skin->mesh);  // the model refers to the skin's own mesh
}

TEST(SkinSetup, AHalfSkinIsTheHalfOfTheWhole) {
  const Scene s = layer();
  const std::shared_ptr<Skin> half = skin_setup(s, MeshPart::half_y), whole = skin_setup(s);
  EXPECT_TRUE(is_half_y(half->mesh));
  EXPECT_FALSE(is_half_y(whole->mesh));
  EXPECT_LT(half->model->solver().free_dofs(), whole->model->solver().free_dofs());
  // The half's mirror image covers the whole box: (2 · 4)² · 1.5 mm³ (planar faces: exact to round-off).
  const double box = 8.0 * 8.0 * 1.5;
  EXPECT_NEAR(assess_quality(mirror_half(half->mesh)).volume_mm3, box, 1e-12 * box);
  EXPECT_NEAR(assess_quality(whole->mesh).volume_mm3, box, 1e-12 * box);
}

TEST(SkinSetup, ASensorOffTheSkinIsRefusedNamingIt) {
  Scene s = layer();
  s.sensors.positions = {{0, 0}, {3.98, 0}};  // its disc (0.2 mm) crosses the edge at x = 4
  try {
    skin_setup(s);
    ADD_FAILURE() << "a sensor off the skin was accepted";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("sensor 2"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace skinfem::pipeline
