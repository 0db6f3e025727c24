// Each stage's output: its files in DIR and its summary lines, from the typed result and the summary its
// pipeline/ function built. The single-purpose subcommands (mesh, green, kfit, contact, defect) compute one
// stage and write it; `report` writes them all as pipeline::report hands them over (app/report_writer.hpp).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "skinfem/pipeline/contact.hpp"
#include "skinfem/pipeline/defect.hpp"
#include "skinfem/pipeline/green.hpp"
#include "skinfem/pipeline/hole_budget.hpp"
#include "skinfem/pipeline/kfit.hpp"
#include "skinfem/pipeline/mesh_summary.hpp"
#include "skinfem/pipeline/post_design.hpp"
#include "skinfem/pipeline/report_perception.hpp"
#include "skinfem/pipeline/sensor_greens.hpp"
#include "skinfem/validation/crosscheck.hpp"

namespace skinfem::app {

// lines: where the lines go instead of stdout (common.hpp say: the report's mesh is written on a thread
// beside its green stage, and both are printed in order).
// mesh.vtu, boundary.vtu, summary.json (pipeline::mesh_json's).
void write_mesh(const Scene& scene, const TetMesh& mesh, const pipeline::MeshSummary& s,
                const nlohmann::json& summary, const std::string& out_dir, std::string* lines = nullptr);
// green.csv, green_maps.vtp, summary.json (pipeline::green_json's), and kernel.h5, kernel.vti with a grid.
void write_green(const Scene& scene, const SensorGreens& greens, const pipeline::GreenRun& run,
                 const nlohmann::json& summary, const std::string& out_dir, std::string* lines = nullptr);
// kfit.json (file: pipeline::kfit_json's).
void write_kfit(const Scene& scene, const pipeline::KfitResult& r, const nlohmann::json& file,
                const std::string& out_dir);
// pressure.vtp, fields.vtu, sensors.csv, modes.csv, summary.json (pipeline::contact_json's, given the
// writing's seconds).
void write_contact(const Scene& scene, const pipeline::ContactRun& run, nlohmann::json& summary,
                   const std::string& out_dir);
// defect.csv, summary.json (pipeline::defect_json's, given the writing's seconds) and, with write_frames,
// defect.pvd and frames/ (without: an earlier run's are removed; report --fast).
void write_defect(const Scene& scene, const pipeline::DefectRun& run, nlohmann::json& summary,
                  const std::string& out_dir, bool write_frames = true);
// The hole-signal budget's tables, in the crosscheck's folder (app/write_hole_budget.cpp).
void write_hole_budget(const Scene& scene, const pipeline::HoleBudget& b, const validation::Crosscheck& x,
                       const std::string& out_dir);
// The report's perception section: row.csv, pairs.csv, detection.csv, detection_map.csv, features.csv and
// summary.json (entry) (app/write_perception.cpp).
void write_perception(const Scene& scene, const pipeline::ReportPerception& p, const nlohmann::json& entry,
                      const std::string& out_dir);
// post_design.csv, and the entry's answer printed (app/write_post_design.cpp).
void write_post_design(const pipeline::PostDesign& p, const nlohmann::json& entry,
                       const std::string& out_dir);

}  // namespace skinfem::app
