#include "skinfem/pipeline/green.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "skinfem/fem/sensor_reading.hpp"
#include "skinfem/mesh/mirror.hpp"
#include "skinfem/mesh/shape.hpp"
#include "skinfem/mesh/surface.hpp"
#include "skinfem/pipeline/clock.hpp"
#include "skinfem/pipeline/progress.hpp"
#include "skinfem/pipeline/scene_json.hpp"
#include "skinfem/scene/parallel.hpp"

namespace skinfem::pipeline {

namespace {

// The top of an axisymmetric skin as a polar P2 surface about (cx, cy) out to `radius`, for the meridian
// path's maps: rings growing geometrically from the centre, 72 angles.
TetMesh polar_top(const Scene& scene, double cx, double cy, double radius) {
  const SkinShape shape(scene.geometry);
  constexpr int n = 60, m = 72;   // rings, angles
  const auto ring = [&](int i) {  // i in 0 … 2n: vertex rings at even i, mid-edge rings at odd i
    const auto r = [&](int k) { return radius * std::expm1(3.0 * k / n) / std::expm1(3.0); };
    return i % 2 == 0 ? r(i / 2) : 0.5 * (r(i / 2) + r(i / 2 + 1));
  };
  TetMesh t;
  const auto id = [&](int i, int j) { return i == 0 ? 0 : 1 + (i - 1) * 2 * m + (j % (2 * m)); };
  t.nodes.resize(1 + 2 * n * 2 * m, 3);
  for (int i = 0; i <= 2 * n; ++i)
    for (int j = 0; j < (i == 0 ? 1 : 2 * m); ++j) {
      const double r = ring(i), th = M_PI * j / m, x = cx + r * std::cos(th), y = cy + r * std::sin(th);
      t.nodes.row(id(i, j)) << x, y, shape.top_z(x, y);
    }
  std::vector<std::array<int, 6>> faces;
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < m; ++b) {
      const int i = 2 * a, j = 2 * b;
      if (a == 0) {
        faces.push_back({id(0, 0), id(2, j), id(2, j + 2), id(1, j), id(2, j + 1), id(1, j + 2)});
        continue;
      }
      faces.push_back(
          {id(i, j), id(i + 2, j), id(i + 2, j + 2), id(i + 1, j), id(i + 2, j + 1), id(i + 1, j + 1)});
      faces.push_back(
          {id(i, j), id(i + 2, j + 2), id(i, j + 2), id(i + 1, j + 1), id(i + 1, j + 2), id(i, j + 1)});
    }
  t.faces.resize(faces.size(), 6);
  for (size_t f = 0; f < faces.size(); ++f)
    for (int k = 0; k < 6; ++k) t.faces(f, k) = faces[f][k];
  t.face_marker = Eigen::VectorXi::Constant(faces.size(), kTop);
  t.node_marker = Eigen::VectorXi::Constant(t.nodes.rows(), kTop);
  return t;
}

}  // namespace

std::array<double, 4> footprint_box(const Scene& scene) {
  const Geometry& g = scene.geometry;
  if (g.kind == GeometryKind::flat)
    return {-g.flat.half_width, g.flat.half_width, -g.flat.half_width, g.flat.half_width};
  if (g.kind == GeometryKind::cap)
    return {g.cap.apex_x - g.cap.truncation_radius, g.cap.apex_x + g.cap.truncation_radius,
            g.cap.apex_y - g.cap.truncation_radius, g.cap.apex_y + g.cap.truncation_radius};
  const SurfaceMesh surface = import_surface(g.surface.path);
  const Eigen::RowVector3d lo = surface.vertices.colwise().minCoeff(),
                           hi = surface.vertices.colwise().maxCoeff();
  return {lo(0), hi(0), lo(1), hi(1)};
}

void check_kernel_grid(const Scene& scene, double dx) {
  const auto box = footprint_box(scene);
  const double points = (std::floor((box[1] - box[0]) / dx) + 1) * (std::floor((box[3] - box[2]) / dx) + 1);
  const double values = 4.0 * points * static_cast<double>(scene.sensors.positions.size());
  if (points > 1e6 || values > 2.5e7) {
    char line[256];
    std::snprintf(
        line, sizeof line,
        "--grid = %g: the kernel grid over the %.4g × %.4g mm footprint would have %.3g points (%.3g "
        "values for %zu sensors); allowed at most 1e6 points and 2.5e7 values: use a larger --grid",
        dx, box[1] - box[0], box[3] - box[2], points, values, scene.sensors.positions.size());
    throw SceneError(line);
  }
}

