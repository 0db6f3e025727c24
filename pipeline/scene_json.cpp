#include "skinfem/pipeline/scene_json.hpp"

namespace skinfem::pipeline {

nlohmann::json scene_json(const Scene& scene) {
  nlohmann::json j = {{"name", scene.name},
                      {"source", scene.source_path},
                      {"E_MPa", scene.material.E},
                      {"nu", scene.material.nu},
                      {"material_model", to_string(scene.material.model)},
                      {"sensors", scene.sensors.positions.size()}};
  if (scene.sensors.model == SensorModel::post)
    j["post_sensors"] = {{"diameter_mm", scene.sensors.post.diameter},
                         {"height_mm", scene.sensors.post.height}};
  return j;
}

}  // namespace skinfem::pipeline
