// The common first half of `green` and `kfit`: mesh, factor, and the adjoint solves of every sensor,
// each stage timed into `wall` (mesh, assemble, factor, adjoint_solves).
#pragma once

#include <memory>
#include <nlohmann/json.hpp>

#include "green/fe_green.hpp"
#include "mesh/tet_mesh.hpp"
#include "scene/scene.hpp"

namespace skinfem::app {

struct AdjointSetup {
  TetMesh mesh;
  std::unique_ptr<ElasticModel> model;  // refers to mesh
  std::unique_ptr<green::FeGreen> fe;   // refers to model
  nlohmann::json wall;
};

std::unique_ptr<AdjointSetup> adjoint_setup(const Scene& scene);

// Skin thickness above a sensor (exact shapes) or the scene's nominal thickness.
double thickness_at(const Scene& scene, const Vec2& sensor);
// Half-width of the calibration scan: at least 4h, more if the scene asks.
double scan_half_width(const Scene& scene, double h);

}  // namespace skinfem::app
