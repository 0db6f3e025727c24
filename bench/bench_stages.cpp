// Time per stage against DOFs: the flat layer (scenes/flat_layer.json) and the paper's cap
// (scenes/candelier2011.json) with every mesh size scaled by 2.83, 2 and 1.41 (flat) or 2 and 1.41 (cap),
// and the meridian solver of kfit's axisymmetric path on the flat layer.
// Each benchmark reports its DOFs as a counter, so bench/exponents.py can fit time ∝ DOFs^e per stage.
//
//   $ build/bench/skinfem_bench --benchmark_format=json > bench.json && bench/exponents.py bench.json
#include <benchmark/benchmark.h>

#include <chrono>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "skinfem/contact/condensed.hpp"
#include "skinfem/fem/assembly.hpp"
#include "skinfem/fem/elastic_model.hpp"
#include "skinfem/green/calibration.hpp"
#include "skinfem/green/fe_green.hpp"
#include "skinfem/green/kfit.hpp"
#include "skinfem/green/meridian.hpp"
#include "skinfem/mesh/build.hpp"
#include "skinfem/mesh/sizing.hpp"
#include "skinfem/scene/load.hpp"

namespace skinfem {
namespace {

const char* kScenes[2] = {"flat_layer", "candelier2011"};

Scene scaled(int scene, double s) {
  Scene sc = load_scene(std::string(SKINFEM_SOURCE_DIR) + "/scenes/" + kScenes[scene] + ".json");
  sc.contact.reset();  // the Green and k stages: the skin without the contact refinement
  sc.mesh.sensor_h = sensor_mesh_size(sc) * s;
  sc.mesh.h_min *= s;
  sc.mesh.h_max *= s;
  for (auto& r : sc.mesh.regions) r.h *= s;
  return sc;
}

// One meshed and factored skin per (scene, scale), shared by the benchmarks that need it.
struct Skin {
  Scene scene;
  TetMesh mesh;
  std::unique_ptr<ElasticModel> model;
};
const Skin& skin(int scene, double s) {
  static std::map<std::pair<int, double>, std::unique_ptr<Skin>> cache;
  auto& p = cache[{scene, s}];
  if (!p) {
    p = std::make_unique<Skin>();
    p->scene = scaled(scene, s);
    p->mesh = build_mesh(p->scene);
    p->model = std::make_unique<ElasticModel>(p->mesh, p->scene.material, p->scene.geometry.side,
                                              std::vector<Punch>{});
  }
  return *p;
}

double scale_of(const benchmark::State& st) { return st.range(1) / 100.0; }
void dofs(benchmark::State& st, const Skin& k) {
  st.counters["dofs"] = k.model->solver().free_dofs();
  st.SetLabel(std::string(kScenes[st.range(0)]) + " x" + std::to_string(scale_of(st)).substr(0, 4));
}

void BM_Mesh(benchmark::State& st) {
  const Scene sc = scaled(st.range(0), scale_of(st));
  for (auto _ : st) benchmark::DoNotOptimize(build_mesh(sc));
  dofs(st, skin(st.range(0), scale_of(st)));
}
void BM_Assemble(benchmark::State& st) {
  const Skin& k = skin(st.range(0), scale_of(st));
  const Lame lame = Lame::from(k.scene.material.E, k.scene.material.nu);
  for (auto _ : st) benchmark::DoNotOptimize(assemble_mixed(k.mesh, lame));
  dofs(st, k);
}
void BM_Factor(benchmark::State& st) {
  const Skin& k = skin(st.range(0), scale_of(st));
  for (auto _ : st)
    MixedSolver(k.model->matrices(), k.model->lame(), k.model->fixed(), SolverKind::direct_ldlt);
  dofs(st, k);
}
// The 40 adjoint solves of 10 sensors as one block (green/fe_green).
void BM_BlockSolve40(benchmark::State& st) {
  const Skin& k = skin(st.range(0), scale_of(st));
  Eigen::MatrixXd F = Eigen::MatrixXd::Random(3 * k.mesh.num_nodes(), 40);
  for (auto _ : st) benchmark::DoNotOptimize(k.model->solver().solve_block(F));
  dofs(st, k);
}
// Adjoints of every sensor, then sensor #1's calibration scan (the punch-load profile) and both k fits.
void BM_KfitEndToEnd(benchmark::State& st) {
  const Skin& k = skin(st.range(0), scale_of(st));
  const auto& sc = k.scene;
  const double h = sc.geometry.kind == GeometryKind::flat ? sc.geometry.flat.h : sc.geometry.cap.h;
  for (auto _ : st) {
    const green::FeGreen fe(*k.model, sc.sensors);
    const auto prof = green::scan_profile(fe, 0, green::LayerLoad::punch, 0.5 * sc.calibration.punch_diameter,
                                          std::min(4 * h, 9.0), sc.calibration.spacing);
    benchmark::DoNotOptimize(green::fit_profile(prof.offset_x, prof.point, h));
  }
  dofs(st, k);
}
// Green map evaluation alone: sensor #1's scan on already solved adjoints.
void BM_GreenScan(benchmark::State& st) {
  const Skin& k = skin(st.range(0), scale_of(st));
  const green::FeGreen fe(*k.model, k.scene.sensors);
  for (auto _ : st)
    benchmark::DoNotOptimize(green::scan_profile(fe, 0, green::LayerLoad::punch,
                                                 0.5 * k.scene.calibration.punch_diameter, 9.0,
                                                 k.scene.calibration.spacing));
  dofs(st, k);
}

// kfit's meridian path on the flat layer (green/meridian): mesh, assemble, factor and block-solve both
// Fourier modes (point and disc readings) at MeridianSizes::for_thickness(h, scale), scale 2, 1.41, 1 (the
// default).
void BM_MeridianGreen(benchmark::State& st) {
  const double h = 3.04, s = st.range(0) / 100.0;
  int n = 0;
  MeridianGreen::Cost cost;
  double mesh_s = 0;
  for (auto _ : st) {
    const auto t0 = std::chrono::steady_clock::now();
    const MeridianMesh m =
        meridian_mesh([&](double) { return h; }, 20 * h, MeridianSizes::for_thickness(h, s));
    mesh_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const MeridianGreen g(m, 0.5, SideCondition::free, disc_site({0, 0}, 0.2));
    n = g.dofs();
    cost = g.cost();
  }
  st.counters["dofs"] = n;
  st.counters["mesh_s"] = mesh_s;
  st.counters["assemble_s"] = cost.assemble_s;
  st.counters["factor_s"] = cost.factor_s;
  st.counters["solve_s"] = cost.solve_s;
  st.SetLabel("meridian_flat x" + std::to_string(s).substr(0, 4));
}
// The exact layer's tensor (green/layer_exact.hpp) at scan offsets: what the crosscheck's exact kernels and
// every kfit comparison pay per evaluation.
void BM_LayerGreenAt(benchmark::State& st) {
  const green::LayerGreen g(3.04, 0.5, green::LayerLoad::punch, 0.25);
  int i = 0;
  for (auto _ : st) {
    benchmark::DoNotOptimize(g.at(-9.12 + 18.24 * (i % 2000) / 1999.0, 0.304 * (i % 7)));
    ++i;
  }
}
BENCHMARK(BM_LayerGreenAt);

BENCHMARK(BM_MeridianGreen)
    ->Arg(200)
    ->Arg(141)
    ->Arg(100)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Repetitions(2)
    ->ReportAggregatesOnly(false);

// The contact's condensation (contact/condensed.hpp) on the shipped contact scenes as `contact` meshes them
// (hertz_layer whole, candelier2011's half): factor + condense by block solves of the plain factorization
// (method 0), from the factorization bordered by the condensation's columns (method 1, MUMPS's Schur
// complement), or the one MUMPS's estimates choose (method 2, what `contact` does). Counters: the two
// stages' seconds, DOFs, multipliers, right-hand sides solved, the factorization's flops, bordered or not.
//   $ build/bench/skinfem_bench --benchmark_filter=Condense
void BM_Condense(benchmark::State& st) {
  static const char* names[2] = {"hertz_layer", "candelier2011"};
  const Scene sc = load_scene(std::string(SKINFEM_SOURCE_DIR) + "/scenes/" + names[st.range(0)] + ".json");
  const TetMesh mesh = build_mesh(sc, st.range(0) == 1 ? MeshPart::half_y : MeshPart::whole);
  const contact::Indenter indenter(sc, mesh);
  const auto zone = contact::mortar_zone(mesh, contact_center(sc), contact_zone_radius(sc));
  const SensorReadings readings(mesh, reading_sites(sc.sensors));
  const bool bordered = st.range(1) > 0;
  double factor_s = 0, condense_s = 0;
  int dofs = 0, rhs = 0;
  double flops = 0;
  bool chose_border = false;
  for (auto _ : st) {
    const auto t0 = std::chrono::steady_clock::now();
    std::optional<contact::CondenseColumns> cols;
    ModelOptions options;
    if (bordered) {
      cols = contact::condense_columns(mesh, zone, readings.weight_block(), sc.contact->direction, {});
      if (st.range(1) == 1) cols->coupling.solves_instead = 0;  // bordered whatever it costs
      options.coupling = &cols->coupling;
    }
    const ElasticModel model(mesh, sc.material, sc.geometry.side, {}, options);
    const auto t1 = std::chrono::steady_clock::now();
    const auto c = contact::condense(model, zone, indenter, readings, sc.contact->direction, {}, {},
                                     bordered ? &*cols : nullptr);
    const auto t2 = std::chrono::steady_clock::now();
    factor_s = std::chrono::duration<double>(t1 - t0).count();
    condense_s = std::chrono::duration<double>(t2 - t1).count();
    dofs = model.solver().free_dofs();
    rhs = c.block_solves;
    flops = model.solver().factor_flops();
    chose_border = bordered && model.solver().border_choice()->bordered;
  }
  st.counters["factor_s"] = factor_s;
  st.counters["condense_s"] = condense_s;
  st.counters["dofs"] = dofs;
  st.counters["multipliers"] = zone.size();
  st.counters["rhs"] = rhs;
  st.counters["flops"] = flops;
  st.counters["bordered"] = chose_border;
  const char* method[3] = {" block solves", " bordered", " chosen by MUMPS's estimates"};
  st.SetLabel(std::string(names[st.range(0)]) + method[st.range(1)]);
}
BENCHMARK(BM_Condense)
    ->ArgsProduct({{0, 1}, {0, 1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Repetitions(2)
    ->ReportAggregatesOnly(false);

// (scene, scale × 100): flat at 2.83, 2, 1.41; the cap at 2, 1.41.
void levels(benchmark::internal::Benchmark* b) {
  for (int s : {283, 200, 141}) b->Args({0, s});
  for (int s : {200, 141}) b->Args({1, s});
  b->Unit(benchmark::kMillisecond)->Iterations(1)->Repetitions(2)->ReportAggregatesOnly(false);
}
BENCHMARK(BM_Mesh)->Apply(levels);
BENCHMARK(BM_Assemble)->Apply(levels);
BENCHMARK(BM_Factor)->Apply(levels);
BENCHMARK(BM_BlockSolve40)->Apply(levels);
BENCHMARK(BM_GreenScan)->Apply(levels);
BENCHMARK(BM_KfitEndToEnd)->Apply(levels);

}  // namespace
}  // namespace skinfem

BENCHMARK_MAIN();
