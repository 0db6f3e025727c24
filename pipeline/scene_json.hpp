// What a result file says of its scene: name, source file, material, number of sensors, and for post
// sensors their diameter and height (post_sensors).
#pragma once

#include <nlohmann/json.hpp>

#include "skinfem/scene/scene.hpp"

namespace skinfem::pipeline {

nlohmann::json scene_json(const Scene& scene);

}  // namespace skinfem::pipeline