GreenRun green_run(const Scene& scene, const SensorGreens& greens, const AdjointSetup* setup, double grid_dx,
                   const MeridianScan* axis_scan) {
  using green::GreenSample;
  using green::LayerLoad;
  const double radius = 0.5 * scene.calibration.punch_diameter;
  GreenRun run;
  run.wall = greens.wall;
  run.flat = scene.geometry.kind == GeometryKind::flat;
  run.ridged = scene.geometry.ridges.present();
  run.post = scene.sensors.model == SensorModel::post;
  Stopwatch clock;

  // The 3D path's reciprocity check: a direct solve with a point force at 1 mm from sensor 1 against the
  // adjoint value. On a half mesh the force lies on the cut, where the half carries half of it.
  const bool half = setup && is_half_y(setup->mesh);
  if (setup) {
    const auto& s0 = scene.sensors.positions[0];
    const ElasticModel& model = *setup->model;
    const LoadCaseResult direct =
        model.solve(model.point_load(s0[0] + 1.0, s0[1], {0, 0, half ? -0.5 : -1.0}), {});
    const SensorReading direct_reading =
        SensorReadings(setup->mesh, reading_sites(scene.sensors), &model.solver()).read(0, direct.reactions);
    const GreenSample adjoint_value = greens.at(0, true, 1.0, 0.0, LayerLoad::point, 0);
    run.reciprocity_rel =
        std::abs(direct_reading.sigma_z - adjoint_value.zz) / std::abs(direct_reading.sigma_z);
    run.mesh_part = half ? "half y >= 0 (mirror symmetry about y = 0)" : "whole";
    run.wall["reciprocity_check"] = clock.seconds();
  }

  clock = Stopwatch();
  const int ns = static_cast<int>(scene.sensors.positions.size());
  // The meridian is the linear skin's: under a preload the axis sensor's 3D tangent differs from it by the
  // preload's effect, not by a path's error, so it is no check there.
  const bool preloaded = scene.material.model == MaterialModel::neo_hookean && !scene.loads.patches.empty();
  const int axis = preloaded ? -1 : axis_sensor(scene, greens);
  // The scans are independent and read the 3D maps only: on the machine's cores (as kfit's).
  std::vector<GreenScan> scans(ns);
  for_each_index(
      ns,
      [&](std::size_t s) {
        GreenScan& scan = scans[s];
        scan.sensor = static_cast<int>(s) + 1;
        scan.h_mm = greens.thickness[s];
        scan.profile = green::scan_profile(greens.of(static_cast<int>(s)), LayerLoad::punch, radius,
                                           greens.scan_half_width[s], scene.calibration.spacing);
        if (run.flat) {
          const green::LayerGreen layer(scan.h_mm, scene.material.nu, LayerLoad::punch, radius);
          scan.exact_point = green::exact_profile(layer, scan.profile.offset_x);
          scan.exact_disc = green::exact_profile(layer, scan.profile.offset_x, scene.sensors.disc_diameter);
          scan.disc_max_diff_over_peak = green::max_error_over_peak(scan.profile.disc, scan.exact_disc);
        }
      },
      greens.path == "3d",
      [&](std::size_t done) {
        progress_step("green: calibration scans", static_cast<int>(done), ns, clock.seconds());
      });
  if (axis >= 0 && axis < ns)
    run.meridian_check =
        axis_scan && axis_scan->sensor == axis && axis_scan->load == LayerLoad::punch &&
                axis_scan->radius == radius && axis_scan->profile.offset_x == scans[axis].profile.offset_x
            ? meridian_check(scene, *axis_scan, scans[axis].profile, scans[axis].h_mm)
            : meridian_check(scene, axis, scans[axis].profile, LayerLoad::punch, radius, scans[axis].h_mm);
  run.scans = std::move(scans);
  run.wall["profiles"] = clock.seconds();

  // Maps: the 3D mesh's top (a half mesh's written whole, each node's value that of the node it mirrors: g
  // is even in y); the meridian: a polar surface over the footprint.
  std::vector<int> source;
  if (!setup) {
    const Geometry& g = scene.geometry;
    run.top = std::make_shared<const TetMesh>(
        run.flat ? polar_top(scene, 0, 0, g.flat.half_width)
                 : polar_top(scene, g.cap.apex_x, g.cap.apex_y, g.cap.truncation_radius));
  } else if (half) {
    run.top = std::make_shared<const TetMesh>(mirror_half(setup->mesh, &source));
  } else {
    run.top = std::shared_ptr<const TetMesh>(setup->skin, &setup->skin->mesh);
  }
  const TetMesh& top = *run.top;
  for (int s = 0; s < ns; ++s) {
    std::array<std::vector<double>, 4>& map = run.maps.emplace_back();
    for (auto& m : map) m.assign(top.num_nodes(), 0.0);
    for (int j = 0; j < top.num_nodes(); ++j) {
      GreenSample g;
      if (setup) {  // nodal values of the adjoints, as FeGreen::disc_map_at reads them
        const Eigen::VectorXd &yz = setup->fe->adjoint(s, 'z', true), &yx = setup->fe->adjoint(s, 'x', true);
        const int i = half ? source[j] : j;
        g = {-yz[3 * i + 2], -yx[3 * i + 2], yz[3 * i], yx[3 * i]};
      } else {
        greens.disc_map(s, top.nodes(j, 0), top.nodes(j, 1), g);
      }
      for (int c = 0; c < 4; ++c) map[c][j] = green::component(g, green::kComponents[c]);
    }
  }
  if (grid_dx > 0) {
    clock = Stopwatch();
    const auto box = footprint_box(scene);
    run.grid = green::kernel_grid(greens.disc_map, scene.sensors, box[0], box[1], box[2], box[3], grid_dx);
    run.wall["kernel_grid"] = clock.seconds();
  }
  return run;
}

