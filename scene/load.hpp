// Reading and validating scene files (JSON). The format is documented in load.cpp's header comment
// and by the shipped scenes in scenes/. Units: mm, N, MPa.
#pragma once

#include <string>

#include "skinfem/scene/scene.hpp"

namespace skinfem {

// Reads the JSON scene file at `path`, validates it and returns the Scene. A relative
// geometry.path (imported surface) is resolved against the directory of `path`;
// Scene::source_path is `path`; Scene::name is the JSON "name" or, if absent, the file stem.
// Throws SceneError (one line: "<file>: <json.path> = <value>: <what is allowed>") on any problem,
// including a file that cannot be read and JSON syntax errors (with line and column).
Scene load_scene(const std::string& path);

// Same as load_scene on JSON text already in memory. `source_path` names the text in error messages,
// sets Scene::source_path, anchors a relative geometry.path (its directory; the working directory if
// it has none) and gives the default name (its stem). It need not exist.
Scene parse_scene(const std::string& json_text, const std::string& source_path);

// The placement rules of punches and patches (on the skin with mesh.h_min to spare, apart, above the mesh
// generator's tolerance) for a scene changed in code, e.g. its mesh sizes scaled by a study; `what` names
// the change in the message. Throws SceneError like load_scene.
// A scene's or a sweep's "name", which becomes a folder (out/<name>): one path component that cannot climb
// out, hide, pose as an option or carry a quote or control character. kNameRule says what is allowed.
bool is_path_component(const std::string& s);
extern const char* const kNameRule;

void check_load_placement(const Scene& scene, const std::string& what);

}  // namespace skinfem
