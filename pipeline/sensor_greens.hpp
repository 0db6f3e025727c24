// The Green tensors of a scene's sensors as the calibration stages read them, from whichever path computed
// them: the 3D body (green/fe_green.hpp, every scene) or the meridian (green/meridian.hpp, sensors on the
// axis of a body of revolution: two 2D solves instead of one 3D one).
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "skinfem/green/calibration.hpp"
#include "skinfem/green/kernel_grid.hpp"
#include "skinfem/green/meridian.hpp"
#include "skinfem/pipeline/adjoint_setup.hpp"
#include "skinfem/pipeline/clock.hpp"

namespace skinfem::pipeline {

enum class GreenPath { automatic, full3d, meridian };

struct SensorGreens {
  // g_ab (1/mm²) of `sensor` for a unit load centred at offset (ox, oy) from it, spread as `load` over
  // radius; disc: the sensor's disc mean, else its centre value.
  using At = std::function<green::GreenSample(int sensor, bool disc, double ox, double oy,
                                              green::LayerLoad load, double radius)>;
  std::string path;   // "3d" or "meridian"
  std::string model;  // what was solved, one sentence
  At at;
  // Meridian only: the point reading (disc = false) at half the resolution (every size doubled), whose
  // change bounds the error.
  At coarse_at;
  // The disc reading for a unit point force at an absolute top point (the kernel export).
  green::DiscMap disc_map;
  std::vector<double> thickness, scan_half_width;  // per sensor, mm
  int dofs = 0, adjoint_solves = 0;
  double max_adjoint_residual = 0;
  Timings wall;                       // seconds: mesh, assemble, factor, adjoint_solves
  std::shared_ptr<const void> owner;  // keeps the meridian solutions alive
  // The 3D path's adjoint set-up when green_path made it (maps on the mesh, reciprocity); else null.
  std::shared_ptr<const AdjointSetup> adjoints;