nlohmann::json green_json(const Scene& scene, const SensorGreens& greens, const GreenRun& run,
                          double grid_dx) {
  nlohmann::json per_sensor = nlohmann::json::array();
  for (const GreenScan& scan : run.scans) {
    nlohmann::json js = {
        {"sensor", scan.sensor}, {"h_mm", scan.h_mm}, {"scan_half_width_mm", scan.profile.offset_x.back()}};
    if (scan.disc_max_diff_over_peak)
      for (size_t c = 0; c < 4; ++c)
        js[run.ridged ? "disc_vs_smooth_max_diff_over_peak"
           : run.post ? "post_vs_exact_disc_max_diff_over_peak"
                      : "fe_vs_exact_max_err_over_peak"][green::component_name(green::kComponents[c])] =
            (*scan.disc_max_diff_over_peak)[c];
    if (run.meridian_check && scan.sensor == run.meridian_check->sensor)
      js["meridian_check"] = meridian_check_json(*run.meridian_check);
    per_sensor.push_back(js);
  }
  nlohmann::json summary = {
      {"scene", scene_json(scene)},
      {"path", greens.path},
      {"path_model", greens.model},
      {"dofs", greens.dofs},
      {"sensors", per_sensor},
      {"adjoint_solves", greens.adjoint_solves},
      {"load_model", "rigid-punch half-space profile F/(2πa√(a²−r²)), normal and tangential"},
      {"punch_diameter_mm", scene.calibration.punch_diameter},
      {"wall_s", run.wall},
      {"wall_total_s", run.wall.total()},
      {"peak_rss_mb", peak_rss_mb()}};
  if (run.reciprocity_rel) {
    summary["mesh_part"] = run.mesh_part;
    summary["max_adjoint_residual"] = greens.max_adjoint_residual;
    summary["reciprocity_check_rel"] = *run.reciprocity_rel;
  }
  if (run.meridian_check) summary["meridian_check"] = meridian_check_json(*run.meridian_check);
  if (run.grid) {
    const green::KernelGrid& grid = *run.grid;
    summary["kernel_grid"] = {{"spacing_mm", grid_dx},
                              {"nx", grid.x.size()},
                              {"ny", grid.y.size()},
                              {"x_range_mm", {grid.x.front(), grid.x.back()}},
                              {"y_range_mm", {grid.y.front(), grid.y.back()}},
                              {"points_on_skin", std::count(grid.on_skin.begin(), grid.on_skin.end(), 1)}};
  }
  return summary;
}

}  // namespace skinfem::pipeline
