// What a post changes (pipeline/post_design.hpp) written out: DIR/post_design.csv, one row per design
// (row,diameter_mm,height_mm,g_zz_peak_per_mm2,g_zz_half_width_mm,g_zz_integral,g_xx_peak_per_mm2,
// g_xx_half_width_mm,g_xx_integral,peak_change,half_width_change,integral_change; height 0 is the disc):
// rows "post" and "disc" (the scene's post and its disc, mesh scale 1), then "sweep"; prints its answer.
#include <sstream>

#include "app/common.hpp"
#include "app/stages.hpp"

namespace skinfem::app {

void write_post_design(const pipeline::PostDesign& p, const nlohmann::json& entry,
                       const std::string& out_dir) {
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
  std::printf("  post design: %s\n", entry.at("answer").get<std::string>().c_str());
}

}  // namespace skinfem::app