  // One sensor's `at`, as the calibration scan takes it.
  green::SensorGreen of(int sensor) const {
    return [this, sensor](bool disc, double ox, double oy, green::LayerLoad load, double radius) {
      return at(sensor, disc, ox, oy, load, radius);
    };
  }
};

// The 3D path on an adjoint setup, which must outlive the result.
SensorGreens sensor_greens(const Scene& scene, const AdjointSetup& setup);

// Why the skin is not a body of revolution (a sentence); empty for a flat layer or a spherical cap without
// ridges.
std::string not_of_revolution(const Geometry& g);
// The meridian stands for the unbounded layer: a flat layer's side must lie at least 2.5 h beyond every load
// and reading (the side's influence decays as exp(−0.739 d/h), docs/scenes.md "Truncation": below 0.2 % of
// g_xx's peak there). Why `what` at `margin` mm from the side is too near (a sentence), or empty.
std::string side_too_near(const Geometry& g, const std::string& what, double margin);

// Why the meridian path cannot serve the scene (a sentence naming what breaks the symmetry); empty when it
// can: a flat layer without ridges (read as the unbounded layer of its thickness) or a spherical cap without
// ridges with every sensor at its apex.
std::string meridian_unavailable(const Scene& scene);
// greens (the 3D path's) with, when `path` was automatic, why the meridian did not serve the scene appended
// to its model (said in stdout and summary.json).
SensorGreens with_path_reason(SensorGreens greens, const Scene& scene, GreenPath path);
// The meridian path; throws SceneError (with meridian_unavailable's reason) where it does not apply.
SensorGreens meridian_sensor_greens(const Scene& scene);

// The meridian of a skin with an axis (a flat layer, read as the unbounded layer of its thickness, or a
// spherical cap about its apex; check meridian_unavailable first): its top, extent and side.
struct MeridianSkin {
  std::function<double(double)> top;  // z of the top at radius r, mm
  double radius = 0, h = 0;           // mm: the meridian's extent, the thickness on the axis
  bool flat = false;
  SideCondition side = SideCondition::free;
  std::string model;  // what is solved, one sentence
  // The meridian mesh for a site on the axis (a post is cut from it) at MeridianSizes::for_thickness(h,
  // scale).
  MeridianMesh mesh(const ReadingSite& site, double scale) const;
};
MeridianSkin meridian_skin(const Scene& scene);

// A sensor's gains in the k model (green::ChannelGains) at skin thickness h: a disc's are 1 and 1 (by
// equilibrium). A post's are its readings under a uniform unit pressure and shear on the unbounded flat layer
// of thickness h, the post held: σ_z's is 1 at ν = 0.5 (hydrostatic, exact), else ∬ g_zz dA, and σ_x's
// ∬ g_xx dA (MeridianGreen::Shape::integral), both on the meridian at MeridianSizes scale `scale`; `change`
// is the larger relative change of the computed ones from the level at twice every size. A post on membrane
// springs is given its held post's gains: the springs' transfer is not in the model.
struct SensorGains {
  green::ChannelGains gains;
  double change = 0;
  int dofs = 0;  // of the finer meridian, both modes
  double seconds = 0;
};
SensorGains sensor_gains(const Sensors& sensors, double nu, double h, double scale = 1);

// The Green tensors by `path`: the meridian's where asked, or where automatic and meridian_unavailable is
// empty; else the 3D path's (with_path_reason), with the adjoint set-up it made in `adjoints`. A
// neo-Hookean scene takes the 3D tangent about its patches' state (pipeline/preloaded_skin.hpp; SceneError
// for the meridian).
SensorGreens green_path(const Scene& scene, GreenPath path);
// The path a name stands for (auto, 3d, meridian; as --path and Python's path= spell it); throws SceneError
// naming the choices otherwise.
GreenPath green_path_named(const std::string& name);

// The first sensor on the axis of a cap solved in 3D (greens.path "3d"), or −1 (also for a post among others,
// which the isolated post of the meridian does not stand for): the one sensor the meridian
// path, an independent 2D solve about 100× more accurate than the 3D mesh, can check.
int axis_sensor(const Scene& scene, const SensorGreens& greens);
// That check: the 3D scan `prof` of `sensor` (thickness h) against the meridian's over the same offsets, for
// the same load. Arrays over components are in green::kComponents order (zz, zx, xz, xx).
struct MeridianCheck {
  int sensor = 0;  // 1-based
  std::string path_model;
  int dofs = 0;
  double k_central = 0, k_lsq_line = 0;                                // the meridian's
  double k_central_3d_vs_meridian = 0, k_lsq_line_3d_vs_meridian = 0;  // relative differences
  std::array<double, 4> component_k_3d_minus_meridian{}, point_max_diff_over_peak{},
      disc_max_diff_over_peak{};
  double seconds = 0;
};
MeridianCheck meridian_check(const Scene& scene, int sensor, const green::ScanProfile& prof,
                             green::LayerLoad load, double radius, double h);
// Its meridian half, which needs no 3D solve: the sensor's scan on the meridian path over offsets
// |x| ≤ half_width. A fast report makes it beside its 3D factorization, for a cap whose shape gives the axis
// sensor's thickness (planned_axis_scan: the sensor (0-based) and half-width green_run will scan, from the
// scene alone; nullopt elsewhere).
struct MeridianScan {
  int sensor = -1;  // 0-based
  green::LayerLoad load = green::LayerLoad::punch;
  double radius = 0;
  std::string path_model;
  int dofs = 0;
  green::ScanProfile profile;
  double seconds = 0;
};
MeridianScan meridian_scan(const Scene& scene, int sensor, green::LayerLoad load, double radius,
                           double half_width);
std::optional<std::pair<int, double>> planned_axis_scan(const Scene& scene);
// The check from a scan made before; throws std::invalid_argument unless it holds prof's offsets.
MeridianCheck meridian_check(const Scene& scene, const MeridianScan& scan, const green::ScanProfile& prof,
                             double h);
// As kfit.json and green's summary.json hold it.
nlohmann::json meridian_check_json(const MeridianCheck& check);
// One line for stdout, from the check's numbers.
std::string meridian_check_line(const MeridianCheck& check);

}  // namespace skinfem::pipeline
