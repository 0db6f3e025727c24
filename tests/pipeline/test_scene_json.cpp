// What a result file says of its scene (pipeline/scene_json.hpp): name, source file, material and number of
// sensors, against the shipped scenes/flat_layer.json read as plain JSON (not through skinfem's loader) and
// against a scene built in code; a post sensor's size is written only for post sensors.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "skinfem/pipeline/scene_json.hpp"
#include "skinfem/scene/load.hpp"

namespace skinfem::pipeline {
namespace {

TEST(SceneJson, CarriesTheScenesFileFields) {
  const std::string path = std::string(SKINFEM_SOURCE_DIR) + "/scenes/flat_layer.json";
  std::ifstream in(path);
  ASSERT_TRUE(in) << path;
  const nlohmann::json file = nlohmann::json::parse(in);

  const nlohmann::json j = scene_json(load_scene(path));
  EXPECT_EQ(j.at("name"), file.at("name"));
  EXPECT_EQ(j.at("source").get<std::string>(), path);
  EXPECT_EQ(j.at("E_MPa").get<double>(), file.at("material").at("E").get<double>());
  EXPECT_EQ(j.at("nu").get<double>(), file.at("material").at("nu").get<double>());
  EXPECT_EQ(j.at("sensors").get<size_t>(), file.at("sensors").at("positions").size());
  EXPECT_FALSE(j.contains("post_sensors"));  // disc sensors
}

TEST(SceneJson, CarriesASceneBuiltInCode) {
  Scene s;
  s.name = "in_code";
  s.material = {1.7, 0.45};
  s.sensors.positions = {{0, 0}, {1.5, 0}, {-2, 0.5}};
  const nlohmann::json j = scene_json(s);
  EXPECT_EQ(j.at("name").get<std::string>(), "in_code");
  EXPECT_EQ(j.at("source").get<std::string>(), "");  // built in code: no file
  EXPECT_EQ(j.at("E_MPa").get<double>(), 1.7);
  EXPECT_EQ(j.at("nu").get<double>(), 0.45);
  EXPECT_EQ(j.at("sensors").get<int>(), 3);
  EXPECT_FALSE(j.contains("post_sensors"));

  s.sensors.positions.clear();
  EXPECT_EQ(scene_json(s).at("sensors").get<int>(), 0);
}

TEST(SceneJson, PostSensorsCarryTheirSize) {
  Scene s;
  s.name = "posts";
  s.sensors.positions = {{0, 0}};
  s.sensors.model = SensorModel::post;
  s.sensors.post.diameter = 0.3;
  s.sensors.post.height = 0.6;
  s.sensors.disc_diameter = 0.9;  // a disc's size, not the post's: not written
  const nlohmann::json j = scene_json(s);
  ASSERT_TRUE(j.contains("post_sensors"));
  EXPECT_EQ(j.at("post_sensors").at("diameter_mm").get<double>(), 0.3);
  EXPECT_EQ(j.at("post_sensors").at("height_mm").get<double>(), 0.6);
  EXPECT_EQ(j.at("sensors").get<int>(), 1);
}

}  // namespace
}  // namespace skinfem::pipeline
