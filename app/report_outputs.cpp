#include "app/report_outputs.hpp"

#include <cmath>
#include <sstream>

#include "app/common.hpp"
#include "skinfem/green/kfit.hpp"
#include "skinfem/validation/text.hpp"

namespace skinfem::app {

using validation::fmt;

void write_crosscheck(const validation::Crosscheck& x, const Sensors& sensors, const std::string& dir) {
  prepare_output_dir(dir);
  const char* cases[2] = {"static", "sliding"};
  const int ns = static_cast<int>(sensors.positions.size());
  std::ostringstream r, d, p, a;
  for (auto* s : {&r, &d, &p, &a}) s->precision(10);
  r << "case,variant,sensor,x_mm,sigma_z_kPa,sigma_x_kPa\n";
  for (size_t v = 0; v < x.readings.size(); ++v)
    for (int c = 0; c < 2; ++c)
      for (int k = 0; k < ns; ++k)
        r << cases[c] << "," << x.reading_variants[v].name << "," << k + 1 << "," << sensors.positions[k][0]
          << "," << 1e3 * x.readings[v][c][2 * k] << "," << 1e3 * x.readings[v][c][2 * k + 1] << "\n";
  d << "case,variant,u_mm,sensor,varsigma_z_kPa,varsigma_x_kPa\n";
  for (size_t v = 0; v < x.signals.size(); ++v)
    for (int c = 0; c < 2; ++c)
      for (size_t i = 0; i < x.u.size(); ++i)
        for (int k = 0; k < ns; ++k)
          d << cases[c] << "," << x.signal_variants[v].name << "," << x.u[i] << "," << k + 1 << ","
            << 1e3 * x.signals[v][c](i, 2 * k) << "," << 1e3 * x.signals[v][c](i, 2 * k + 1) << "\n";
  p << "x_mm,p_hertz_halfspace_kPa,p_layer_exact_kPa,p_fe_frictionless_kPa,p_fe_coupled_kPa,q_fe_coupled_"
       "kPa,p_meridian_frictionless_kPa\n";
  for (const auto& row : x.pressure_profile) {
    p << row[0];
    for (int j = 1; j < 7; ++j) {
      p << ",";
      if (std::isfinite(row[j])) p << 1e3 * row[j];
    }
    p << "\n";
  }
  a << "case,variant,sensor,component,amplitude_ratio,peak_shift_mm,shape_error\n";
  for (size_t v = 0; v < x.metrics.size(); ++v)
    for (int c = 0; c < 2; ++c)
      for (int k = 0; k < ns; ++k)
        for (int b = 0; b < 2; ++b) {
          const auto& m = x.metrics[v][c][k][b];
          a << cases[c] << "," << x.signal_variants[v].name << "," << k + 1 << "," << (b ? "x" : "z") << ","
            << m.amplitude_ratio << "," << m.peak_shift_mm << "," << m.shape_error << "\n";
        }
  write_text_atomic(dir + "/readings.csv", r.str());
  write_text_atomic(dir + "/defect.csv", d.str());
  write_text_atomic(dir + "/pressure.csv", p.str());
  write_text_atomic(dir + "/attribution.csv", a.str());
}

nlohmann::json front_sensor_json(const validation::FrontSensorAnswer& a) {
  nlohmann::json j;
  std::string front;
  for (const int k : a.front) front += (front.empty() ? "#" : ", #") + std::to_string(k + 1);
  j["front_sensors"] = front;
  if (!a.front.empty()) {
    j["coupling_amplitude_factor_z"] = {a.coupling_lo[0], a.coupling_hi[0]};
    j["coupling_amplitude_factor_x"] = {a.coupling_lo[1], a.coupling_hi[1]};
  }
  if (a.model_lo) {
    j["fe_over_paper_model_amplitude_z"] = {(*a.model_lo)[0], (*a.model_hi)[0]};
    j["fe_over_paper_model_amplitude_x"] = {(*a.model_lo)[1], (*a.model_hi)[1]};
  }
  j["answer"] = a.answer;
  return j;
}

validation::KTargetAnswer k_paper_sweep(const Scene& scene, double h) {
  validation::KProtocol base;
  base.h = h;
  base.nu = scene.material.nu;
  base.punch_diameter = scene.calibration.punch_diameter;
  return validation::k_target_answer(base, green::kPaperK);
}

void write_k_paper_answer(validation::KTargetAnswer& a, const std::vector<validation::KSweepPoint>& mesh_rows,
                          const std::string& dir, nlohmann::json& entry) {
  validation::add_points(a, mesh_rows);
  std::ostringstream csv;
  csv.precision(10);
  csv << "parameter,value,k_central,k_lsq_line\n";
  for (const auto& p : a.points)
    csv << p.parameter << "," << p.value << "," << p.k_central << "," << p.k_lsq_line << "\n";
  write_text_atomic(dir + "/k_sweep.csv", csv.str());
  nlohmann::json j;
  for (const auto& n : a.near)
    j["within_0.01"].push_back(
        {{"parameter", n.parameter}, {"value", n.value}, {"criterion", n.criterion}, {"k", n.k}});
  for (const auto& c : a.crossings)
    j["crossings"].push_back({{"parameter", c.parameter},
                              {"criterion", c.criterion},
                              {"value", c.value},
                              {"linear_interpolation", c.interpolated}});
  j["answer"] = a.answer;
  entry = j;
}

std::vector<ErrorBar> error_bars(const std::vector<ChainError>& errors,
                                 const std::vector<double>& coarse_scales) {
  struct Display {
    const char* name;
    const char* what;
    const char* unit;
    double factor;
  };
  const Display table[] = {
      {"k_central", "k, central criterion (sensor #1)", "", 1},
      {"k_lsq_line", "k, line fit (sensor #1)", "", 1},
      {"contact_radius", "contact radius (coupled friction)", "mm", 1},
      {"contact_p0", "central pressure (coupled friction)", "kPa", 1e3},
      {"indentation", "indentation (coupled friction)", "um", 1e3},
      {"hole_signal", "largest sliding |varsigma_z| over sensors and hole positions", "kPa", 1e3}};
  std::string levels;
  for (double s : coarse_scales) levels += fmt("%g", s) + ", ";
  levels += "1";
  std::vector<ErrorBar> out;
  for (const ChainError& e : errors)
    for (const Display& d : table)
      if (e.name == d.name)
        out.push_back({e.name, d.what, d.unit,
                       e.asymptotic ? "|value - Richardson limit| over mesh scales " + levels +
                                          ", observed order " + fmt("%.2f", e.order)
                                    : "last change between mesh scales " + fmt("%g", coarse_scales.back()) +
                                          " and 1; no asymptotic regime over " + levels + " (" + e.why_not +
                                          "), so an order of magnitude only",
                       d.factor * e.value, d.factor * e.error, e.error / std::abs(e.value)});
  return out;
}

nlohmann::json error_bars_json(const std::vector<ErrorBar>& bars) {
  nlohmann::json j = nlohmann::json::array();
  for (const ErrorBar& e : bars)
    j.push_back({{"quantity", e.quantity},
                 {"what", e.what},
                 {"unit", e.unit},
                 {"value", e.value},
                 {"error", e.error},
                 {"relative_error", e.relative_error},
                 {"method", e.method}});
  return j;
}

}  // namespace skinfem::app
