// The typed description of one skinfem run. Units everywhere: mm, N, MPa.
// scene/load.cpp turns a JSON file into this struct; nothing else in skinfem reads JSON.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace skinfem {

using Vec2 = std::array<double, 2>;
using Vec3 = std::array<double, 3>;

// The error bars' coarser levels (`--error-scales`, a sweep's error_scales) multiply every mesh size by a
// scale in (1, kMaxErrorScale]: beyond it a level no longer resolves the scene and its change is no error.
inline constexpr double kMaxErrorScale = 4;

// Spherical or ellipsoidal cap bonded to z = 0, cut by the vertical cylinder of radius truncation_radius
// about the apex axis. R and R_y are the top's radii of curvature at the apex along x and y (R_y = 0: R_y =
// R, a sphere). The top is the ellipsoid with semi-axes a = sqrt(R c) (x), b = sqrt(R_y c) (y) and
// c = sqrt(R R_y) (z), whose apex curvatures are a²/c = R and b²/c = R_y:
//   z = h − c + c sqrt(1 − ((x − x_a)/a)² − ((y − y_a)/b)²);  for R_y = R, h − R + sqrt(R² − r²).
struct CapGeometry {
  double R = 129.7;
  double h = 3.04;
  double apex_x = 0.0, apex_y = 0.0;
  double truncation_radius = 12.0;
  double R_y = 0;  // mm; 0 → R (spherical). Last, so that {R, h, x_a, y_a, r_t} still means a sphere.

  double radius_y() const { return R_y > 0 ? R_y : R; }
  bool spherical() const { return radius_y() == R; }
  double semi_axis_z() const { return spherical() ? R : std::sqrt(R * radius_y()); }
  double semi_axis_x() const { return spherical() ? R : std::sqrt(R * semi_axis_z()); }
  double semi_axis_y() const { return spherical() ? R : std::sqrt(radius_y() * semi_axis_z()); }
  // Smallest distance from the apex axis at which the top meets the base plane (along the shorter axis).
  double rim_radius() const {
    if (spherical()) return std::sqrt(R * R - (R - h) * (R - h));
    const double c = semi_axis_z(), t = 1 - h / c;
    return std::min(semi_axis_x(), semi_axis_y()) * std::sqrt(1 - t * t);
  }
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

// Fingerprint-like ridges on the top of a cap or flat layer (Scheibert et al., Science 2009: period about
// 220 µm): the top becomes s(x, y) + (height/2) w(ρ) P(ξ), ξ = (p − center)·(cos θ, sin θ) the distance
// across the crests (crests run at angle_deg + 90° from x; angle_deg = 0: crests along y, ridges crossed by a
// scan along x), ρ = |p − center|. The window w is 1 for ρ ≤ radius − period and falls to 0 at ρ = radius as
// a half cosine, so the top stays smooth (C¹) where the pattern ends. The profile P, period-periodic with a
// crest at ξ = 0 and P(ξ + period/2) = −P(ξ):
//   sinusoidal:  P = cos(2πξ / period);
//   rectangular: flat crests and troughs joined by walls edge_width wide across which P goes from 1 to −1 as
//                a half sine, so the wall meets each plateau with zero slope (C¹). Truly vertical walls are
//                no height field z = s(x, y); edge_width = period/2 leaves no plateau and is the sinusoid.
enum class RidgeProfile { sinusoidal, rectangular };

struct Ridges {
  double period = 0;  // mm; 0: no ridges
  double height = 0;  // mm, crest to trough
  double angle_deg = 0;
  Vec2 center{0, 0};  // mm
  double radius = 0;  // mm, the patterned disc
  double h = 0;  // mm, mesh size on the pattern; 0 → period/6 (sinusoidal), min(period/6, edge_width/2)
  RidgeProfile profile = RidgeProfile::sinusoidal;
  double edge_width = 0;  // mm, rectangular only: the width of each wall, in (0, period/2]

