// Where the holes are: a scan's sensor signals deconvolved over a dictionary of single-hole responses (the
// paper's conclusion: "an inversion method … based on multi-sensor signal analysis"), with the contact's
// offset from the sensors as a nuisance parameter.
//
// The model: a hole at plate position q (relative to the contact at scan position u = 0) with amplitude a
// gives sensor i the signal a·R_{x_i − δ}(q + u), where R_s(x) is the response of a sensor at s (in the
// contact's frame) to a hole at x, computed for the scene's hole (a = (D/D₀)³ for a hole of diameter D under
// the bulge model, whose signal is the hole's volume times the pressure it sits in), and δ is the contact's
// offset from its nominal place relative to the sensors. For each δ on a grid the amplitudes on a grid of
// q (the scan's step) solve the non-negative least squares min ‖W (y − A_δ a)‖², a ≥ 0 (Lawson & Hanson,
// Solving Least Squares Problems, 1974, ch. 23), W the noise's 1/σ per component; the δ of the least
// residual wins. A hole position whose response is below 1e-6 of the largest (a hole the scan never brings
// into the contact: the FE's round-off) is left out of the fit. Adjacent non-zero amplitudes (one hole
// between grid points) merge into one feature at their amplitude-weighted position; a feature whose own SNR
// is below the detector's threshold is dropped.
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "skinfem/validation/detection.hpp"

namespace skinfem::validation {

// min ‖A x − b‖², x ≥ 0, by Lawson–Hanson's active set (A: m × n, any m). Converges in finitely many steps;
// max_iterations bounds them (3n if 0). Throws std::runtime_error when they run out.
Eigen::VectorXd nnls(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, int max_iterations = 0);
// The same from the normal equations: G = AᵀA (n × n), c = Aᵀb.
Eigen::VectorXd nnls_gram(const Eigen::MatrixXd& G, const Eigen::VectorXd& c, int max_iterations = 0);

// The dictionary: responses R_s(x) of sensors at `sites` (mm along the scan, in the contact's frame) to the
// scene's hole at x = x0 + m·dx, m = 0 … rows − 1 (outside the grid R = 0).
struct HoleResponses {
  double x0 = 0, dx = 0;
  std::vector<double> sites;  // mm
  Eigen::MatrixXd R;          // rows × 2·sites, kPa (σ_z of site k in column 2k, σ_x in 2k + 1)
  double diameter = 0;        // mm, the hole the responses are of
};

// The scan's signals: y(u_i) for sensors at `sensors` (mm along the scan).
struct ScanSignals {
  std::vector<double> u;        // mm, evenly spaced
  std::vector<double> sensors;  // mm
  Eigen::MatrixXd y;            // positions × 2·sensors, kPa
};

struct Feature {
  double position_mm = 0;  // on the plate at u = 0 (q + δ: in the sensors' frame)
  double diameter_mm = 0;  // D₀ a^(1/3)
  double amplitude = 0;    // a
  double snr = 0;          // its own matched-filter SNR
};

struct Inversion {
  std::vector<Feature> features;
  double offset_mm = 0;  // δ
  // The least residual's δ between grid points: the vertex of the parabola through the best δ and its two
  // neighbours (offset_mm at the grid's ends, or where the three do not open upwards).
  double offset_refined_mm = 0;
  double weighted_residual = 0;            // ‖W (y − A a)‖² at the chosen δ
  std::vector<double> offsets, residuals;  // every δ tried and its residual
};

// The index of site s (mm, to 1e-6 mm) in responses.sites, or −1.
int site_column(const HoleResponses& responses, double s);

// offsets: the δ grid (mm, ascending); every x_i − δ must be one of responses.sites (to 1e-6 mm). p_fa: a
// feature whose own SNR is below the threshold Φ⁻¹(1 − p_fa) is dropped. single_sensor ≥ 0: invert that
// sensor's signals alone (the paper's "naive" inversion), else all of them. Throws std::invalid_argument when
// a site is missing or the grids do not match (u's step must be dx).
Inversion invert_scan(const ScanSignals& signals, const HoleResponses& responses, const SensorNoise& noise,
                      const std::vector<double>& offsets, double p_fa = 0.01, int single_sensor = -1);

// The Cramér–Rao bound on the position (mm) of one feature of amplitude a at q (known δ, unknown q and a),
// from the dictionary's derivative along x: the inverse Fisher matrix's (q, q) entry, square-rooted.
double position_crb(const ScanSignals& signals, const HoleResponses& responses, const SensorNoise& noise,
                    double q, double a, double offset, int single_sensor = -1);

// The signals of `features` (q = position − δ) under the dictionary model, noise-free.
Eigen::MatrixXd simulated_signals(const std::vector<double>& u, const std::vector<double>& sensors,
                                  const HoleResponses& responses, const std::vector<Feature>& features,
                                  double offset);

// One inversion against the truth (score_inversion).
struct InversionScore {
  int found = 0, missed = 0, false_features = 0;
  double rms_error_mm = 0, largest_error_mm = 0;  // over the matched holes
};

// Features against the true holes (positions, mm): each feature goes to the nearest hole within `reach`,
// the rest are false; a hole with no feature is missed; with several, the nearest is the hole's and the
// others are false (a hole split in two is one feature too many).
InversionScore score_inversion(const std::vector<Feature>& features, const std::vector<double>& truth,
                               double reach);

// The seeded noise of N passages added to signals (kPa, positions × 2·sensors).
Eigen::MatrixXd with_noise(const Eigen::MatrixXd& y, const SensorNoise& noise, std::uint64_t seed);

}  // namespace skinfem::validation
