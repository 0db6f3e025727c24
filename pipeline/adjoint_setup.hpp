// The common first half of `green` and `kfit`: a meshed and factored skin (shared, pipeline/skin_setup.hpp)
// and the adjoint solves of every sensor, each stage timed into `wall` (mesh, assemble, factor,
// adjoint_solves).
#pragma once

#include <memory>
#include <nlohmann/json.hpp>

#include "skinfem/green/fe_green.hpp"
#include "skinfem/pipeline/clock.hpp"
#include "skinfem/pipeline/skin_setup.hpp"

namespace skinfem::pipeline {

struct AdjointSetup {
  explicit AdjointSetup(std::shared_ptr<Skin> s)
      : skin(std::move(s)), mesh(skin->mesh), model(skin->model.get()) {}
  std::shared_ptr<Skin> skin;
  const TetMesh& mesh;
  const ElasticModel* model;
  std::unique_ptr<green::FeGreen> fe;  // refers to model
  Timings wall;
};

// skin: an already factored skin of this scene, or null to mesh and factor one (its half y ≥ 0 where the
// scene is mirror-symmetric: pipeline/symmetry.hpp).
std::unique_ptr<AdjointSetup> adjoint_setup(const Scene& scene, std::shared_ptr<Skin> skin = nullptr);

// Skin thickness above a base point (fem/face_index.hpp skin_thickness); a point with no skin above it is a
// scene error naming it.
double thickness_at(const Scene& scene, const TetMesh& mesh, const Vec2& p);
// Throws SceneError naming the first sensor whose disc is not entirely under the skin (imported skins: the
// scene cannot check it before meshing).
void check_sensors_on_skin(const Scene& scene, const TetMesh& mesh);
// Half-width of the calibration scan along x through a sensor: calibration.scan_half_width if given, else 4h,
// shortened so that the loaded disc stays on the skin's footprint on both sides (flat and cap skins exactly,
// imported skins by walking along the meshed top, which `mesh` must then give).
double scan_half_width(const Scene& scene, const TetMesh* mesh, double h, const Vec2& sensor);

}  // namespace skinfem::pipeline
