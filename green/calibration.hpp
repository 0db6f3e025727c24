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
  double k_central = 0;              // g_zz(0) / (3/(2πh²)), point value at the base
  double k_lsq_line = 0;             // least squares of g_k to g_zz on |x| ≤ 3h, uniform weight in x
  std::array<KFit, 4> components{};  // best k and rms residual / peak per component (zz, zx, xz, xx)
};

// k fits of a profile of point values along x (offset 0 must be present) for thickness h.
KReport fit_profile(const std::vector<double>& x, const std::vector<GreenSample>& g, double h);

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
double effective_thickness(const std::vector<double>& x, const std::vector<double>& g_zz, double h0,
                           double nu, LayerLoad load, double radius);

}  // namespace skinfem::green
