// The main job as one call (pipeline/report.hpp), fast, on coarse scenes. References: the ReportSink
// contract as the header states it (each call once at most, in the declared order, mesh() before green();
// no contact, defect, crosscheck or budget without a contact; a contact summary the sink adds to is kept so
// in report.json); the mesh handed on whole (mirrored from the half solved), whose volume is the flat
// layer's box exactly; report.json's entries against the typed results the sink received (kfit, contact,
// mesh); a fast report's left_out naming what the header says it leaves out; the error bars against
// chain_errors over the result's own levels (pipeline/chain_level.hpp); bad error scales refused before any
// stage runs.
#include <gtest/gtest.h>

#include <algorithm>
#include <mutex>
#include <string>
#include <vector>

#include "skinfem/pipeline/report.hpp"

namespace skinfem::pipeline {
namespace {

constexpr double kRoundOff = 1e-12;  // relative: sums of a few thousand tet volumes; copies of one number

bool has(const std::string& text, const std::string& what) { return text.find(what) != std::string::npos; }

// Records every call (mesh() comes from another thread) and what it was given.
class Recorder : public ReportSink {
 public:
  void mesh(const TetMesh& m, const MeshSummary& s, const nlohmann::json& summary) override {
    const std::lock_guard<std::mutex> lock(mutex_);
    calls.push_back("mesh");
    mesh_half = is_half_y(m);
    mesh_volume = s.quality.volume_mm3;
    mesh_summary = summary;
  }
  void green(const SensorGreens&, const GreenRun& run, const nlohmann::json&) override {
    add("green");
    green_scans = static_cast<int>(run.scans.size());
  }
  void kfit(const KfitResult& r, const nlohmann::json& file) override {
    add("kfit");
    kfit_file = file;
    k_central = r.sensors.at(0).fe.k_central;
    k_lsq_line = r.sensors.at(0).fe.k_lsq_line;
  }
  void contact(const ContactRun& run, nlohmann::json& summary) override {
    add("contact");
    contact_force = run.result().force_N;
    summary["added_by_the_sink"] = 1.5;
  }
  void defect(const DefectRun& run, nlohmann::json&) override {
    add("defect");
    largest_sliding = contact::largest_varsigma_z(run.sweeps.back().varsigma);
  }
  void crosscheck(const validation::Crosscheck&) override { add("crosscheck"); }
  void hole_budget(const HoleBudget&, const validation::Crosscheck&) override { add("hole_budget"); }
  void chain_done() override { add("chain_done"); }
  void chain_study(const std::vector<ChainLevel>&, const nlohmann::json&) override { add("chain_study"); }
  void k_sweep(const validation::KTargetAnswer&) override { add("k_sweep"); }
  void post_design(const PostDesign&, const nlohmann::json&) override { add("post_design"); }

  std::vector<std::string> calls;
  bool mesh_half = true;
  double mesh_volume = 0, k_central = 0, k_lsq_line = 0, contact_force = 0, largest_sliding = 0;
  int green_scans = 0;
  nlohmann::json mesh_summary, kfit_file;

