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

}  // namespace skinfem::app
