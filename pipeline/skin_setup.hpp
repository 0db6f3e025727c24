// One meshed and factored skin, shared by every stage of a run (green, kfit, contact, defect, report):
// meshing and the factorization are done once per scene.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>

#include "fem/elastic_model.hpp"
#include "mesh/tet_mesh.hpp"
#include "scene/scene.hpp"

namespace skinfem::pipeline {

struct Skin {
  TetMesh mesh;
  std::unique_ptr<ElasticModel> model;  // refers to mesh; bonded base, no punches
  nlohmann::json wall;                  // seconds: mesh, assemble, factor
};

// Meshes the scene (with its contact zone and hole path refined when it has a contact), whole or its half
// y ≥ 0 (pipeline/symmetry.hpp), and factors it.
std::shared_ptr<Skin> skin_setup(const Scene& scene, MeshPart part = MeshPart::whole);
// Factors an already meshed skin of the scene (mesh_seconds: what meshing it took, for `wall`).
std::shared_ptr<Skin> factored_skin(const Scene& scene, TetMesh mesh, double mesh_seconds);

}  // namespace skinfem::pipeline
