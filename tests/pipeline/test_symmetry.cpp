// Which scenes are solved on their half y >= 0 (pipeline/symmetry.hpp), case by case against the header's
// rules: a generated flat layer or a cap with its apex on y = 0, no ridges, every sensor on y = 0 and
// "symmetry": "auto" gives the half for the Green commands; an imported surface, ridges, a cap's apex or a
// sensor off y = 0, or "symmetry": "none" give the whole, with a reason naming what breaks it. The contact
// commands also need the contact's centre, sliding direction, holes and hole sweep on the mirror. The shipped
// scenes are read through load_scene; every variant is the scene changed in one field.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "skinfem/pipeline/symmetry.hpp"
#include "skinfem/scene/load.hpp"

namespace skinfem::pipeline {
namespace {

Scene shipped(const std::string& name) {
  return load_scene(std::string(SKINFEM_SOURCE_DIR) + "/scenes/" + name + ".json");
}

bool names(const std::string& reason, const std::string& what) {
  return reason.find(what) != std::string::npos;
}

// A flat layer with sensors on y = 0 and a sphere pressed at the origin, sliding along x over a hole on the
// mirror: symmetric in every respect the header lists.
Scene symmetric_contact_scene() {
  Scene s;
  s.name = "mirror";
  s.geometry.kind = GeometryKind::flat;
  s.sensors.positions = {{-1, 0}, {0, 0}, {2, 0}};
  ContactLoad c;
  c.indenter = IndenterKind::sphere;
  c.sphere_R = 50;
  c.force = 0.5;
  c.direction = {1, 0};
  c.holes = {Hole{{0.5, 0}}};
  c.sweep = HoleSweep{{-1, 0}, {1, 0}};
  s.contact = c;
  return s;
}

TEST(Symmetry, ASymmetricFlatLayerIsSolvedOnItsHalf) {
  const Scene s = shipped("flat_layer");  // one sensor at the origin, a punch at the origin
  EXPECT_EQ(mirror_unavailable(s), "");
  EXPECT_EQ(green_mesh_part(s), MeshPart::half_y);
  EXPECT_EQ(contact_mirror_unavailable(s), "");  // no contact
  EXPECT_EQ(contact_mesh_part(s), MeshPart::half_y);
}

TEST(Symmetry, SymmetryNoneMeshesTheWhole) {
  Scene s = shipped("flat_layer");
  s.symmetry = SymmetryUse::none;
  EXPECT_EQ(green_mesh_part(s), MeshPart::whole);
  EXPECT_EQ(contact_mesh_part(s), MeshPart::whole);
  // As read from the file: the shipped scene's JSON with "symmetry": "none" added.
  std::ifstream in(std::string(SKINFEM_SOURCE_DIR) + "/scenes/flat_layer.json");
  nlohmann::json file = nlohmann::json::parse(in);
  file["symmetry"] = "none";
  const Scene none = parse_scene(file.dump(), "none.json");
  EXPECT_EQ(green_mesh_part(none), MeshPart::whole);
  Scene automatic = none;
  automatic.symmetry = SymmetryUse::automatic;
  EXPECT_EQ(green_mesh_part(automatic), MeshPart::half_y);
}

TEST(Symmetry, ASensorOffTheMirrorMeshesTheWholeAndIsNamed) {
  Scene s = shipped("flat_layer");
  s.sensors.positions = {{0, 0}, {1, 0.5}, {2, 0}};
  const std::string why = mirror_unavailable(s);
  EXPECT_TRUE(names(why, "sensor 2")) << why;  // sensors are numbered from 1 (scene.hpp)
  EXPECT_TRUE(names(why, "0.5")) << why;
  EXPECT_EQ(green_mesh_part(s), MeshPart::whole);
  EXPECT_EQ(contact_mesh_part(s), MeshPart::whole);
  // Sensors anywhere along x on y = 0 keep the symmetry, on either side of the origin and off the axis.
  s.sensors.positions = {{-7, 0}, {0.3, 0}, {4, 0}};
  EXPECT_EQ(green_mesh_part(s), MeshPart::half_y);
  // So does a post sensor there (its outline is a disc about its centre).
  s.sensors.model = SensorModel::post;
  EXPECT_EQ(green_mesh_part(s), MeshPart::half_y);
}

TEST(Symmetry, TheGreenCommandsLoadsAreTheCalibrationScanNotTheScenesLoads) {
  // The Green commands apply the calibration scan along x through the sensors, always symmetric; the scene's
  // own punches and patches are `solve`'s, which meshes the whole skin, so they do not decide the part.
  Scene s = shipped("flat_layer");
  s.loads.punches.at(0).center = {0, 2};
  s.loads.patches = {TractionPatch{{1, -3}, 0.5, {0, 1, 0}, 1.0}};
  EXPECT_EQ(green_mesh_part(s), MeshPart::half_y);
}

TEST(Symmetry, TheSkinItselfMustBeMirrorSymmetric) {
  Scene cap;
  cap.geometry.kind = GeometryKind::cap;
  cap.sensors.positions = {{0, 0}};
  cap.geometry.cap.apex_x = 0.5;  // along x: still symmetric about y = 0
  EXPECT_EQ(green_mesh_part(cap), MeshPart::half_y);
  cap.geometry.cap.R_y = 8;  // an ellipsoid with its axes along x and y
  EXPECT_EQ(green_mesh_part(cap), MeshPart::half_y);
  cap.geometry.cap.apex_y = 0.25;
  EXPECT_TRUE(names(mirror_unavailable(cap), "apex")) << mirror_unavailable(cap);
  EXPECT_EQ(green_mesh_part(cap), MeshPart::whole);

  const Scene ridged = shipped("ridged_layer");  // ridges centred on the origin, sensor at the origin
  EXPECT_TRUE(names(mirror_unavailable(ridged), "ridge")) << mirror_unavailable(ridged);
  EXPECT_EQ(green_mesh_part(ridged), MeshPart::whole);

  Scene surface = shipped("flat_layer");
  surface.geometry.kind = GeometryKind::surface;
  surface.geometry.surface.path = "dome.stl";
  EXPECT_TRUE(names(mirror_unavailable(surface), "surface")) << mirror_unavailable(surface);
  EXPECT_EQ(green_mesh_part(surface), MeshPart::whole);
  EXPECT_EQ(contact_mesh_part(surface), MeshPart::whole);
}

TEST(Symmetry, ASymmetricContactIsSolvedOnTheHalf) {
  Scene s = symmetric_contact_scene();
  EXPECT_EQ(contact_mirror_unavailable(s), "");
  EXPECT_EQ(contact_mesh_part(s), MeshPart::half_y);
  s.contact->direction = {-1, 0};  // sliding towards −x is its own mirror image too
  EXPECT_EQ(contact_mesh_part(s), MeshPart::half_y);
  // The shipped sphere on a flat layer, sensors along x.
  EXPECT_EQ(contact_mesh_part(shipped("hertz_layer")), MeshPart::half_y);
}

TEST(Symmetry, EachContactFieldOffTheMirrorMeshesTheWhole) {
  const auto check = [](const Scene& s, const std::string& what) {
    const std::string why = contact_mirror_unavailable(s);
    EXPECT_TRUE(names(why, what)) << "'" << why << "' should name " << what;
    EXPECT_EQ(contact_mesh_part(s), MeshPart::whole) << what;
    EXPECT_EQ(green_mesh_part(s), MeshPart::half_y) << what;  // the skin and sensors alone still are
  };
  Scene centre = symmetric_contact_scene();
  centre.contact->center = {0, 1};
  check(centre, "centre");
  Scene direction = symmetric_contact_scene();
  direction.contact->direction = {0.6, 0.8};
  check(direction, "direction");
  Scene hole = symmetric_contact_scene();
  hole.contact->holes.push_back(Hole{{0, -0.5}});
  check(hole, "hole 2");
  Scene sweep = symmetric_contact_scene();
  sweep.contact->sweep->to = {1, 0.1};
  check(sweep, "sweep");
  Scene texture = symmetric_contact_scene();
  texture.contact->texture = Texture{};
  texture.contact->texture->holes = {Hole{{0, 0}}, Hole{{1, 0.8}}, Hole{{1, -0.8}, 0.4}};
  check(texture, "texture hole 2");  // its image is smaller
}

TEST(Symmetry, ATextureOffTheMirrorWithEveryImageIsSolvedOnTheHalf) {
  Scene s = symmetric_contact_scene();
  s.contact->texture = Texture{};
  s.contact->texture->holes = {Hole{{0, 0}}, Hole{{1, 0.8}}, Hole{{-2, -1.5}}, Hole{{1, -0.8}},
                               Hole{{-2, 1.5}}};
  EXPECT_EQ(contact_mirror_unavailable(s), "");
  EXPECT_EQ(contact_mesh_part(s), MeshPart::half_y);
}

TEST(Symmetry, APlaneOnACapTouchesAtTheApex) {
  // A plane's centre is ignored (scene.hpp): on a cap it touches first at the apex, which decides.
  Scene s;
  s.geometry.kind = GeometryKind::cap;
  s.sensors.positions = {{0, 0}};
  ContactLoad c;
  c.indenter = IndenterKind::plane;
  c.force = 0.8;
  c.center = {0, 3};
  s.contact = c;
  EXPECT_EQ(contact_mirror_unavailable(s), "");
  EXPECT_EQ(contact_mesh_part(s), MeshPart::half_y);
  // The shipped caps: apex on y = 0, plane sliding along x, sweep along x.
  EXPECT_EQ(contact_mesh_part(shipped("candelier2011")), MeshPart::half_y);
  EXPECT_EQ(contact_mesh_part(shipped("fingertip")), MeshPart::half_y);
}

TEST(Symmetry, AContactOnAnAsymmetricSkinMeshesTheWhole) {
  Scene s = symmetric_contact_scene();
  s.sensors.positions.push_back({0, 1});
  EXPECT_EQ(contact_mirror_unavailable(s), "");  // the contact alone is symmetric
  EXPECT_EQ(contact_mesh_part(s), MeshPart::whole);
  s = symmetric_contact_scene();
  s.symmetry = SymmetryUse::none;
  EXPECT_EQ(contact_mesh_part(s), MeshPart::whole);
}

}  // namespace
}  // namespace skinfem::pipeline
