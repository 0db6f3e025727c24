// One meshed and factored skin, shared by every stage of a run (green, kfit, contact, defect, report):
// meshing and the factorization are done once per scene.
#pragma once

#include <functional>
#include <memory>
#include <nlohmann/json.hpp>

#include "skinfem/fem/elastic_model.hpp"
#include "skinfem/mesh/tet_mesh.hpp"
#include "skinfem/pipeline/clock.hpp"
#include "skinfem/scene/scene.hpp"

namespace skinfem::pipeline {

struct Skin {
  TetMesh mesh;
  std::unique_ptr<ElasticModel> model;  // refers to mesh; bonded base, no punches
  Timings wall;                         // seconds: mesh, assemble, factor
};

// The stages built on the linear skin (every one but solve so far) refuse a finite-strain scene: throws
// SceneError naming material.model, its value and what `stage` takes.
void require_linear(const Scene& scene, const std::string& stage);
// The finite-strain skin holds its posts rigid: throws SceneError naming sensors.post.support otherwise.
void require_rigid_posts(const Scene& scene);

// Given the skin's mesh before it is factored, columns to border the factorization with
// (MixedSolver::Coupling: their products come with it), or null; what it returns must outlive the call.
using Border = std::function<const MixedSolver::Coupling*(const TetMesh&)>;

// Meshes the scene (with its contact zone and hole path refined when it has a contact), whole or its half
// y ≥ 0 (pipeline/symmetry.hpp), and factors it.
std::shared_ptr<Skin> skin_setup(const Scene& scene, MeshPart part = MeshPart::whole,
                                 const Border& border = {});
// Factors an already meshed skin of the scene (mesh_seconds: what meshing it took, for `wall`).
std::shared_ptr<Skin> factored_skin(const Scene& scene, TetMesh mesh, double mesh_seconds,
                                    const Border& border = {});

}  // namespace skinfem::pipeline
