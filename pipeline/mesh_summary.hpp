// What `mesh` and the report say of a skin's mesh: its counts and quality (mesh/quality.hpp) and its volume
// against the exact one where the shape is known. Units: mm, degrees.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>

#include "skinfem/mesh/quality.hpp"
#include "skinfem/mesh/tet_mesh.hpp"
#include "skinfem/scene/scene.hpp"

namespace skinfem::pipeline {

struct MeshSummary {
  MeshQuality quality;
  // The skin's exact volume where its shape is known: the generated layer's, less its post sensors'
  // cavities; none for a skin read from a file.
  std::optional<double> exact_volume_mm3;
  int straightened = 0;  // elements folded by their curved edges, given straight ones
  double seconds = 0;    // the meshing's
};

MeshSummary mesh_summary(const Scene& scene, const TetMesh& mesh, double mesh_seconds);

// mesh/summary.json: counts, quality, volume (with its relative error), the scene, the straightened
// elements, wall_s and the peak memory so far.
nlohmann::json mesh_json(const Scene& scene, const MeshSummary& s);

}  // namespace skinfem::pipeline
