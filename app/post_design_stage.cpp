// What a post changes (pipeline/post_design.hpp) written out: DIR/post_design.csv, one row per design
// (row,diameter_mm,height_mm,g_zz_peak_per_mm2,g_zz_half_width_mm,g_zz_integral,g_xx_peak_per_mm2,
// g_xx_half_width_mm,g_xx_integral,peak_change,half_width_change,integral_change; height 0 is the disc):
// rows "post" and "disc" (the scene's post and its disc, mesh scale 1), then "sweep"; returns the report.json
// entry `post_design` with its sentence.
#include <algorithm>
#include <sstream>

#include "app/common.hpp"
#include "app/stages.hpp"
#include "skinfem/validation/text.hpp"

namespace skinfem::app {

namespace {
using validation::fmt;

nlohmann::json design_json(const pipeline::SensorDesign& d) {
  const auto shape = [](const MeridianGreen::Shape& s) {
    return nlohmann::json{{"peak_per_mm2", s.peak},
                          {"peak_at_mm", s.peak_at},
                          {"half_width_mm", s.half_width},
                          {"integral", s.integral}};
  };
  return {{"diameter_mm", d.diameter},
          {"height_mm", d.height},
          {"g_zz", shape(d.zz)},
          {"g_xx", shape(d.xx)},
          {"peak_change", d.peak_change},
          {"half_width_change", d.half_width_change},
          {"integral_change", d.integral_change}};
}

// The heights of the sweep a skin of thickness h takes (a post stays below 0.9 h, the scene rule).
std::vector<double> sweep_heights(double h) {
  std::vector<double> out;
  for (double t : {0.0, 0.2, 0.4, 0.6, 0.8, 1.0})
    if (t < 0.9 * h) out.push_back(t);
  return out;
}
}  // namespace

StageOutput<pipeline::PostDesign> post_design_stage(const Scene& scene, const std::string& out_dir) {
  if (const std::string why = pipeline::post_design_unavailable(scene); !why.empty())
    return {{}, nlohmann::json{{"skipped", "no meridian at the skin's axis: " + why}}};
  progress("post design: a post against a disc at the skin's axis, and a sweep of post height and diameter");
  const double h = scene.geometry.kind == GeometryKind::flat ? scene.geometry.flat.h : scene.geometry.cap.h;
  pipeline::PostDesign p = pipeline::post_design(scene, {0.1, 0.2, 0.3, 0.4}, sweep_heights(h));
  std::ostringstream csv;
  csv.precision(8);
  csv << "row,diameter_mm,height_mm,g_zz_peak_per_mm2,g_zz_half_width_mm,g_zz_integral,g_xx_peak_per_mm2,"
         "g_xx_half_width_mm,g_xx_integral,peak_change,half_width_change,integral_change\n";
  std::vector<std::pair<const char*, const pipeline::SensorDesign*>> rows = {{"post", &p.post},
                                                                             {"disc", &p.disc}};
  for (const auto& d : p.sweep) rows.push_back({"sweep", &d});
  for (const auto& [row, d] : rows)
    csv << row << "," << d->diameter << "," << d->height << "," << d->zz.peak << "," << d->zz.half_width
        << "," << d->zz.integral << "," << d->xx.peak << "," << d->xx.half_width << "," << d->xx.integral
        << "," << d->peak_change << "," << d->half_width_change << "," << d->integral_change << "\n";
  prepare_output_dir(out_dir);
  write_text_atomic(out_dir + "/post_design.csv", csv.str());

  // The sentence, from the numbers: the scene's post against its disc, then the sweep's ranges.
  const pipeline::SensorDesign &post = p.post, &disc = p.disc;
  double gain_lo = 1e300, gain_hi = -1e300, width_lo = 1e300, width_hi = -1e300, change = 0;
  double t_lo = 1e300, t_hi = 0, d_lo = 1e300, d_hi = 0;
  for (const auto& d : p.sweep) {
    t_lo = std::min(t_lo, d.height), t_hi = std::max(t_hi, d.height);
    d_lo = std::min(d_lo, d.diameter), d_hi = std::max(d_hi, d.diameter);
    gain_lo = std::min(gain_lo, d.zz.integral), gain_hi = std::max(gain_hi, d.zz.integral);
    width_lo = std::min(width_lo, d.zz.half_width), width_hi = std::max(width_hi, d.zz.half_width);
    change = std::max({change, d.peak_change, d.half_width_change, d.integral_change});
  }
  const std::string answer =
      "At the skin's axis (" + p.skin + "), an isolated post " + fmt("%.3g", post.diameter) +
      " mm wide and " + fmt("%.3g", post.height) +
      " mm high against the disc of its diameter: g_zz peaks at " + fmt("%.4g", post.zz.peak) + " against " +
      fmt("%.4g", disc.zz.peak) + " /mm² (" + fmt("%.2f", post.zz.peak / disc.zz.peak) + "×), half width " +
      fmt("%.3g", post.zz.half_width) + " against " + fmt("%.3g", disc.zz.half_width) + " mm, ∫ g_zz dA " +
      fmt("%.3g", post.zz.integral) + " against " + fmt("%.3g", disc.zz.integral) + "; g_xx peaks at " +
      fmt("%.4g", post.xx.peak) + " against " + fmt("%.4g", disc.xx.peak) + " /mm² (" +
      fmt("%.2f", post.xx.peak / disc.xx.peak) + "×), half width " + fmt("%.3g", post.xx.half_width) +
      " against " + fmt("%.3g", disc.xx.half_width) + " mm, ∫ g_xx dA " + fmt("%.3g", post.xx.integral) +
      " against " + fmt("%.3g", disc.xx.integral) + " (largest change from the mesh twice as coarse: " +
      fmt("%.2g", 100 * std::max({post.peak_change, post.half_width_change, post.integral_change})) +
      " %). Over the sweep (heights " + fmt("%g", t_lo) + "–" + fmt("%g", t_hi) + " mm, diameters " +
      fmt("%g", d_lo) + "–" + fmt("%g", d_hi) + " mm) ∫ g_zz dA runs " + fmt("%.3g", gain_lo) + "–" +
      fmt("%.3g", gain_hi) + " and its half width " + fmt("%.3g", width_lo) + "–" + fmt("%.3g", width_hi) +
      " mm (mesh change up to " + fmt("%.2g", 100 * change) +
      " %). The integrals are the readings under a uniform vertical load (or shear) per unit base area over "
      "the "
      "whole top, on a curved top not a pressure; under a uniform pressure a post reads it exactly "
      "(hydrostatic).";
  nlohmann::json j = {{"skin", p.skin},
                      {"post", design_json(post)},
                      {"disc", design_json(disc)},
                      {"sweep_mesh_scale", p.sweep_scale},
                      {"dofs", p.dofs},
                      {"seconds", p.seconds},
                      {"answer", answer}};
  for (const auto& d : p.sweep) j["sweep"].push_back(design_json(d));
  std::printf("  post design: %s\n", answer.c_str());
  return {std::move(p), std::move(j)};
}

}  // namespace skinfem::app
