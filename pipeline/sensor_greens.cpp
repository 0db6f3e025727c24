#include "skinfem/pipeline/sensor_greens.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "skinfem/mesh/shape.hpp"
#include "skinfem/pipeline/clock.hpp"
#include "skinfem/pipeline/kfit.hpp"
#include "skinfem/pipeline/preloaded_skin.hpp"
#include "skinfem/pipeline/progress.hpp"
#include "skinfem/pipeline/skin_setup.hpp"

namespace skinfem::pipeline {

SensorGreens sensor_greens(const Scene& scene, const AdjointSetup& setup) {
  SensorGreens g;
  g.path = "3d";
  g.model = is_half_y(setup.mesh) ? "the meshed 3D skin, its half y >= 0 (mirror symmetry about y = 0)"
                                  : "the meshed 3D skin";
  const green::FeGreen& fe = *setup.fe;
  g.at = [&fe](int s, bool disc, double ox, double oy, green::LayerLoad load, double radius) {
    return fe.at(s, disc, ox, oy, load, radius);
  };
  g.disc_map = [&fe](int s, double x, double y, green::GreenSample& v) { return fe.disc_map_at(s, x, y, v); };
  for (const auto& pos : scene.sensors.positions) {
    g.thickness.push_back(thickness_at(scene, setup.mesh, pos));
    g.scan_half_width.push_back(scan_half_width(scene, &setup.mesh, g.thickness.back(), pos));
  }
  g.dofs = setup.model->solver().free_dofs();
  g.adjoint_solves = fe.adjoint_solves();
  g.max_adjoint_residual = fe.max_adjoint_residual();
  g.wall = setup.wall;
  return g;
}

SensorGreens with_path_reason(SensorGreens greens, const Scene& scene, GreenPath path) {
  if (path == GreenPath::automatic) greens.model += "; not the meridian path: " + meridian_unavailable(scene);
  return greens;
}

namespace {
// A post is a rigid inclusion: the others stiffen the skin around each (on the paper's skin with posts 1 mm
// apart, the apex post's 3D k was 7 % off the isolated post's), where other discs are only base. The
// meridian's isolated post does not stand for one among others.
bool posts_among_others(const Scene& scene) {
  return scene.sensors.model == SensorModel::post && scene.sensors.positions.size() > 1;
}
}  // namespace

std::string not_of_revolution(const Geometry& g) {
  if (g.kind == GeometryKind::surface) return "an imported surface is not known to be a body of revolution";
  if (g.ridges.present()) return "the ridged top is not a body of revolution";
  if (g.kind == GeometryKind::cap && !g.cap.spherical())
    return "the ellipsoidal cap (R_y ≠ R) is not a body of revolution";
  return "";
}

std::string side_too_near(const Geometry& g, const std::string& what, double margin) {
  constexpr double kSideMarginOverH = 2.5;
  const double h = g.flat.h;
  if (g.kind != GeometryKind::flat || margin >= kSideMarginOverH * h) return "";
  char buf[200];
  std::snprintf(buf, sizeof buf,
                " %.3g mm (%.2g h) from the layer's %s side, closer than %.3g h: the unbounded layer of the "
                "meridian path would not be this scene",
                margin, margin / h, g.side == SideCondition::fixed ? "clamped" : "free", kSideMarginOverH);
  return what + buf;
}

std::string meridian_unavailable(const Scene& scene) {
  const Geometry& g = scene.geometry;
  if (std::string why = not_of_revolution(g); !why.empty()) return why;
  if (posts_among_others(scene)) return "the other posts are rigid inclusions off the axis of each";
  if (scene.sensors.model == SensorModel::post && !scene.sensors.post.support.rigid())
    return "the meridian post is held rigidly; its membrane springs are modelled in 3D only";
  if (g.kind == GeometryKind::flat) {
    const double h = g.flat.h;
    for (size_t i = 0; i < scene.sensors.positions.size(); ++i) {
      const Vec2& p = scene.sensors.positions[i];
      const double reach = std::abs(p[0]) + scan_half_width(scene, nullptr, h, p);
      const double margin = g.flat.half_width - std::max(reach, std::abs(p[1]));
      if (std::string why =
              side_too_near(g, "sensor " + std::to_string(i + 1) + "'s calibration scan ends", margin);
          !why.empty())
        return why;
    }
    return "";
  }
  for (size_t i = 0; i < scene.sensors.positions.size(); ++i) {
    const Vec2& p = scene.sensors.positions[i];
    if (std::hypot(p[0] - g.cap.apex_x, p[1] - g.cap.apex_y) > 1e-9) {
      char buf[200];
      std::snprintf(buf, sizeof buf, "sensor %zu at (%g, %g) mm is off the cap's axis at (%g, %g) mm", i + 1,
                    p[0], p[1], g.cap.apex_x, g.cap.apex_y);
      return buf;
    }
  }
  return "";
}

namespace {
// A flat scene stands for the unbounded layer (what kfit compares it with): its meridian reaches 20 h, where
// the side's influence on the readings, exp(−0.739 r/h) (docs/scenes.md, "Truncation"), is below 1e-6.
constexpr double kUnboundedRadiusOverH = 20;

struct MeridianPair {
  MeridianGreen fine, coarse;
};
}  // namespace

MeridianSkin meridian_skin(const Scene& scene) {
  require_linear(scene, "the meridian (axisymmetric) skin");
  const Geometry& geo = scene.geometry;
  MeridianSkin m;
  m.flat = geo.kind == GeometryKind::flat;
  m.h = m.flat ? geo.flat.h : geo.cap.h;
  const double h = m.h, R = geo.cap.R;
  m.radius = m.flat ? kUnboundedRadiusOverH * h : geo.cap.truncation_radius;
  m.top = [flat = m.flat, h, R](double r) { return flat ? h : h - R + std::sqrt(R * R - r * r); };
  // The unbounded layer's side is far enough not to matter; a cap's is the scene's.
  m.side = m.flat ? SideCondition::free : geo.side;
  char model[300];
  if (m.flat)
    std::snprintf(model, sizeof model,
                  "the unbounded layer h = %.4g mm (meridian radius %.4g mm = %.0f h, traction-free there)",
                  h, m.radius, kUnboundedRadiusOverH);
  else
    std::snprintf(model, sizeof model,
                  "the spherical cap R = %.4g mm, h = %.4g mm on its meridian to r = %.4g mm", R, h,
                  m.radius);
  m.model = model;
  return m;
}

MeridianMesh MeridianSkin::mesh(const ReadingSite& site, double scale) const {
  const MeridianSizes sizes = MeridianSizes::for_thickness(h, scale);
  return site.post() ? meridian_mesh(top, radius, sizes, MeridianPost{0.5 * site.diameter, site.post_height})
                     : meridian_mesh(top, radius, sizes);
}

SensorGains sensor_gains(const Sensors& sensors, double nu, double h, double scale) {
  SensorGains g;
  if (sensors.model != SensorModel::post) return g;
  if (!sensors.post.support.rigid()) {
    g.gains.fitted = true;
    return g;
  }
  Stopwatch clock;
  const ReadingSite post = post_site({0, 0}, sensors.post.diameter, sensors.post.height);
  const auto at = [&](double s) {
    const MeridianSizes sizes = MeridianSizes::for_thickness(h, s);
    // The rim's cells at their default (green/meridian.hpp), or finer on a post too short or thin for it,
    // down to a sixteenth of the default: a post shorter than that reads as the disc it tends to.
    const double rim_default = 7.5 * sizes.axis_cell * sizes.axis_cell / h;
    const double rim =
        std::clamp(std::min(post.post_height, 0.5 * post.diameter) / 16, rim_default / 16, rim_default);
    const MeridianMesh mesh = meridian_mesh([h](double) { return h; }, kUnboundedRadiusOverH * h, sizes,
                                            MeridianPost{0.5 * post.diameter, post.post_height, rim});
    const MeridianGreen m(mesh, nu, SideCondition::free, post);
    if (s == scale) g.dofs = m.dofs();
    return green::ChannelGains{nu == 0.5 ? 1.0 : m.shape_zz().integral, m.shape_xx().integral};
  };
  g.gains = at(scale);
  const green::ChannelGains coarse = at(2 * scale);
  g.change = std::max(std::abs(coarse.z / g.gains.z - 1), std::abs(coarse.x / g.gains.x - 1));
  g.seconds = clock.seconds();
  return g;
}

SensorGreens meridian_sensor_greens(const Scene& scene) {
  if (const std::string why = meridian_unavailable(scene); !why.empty())
    throw SceneError(scene.source_path + ": the meridian (axisymmetric) path does not apply: " + why +
                     "; use the 3D path");
  const MeridianSkin skin = meridian_skin(scene);
  const Geometry& geo = scene.geometry;
  const bool flat = skin.flat;
  const double h = skin.h, radius = skin.radius;
  const ReadingSite disc = reading_sites(scene.sensors).at(0);
  SensorGreens g;
  g.path = "meridian";
  g.model = skin.model;
  Stopwatch clock;
  const MeridianMesh mesh = skin.mesh(disc, 1), coarse = skin.mesh(disc, 2);
  g.wall["mesh"] = clock.seconds();
  // The coarse level's point reading is what is read of it (a post's reading either way).
  const ReadingSite coarse_site = disc.post() ? disc : ReadingSite{};
  auto pair = std::make_shared<const MeridianPair>(
      MeridianPair{MeridianGreen(mesh, scene.material.nu, skin.side, disc),
                   MeridianGreen(coarse, scene.material.nu, skin.side, coarse_site)});
  const MeridianGreen::Cost& c = pair->fine.cost();
  const MeridianGreen::Cost& cc = pair->coarse.cost();
  g.wall["assemble"] = c.assemble_s + cc.assemble_s;
  g.wall["factor"] = c.factor_s + cc.factor_s;
  g.wall["adjoint_solves"] = c.solve_s + cc.solve_s;
  g.at = [m = &pair->fine](int, bool d, double ox, double oy, green::LayerLoad load, double a) {
    return m->at(d, ox, oy, load, a);
  };
  g.coarse_at = [m = &pair->coarse](int, bool d, double ox, double oy, green::LayerLoad load, double a) {
    return m->at(d, ox, oy, load, a);
  };
  // Where the skin is: the unbounded layer everywhere, a cap within its truncation radius.
  g.disc_map = [m = &pair->fine, flat, radius, sensors = scene.sensors.positions,
                apex = Vec2{geo.cap.apex_x, geo.cap.apex_y}](int s, double x, double y,
                                                             green::GreenSample& v) {
    if (!flat && std::hypot(x - apex[0], y - apex[1]) > radius) return false;
    v = m->at(x - sensors[s][0], y - sensors[s][1], true);
    return true;
  };
  g.owner = pair;
  g.dofs = pair->fine.dofs();
  g.adjoint_solves = 4;  // two modes, two readings each, in one block solve per mode
  for (const auto& pos : scene.sensors.positions) {
    g.thickness.push_back(h);
    g.scan_half_width.push_back(scan_half_width(scene, nullptr, h, pos));
  }
  return g;
}

namespace {
// The scene with only sensor s.
Scene with_sensor(const Scene& scene, size_t s) {
  Scene one = scene;
  one.sensors.positions = {scene.sensors.positions[s]};
  return one;
}
}  // namespace

int axis_sensor(const Scene& scene, const SensorGreens& greens) {
  if (greens.path != "3d" || scene.geometry.kind != GeometryKind::cap) return -1;
  if (posts_among_others(scene)) return -1;  // each sensor alone would pass meridian_unavailable
  for (size_t s = 0; s < scene.sensors.positions.size(); ++s)
    if (meridian_unavailable(with_sensor(scene, s)).empty()) return static_cast<int>(s);
  return -1;
}

GreenPath green_path_named(const std::string& name) {
  if (name == "auto") return GreenPath::automatic;
  if (name == "3d") return GreenPath::full3d;
  if (name == "meridian") return GreenPath::meridian;
  throw SceneError("path: '" + name + "' is not one of auto, 3d, meridian");
}

MeridianScan meridian_scan(const Scene& scene, int sensor, green::LayerLoad load, double radius,
                           double half_width) {
  Stopwatch clock;
  const SensorGreens m = meridian_sensor_greens(with_sensor(scene, sensor));
  MeridianScan out;
  out.sensor = sensor;
  out.load = load;
  out.radius = radius;
  out.path_model = m.model;
  out.dofs = m.dofs;
  out.profile = green::scan_profile(m.of(0), load, radius, half_width, scene.calibration.spacing);
  out.seconds = clock.seconds();
  return out;
}

std::optional<std::pair<int, double>> planned_axis_scan(const Scene& scene) {
  const SkinShape shape(scene.geometry);
  if (scene.geometry.kind != GeometryKind::cap || !shape.exact() || posts_among_others(scene)) return {};
  for (size_t s = 0; s < scene.sensors.positions.size(); ++s)
    if (meridian_unavailable(with_sensor(scene, s)).empty()) {
      const Vec2& p = scene.sensors.positions[s];
      const double w = scan_half_width(scene, nullptr, shape.mean_top_z(p[0], p[1]), p);
      // The grid's last offset, as green::scan_profile places it.
      return std::pair{static_cast<int>(s),
                       std::floor(w / scene.calibration.spacing + 1e-9) * scene.calibration.spacing};
    }
  return {};
}

MeridianCheck meridian_check(const Scene& scene, int sensor, const green::ScanProfile& prof,
                             green::LayerLoad load, double radius, double h) {
  return meridian_check(scene, meridian_scan(scene, sensor, load, radius, prof.offset_x.back()), prof, h);
}

MeridianCheck meridian_check(const Scene& scene, const MeridianScan& scan, const green::ScanProfile& prof,
                             double h) {
  const auto& mp = scan.profile;
  if (mp.offset_x != prof.offset_x)
    throw std::invalid_argument("meridian_check: the meridian scan's offsets are not the 3D scan's");
  Stopwatch clock;
  const green::ChannelGains gains = sensor_gains(scene.sensors, scene.material.nu, h).gains;
  const green::KReport k3 = green::fit_profile(prof.offset_x, prof.point, h, gains);
  const green::KReport mk = green::fit_profile(mp.offset_x, mp.point, h, gains);
  MeridianCheck c;
  c.sensor = scan.sensor + 1;
  c.path_model = scan.path_model;
  c.dofs = scan.dofs;
  c.k_central = mk.k_central;
  c.k_lsq_line = mk.k_lsq_line;
  c.k_central_3d_vs_meridian = k3.k_central / mk.k_central - 1;
  c.k_lsq_line_3d_vs_meridian = k3.k_lsq_line / mk.k_lsq_line - 1;
  for (size_t i = 0; i < 4; ++i) c.component_k_3d_minus_meridian[i] = k3.components[i].k - mk.components[i].k;
  c.point_max_diff_over_peak = green::max_error_over_peak(prof.point, mp.point);
  c.disc_max_diff_over_peak = green::max_error_over_peak(prof.disc, mp.disc);
  c.seconds = scan.seconds + clock.seconds();
  return c;
}

nlohmann::json meridian_check_json(const MeridianCheck& c) {
  nlohmann::json j = {{"sensor", c.sensor},
                      {"path_model", c.path_model},
                      {"dofs", c.dofs},
                      {"k_central", c.k_central},
                      {"k_lsq_line", c.k_lsq_line},
                      {"k_central_3d_vs_meridian", c.k_central_3d_vs_meridian},
                      {"k_lsq_line_3d_vs_meridian", c.k_lsq_line_3d_vs_meridian},
                      {"wall_s", c.seconds}};
  for (size_t i = 0; i < 4; ++i) {
    const char* name = green::component_name(green::kComponents[i]);
    j["component_k_3d_minus_meridian"][name] = c.component_k_3d_minus_meridian[i];
    j["point_max_diff_over_peak"][name] = c.point_max_diff_over_peak[i];
    j["disc_max_diff_over_peak"][name] = c.disc_max_diff_over_peak[i];
  }
  return j;
}

std::string meridian_check_line(const MeridianCheck& c) {
  const auto &k = c.component_k_3d_minus_meridian, &d = c.disc_max_diff_over_peak;
  char buf[600];
  std::snprintf(
      buf, sizeof buf,
      "independent check, sensor #%d on the cap's axis against the meridian path (%d DOFs, %.2f s): 3D "
      "k_central %+.1e, k_lsq_line %+.1e relative; component k zz %+.1e zx %+.1e xz %+.1e xx %+.1e; "
      "disc readings max |difference| / peak zz %.1e zx %.1e xz %.1e xx %.1e",
      c.sensor, c.dofs, c.seconds, c.k_central_3d_vs_meridian, c.k_lsq_line_3d_vs_meridian, k[0], k[1], k[2],
      k[3], d[0], d[1], d[2], d[3]);
  return buf;
}

SensorGreens green_path(const Scene& scene, GreenPath path) {
  if (scene.material.model == MaterialModel::neo_hookean) {
    // The tangent about the patches' state is a 3D skin of its own: no meridian, no linear skin to share.
    if (path == GreenPath::meridian)
      throw SceneError(
          "--path meridian: with material.model \"neo_hookean\" the Green tensor is the 3D "
          "tangent's");
    Preload preload;
    std::shared_ptr<const AdjointSetup> setup =
        adjoint_setup(scene, preloaded_skin(scene, preload_mesh_part(scene), &preload));
    SensorGreens g = sensor_greens(scene, *setup);
    g.model += "; the neo-Hookean skin " + preload.said();
    g.adjoints = std::move(setup);
    return g;
  }
  if (path == GreenPath::meridian || (path == GreenPath::automatic && meridian_unavailable(scene).empty()))
    return meridian_sensor_greens(scene);
  std::shared_ptr<const AdjointSetup> setup = adjoint_setup(scene);
  SensorGreens g = with_path_reason(sensor_greens(scene, *setup), scene, path);
  g.adjoints = std::move(setup);
  return g;
}

}  // namespace skinfem::pipeline