  bool present() const { return period > 0; }
  double mesh_size() const {
    if (h > 0) return h;
    return profile == RidgeProfile::rectangular ? std::min(period / 6, edge_width / 2) : period / 6;
  }
};

enum class GeometryKind { cap, flat, surface };
// What holds the lateral (truncation) face: nothing (traction-free) or u = 0.
enum class SideCondition { free, fixed };

struct Geometry {
  GeometryKind kind = GeometryKind::cap;
  CapGeometry cap;
  FlatGeometry flat;
  SurfaceGeometry surface;
  Ridges ridges;  // cap or flat only
  SideCondition side = SideCondition::free;
};

// The skin's constitutive law: linear elasticity at small strain, or the incompressible neo-Hookean solid at
// finite strain (shear modulus E/3; fem/neo_hookean.hpp), which needs nu = 0.5.
enum class MaterialModel { linear, neo_hookean };

struct Material {
  double E = 3.0;   // MPa
  double nu = 0.5;  // 0 ≤ nu ≤ 0.5; 0.5 exactly is incompressible
  MaterialModel model = MaterialModel::linear;
};
inline const char* to_string(MaterialModel m) {
  return m == MaterialModel::linear ? "linear" : "neo_hookean";
}

// Sensors sit on the base z = 0. A disc reads the mean base traction over it; a post (the paper's sensor: a
// rigid cylinder standing on the base, bonded to the skin around it) reads the force the skin exerts on it,
// as that force over its cross-section (fem/sensor_reading.hpp).
enum class SensorModel { disc, post };
// The membrane a post stands on, as springs between the post's foot and the frame: the gauges read the force
// the springs carry. All zero: a rigid support (the post held still).
struct MembraneSprings {
  double k_normal = 0;      // N/mm, along z
  double k_tangential = 0;  // N/mm, along x and y
  double k_tilt = 0;        // N·mm/rad, about x and y through the foot's centre
  bool rigid() const { return k_normal == 0; }
};
struct PostSensor {
  double diameter = 0.2;  // mm
  double height = 0.4;    // mm, above the base; less than the skin's thickness there
  MembraneSprings support{};
};
struct Sensors {
  std::vector<Vec2> positions;  // mm, numbered 1..n in this order
  double disc_diameter = 0.2;   // mm
  SensorModel model = SensorModel::disc;
  PostSensor post;  // model post only
  // The radius of the base each sensor occupies: the disc's or the post's.
  double footprint_radius() const {
    return 0.5 * (model == SensorModel::post ? post.diameter : disc_diameter);
  }
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
  // mm, ≤ h_min: edge length at each sensor disc on the base, growing with the distance from the disc in
  // every direction (if refine_sensors); 0 → min(h_min, disc radius), or h_min for point sensors.
  double sensor_h = 0.0;
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
  double scan_half_width = 0;  // mm, |offset| range; 0 → 4 h; kept on the skin (pipeline/adjoint_setup.hpp)
  double spacing = 0.05;       // mm
};

// Unilateral contact of a rigid indenter with the skin's top (contact/). The indenter's lower surface is
// z = z_touch − depth + φ(x, y) over the (x, y) plane, with z_touch the height at which it first touches the
// undeformed skin: φ = 0 for a plane (the paper's plate on the cap), φ = R − sqrt(R² − r²) for a sphere of
// radius R centred above `center`. Holes are discs where the indenter is absent (deep holes: the skin never
// reaches their bottom).
enum class IndenterKind { plane, sphere };
// How the tangential traction of a sliding or resting plate enters (contact/contact_solver.hpp):
//   none: frictionless; static: p_t = static_ratio·p_z; uncoupled: frictionless pressure, then p_t = μ p_z
//   added (the paper's assumption); coupled: p_t = μ p_z acting while pressure and zone are solved.
enum class FrictionMode { none, static_residual, uncoupled, coupled };
// What the tangential traction of a sliding plate is (contact/contact_solver.hpp):
//   coulomb: p_t = μ p; shear_strength: p_t = τ0 wherever the skin touches (a pressure-independent shear
//   strength, as measured for PDMS on smooth glass); mixed: p_t = τ0 + μ p. At rest (the static mode) the
//   plate keeps the fraction static_ratio/μ of the sliding traction.
enum class FrictionLaw { coulomb, shear_strength, mixed };

struct Hole {
  Vec2 center{0, 0};
  double diameter = 0.5;  // mm
  double h = 0;           // mm, mesh size over the hole's disc; 0 → the contact zone's (contact_zone_h)
  // mm, how deep the hole goes into the indenter (the paper's: 500 µm). The skin that bulges into it must
  // stay above its bottom (the solve assumes it touches nothing there); gaps inside are measured to it.
  double depth = 0.5;
  // A groove (contact.texture.grooves) when > 0: the rectangle `diameter` wide and `length` (mm) long, its
  // length along the unit vector `across` (the normal of the sliding direction). 0: a disc.
  double length = 0;
  Vec2 across{0, 1};
  bool groove() const { return length > 0; }
};

// A hole swept along a straight path: `positions` solves with the hole centre evenly spaced from `from`
// to `to` (inclusive), each a full contact solve (skinfem defect).
// How a swept hole is modelled (contact/holes/sweep.hpp): bulge, the small hole's asymptotic solution (the
// skin bulging into it as into a penny-shaped crack, seen by the contact as a dimple of the indenter,
// contact/holes/dimple.hpp); resolved, the hole's exact disc cutting the multipliers' hats
// (contact/holes/cut.hpp).
enum class HoleModel { bulge, resolved };
struct HoleSweep {
  Vec2 from{0, 0}, to{0, 0};
  int positions = 201;
  double hole_diameter = 0.5;  // mm
  double h = 0;  // mm, mesh size along the path (a region of interest of radius hole/2 + h); 0 → none
  HoleModel model = HoleModel::bulge;
  double hole_depth = 0.5;  // mm, as Hole::depth
};

// A textured plate (contact.texture) scanned over the skin (contact.scan, `skinfem scan`): holes listed one
// by one, a lattice of identical holes (a row is a lattice one hole across) and holes at random. Positions
// are on the plate at scan position u = 0; at u the plate and its holes have moved by u along the sliding
// direction (contact.friction.direction). Every hole is resolved (contact/holes/cut.hpp). Grooves (a
// grating) are rectangular holes across the sliding direction, cut on their exact rectangle.
struct HoleLattice {
  Vec2 origin{0, 0};  // mm, the first hole's centre
  Vec2 period{1, 1};  // mm, along x and y
  int nx = 1, ny = 1;
  double diameter = 0.5, depth = 0.5;  // mm
};

// A grating: `count` parallel grooves across the sliding direction, `period` apart along it, the first
// centred at `origin`; each `width` wide along the sliding direction and `length` long across it.
struct Grooves {
  Vec2 origin{0, 0};                                        // mm
  double width = 0.5, length = 0, period = 1, depth = 0.5;  // mm
  int count = 1;
  Vec2 direction{1, 0};  // the sliding direction (contact.friction.direction), set by the loader
};

// Holes drawn uniformly on the plate's rectangle [from, to], round(density × area) of them, diameters
// uniform in [diameter_min, diameter_max], none overlapping another feature (rejection; refused when 20,000
// draws in a row find no room): deterministic for a seed on every platform (splitmix64, not the standard
// library's distributions).
struct RandomHoles {
  Vec2 from{0, 0}, to{0, 0};                                   // mm, the rectangle's corners
  double density = 0;                                          // holes per mm²
  double diameter_min = 0.5, diameter_max = 0.5, depth = 0.5;  // mm
  std::uint64_t seed = 1;
  // Drawn in pairs mirrored about y = 0 (the rectangle symmetric about it): the plate, the contact and the
  // sensors on y = 0 are then mirror-symmetric and the half skin solves them (pipeline/symmetry.hpp). A pair
  // must not overlap itself: no centre lies within its radius of y = 0.
  bool mirror = false;
};

struct Texture {
  std::vector<Hole> listed;
  std::optional<HoleLattice> lattice;
  std::optional<Grooves> grooves;
  std::optional<RandomHoles> random;
  double h = 0;  // mm, mesh size along the holes' tracks through the contact zone; 0 → the zone's
  // Every hole: the listed ones, the lattice's row by row, the grooves, the random ones (texture_holes,
  // which places the random ones clear of the others); set by the loader.
  std::vector<Hole> holes;
};

// The plate's scan: u from `from` to `to` (mm, inclusive within 1e-9 of a step) by `step`.
struct Scan {
  double from = 0, to = 0, step = 0.025;
  int positions() const;
  double u(int i) const { return from + i * step; }
};

// The skin–indenter interface (contact/contact_solver.hpp): hard (exact complementarity: no interpenetration)
// or linear (a rough interface that closes by p/K before the surfaces meet: p = K·max(0, −gap); K in MPa/mm;
// the Winkler layer of asperities in series with the skin) or exponential (the rough-surface law
// p = p_ref·exp(−gap/u0), gap the separation of the mean planes, any sign; u0 in mm of the order of the rms
// roughness, p_ref in MPa the pressure at zero separation: under force control it only shifts the depth).
enum class InterfaceLaw { hard, linear, exponential };
struct Interface {
  InterfaceLaw law = InterfaceLaw::hard;
  double K = 0;      // MPa/mm, linear only
  double u0 = 0;     // mm, exponential only
  double p_ref = 0;  // MPa, exponential only
};

struct ContactLoad {
  IndenterKind indenter = IndenterKind::plane;
  double sphere_R = 0;          // mm, sphere only
  Vec2 center{0, 0};            // mm, sphere's lowest point; plane: ignored (the skin's highest point)
  std::optional<double> force;  // N, total normal force (> 0), or
  std::optional<double> depth;  // mm, rigid approach from first touch (> 0)
  std::vector<Hole> holes;      // static holes in the indenter
  double zone_radius = 0;       // mm, candidate contact zone about the first-touch point; 0 → auto
  double h = 0;                 // mm, mesh size inside the candidate zone; 0 → mesh.h_min
  double mu = 0;                // sliding friction coefficient μ ≥ 0
  double static_ratio = 0;      // residual p_t / p_z at rest ≥ 0
  FrictionLaw law = FrictionLaw::coulomb;
  // MPa, τ0 of shear_strength and mixed (≥ 0); absent: μ F / A, the sliding force μF spread over the
  // frictionless contact area A (ContactSolver::tau0)
  std::optional<double> tau0;
  Interface interface;
  Vec2 direction{1, 0};                        // unit sliding direction of the indenter over the skin (x, y)
  FrictionMode friction = FrictionMode::none;  // default mode of `skinfem contact`
  std::optional<HoleSweep> sweep;
  std::optional<Texture> texture;  // with scan, or neither
  std::optional<Scan> scan;
};

// Whether a mirror-symmetric scene may be solved on its half (pipeline/symmetry.hpp decides where it
// applies).
enum class SymmetryUse { automatic, none };

// What a run may use, set by its caller and not by the scene file: the command line's --max-dofs, Python's
// Scene.max_dofs. It travels with the scene, so every stage and every scene made from it (an error level, a
// study's level) honours it.
struct RunLimits {
  double max_dofs =
      0;  // refuse a mesh estimated or built above this many DOFs (0: the available memory only)
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
  std::optional<ContactLoad> contact;
  SymmetryUse symmetry = SymmetryUse::automatic;
  RunLimits limits;
};

// Thrown for any invalid scene; what() is one line naming the JSON path, the value and what is allowed.
struct SceneError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Thickness of the skin at the apex (cap) or everywhere (flat), mm. For an imported surface the
// thickness is not known before the file is read: returns 0, meaning "unknown" (ask the mesh).
double nominal_thickness(const Scene& scene);

// Where the indenter first touches the skin: a plane on a cap touches at the apex, a sphere at its centre.
Vec2 contact_center(const Scene& scene);
// The sphere-on-flat equivalent of the contact's relative curvature, 1/R = 1/R_sphere + 1/R_cap (a plane:
// no sphere term, a flat layer or imported surface: no cap term; an ellipsoidal cap: R_cap = sqrt(R R_y), the
// geometric mean of its apex radii); none when both vanish.
std::optional<double> equivalent_sphere_radius(const Scene& scene);
// Radius of the candidate contact zone (the multipliers' disc): contact.zone_radius, else 1.25 × an upper
// bound of the contact radius: under a force, the half-space Hertz radius (a bonded layer is stiffer than
// the half-space, so its contact is smaller than Hertz's); at a depth, twice Hertz's sqrt(R δ) (there the
// incompressible layer bulges around the indenter and its contact is larger than Hertz's, up to the
// thin-layer limit 2 sqrt(R δ)); on an ellipsoidal cap, the long semi-axis of the contact ellipse. The margin
// covers the shift of a sliding contact. Commands check the answer stays inside. Throws SceneError for a
// plane off a cap without contact.zone_radius.
double contact_zone_radius(const Scene& scene);
// Mesh size inside the candidate zone: contact.h, else mesh.h_min.
double contact_zone_h(const Scene& scene);
// Mesh size over a hole whose own size is hole_h (0: none): the finer of it and the zone's, mm.
double hole_mesh_h(const Scene& scene, double hole_h);

}  // namespace skinfem
