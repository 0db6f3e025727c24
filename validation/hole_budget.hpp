// The hole-signal budget: which interface physics reproduces the five facts the paper reports for a hole
// in the sliding plate (shared paper, §"elementary topological defects", fig. 3):
//   F1  at rest a hole inside the contact is not detected;
//   F2  sliding, it is clearly detected, and the back sensors' amplitudes match the paper's model;
//   F3  the front sensors reach up to 4× the model;
//   F4  ς_z goes from a positive hump on the left-hand sensors to a negative one on the right-hand ones
//       through antisymmetric profiles; ς_x has one dominant hump on the outer sensors and two comparable
//       maxima on some sensor in between;
//   F5  the outermost sensors respond although they lie outside the contact.
// Each hypothesis (a friction law, later an interface law or a sensor model) is one FE hole sweep per case
// on the same condensed skin; each fact is judged from its numbers with the thresholds stated in NoiseModel
// and FactRules, and the verdict's sentence is built from them.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "skinfem/contact/contact_solver.hpp"
#include "skinfem/contact/holes/sweep.hpp"
#include "skinfem/fem/face_index.hpp"

namespace skinfem::validation {

// Detection: the paper averages 14 passages of noise σ_z = 0.6 kPa, σ_x = 0.4 kPa (its §"elementary
// topological defects"); a signal is detected when its amplitude exceeds k standard deviations of that mean.
struct NoiseModel {
  double sigma_z_MPa = 0.6e-3, sigma_x_MPa = 0.4e-3;
  int passages = 14;
  double k = 2;
  double threshold(int component) const;  // MPa; component 0: z, 1: x
};

// The judgement's bands, stated once: "match" (F2) is an amplitude ratio FE/model in [match_lo, match_hi];
// F3 is an asymmetry, the front sensors "up to 4×" the model while the back ones match it: the front's
// largest ratio reaches front_min and front_over_back times the back's largest; a profile is antisymmetric
// (F4) when its smaller lobe reaches antisym of its larger; two maxima are comparable when the second reaches
// comparable of the first with a dip of at least dip between them.
struct FactRules {
  double match_lo = 0.5, match_hi = 2.0, front_min = 2.0, front_over_back = 2.0, antisym = 0.5,
         comparable = 0.5, dip = 0.2;
};

struct FactVerdict {
  std::string fact;  // "F1" … "F5"
  bool met = false;
  std::string why;  // one sentence from the numbers
};

struct FactsInput {
  std::vector<double> u;              // hole positions along the path, mm
  std::array<Eigen::MatrixXd, 2> fe;  // static, sliding: positions × 2·sensors (σ_z at 2k, σ_x at 2k+1), MPa
  std::array<Eigen::MatrixXd, 2> model;  // the paper's model, same layout
  Sensors sensors;
  Vec2 center{0, 0}, direction{1, 0};  // first touch; sliding direction
  double contact_radius_mm = 0;        // of the sliding contact
  NoiseModel noise;
  FactRules rules;
  // 2·sensors: what each FE reading column is divided by to be in the paper's units (its calibration's
  // scale, green::PaperCalibration); empty when the readings are in them already (disc sensors).
  Eigen::VectorXd reading_scale;
};

// How jagged a signal curve sampled at even steps is: max |ς_{i+1} − 2ς_i + ς_{i−1}| / max |ς| (0 for a zero
// curve). A smooth curve sampled finely gives a small value that falls as the steps shrink; a jump (a
// multiplier entering or leaving the hole) keeps a fixed share of its size whatever the step.
double roughness(const Eigen::VectorXd& curve);

// FE/model amplitude ratio (max|ς_FE| / max|ς_model|) per case, sensor and component.
std::array<std::vector<std::array<double, 2>>, 2> amplitude_ratios(const FactsInput& in);
std::vector<FactVerdict> judge_facts(const FactsInput& in);

struct Hypothesis {
  std::string name, what;
  ContactLoad load;
};
// The friction laws at the scene's μ and static ratio: Coulomb; a shear strength with τ0 = μF/A (the same
// sliding force); both at half strength (the same sliding force again).
std::vector<Hypothesis> friction_hypotheses(const ContactLoad& scene_load);
// A rough interface in series (InterfaceLaw::linear) under Coulomb friction and under the shear strength, for
// asperity heights u0 (mm): K = p_mean / u0, the stiffness of an exponential law p = p_ref exp(−gap/u0) at
// the mean contact pressure p_mean (MPa, F/A of the hard frictionless contact).
std::vector<Hypothesis> interface_hypotheses(const ContactLoad& scene_load, double p_mean,
                                             const std::vector<double>& u0 = {0.3e-3, 1e-3, 3e-3, 10e-3});

struct HypothesisResult {
  Hypothesis hypothesis;
  double tau0_MPa = 0, contact_radius_mm = 0, tangential_force_N = 0, seconds = 0;
  std::array<Eigen::MatrixXd, 2> signals;  // static, sliding (coupled), over base.reading_scale
  std::array<std::vector<std::array<double, 2>>, 2> ratio;
  std::vector<FactVerdict> facts;
};
// r.signals (static, sliding: the FE readings' ς, MPa) put in base's units (over base.reading_scale) and
// judged against base.model with r.contact_radius_mm: sets r.signals, r.ratio and r.facts.
void judge_hypothesis(HypothesisResult& r, FactsInput base);
// One static and one coupled sliding sweep on `condensed` (seen whole through `mirror` when not null), judged
// against base.model. The hole is the scene sweep's model under a hard interface, resolved under any other
// (then `condensed` needs its hole path: std::runtime_error otherwise). mesh, top: the whole mesh and its top
// index; material: the skin's (a bulge sweep's). Throws std::runtime_error when the contact reaches the
// candidate zone's edge (a multiplier next to a face outside the zone is active): the zone would cut it, so
// the hypothesis needs a larger contact.zone_radius. cuts: the resolved sweep's cut problems
// (contact::hole_cuts), shared by the hypotheses; none: computed per position.
HypothesisResult run_hypothesis(const Hypothesis& h, const contact::CondensedContact& condensed,
                                const contact::MirrorView* mirror, const TetMesh& mesh,
                                const PlanarFaceIndex& top, const HoleSweep& sweep, const Material& material,
                                FactsInput base, const contact::HoleCuts* cuts = nullptr);

}  // namespace skinfem::validation
