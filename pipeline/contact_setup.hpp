// The common first half of `contact` and `defect`: a meshed and factored skin (shared,
// pipeline/skin_setup.hpp; the contact zone and hole path refined), and its condensation onto the contact
// multipliers (block right-hand sides, or the Schur complement of a bordered factorization), each stage timed
// into `wall` (mesh, assemble, factor, condense). A mirror-symmetric scene (pipeline/symmetry.hpp) is solved
// on its half and seen whole: mesh(), the solver's results and `top` are the mirrored whole skin's.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "skinfem/contact/condensed.hpp"
#include "skinfem/contact/contact_solver.hpp"
#include "skinfem/contact/mortar.hpp"
#include "skinfem/fem/face_index.hpp"
#include "skinfem/fem/sensor_reading.hpp"
#include "skinfem/pipeline/clock.hpp"
#include "skinfem/pipeline/skin_setup.hpp"

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
  Timings wall;
};

// Whether to condense, with a contact.sweep, the compliance of the nodes its hole can reach, so that the
// sweep can cut the hats on the exact disc (contact/holes/cut.hpp; one more solve per such node): never, when
// the scene's sweep is resolved (HoleModel::resolved), or always (the report: its hole budget sweeps the
// interface hypotheses resolved, and its perception section scans holes that enter and leave the zone: the
// path runs on along the sweep's line to the zone's edges). A contact.texture's tracks are watched unless
// never (its holes are always resolved, contact/holes/scan.hpp).
enum class HolePath { none, as_scene, always };

// A skin of this scene meshed and factored for its contact (its half where contact_mesh_part says so):
// bordered by the condensation's columns where MUMPS's estimates make that the cheaper road
// (contact/condensed.hpp), so that the condensation costs no solve. Every other stage sharing the skin
// (green's and kfit's adjoint solves) solves on the interior block, the skin's own factor, unchanged. Posts
// on springs read through the factored skin itself, so their columns come after it: a plain factorization.
struct ContactSkin {
  std::shared_ptr<Skin> skin;
  HolePath hole_path = HolePath::as_scene;
  std::unique_ptr<contact::CondenseColumns> columns;  // null: the condensation's columns by block solves
  std::optional<contact::MortarZone> zone;            // on the skin's mesh, once found
  std::vector<int> watch_faces;                       // the faces a swept hole reaches (hole_path)
};
// Throws SceneError when the scene has no contact section.
ContactSkin contact_skin(const Scene& scene, HolePath hole_path = HolePath::as_scene);
// The skin every stage of a chain shares (report, its error levels): contact_skin with a contact, else a
// plain factorization.
ContactSkin chain_skin(const Scene& scene, HolePath hole_path = HolePath::as_scene);
// The condensation on that skin.
std::unique_ptr<ContactSetup> contact_setup(const Scene& scene, ContactSkin skin);
// skin: an already factored skin of this scene (its half when contact_mesh_part says so; its condensation
// then by block solves), or null to make one by contact_skin.
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
// The same for a solver on `mesh` (the results' mesh: the whole under mirror symmetry) before its setup is
// complete.
void check_zone(const Scene& scene, const TetMesh& mesh, const contact::ContactSolver& solver,
                double zone_radius, double zone_h, const contact::ContactResult& r);
// The same for a contact whose farthest active multiplier lies `reach` mm from the centre (a zone of
// zone_radius, meshed at zone_h).
void check_zone_reach(const Scene& scene, double zone_radius, double zone_h, double reach, FrictionMode mode);

}  // namespace skinfem::pipeline
