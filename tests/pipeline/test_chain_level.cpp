// The chain's levels and error bars (pipeline/chain_level.hpp). References: synthetic levels built here from
// closed forms, Q(s) = Q∞ + C sᵖ (Richardson must return p and Q∞; an order above kMaxPlausibleOrder or
// differences that change sign must fall back to the last change), and stage times t = c·DOFsᵉ (the fitted
// exponent must be e); the JSON and the display bars against the typed ChainError they are built from (unit
// factors kPa = 1e3 MPa, µm = 1e3 mm); check_error_scales against scene.hpp's rule (none, or ≥ 2 scales in
// (1, kMaxErrorScale]); and chain_level on a coarse flat layer against a second path, kfit on the same
// scaled scene (pipeline/kfit.hpp: its own set-up, scan and fit), which must give the same k.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "skinfem/mesh/sizing.hpp"
#include "skinfem/pipeline/chain_level.hpp"
#include "skinfem/pipeline/kfit.hpp"
#include "skinfem/pipeline/scene_json.hpp"

namespace skinfem::pipeline {
namespace {

// Richardson's order is found by bisection to 1e-14 relative (validation/richardson.cpp); its effect on the
// limit, through sᵖ ln s with s ≤ 2, stays far below this.
constexpr double kBisection = 1e-10;
constexpr double kRoundOff = 1e-12;  // relative, a few floating-point operations

bool has(const std::string& text, const std::string& what) { return text.find(what) != std::string::npos; }

// Levels at the given scales, coarse to fine, each quantity q_i(s) given.
struct Quantity {
  std::string name;
  double (*q)(double s);
};
std::vector<ChainLevel> levels(const std::vector<double>& scales, const std::vector<Quantity>& qs) {
  std::vector<ChainLevel> out;
  for (double s : scales) {
    ChainLevel l;
    l.scale = s;
    l.dofs = static_cast<int>(1000 / (s * s * s));
    for (const Quantity& q : qs) {
      l.names.push_back(q.name);
      l.value.push_back(q.q(s));
      l.seconds.push_back(1);
    }
    out.push_back(l);
  }
  return out;
}

double second_order(double s) { return 0.8 + 0.1 * s * s; }               // Q∞ = 0.8, p = 2
double sixth_order(double s) { return 2e-3 + 1e-5 * std::pow(s, 6); }     // p = 6 > kMaxPlausibleOrder
double oscillating(double s) { return s == 1 ? 1.5 : (s == 2 ? 1 : 2); }  // differences −1, then +0.5

TEST(ChainLevel, RichardsonRecoversTheOrderAndLimitOfASecondOrderQuantity) {
  // A first, much coarser level that does not follow the law: only the three finest count.
  std::vector<ChainLevel> l = levels({3, 2, 1.5, 1}, {{"k_central", second_order}});
  l[0].value[0] = 1e3;
  const std::vector<ChainError> e = chain_errors(l);
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0].name, "k_central");
  EXPECT_TRUE(e[0].asymptotic);
  EXPECT_EQ(e[0].why_not, "");
  EXPECT_NEAR(e[0].order, 2, kBisection);
  EXPECT_NEAR(e[0].reference, 0.8, kBisection);
  EXPECT_EQ(e[0].value, second_order(1));
  EXPECT_NEAR(e[0].error, 0.1, kBisection);  // |Q(1) − Q∞| = C
}

TEST(ChainLevel, AnImplausibleOrderOrASignChangeGivesTheLastChange) {
  const std::vector<ChainError> e =
      chain_errors(levels({2, 1.5, 1}, {{"contact_p0", sixth_order}, {"indentation", oscillating}}));
  ASSERT_EQ(e.size(), 2u);
  // Order 6: found, but above the plausible 4, so not asymptotic; the error is |Q₃ − Q₂|, the reference
  // the finest value.
  EXPECT_FALSE(e[0].asymptotic);
  EXPECT_NEAR(e[0].order, 6, 1e-9);
  EXPECT_TRUE(has(e[0].why_not, "observed order 6.00 above 4")) << e[0].why_not;
  EXPECT_NEAR(e[0].error, sixth_order(1.5) - sixth_order(1), kRoundOff * sixth_order(1.5));
  EXPECT_EQ(e[0].reference, sixth_order(1));
  // Differences of opposite signs: no order at all.
  EXPECT_FALSE(e[1].asymptotic);
  EXPECT_EQ(e[1].order, 0);
  EXPECT_EQ(e[1].why_not, "differences change sign or grow");
  EXPECT_EQ(e[1].error, 0.5);
  EXPECT_EQ(e[1].reference, 1.5);
}

