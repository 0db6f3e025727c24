// The paper's convolution model against the full FE contact computation, one assumption at a time.
//
// Start from full FE (contact/ with the FE Green maps, exact by reciprocity) and swap in one of the paper's
// assumptions (validation/paper_model.hpp) per variant, so that each assumption's cost is one column:
//   readings (mean sensor stresses, paper fig. 2), for the static case (p_x = c·p_z, solved with it) and
//   the sliding one (coupled Coulomb slip p_x = μ·p_z):
//     fe                 full FE;
//     green_k_paper      FE tractions convolved with the half-space Green tensor rescaled by the paper's k;
//     green_k_best       the same with the best-fit k (kfit);
//     uncoupled          the frictionless FE pressure with the FE's traction added (the paper's friction:
//                        p_x = ratio·p_z, plus a shear strength on the frictionless contact where the
//                        scene's law has one);
//     pressure_hertz     half-space Hertz pressure (same force, equivalent radius), FE Green;
//     pressure_layer     the exact bonded-layer Hertz pressure (the paper's finite-thickness Hertz), FE
//     Green; paper_model        exact-layer pressure, Coulomb friction p_x = μ p_z uncoupled (whatever the
//                        scene's law: it is the paper's model), Green rescaled by the paper's k.
//   hole signals ς(u) (paper figs. 3–4):
//     fe                 a full FE contact solve per hole position (contact/holes/sweep.hpp);
//     green_k_paper      each position's FE tractions convolved with the rescaled half-space;
//     uncoupled          the frictionless FE sweep with the FE's traction added;
//     first_order_hole   eqs. (2)–(3) with the FE hole-free tractions and the FE Green maps;
//     small_hole         the hole as the penny-crack bulge it lets into it, in the intact FE contact
//                        (contact/holes/small_hole.hpp): the first-order formula with the right physics;
//     paper_model        eqs. (2)–(3), exact-layer pressure, uncoupled Coulomb, Green rescaled by the
//                        paper's k.
// Metrics of a signal against FE per sensor and component: amplitude ratio max|ς| / max|ς_FE|, peak shift
// u(max|ς|) − u(max|ς_FE|) and shape error ‖ς/‖ς‖ − ς_FE/‖ς_FE‖‖ (L2 over u: 0 same shape, √2 orthogonal,
// 2 opposite). Units: mm, MPa.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "skinfem/contact/holes/sweep.hpp"
#include "skinfem/contact/meridian_contact.hpp"
#include "skinfem/validation/paper_model.hpp"

namespace skinfem::validation {

struct CrosscheckInput {
  const TetMesh* mesh = nullptr;
  const contact::ContactSolver* solver = nullptr;  // condensed on `mesh`, with the scene's contact load
  const green::FeGreen* fe = nullptr;              // adjoints of the same sensors on the same mesh
  Sensors sensors;
  std::vector<double> thickness;            // skin above each sensor, mm (the rescaled half-space's depth)
  double E = 0, nu = 0.5;                   // MPa
  double force = 0;                         // N
  std::optional<double> equivalent_radius;  // mm, sphere-on-flat equivalent of the contact (none: skipped)
  double center_thickness = 0;              // mm, skin thickness at the first-touch point
  Vec2 center{0, 0};                        // first-touch point
  double k_paper = 1.48, k_best = 1.48;
  // The FE sweeps (static, then coupled sliding) with each position's solution, from the same solver.
  const std::vector<contact::SweepResult>* sweeps = nullptr;
  const std::vector<std::vector<contact::ContactResult>>* frames = nullptr;
  HoleSweep sweep;
  // The frictionless contact on the meridian about `center` (pipeline/meridian_contact.hpp), where the scene
  // has it: its edge-resolved pressure is one more profile. Optional.
  const contact::MeridianContactResult* meridian = nullptr;
};

struct Variant {
  std::string name;
  std::string what;  // one line: which assumption is swapped in
};

struct SignalMetrics {
  double amplitude_ratio = 0, peak_shift_mm = 0, shape_error = 0;
};

struct Crosscheck {
  static constexpr int kStatic = 0, kSliding = 1;
  double ratio[2] = {0, 0};        // p_x / p_z of each case (the FE's Coulomb part)
  double shear[2] = {0, 0};        // MPa, the FE's shear-strength part of p_x where the skin touches
  double paper_ratio[2] = {0, 0};  // the paper's p_x / p_z (static_ratio, μ) whatever the FE's law
  std::vector<Variant> reading_variants;
  std::vector<std::array<Eigen::VectorXd, 2>> readings;  // [variant][case]: 2·sensors, MPa
  std::vector<Variant> signal_variants;
  std::vector<std::array<Eigen::MatrixXd, 2>> signals;  // [variant][case]: positions × 2·sensors, MPa
  std::vector<double> u;                                // hole positions (x of the centre), mm
  // [variant][case][sensor][component z, x] against signals[0] (FE); variant 0 is all ones and zeros.
  std::vector<std::array<std::vector<std::array<SignalMetrics, 2>>, 2>> metrics;
  // Pressure profiles along y = center_y: x, Hertz half-space, exact layer, FE frictionless, FE coupled
  // (and its traction μ p), FE frictionless on the meridian; NaN where a variant was skipped.
  std::vector<std::array<double, 7>> pressure_profile;
};

Crosscheck crosscheck(const CrosscheckInput& in);

SignalMetrics compare_signals(const std::vector<double>& u, const Eigen::VectorXd& model,
                              const Eigen::VectorXd& reference);

// The paper's "front" sensors (§IV): those ahead of the contact centre along the sliding direction
// (unit, in the base plane), those on the centre's line across it included. 0-based, ascending; empty when
// no sensor lies strictly ahead (the front-sensor question does not arise).
std::vector<int> front_sensors(const Sensors& sensors, const Vec2& center, const Vec2& direction);

// The paper's measured excess of the front sensors' hole signals over its model (§IV: "up to 4 times").
constexpr double kPaperFrontExcess = 4.0;

// Does friction-pressure coupling explain the front sensors' excess? The sliding amplitude factor of FE
// coupled over FE uncoupled on the front sensors (min, max over them; z then x), and of FE over the paper's
// model when that variant exists; `answer` is the sentence these numbers give.
struct FrontSensorAnswer {
  std::vector<int> front;  // 0-based, validation::front_sensors
  std::array<double, 2> coupling_lo{}, coupling_hi{};
  std::optional<std::array<double, 2>> model_lo, model_hi;
  std::string answer;
};
FrontSensorAnswer front_sensor_answer(const Crosscheck& x, const std::vector<int>& front,
                                      const Vec2& direction);

}  // namespace skinfem::validation
