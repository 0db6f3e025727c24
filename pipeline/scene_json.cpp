#include "pipeline/scene_json.hpp"

namespace skinfem::pipeline {

nlohmann::json scene_json(const Scene& scene) {
  return {{"name", scene.name},
          {"source", scene.source_path},
          {"E_MPa", scene.material.E},
          {"nu", scene.material.nu},
          {"sensors", scene.sensors.positions.size()}};
}

}  // namespace skinfem::pipeline
