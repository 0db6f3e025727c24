// The typed description of one skinfem run. Units everywhere: mm, N, MPa.
// scene/load.cpp turns a JSON file into this struct; nothing else in skinfem reads JSON.
#pragma once

#include <array>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace skinfem {

using Vec2 = std::array<double, 2>;
using Vec3 = std::array<double, 3>;

// Spherical cap bonded to z = 0: top z = h − R + sqrt(R² − (x − x_a)² − (y − y_a)²),
// cut by the vertical cylinder of radius truncation_radius about the apex axis.
struct CapGeometry {
  double R = 129.7;
  double h = 3.04;
  double apex_x = 0.0, apex_y = 0.0;
  double truncation_radius = 12.0;
};

// Flat layer of thickness h over the square |x|, |y| ≤ half_width.
struct FlatGeometry {
  double h = 3.04;
  double half_width = 15.0;
};

// Closed triangulated surface (STL/OBJ/OFF) whose base lies on z = 0.
struct SurfaceGeometry {
  std::string path;  // resolved relative to the scene file
};

enum class GeometryKind { cap, flat, surface };
// What holds the lateral (truncation) face: nothing (traction-free) or u = 0.
enum class SideCondition { free, fixed };

struct Geometry {
  GeometryKind kind = GeometryKind::cap;
  CapGeometry cap;
  FlatGeometry flat;
  SurfaceGeometry surface;
  SideCondition side = SideCondition::free;
};

struct Material {
  double E = 3.0;   // MPa
  double nu = 0.5;  // 0 ≤ nu ≤ 0.5; 0.5 exactly is incompressible
};

// Sensors sit on the base z = 0 and read the mean traction over a disc.
struct Sensors {
  std::vector<Vec2> positions;  // mm, numbered 1..n in this order
  double disc_diameter = 0.2;   // mm
};

// A region where the mesh must be fine: every point within `radius` of the
// segment a→b (a point when a == b). Measured in the (x, y) plane; applies at all z.
struct RegionOfInterest {
  Vec2 a{0, 0}, b{0, 0};
  double radius = 0.0;
  double h = 0.0;  // target edge length inside, mm; 0 → mesh.h_min
};

struct MeshControls {
  double h_min = 0.25;         // mm, edge length inside regions of interest
  double growth = 1.3;         // geometric growth rate of the edge length away from them (> 1)
  double h_max = 2.0;          // mm, cap on the edge length
  bool refine_sensors = true;  // sensor discs are regions of interest
  std::vector<RegionOfInterest> regions;
  double max_radius_edge = 1.5;  // TetGen quality bound (q switch): max radius-edge ratio, >= 1.1
  double min_dihedral_deg = 10;  // TetGen quality bound (q switch): min dihedral angle, in (0, 30)
};

// Rigid flat punch on the top surface.
struct Punch {
  Vec2 center{0, 0};
  double diameter = 0.5;               // mm
  std::optional<double> force;         // N, total normal force (pressing = positive)
  std::optional<double> displacement;  // mm, downward indentation
};

// Uniform traction over a disc of the top surface; total force given.
struct TractionPatch {
  Vec2 center{0, 0};
  double diameter = 0.5;     // mm
  Vec3 direction{0, 0, -1};  // unit vector, normalised on load
  double force = 1.0;        // N
};

struct Loads {
  std::vector<Punch> punches;
  std::vector<TractionPatch> patches;
};

// The paper's calibration: a punch (normal) and a tangential patch of this
// diameter, unit total force, scanned along x through the sensors.
struct Calibration {
  double punch_diameter = 0.5;  // mm
  double scan_half_width = 0;   // mm, |offset| range; 0 → 4 h
  double spacing = 0.05;        // mm
};

struct Scene {
  std::string name;
  std::string source_path;  // the JSON file this came from (empty if built in code)
  Geometry geometry;
  Material material;
  Sensors sensors;
  MeshControls mesh;
  Loads loads;
  Calibration calibration;
};

// Thrown for any invalid scene; what() is one line naming the JSON path, the value and what is allowed.
struct SceneError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Thickness of the skin at the apex (cap) or everywhere (flat), mm. For an imported surface the
// thickness is not known before the file is read: returns 0, meaning "unknown" (ask the mesh).
double nominal_thickness(const Scene& scene);

}  // namespace skinfem