TEST(ChainLevel, FewerThanThreeLevelsAreRefused) {
  EXPECT_THROW(chain_errors(levels({2, 1}, {{"k_central", second_order}})), std::invalid_argument);
}

TEST(ChainLevel, ErrorScalesAreNoneOrAtLeastTwoCoarserWithinTheLimit) {
  EXPECT_NO_THROW(check_error_scales({}));
  EXPECT_NO_THROW(check_error_scales({2, 1.41}));
  EXPECT_NO_THROW(check_error_scales({kMaxErrorScale, 2, 1.5}));
  EXPECT_THROW(check_error_scales({2}), SceneError);  // Richardson needs two
  EXPECT_THROW(check_error_scales({2, 1}), SceneError);
  EXPECT_THROW(check_error_scales({2, 0.5}), SceneError);
  EXPECT_THROW(check_error_scales({2, std::nan("")}), SceneError);
  EXPECT_THROW(check_error_scales({kMaxErrorScale * 1.01, 2}), SceneError);
  try {
    check_error_scales({3, 0.7});
    ADD_FAILURE() << "0.7 accepted";
  } catch (const SceneError& e) {
    EXPECT_TRUE(has(e.what(), "--error-scales: 0.7")) << e.what();
  }
}

TEST(ChainLevel, TimeExponentsAreThePowerLawsOfTheStagesTimedOnTwoLevelsOrMore) {
  std::vector<ChainLevel> l(3);
  const int dofs[] = {1000, 4000, 16000};
  for (int i = 0; i < 3; ++i) {
    l[i].dofs = dofs[i];
    l[i].wall["factor"] = 1e-6 * std::pow(dofs[i], 1.5);
    if (i > 0) l[i].wall["mesh"] = 0.01 * dofs[i];  // two levels: still a fit
  }
  l[2].wall["condense"] = 1;  // one level: no fit, left out
  l[0].wall["sweep"] = 1;     // not timed on the finest level: not a stage of the chain's
  l[1].wall["sweep"] = 2;
  const std::map<std::string, double> e = time_vs_dofs_exponent(l);
  EXPECT_EQ(e.size(), 2u);
  EXPECT_NEAR(e.at("factor"), 1.5, kRoundOff);
  EXPECT_NEAR(e.at("mesh"), 1.0, kRoundOff);
  EXPECT_EQ(e.count("condense"), 0u);
  EXPECT_EQ(e.count("sweep"), 0u);
}

TEST(ChainLevel, TheStudyJsonSaysTheLevelsAndTheirExtrapolation) {
  Scene scene;
  scene.name = "synthetic";
  std::vector<ChainLevel> l =
      levels({2, 1.5, 1}, {{"k_central", second_order}, {"indentation", oscillating}});
  l[1].note = "capped";
  for (ChainLevel& c : l) c.wall["factor"] = 1e-3 * c.dofs;
  const nlohmann::json j = chain_study_json(scene, l);
  EXPECT_EQ(j.at("scene"), scene_json(scene));
  ASSERT_EQ(j.at("levels").size(), 3u);
  for (size_t i = 0; i < 3; ++i) {
    const nlohmann::json& jl = j.at("levels")[i];
    EXPECT_EQ(jl.at("scale").get<double>(), l[i].scale);
    EXPECT_EQ(jl.at("dofs").get<int>(), l[i].dofs);
    EXPECT_EQ(jl.at("values").at("k_central").get<double>(), l[i].value[0]);
    EXPECT_EQ(jl.at("values").at("indentation").get<double>(), l[i].value[1]);
    EXPECT_EQ(jl.at("wall_s").at("factor").get<double>(), l[i].wall.at("factor"));
    EXPECT_EQ(jl.contains("note"), i == 1);
  }
  const std::vector<ChainError> e = chain_errors(l);
  const nlohmann::json& k = j.at("extrapolation").at("k_central");
  EXPECT_EQ(k.at("observed_order").get<double>(), e[0].order);
  EXPECT_EQ(k.at("reference").get<double>(), e[0].reference);
  EXPECT_EQ(k.at("reference_is"), "Richardson limit");
  const nlohmann::json& d = j.at("extrapolation").at("indentation");
  EXPECT_EQ(d.at("observed_order"), "none: differences change sign or grow");
  EXPECT_EQ(d.at("reference").get<double>(), 1.5);
  EXPECT_EQ(d.at("reference_is"), "finest level");
  // The factor's seconds are 1e-3 × DOFs on every level: exponent 1 up to the DOFs' rounding to integers.
  EXPECT_NEAR(j.at("time_vs_dofs_exponent").at("factor").get<double>(), 1.0, kRoundOff);
}

