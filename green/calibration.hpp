// The paper's calibration simulated (§II): a unit load of the calibration diameter scanned along x
// through each sensor, its four Green components, and the k fits of the rescaled half-space model.
#pragma once

#include <array>
#include <functional>
#include <optional>
#include <vector>

#include "green/fe_green.hpp"
#include "green/kfit.hpp"

namespace skinfem::green {

inline constexpr std::array<GreenComponent, 4> kComponents{GreenComponent::zz, GreenComponent::zx,
                                                           GreenComponent::xz, GreenComponent::xx};
const char* component_name(GreenComponent c);

struct ScanProfile {
  std::vector<double> offset_x;          // load position − sensor position along x, mm (y offset 0)
  std::vector<GreenSample> point, disc;  // sensor-centre value and disc mean, 1/mm²
};

// A sensor's g_ab (1/mm²) for a unit load centred at offset (ox, oy) from it, spread as `load` over `radius`:
// its disc mean (disc) or centre value (FeGreen::at with the sensor fixed, or MeridianGreen::at).
using SensorGreen =
    std::function<GreenSample(bool disc, double ox, double oy, LayerLoad load, double radius)>;

// Offsets −half_width … +half_width at `spacing` (symmetric, 0 included).
ScanProfile scan_profile(const SensorGreen& g, LayerLoad load, double radius, double half_width,
                         double spacing);
inline ScanProfile scan_profile(const FeGreen& fe, int sensor, LayerLoad load, double radius,
                                double half_width, double spacing) {
  return scan_profile([&](bool disc, double ox, double oy, LayerLoad l,
                          double a) { return fe.at(sensor, disc, ox, oy, l, a); },
                      load, radius, half_width, spacing);
}

struct KReport {
  double k_central = 0;              // g_zz(0) / (gain · 3/(2πh²)), point value at the base
  double k_lsq_line = 0;             // least squares of gain·g_k to g_zz on |x| ≤ 3h, uniform weight in x
  double gain = 1;                   // of g_zz: 1, or fitted with k_lsq_line (Gain::fitted)
  std::array<KFit, 4> components{};  // best k, gain and rms residual / peak per component (zz, zx, xz, xx)
};

// k fits of a profile of point values along x (offset 0 must be present) for thickness h. With
// Gain::fitted (post sensors) every fit has its own gain, and k_central divides by g_zz's.
KReport fit_profile(const std::vector<double>& x, const std::vector<GreenSample>& g, double h,
                    Gain gain = Gain::fixed);

// The exact flat-layer reference on the same offsets: point values, or (disc_diameter > 0) the mean over
// the sensor disc (LayerGreen's sensor_radius: exact, no rule over the disc).
std::vector<GreenSample> exact_profile(const LayerGreen& layer, const std::vector<double>& x,
                                       double disc_diameter = 0);

// max over the offsets of |g_c|, 1/mm².
double peak_abs(const std::vector<GreenSample>& profile, GreenComponent c);

// max over the offsets of |fe − exact| / max|exact|, per component.
std::array<double, 4> max_error_over_peak(const std::vector<GreenSample>& fe,
                                          const std::vector<GreenSample>& exact);

// Thickness of the flat bonded layer whose exact g_zz (same load) best fits `g_zz` on the offsets
// (least squares, golden section on [0.5 h0, 1.5 h0]): the effective skin thickness at a sensor.
// Throws std::domain_error when the best thickness is a bound of that range.
double effective_thickness(const std::vector<double>& x, const std::vector<double>& g_zz, double h0,
                           double nu, LayerLoad load, double radius);

// The paper's calibration (§II: "a Volt-to-Pascal calibration of the sensors, as well as an estimated value
// of the thickness of the layer at each sensor's location"): a sensor's scan is fitted by the exact bonded
// layer's base stress under the same load, with the layer's thickness and the reading's scale both free.
// σ_z's scan (g_zz) gives the thickness and scale_z; σ_x's (g_zx, the same normal load) its own scale_x
// at that thickness. A reading divided by its scale is in the calibration's units, the paper's kPa.
struct PaperCalibration {
  double thickness_mm = 0;
  double scale_z = 0, scale_x = 0;                  // reading / fitted layer stress
  double rms_z_over_peak = 0, rms_x_over_peak = 0;  // the fits' residuals
};
// Least squares over the offsets; the thickness by golden section on [0.25 h0, 2 h0], the scales linear.
// Throws std::domain_error when the best thickness is a bound of that range.
PaperCalibration paper_calibration(const std::vector<double>& x, const std::vector<GreenSample>& g, double h0,
                                   double nu, LayerLoad load, double radius);

}  // namespace skinfem::green
