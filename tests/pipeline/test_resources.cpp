// Resource guards (pipeline/resources.hpp): a scene estimated above max_dofs, or above the available memory,
// is refused before meshing in one line naming the limit; one below is accepted, its estimate reported as a
// progress line. References: estimate_mesh itself (mesh/size_estimate.hpp) for the figures the guard must
// return, the header's memory model (19 kB per DOF up to 200k DOFs, growing as DOFs^(1/3); the measured peak
// it must stay above), /proc/meminfo read here for the available memory, and meshes built by hand for the
// unknowns bound (3 per node + 1 per vertex). One tiny flat layer is meshed, for guarded_mesh.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "../common/progress_lines.hpp"
#include "skinfem/mesh/size_estimate.hpp"
#include "skinfem/pipeline/progress.hpp"
#include "skinfem/pipeline/resources.hpp"
#include "skinfem/scene/load.hpp"

namespace skinfem::pipeline {
namespace {

using Collect = testing::ProgressLines;

bool names(const std::string& line, const std::string& what) { return line.find(what) != std::string::npos; }

// The shipped flat layer: a few ten thousand DOFs, estimated in milliseconds.
Scene flat_layer() { return load_scene(std::string(SKINFEM_SOURCE_DIR) + "/scenes/flat_layer.json"); }

// A flat layer 4 mm wide and 1 mm thick at one size throughout: a few hundred elements, meshed in
// milliseconds.
Scene tiny_layer() {
  Scene s;
  s.name = "tiny";
  s.source_path = "tiny.json";
  s.geometry.kind = GeometryKind::flat;
  s.geometry.flat = {1.0, 2.0};
  s.sensors.positions = {{0, 0}};
  s.mesh.refine_sensors = false;
  s.mesh.h_min = s.mesh.h_max = 1.0;
  return s;
}

// A hand-made mesh whose only use is its size: `nodes` nodes of which `vertices` are corners.
TetMesh mesh_of_size(int nodes, int vertices) {
  TetMesh m;
  m.nodes = RowMatrixX3d::Zero(nodes, 3);
  m.num_vertices = vertices;
  return m;
}

// MemAvailable of /proc/meminfo, GB; 0 if missing.
double meminfo_available_gb() {
  std::ifstream in("/proc/meminfo");
  std::string key, unit;
  double kb = 0;
  while (in >> key >> kb >> unit)
    if (key == "MemAvailable:") return kb / (1024.0 * 1024.0);
  return 0;
}

TEST(Resources, MemoryModelIsTheHeaders) {
  EXPECT_NEAR(estimated_memory_gb(2e5), 2e5 * 19e3 / 1e9, 1e-12);  // 19 kB per DOF up to 200k DOFs
  EXPECT_NEAR(estimated_memory_gb(1e4), 1e4 * 19e3 / 1e9, 1e-12);  // and below
  // Beyond, the memory per DOF grows as DOFs^(1/3): 8 times the DOFs, twice the memory per DOF.
  for (double d : {4e5, 1e6, 1e7})
    EXPECT_NEAR(estimated_memory_gb(8 * d) / (8 * d), 2 * estimated_memory_gb(d) / d, 1e-15) << d;
  // Conservative: above the default report's measured peak on its half.
  EXPECT_GT(estimated_memory_gb(88.9e3), 1.13);
}

TEST(Resources, AvailableMemoryIsMemAvailable) {
  const double mine = meminfo_available_gb(), theirs = available_memory_gb();
  if (mine == 0) GTEST_SKIP() << "no MemAvailable in /proc/meminfo";
  // Read a moment apart while other processes run: within 20 % or 0.5 GB.
  EXPECT_NEAR(theirs, mine, std::max(0.5, 0.2 * mine));
}

TEST(Resources, RefusesASceneAboveMaxDofsInOneLine) {
  Scene s = flat_layer();
  const MeshEstimate e = estimate_mesh(s);
  ASSERT_TRUE(e.known);
  s.limits.max_dofs = 0.5 * e.dofs;
  Collect c;
  try {
    check_resources(s);
    FAIL() << "a scene estimated at " << e.dofs << " DOFs passed max_dofs " << s.limits.max_dofs;
  } catch (const SceneError& err) {
    const std::string line = err.what();
    EXPECT_TRUE(names(line, "max_dofs")) << line;
    EXPECT_TRUE(names(line, s.source_path)) << line;
    char limit[32];
    std::snprintf(limit, sizeof limit, "%.3g", s.limits.max_dofs);
    EXPECT_TRUE(names(line, limit)) << line;
    EXPECT_FALSE(names(line, "\n")) << line;
  }
  EXPECT_TRUE(c.lines.empty());  // refused: no estimate reported
}

TEST(Resources, AcceptsASceneBelowMaxDofsAndReportsItsEstimate) {
  Scene s = flat_layer();
  const MeshEstimate e = estimate_mesh(s);
  ASSERT_TRUE(e.known);
  if (estimated_memory_gb(e.dofs) > available_memory_gb()) GTEST_SKIP() << "not enough memory for this scene";
  s.limits.max_dofs = 2 * e.dofs;
  Collect c;
  const MeshEstimate got = check_resources(s);
  EXPECT_TRUE(got.known);
  EXPECT_NEAR(got.dofs, e.dofs, 1e-9 * e.dofs);
  EXPECT_NEAR(got.tets, e.tets, 1e-9 * e.tets);
  ASSERT_EQ(c.lines.size(), 1u);
  EXPECT_TRUE(names(c.lines[0], "estimate")) << c.lines[0];
  // No limit but the memory: accepted too.
  s.limits.max_dofs = 0;
  EXPECT_NEAR(check_resources(s).dofs, e.dofs, 1e-9 * e.dofs);
}

TEST(Resources, AHalfCountsItsCutFace) {
  // The half is integrated over y >= 0 with its own sizing field, and counted 1.1x for the cut TetGen
  // refines.
  const Scene s = flat_layer();
  const MeshEstimate half = estimate_mesh(s, 1e12, MeshPart::half_y), whole = estimate_mesh(s);
  if (estimated_memory_gb(1.1 * half.dofs) > available_memory_gb()) GTEST_SKIP() << "not enough memory";
  const MeshEstimate got = check_resources(s, MeshPart::half_y);
  EXPECT_NEAR(got.dofs, 1.1 * half.dofs, 1e-9 * half.dofs);
  EXPECT_NEAR(got.tets, 1.1 * half.tets, 1e-9 * half.tets);
  EXPECT_LT(got.dofs, whole.dofs);  // a symmetric layer's half, even counted 1.1x, is smaller than the whole
}

TEST(Resources, RefusesASceneAboveTheAvailableMemory) {
  const double avail = available_memory_gb();
  if (avail == 0) GTEST_SKIP() << "available memory unknown";
  // The flat layer at 20 µm everywhere: some 10^10 elements, far past any machine; no max_dofs.
  Scene s = flat_layer();
  s.mesh.h_min = s.mesh.h_max = 0.02;
  s.mesh.regions.clear();
  ASSERT_GT(estimated_memory_gb(kDofsPerTet * fewest_tets(40 * 40 * 3.04, 0.02)), 10 * avail);
  try {
    check_resources(s);
    FAIL() << "a mesh of 20 µm over 40 x 40 mm was accepted";
  } catch (const SceneError& err) {
    const std::string line = err.what();
    EXPECT_TRUE(names(line, "GB available")) << line;
    EXPECT_TRUE(names(line, "mesh.h_min")) << line;  // the fields that set the size
    EXPECT_FALSE(names(line, "\n")) << line;
  }
}

TEST(Resources, AnImportedSurfaceHasNoEstimateAndIsNotRefusedForIt) {
  Scene s = flat_layer();
  s.geometry.kind = GeometryKind::surface;
  s.geometry.surface.path = "dome.stl";
  s.limits.max_dofs = 1;
  const MeshEstimate e = check_resources(s);
  EXPECT_FALSE(e.known);
}

TEST(Resources, MaxTetsAllowedFollowsMaxDofs) {
  // A limit below anything the memory would stop: the limit itself, at kDofsPerTet.
  EXPECT_NEAR(max_tets_allowed(1e4), 1e4 / kDofsPerTet, 1e-9);
  const double avail = available_memory_gb();
  if (avail == 0) GTEST_SKIP() << "available memory unknown";
  // No max_dofs: the memory's limit, the DOFs whose estimated memory just exceeds what is available (the
  // available memory read a moment apart: a factor 1.5 either side).
  const double dofs = kDofsPerTet * max_tets_allowed(0);
  EXPECT_GT(estimated_memory_gb(dofs), avail / 1.5);
  EXPECT_LT(estimated_memory_gb(dofs / 1.1), 1.5 * avail);
  EXPECT_LE(max_tets_allowed(1e12), 1e12 / kDofsPerTet);
}

TEST(Resources, UnknownsBoundIsThreePerNodeAndOnePerVertex) {
  EXPECT_EQ(unknowns_bound(mesh_of_size(10, 4)), 34);
  EXPECT_EQ(unknowns_bound(mesh_of_size(100, 20)), 320);
  EXPECT_EQ(unknowns_bound(TetMesh{}), 0);
}

TEST(Resources, ABuiltMeshAboveMaxDofsIsRefusedInOneLine) {
  Scene s = flat_layer();
  const TetMesh m = mesh_of_size(100, 20);  // 320 unknowns
  s.limits.max_dofs = 319;
  try {
    check_meshed_dofs(s, m);
    FAIL() << "320 unknowns passed max_dofs 319";
  } catch (const SceneError& err) {
    const std::string line = err.what();
    EXPECT_TRUE(names(line, "max_dofs")) << line;
    EXPECT_TRUE(names(line, "320")) << line;
    EXPECT_TRUE(names(line, s.source_path)) << line;
    EXPECT_FALSE(names(line, "\n")) << line;
  }
  s.limits.max_dofs = 320;  // not above: accepted
  EXPECT_NO_THROW(check_meshed_dofs(s, m));
  s.limits.max_dofs = 0;  // the memory only
  EXPECT_NO_THROW(check_meshed_dofs(s, m));
}

TEST(Resources, ABuiltMeshAboveTheAvailableMemoryIsRefused) {
  const double avail = available_memory_gb();
  if (avail == 0) GTEST_SKIP() << "available memory unknown";
  double dofs = 1e5;
  while (estimated_memory_gb(dofs) < 2 * avail) dofs *= 2;
  if (dofs > 3e7) GTEST_SKIP() << "too much memory available for a hand-made mesh past it";
  const Scene s = flat_layer();  // no max_dofs
  try {
    check_meshed_dofs(s, mesh_of_size(static_cast<int>(dofs / 3) + 1, 0));
    FAIL() << dofs << " unknowns passed " << avail << " GB";
  } catch (const SceneError& err) {
    EXPECT_TRUE(names(err.what(), "GB available")) << err.what();
  }
}

TEST(Resources, GuardedMeshRefusesBeforeMeshing) {
  Scene s = tiny_layer();
  s.limits.max_dofs = 10;
  Collect c;
  EXPECT_THROW(guarded_mesh(s), SceneError);
  for (const std::string& line : c.lines) EXPECT_FALSE(names(line, "meshing")) << line;
}

TEST(Resources, GuardedMeshMeshesWithinTheLimit) {
  Scene s = tiny_layer();
  s.limits.max_dofs = 1e5;
  MeshEstimate e;
  Collect c;
  const TetMesh m = guarded_mesh(s, MeshPart::half_y, &e);
  EXPECT_TRUE(e.known);
  EXPECT_NEAR(e.dofs, 1.1 * estimate_mesh(s, 1e12, MeshPart::half_y).dofs, 1e-9 * e.dofs);
  EXPECT_GT(m.num_tets(), 0);
  EXPECT_EQ(m.part, MeshPart::half_y);
  EXPECT_LE(unknowns_bound(m), s.limits.max_dofs);
  bool said_meshing = false;
  for (const std::string& line : c.lines) said_meshing |= names(line, "meshing tiny");
  EXPECT_TRUE(said_meshing);
}

}  // namespace
}  // namespace skinfem::pipeline