TEST(ChainLevel, ErrorBarsAreInDisplayUnitsWithTheirMethod) {
  const std::vector<ChainError> e = chain_errors(levels({2, 1.5, 1}, {{"k_central", second_order},
                                                                      {"contact_p0", sixth_order},
                                                                      {"indentation", oscillating},
                                                                      {"other", second_order}}));
  const std::vector<ErrorBar> bars = error_bars(e, {2, 1.5});
  ASSERT_EQ(bars.size(), 3u);  // "other" has no display row
  EXPECT_EQ(bars[0].quantity, "k_central");
  EXPECT_EQ(bars[0].unit, "");
  EXPECT_EQ(bars[0].value, e[0].value);
  EXPECT_EQ(bars[0].error, e[0].error);
  EXPECT_TRUE(has(bars[0].method, "Richardson limit| over mesh scales 2, 1.5, 1")) << bars[0].method;
  EXPECT_TRUE(has(bars[0].method, "observed order 2.00")) << bars[0].method;
  EXPECT_EQ(bars[1].quantity, "contact_p0");
  EXPECT_EQ(bars[1].unit, "kPa");
  EXPECT_NEAR(bars[1].value, 1e3 * e[1].value, kRoundOff * 1e3 * e[1].value);
  EXPECT_NEAR(bars[1].error, 1e3 * e[1].error, kRoundOff * 1e3 * e[1].error);
  EXPECT_TRUE(has(bars[1].method, "last change between mesh scales 1.5 and 1")) << bars[1].method;
  EXPECT_TRUE(has(bars[1].method, e[1].why_not)) << bars[1].method;
  EXPECT_EQ(bars[2].unit, "um");
  EXPECT_NEAR(bars[2].value, 1500, kRoundOff * 1500);
  EXPECT_NEAR(bars[2].error, 500, kRoundOff * 500);
  // The relative error is unit-free: the same in display and SI units.
  for (size_t i = 0; i < bars.size(); ++i)
    EXPECT_NEAR(bars[i].relative_error, bars[i].error / std::abs(bars[i].value), kRoundOff);
  const nlohmann::json j = error_bars_json(bars);
  ASSERT_EQ(j.size(), bars.size());
  for (size_t i = 0; i < bars.size(); ++i) {
    EXPECT_EQ(j[i].at("quantity"), bars[i].quantity);
    EXPECT_EQ(j[i].at("what"), bars[i].what);
    EXPECT_EQ(j[i].at("unit"), bars[i].unit);
    EXPECT_EQ(j[i].at("value").get<double>(), bars[i].value);
    EXPECT_EQ(j[i].at("error").get<double>(), bars[i].error);
    EXPECT_EQ(j[i].at("relative_error").get<double>(), bars[i].relative_error);
    EXPECT_EQ(j[i].at("method"), bars[i].method);
  }
}

// A coarse flat layer, no contact: the chain's k at a level is kfit's on the same scaled scene.
Scene coarse_layer() {
  Scene s;
  s.name = "coarse_layer";
  s.geometry.kind = GeometryKind::flat;
  s.geometry.flat = {3.04, 13.0};
  s.sensors.positions = {{0, 0}};
  s.mesh.h_min = 0.6;
  s.mesh.growth = 1.7;
  s.mesh.h_max = 3.0;
  s.calibration.spacing = 0.2;
  return s;
}

TEST(ChainLevel, ALevelsKIsKfitsOnTheSameScaledScene) {
  const Scene base = coarse_layer();
  const double scale = 1.5;
  const ChainLevel l = chain_level(base, scale);
  EXPECT_EQ(l.scale, scale);
  EXPECT_EQ(l.note, "");
  ASSERT_EQ(l.names, (std::vector<std::string>{"k_central", "k_lsq_line"}));  // no contact
  EXPECT_GT(l.dofs, 0);
  EXPECT_TRUE(l.wall.contains("factor"));

  const Scene scaled = scaled_scene(base, scale);
  const auto adj = adjoint_setup(scaled);
  const KfitResult k = kfit(scaled, sensor_greens(scaled, *adj), green::LayerLoad::punch, nullptr, false);
  EXPECT_EQ(adj->model->solver().free_dofs(), l.dofs);  // the same mesh: TetGen is deterministic
  ASSERT_FALSE(k.sensors.empty());
  EXPECT_NEAR(l.value[0], k.sensors[0].fe.k_central, kRoundOff * k.sensors[0].fe.k_central);
  EXPECT_NEAR(l.value[1], k.sensors[0].fe.k_lsq_line, kRoundOff * k.sensors[0].fe.k_lsq_line);
}

}  // namespace
}  // namespace skinfem::pipeline
