// What would make the paper's k = 1.48: both k criteria (green/kfit.hpp) of the exact bonded layer
// (green/layer_exact.hpp) as each reading of the paper's calibration protocol is varied alone about a base
// case: Poisson's ratio, the punch diameter (0.5 mm read as a diameter or as a radius), the load model
// (point, uniform disc, rigid punch), the sensor's averaging disc, and the layer's thickness. The FE's own
// error on these numbers is the kfit one (0.1 % on the flat layer, docs/k_correction.md).
#pragma once

#include <string>
#include <vector>

#include "skinfem/green/layer_exact.hpp"

namespace skinfem::validation {

struct KProtocol {
  double h = 3.04;  // layer thickness, mm
  double nu = 0.5;
  double punch_diameter = 0.5;  // mm
  green::LayerLoad load = green::LayerLoad::punch;
  double disc_diameter = 0;  // sensor averaging disc, mm (0: point value)
};

struct KSweepPoint {
  std::string parameter;  // nu, punch_diameter_mm, load, disc_diameter_mm, h_mm
  double value = 0;       // the parameter's value (load: 0 point, 1 uniform, 2 punch)
  double k_central = 0, k_lsq_line = 0;
};

// Both criteria for one protocol.
KSweepPoint k_of(const KProtocol& p, double spacing = 0.05);
// Every parameter over its range (nu 0.30–0.50, punch 0.1–1.5 mm, disc 0–0.6 mm, h 2.5–3.5 mm, the three
// loads), the others at `base`. Offsets every `spacing` mm over |x| ≤ 3h (the fit's range).
std::vector<KSweepPoint> k_sweep(const KProtocol& base, double spacing = 0.05);

// Where k of `criterion` ("k_central" or "k_lsq_line") crosses `target` along one parameter's points, by
// linear interpolation between neighbours; empty when it never does.
std::vector<double> crossings(const std::vector<KSweepPoint>& points, const std::string& parameter,
                              const std::string& criterion, double target);

// The same crossing found on the exact layer itself: k of `criterion` as `parameter` (nu, punch_diameter_mm,
// disc_diameter_mm or h_mm) varies alone about `base`, root-found between lo and hi, where k − target
// changes sign (Illinois' regula falsi to |Δvalue| ≤ 1e-9 of the bracket, at most 40 evaluations of k_of).
// The crossings above interpolate linearly between sweep points, which k is not: on the paper's protocol
// they are about 0.8 % off (tests/validation/test_k_sweep.cpp).
double crossing_root(const KProtocol& base, const std::string& parameter, const std::string& criterion,
                     double target, double lo, double hi);

// Which single change of the protocol gives a target k (the paper's 1.48): the sweep about `base`, the
// readings whose k lies within `band` of the target, and where each parameter's k crosses it (crossing_root,
// from the sweep's brackets). `answer` says so in one sentence computed from these numbers. The exact layer
// alone: it needs no FE, so the report computes it beside its factorization.
struct KTargetAnswer {
  struct Near {
    std::string parameter, criterion;  // criterion: k_central or k_lsq_line
    double value = 0, k = 0;
  };
  struct Crossing {
    std::string parameter, criterion;
    double value = 0;         // crossing_root's: k of the protocol with it equals the target
    double interpolated = 0;  // the linear interpolation between sweep points
  };
  double target = 0, band = 0, h = 0;  // h: the base's layer thickness, mm
  std::vector<KSweepPoint> points;
  std::vector<Near> near;
  std::vector<Crossing> crossings;
  bool extra_points = false;  // add_points added some
  std::string answer;
};
KTargetAnswer k_target_answer(const KProtocol& base, double target, double band = 0.01);
// Points of another axis (the report's FE k per mesh scale, parameter "mesh_scale") join `near` and the
// answer; crossings stay the exact layer's.
void add_points(KTargetAnswer& a, const std::vector<KSweepPoint>& extra);

}  // namespace skinfem::validation
