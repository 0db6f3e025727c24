// `skinfem green` on the neo-Hookean skin: the sensor's sensitivity under a preload. The scene's traction
// patches (loads.patches, dead loads in the reference configuration) bring the skin to a deformed state by
// Newton (fem/newton.hpp); the skin linearized there, its tangent factored (ElasticModel's tangent
// constructor), is what the adjoint solves of green/fe_green.hpp then read: g_ab is the derivative of
// sensor reading a with respect to a point force b added on top of the preload, the force applied at the
// material point above (x, y) in the reference frame. Without patches the state is rest, where the tangent
// is the linear incompressible system exactly, so the Green tensor is the linear skin's. Units: mm, N, MPa.
#pragma once

#include <Eigen/Dense>
#include <memory>
#include <string>
#include <vector>

#include "skinfem/fem/newton.hpp"
#include "skinfem/mesh/build.hpp"
#include "skinfem/pipeline/skin_setup.hpp"

namespace skinfem::pipeline {

struct Preload {
  int patches = 0;
  Eigen::Vector3d force_N = Eigen::Vector3d::Zero();  // Σ the patches' forces on the whole skin
  double max_displacement_mm = 0;                     // largest |u| at the preloaded state
  std::vector<NewtonStep> steps;                      // its Newton load steps (empty without patches)
  int rejected_steps = 0;
  std::string said() const;  // one sentence: what the skin was linearized about
};

// Throws SceneError (one line naming the field) for a preload the tangent Green tensor does not model:
// punches (green/fe_green.hpp reads a skin without punch constraints) and posts on springs
// (require_rigid_posts).
void check_preload(const Scene& scene);

// The mesh part Green tensors take for the scene (pipeline/symmetry.hpp's green_mesh_part), whole unless
// every patch is symmetric about y = 0 too (centred on it, no y component).
MeshPart preload_mesh_part(const Scene& scene);

// Meshes `part` of the scene, solves its patches on the neo-Hookean skin (SolverError when Newton cannot
// carry them) and factors the tangent there. preload: filled with the state's account. wall: mesh, newton,
// assemble (the tangent), factor.
std::shared_ptr<Skin> preloaded_skin(const Scene& scene, MeshPart part, Preload* preload = nullptr);

}  // namespace skinfem::pipeline
