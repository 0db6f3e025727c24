// The paper's calibration simulated (§II): a unit load of the calibration diameter scanned along x
// through each sensor, its four Green components, and the k fits of the rescaled half-space model.
#pragma once

#include <array>
#include <functional>
#include <optional>
#include <vector>

#include "skinfem/green/fe_green.hpp"
#include "skinfem/green/kfit.hpp"

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

// A sensor's gain per reading: its reading under a uniform unit load on the unbounded flat layer of its
// thickness, σ_z under a pressure (z) and σ_x under a shear (x), which the rescaled model of its Green
// tensor must reproduce: g_ab ≈ gain_b·k·g_half,ab(√k x) (b the reading: zz and xz read σ_z, zx and xx σ_x).
// A base-traction reading (a disc) has both 1 by equilibrium. So has a post's σ_z in an incompressible skin:
// a uniform pressure on a bonded layer at ν = 0.5 is hydrostatic (u = 0, p = q), which a rigid post anywhere
// in it does not disturb, and its top reads q. Its σ_x gain is a rigid post's stress concentration in simple
// shear, above 1 (pipeline/sensor_greens.hpp, sensor_gains). `fitted`: no gain is known, each component's is
// fitted with its k (a post on membrane springs).
struct ChannelGains {
  double z = 1, x = 1;
  bool fitted = false;
  std::optional<double> of(GreenComponent c) const {
    if (fitted) return std::nullopt;
    return c == GreenComponent::zz || c == GreenComponent::xz ? z : x;
  }
};

struct KReport {
  double k_central = 0;   // g_zz(0) / (gains.z · 3/(2πh²)), point value at the base
  double k_lsq_line = 0;  // least squares of gains.z·g_k to g_zz on |x| ≤ 3h, uniform weight in x
  ChannelGains gains;     // the model's, as given
  std::array<KFit, 4> components{};  // best k and rms residual / peak per component (zz, zx, xz, xx)
};

// k fits of a profile of point values along x (offset 0 must be present) for thickness h, each component's
// model at its reading's gain.
KReport fit_profile(const std::vector<double>& x, const std::vector<GreenSample>& g, double h,
                    ChannelGains gains = {});

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
