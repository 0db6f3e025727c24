// The report's perception section (pipeline/report_perception.hpp) written out, in DIR:
//   row.csv            u_mm,sensor,varsigma_z_kPa,varsigma_x_kPa,superposed_z_kPa,superposed_x_kPa,
//                      noisy_z_kPa,noisy_x_kPa: the row's sliding scan, its superposition and the signals
//                      the inversion read (with the paper's noise)
//   pairs.csv          case,spacing_mm,rel_diff_z,rel_diff_x
//   detection.csv      case,diameter_mm,array_snr,best_sensor_snr (the ladder at the paper's noise)
//   detection_map.csv  case,passages,array_mm,best_sensor_mm (empty: outside the ladder; summary.json says
//                      above or below)
//   features.csv       source,sensor,position_mm,diameter_mm,amplitude,snr; source truth (the row's holes),
//                      multi (every sensor, the offset fitted) or naive (one sensor alone, its number)
//   summary.json       report.json's "perception"
#include <sstream>

#include "app/common.hpp"
#include "app/stages.hpp"

namespace skinfem::app {

void write_perception(const Scene& scene, const pipeline::ReportPerception& p, const nlohmann::json& entry,
                      const std::string& out_dir) {
  const int ns = static_cast<int>(scene.sensors.positions.size());
  std::ostringstream row, pairs, ladder, map, features;
  for (std::ostringstream* s : {&row, &pairs, &ladder, &map, &features}) s->precision(8);
  row << "u_mm,sensor,varsigma_z_kPa,varsigma_x_kPa,superposed_z_kPa,superposed_x_kPa,noisy_z_kPa,noisy_x_"
         "kPa\n";
  const bool noisy = p.noisy.y.rows() == p.row.varsigma.rows();
  for (size_t i = 0; i < p.row.u.size(); ++i)
    for (int k = 0; k < ns; ++k) {
      row << p.row.u[i] << "," << k + 1;
      for (int c = 0; c < 2; ++c) row << "," << 1e3 * p.row.varsigma(i, 2 * k + c);
      for (int c = 0; c < 2; ++c) row << "," << 1e3 * p.row_superposed(i, 2 * k + c);
      for (int c = 0; c < 2; ++c) {
        row << ",";
        if (noisy) row << p.noisy.y(i, 2 * k + c);
      }
      row << "\n";
    }
  pairs << "case,spacing_mm,rel_diff_z,rel_diff_x\n";
  for (const pipeline::PairPoint& q : p.pairs)
    pairs << q.case_name << "," << q.spacing_mm << "," << q.rel_diff_z << "," << q.rel_diff_x << "\n";
  ladder << "case,diameter_mm,array_snr,best_sensor_snr\n";
  for (const pipeline::PerceptionCase& c : p.detection.cases)
    for (size_t r = 0; r < p.detection.diameters.size(); ++r)
      ladder << c.name << "," << p.detection.diameters[r] << "," << c.ladder_array[r] << ","
             << c.ladder_best[r] << "\n";
  map << "case,passages,array_mm,best_sensor_mm\n";
  for (const pipeline::DetectionPoint& d : p.detection_map) {
    map << d.case_name << "," << d.passages << ",";
    if (d.array_mm) map << *d.array_mm;
    map << ",";
    if (d.sensor_mm) map << *d.sensor_mm;
    map << "\n";
  }
  features << "source,sensor,position_mm,diameter_mm,amplitude,snr\n";
  const double D = scene.contact->sweep->hole_diameter;
  for (double x : p.row_holes_mm) features << "truth,0," << x << "," << D << ",1,\n";
  if (p.inversion) {
    for (const validation::Feature& f : p.inversion->multi.features)
      features << "multi,0," << f.position_mm << "," << f.diameter_mm << "," << f.amplitude << "," << f.snr
               << "\n";
    for (size_t k = 0; k < p.inversion->naive.size(); ++k)
      for (const validation::Feature& f : p.inversion->naive[k].features)
        features << "naive," << k + 1 << "," << f.position_mm << "," << f.diameter_mm << "," << f.amplitude
                 << "," << f.snr << "\n";
  }
  write_text_atomic(out_dir + "/row.csv", row.str());
  write_text_atomic(out_dir + "/pairs.csv", pairs.str());
  write_text_atomic(out_dir + "/detection.csv", ladder.str());
  write_text_atomic(out_dir + "/detection_map.csv", map.str());
  write_text_atomic(out_dir + "/features.csv", features.str());
  write_json(out_dir + "/summary.json", entry);
}

}  // namespace skinfem::app