 private:
  void add(const char* name) {
    const std::lock_guard<std::mutex> lock(mutex_);
    calls.push_back(name);
  }
  std::mutex mutex_;
};

// Whether `calls` follows the sink's declared order, each at most once, with kfit where the header puts it:
// after green, before the crosscheck and chain_done (its fits run on a thread beside the contact).
bool in_declared_order(const std::vector<std::string>& calls) {
  const std::vector<std::string> order{"mesh",        "green",      "contact",     "defect",  "crosscheck",
                                       "hole_budget", "chain_done", "chain_study", "k_sweep", "post_design"};
  int last = -1;
  for (const std::string& c : calls) {
    if (c == "kfit") continue;
    const int at = static_cast<int>(std::find(order.begin(), order.end(), c) - order.begin());
    if (at <= last) return false;
    last = at;
  }
  // kfit once, after green and before the crosscheck and chain_done.
  const auto at = [&](const char* name) {
    return std::find(calls.begin(), calls.end(), name) - calls.begin();
  };
  const long n = static_cast<long>(calls.size());
  return std::count(calls.begin(), calls.end(), "kfit") == 1 && at("green") < at("kfit") &&
         at("kfit") < std::min(at("crosscheck"), n) && at("kfit") < at("chain_done") && at("chain_done") < n;
}

Scene coarse_layer() {
  Scene s;
  s.name = "report_layer";
  s.source_path = "report_layer.json";
  s.geometry.kind = GeometryKind::flat;
  s.geometry.flat = {2.0, 7.0};
  s.sensors.positions = {{-1, 0}, {0, 0}, {1, 0}};
  s.mesh.h_min = 0.6;
  s.mesh.growth = 1.7;
  s.mesh.h_max = 2.0;
  s.mesh.sensor_h = 0.5;
  s.calibration.spacing = 0.25;
  return s;
}

Scene swept_contact() {
  Scene s = coarse_layer();
  ContactLoad c;
  c.indenter = IndenterKind::sphere;
  c.sphere_R = 20;
  c.force = 0.3;
  c.zone_radius = 2.2;
  c.h = 0.4;
  c.mu = 0.5;
  c.static_ratio = 0.1;
  c.friction = FrictionMode::coupled;
  c.sweep = HoleSweep{{-1.5, 0}, {1.5, 0}, 5, 0.4};
  s.contact = c;
  return s;
}

TEST(Report, AFastReportWithAContactCallsTheSinkInOrderAndKeepsWhatItWasGiven) {
  const Scene scene = swept_contact();
  Recorder sink;
  ReportOptions options;
  options.fast = true;
  const ReportResult r = report_run(scene, options, sink);
  EXPECT_TRUE(in_declared_order(sink.calls)) << testing::PrintToString(sink.calls);
  for (const char* call : {"mesh", "green", "kfit", "contact", "defect", "crosscheck", "chain_done"})
    EXPECT_EQ(std::count(sink.calls.begin(), sink.calls.end(), call), 1) << call;
  EXPECT_EQ(sink.calls.size(), 7u);  // fast: no hole budget, chain study, k sweep or post design
  // The mesh handed on whole: the 14 × 14 × 2 mm box, its faces planes.
  EXPECT_FALSE(sink.mesh_half);
  const double box = 14.0 * 14.0 * 2.0;
  EXPECT_NEAR(sink.mesh_volume, box, kRoundOff * box);
  EXPECT_EQ(r.json.at("mesh"), sink.mesh_summary);
  // report.json's kfit entry is kfit.json's object and the ranges over the sensors.
  nlohmann::json kfit_entry = r.json.at("kfit");
  ASSERT_EQ(
      kfit_entry.erase("k_central_range_over_sensors") + kfit_entry.erase("k_lsq_line_range_over_sensors"),
      2u);
  EXPECT_EQ(kfit_entry, sink.kfit_file);
  EXPECT_NEAR(r.json.at("mesh").at("exact_volume_mm3").get<double>(), box, kRoundOff * box);
  EXPECT_EQ(sink.green_scans, 3);
  // report.json's entries are the typed results' the sink saw.
  EXPECT_EQ(r.json.at("kfit").at("sensors")[0].at("k_central").get<double>(), sink.k_central);
  EXPECT_EQ(r.json.at("contact").at("force_N").get<double>(), sink.contact_force);
  EXPECT_EQ(r.json.at("contact").at("added_by_the_sink").get<double>(), 1.5);
  EXPECT_NEAR(sink.contact_force, 0.3, 1e-9 * 0.3);  // force control: the scene's force (LCP round-off)
  EXPECT_GT(sink.largest_sliding, 0);
  // What a fast report leaves out, said in the result and in report.json.
  for (const char* what : {"error bars", "hole-signal budget", "VTK frames", "post design", "k sweep"})
    EXPECT_TRUE(has(r.left_out, what)) << what << " not in: " << r.left_out;
  EXPECT_FALSE(has(r.left_out, "effective-thickness"));  // a flat layer has no such fit
  EXPECT_EQ(r.json.at("fast").at("left_out"), r.left_out);
  EXPECT_FALSE(r.budget.has_value());
  EXPECT_TRUE(r.crosscheck.has_value());
  EXPECT_TRUE(r.front.has_value());
  EXPECT_TRUE(r.error_bars.empty());
  EXPECT_FALSE(r.json.contains("hole_budget"));
  EXPECT_FALSE(r.json.contains("error_bars"));
  EXPECT_EQ(r.json.at("scene").at("name"), "report_layer");
  EXPECT_GT(r.dofs, 0);
  EXPECT_EQ(r.json.at("dofs").get<int>(), r.dofs);
}

TEST(Report, ErrorBarsAreChainErrorsOverTheResultsLevels) {
  const Scene scene = coarse_layer();  // no contact: k only
  Recorder sink;
  ReportOptions options;            // full: a fast report draws no error bars
  options.error_scales = {1.5, 2};  // any order: the levels come coarse to fine
  const ReportResult r = report_run(scene, options, sink);
  EXPECT_TRUE(in_declared_order(sink.calls)) << testing::PrintToString(sink.calls);
  for (const char* absent : {"contact", "defect", "crosscheck", "hole_budget"})
    EXPECT_EQ(std::count(sink.calls.begin(), sink.calls.end(), absent), 0) << absent;
  EXPECT_EQ(std::count(sink.calls.begin(), sink.calls.end(), "chain_study"), 1);
  ASSERT_EQ(r.levels.size(), 3u);
  EXPECT_EQ(r.levels[0].scale, 2);
  EXPECT_EQ(r.levels[1].scale, 1.5);
  EXPECT_EQ(r.levels[2].scale, 1);
  // The finest level is the report's own chain: its k is kfit's.
  EXPECT_NEAR(r.levels[2].value[0], sink.k_central, kRoundOff * sink.k_central);
  EXPECT_NEAR(r.levels[2].value[1], sink.k_lsq_line, kRoundOff * sink.k_lsq_line);
  const std::vector<ChainError> e = chain_errors(r.levels);
  ASSERT_EQ(r.error_bars.size(), 2u);  // k_central and k_lsq_line
  for (size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(r.error_bars[i].quantity, e[i].name);
    EXPECT_EQ(r.error_bars[i].value, e[i].value);
    EXPECT_EQ(r.error_bars[i].error, e[i].error);
  }
  EXPECT_EQ(r.json.at("error_bars"), error_bars_json(r.error_bars));
  EXPECT_EQ(r.json.at("chain_study").at("levels").size(), 3u);
  EXPECT_FALSE(r.json.at("chain_study").contains("scene"));
}

TEST(Report, BadErrorScalesAreRefusedBeforeAnyStage) {
  Recorder sink;
  ReportOptions options;
  options.error_scales = {2};
  EXPECT_THROW(report_run(coarse_layer(), options, sink), SceneError);
  options.error_scales = {2, 0.9};
  EXPECT_THROW(report_run(coarse_layer(), options, sink), SceneError);
  options.error_scales = {2, 1.41};  // valid levels, but a fast report draws no error bars
  options.fast = true;
  EXPECT_THROW(report_run(coarse_layer(), options, sink), SceneError);
  EXPECT_TRUE(sink.calls.empty());
}

}  // namespace
}  // namespace skinfem::pipeline
