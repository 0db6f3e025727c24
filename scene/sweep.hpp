// Parameter sweeps: a base scene, axes of scene keys (JSON pointers such as /material/nu) each with a list or
// a range of values, combined as a grid or zipped, and the skinfem command to run on every member. This
// reads and checks the spec and every member's scene; app/cmd_sweep.cpp writes them out and hands them to
// the workflow engine (Snakemake, sweeps/workflow/). The format is documented in sweep.cpp's header.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "skinfem/scene/scene.hpp"

namespace skinfem {

struct SweepAxis {
  std::string pointer;              // JSON pointer into the scene: /calibration/punch_diameter
  std::string column;               // its column in the results table: calibration.punch_diameter
  std::vector<std::string> values;  // each value as compact JSON text
};

struct SweepMember {
  std::string id;  // 12 hex digits hashing the scene text, the files it names, the command and its options
  std::vector<std::string> values;  // one per axis, compact JSON text
  std::string scene_json;           // the member's scene (a relative geometry.path made absolute)
  Scene scene;                      // the same, validated
};

struct Sweep {
  std::string name;  // the spec's "name", else its file stem
  std::string spec_path, base_scene_path;
  std::string command;               // kfit, green, contact, defect or report
  std::vector<std::string> options;  // the command's options as command-line words
  std::string combine;               // grid (every combination, the last axis fastest) or zip
  long mem_mb = 0;                   // memory each job declares, MB; 0: skinfem's mesh estimate
  std::vector<SweepAxis> axes;
  std::vector<SweepMember> members;
};

// Reads the spec at `path` and builds every member. Throws SceneError, one line naming the spec, the field,
// the value and what is allowed, on any problem: the spec's own fields, a pointer that names nothing in the
// base scene, an empty axis, an axis inside another, zipped axes of unequal length, more than 10000
// members, or a member the scene rules refuse (that member's scene error, prefixed with its values).
Sweep load_sweep(const std::string& path);

}  // namespace skinfem
