// The common first half of `contact` and `defect`: a meshed and factored skin (shared,
// pipeline/skin_setup.hpp; the contact zone and hole path refined), and its condensation onto the contact
// multipliers (block right-hand sides), each stage timed into `wall` (mesh, assemble, factor, condense). A
// mirror-symmetric scene (pipeline/symmetry.hpp) is solved on its half and seen whole: mesh(), the solver's
// results and `top` are the mirrored whole skin's.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>

#include "contact/contact_solver.hpp"
#include "fem/face_index.hpp"
#include "fem/sensor_reading.hpp"
#include "pipeline/skin_setup.hpp"

namespace skinfem::pipeline {

struct ContactSetup {
  explicit ContactSetup(std::shared_ptr<Skin> s) : skin(std::move(s)), model(skin->model.get()) {}
  std::shared_ptr<Skin> skin;  // the skin solved: the half under mirror symmetry
  const ElasticModel* model;
  // Under mirror symmetry: the whole skin mirrored from the half, and each of its nodes' half node.
  std::unique_ptr<TetMesh> whole;
  std::vector<int> source;
  const TetMesh& mesh() const { return whole ? *whole : skin->mesh; }  // the results' mesh
  std::unique_ptr<contact::Indenter> indenter;
  std::unique_ptr<SensorReadings> readings;              // the scene's sensors on the solved skin
  std::unique_ptr<contact::CondensedContact> condensed;  // on the solved skin
  std::unique_ptr<contact::MirrorView> mirror;           // null without mirror symmetry
  std::unique_ptr<contact::ContactSolver> solver;        // refers to condensed and mirror
  std::unique_ptr<PlanarFaceIndex> top;                  // of mesh()
  double zone_radius = 0, zone_h = 0;
  nlohmann::json wall;
};

// Whether to condense, with a contact.sweep, the compliance of the nodes its hole can reach, so that the
// sweep can cut the hats on the exact disc (contact/hole_cut.hpp; one more solve per such node): never, when
// the scene's sweep is resolved (HoleModel::resolved), or always (the report: its hole budget sweeps the
// interface hypotheses resolved).
enum class HolePath { none, as_scene, always };

// Throws SceneError when the scene has no contact section. skin: an already factored skin of this scene (its
// half when contact_mesh_part says so), or null to mesh and factor one.
std::unique_ptr<ContactSetup> contact_setup(const Scene& scene, std::shared_ptr<Skin> skin = nullptr,
                                            HolePath hole_path = HolePath::as_scene);

// How the skin was condensed, for the summary and the printed line: by block solves of a plain
// factorization or from a factorization bordered by the condensation's columns, with MUMPS's estimates that
// chose between them (MixedSolver::BorderChoice) when there was a choice.
nlohmann::json condensation_json(const ContactSetup& setup);
std::string condensation_said(const ContactSetup& setup);

// Throws (one line, naming contact.zone_radius) when an active multiplier lies in the zone's outer ring:
// the contact could be larger than the zone allows, so the answer would be wrong.
void check_zone(const Scene& scene, const ContactSetup& setup, const contact::ContactResult& r);

}  // namespace skinfem::pipeline
