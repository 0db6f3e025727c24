// `skinfem contact` as a stage (pipeline/contact.hpp on pipeline/contact_setup.hpp) on a coarse sphere
// pressed into a bonded flat layer, mirror-symmetric (solved on its half). References: equilibrium (every
// mode carries the scene's force, and the tangential force its law gives: 0, static_ratio·F, μF; the base
// of the volume solution carries both back, summed here from its reactions by fem/base_traction.hpp); the
// modes' definitions in contact/contact_solver.hpp (uncoupled keeps the frictionless pressure and adds a
// traction linear in μ, so its change from frictionless at μ₂ is μ₂/μ₁ times the change at μ₁, checked on a
// second condensation of the same factored skin); the condensation by block solves of a plain
// factorization against the scene's own (bordered where MUMPS estimates it cheaper): the same contact;
// summary.json's numbers against the typed ContactRun (units: kPa = 1e3 MPa, µm = 1e3 mm); and the refusals
// (no contact, an unknown friction name, a zone the contact reaches), each naming its field.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <string>

#include "skinfem/fem/base_traction.hpp"
#include "skinfem/pipeline/contact.hpp"

namespace skinfem::pipeline {
namespace {

// The LCP is solved by pivoting (exact up to round-off) and the condensation by direct solves: sums of a few
// hundred multipliers and readings agree to 1e-9 relative (round-off through the condensed compliance's
// condition number on this coarse mesh).
constexpr double kRoundOff = 1e-9;
constexpr double kForce = 0.3, kMu = 0.5, kStatic = 0.1;

Scene sphere_on_layer(double mu = kMu) {
  Scene s;
  s.name = "contact_layer";
  s.source_path = "contact_layer.json";
  s.geometry.kind = GeometryKind::flat;
  s.geometry.flat = {2.0, 5.0};
  s.sensors.positions = {{-1.5, 0}, {0, 0}, {1, 0}};
  s.mesh.h_min = 0.5;
  s.mesh.growth = 1.7;
  s.mesh.h_max = 1.5;
  s.mesh.sensor_h = 0.5;
  ContactLoad c;
  c.indenter = IndenterKind::sphere;
  c.sphere_R = 20;
  c.force = kForce;
  c.zone_radius = 2;
  c.h = 0.35;
  c.mu = mu;
  c.static_ratio = kStatic;
  c.friction = FrictionMode::coupled;
  c.direction = {1, 0};
  s.contact = c;
  return s;
}

class Contact : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    scene_ = new Scene(sphere_on_layer());
    setup_ = std::shared_ptr<const ContactSetup>(contact_setup(*scene_));
    run_ = new ContactRun(contact_run(*scene_, setup_, FrictionMode::coupled));
  }
  static void TearDownTestSuite() {
    delete run_;
    setup_.reset();
    delete scene_;
  }
  static Scene* scene_;
  static std::shared_ptr<const ContactSetup> setup_;
  static ContactRun* run_;
};
Scene* Contact::scene_ = nullptr;
std::shared_ptr<const ContactSetup> Contact::setup_;
ContactRun* Contact::run_ = nullptr;

TEST_F(Contact, EveryModeCarriesTheForceAndTheTangentialForceOfItsLaw) {
  const std::map<FrictionMode, double> ratio = {{FrictionMode::none, 0},
                                                {FrictionMode::static_residual, kStatic},
                                                {FrictionMode::uncoupled, kMu},
                                                {FrictionMode::coupled, kMu}};
  ASSERT_EQ(run_->results.size(), 4u);
  for (const auto& [mode, r] : run_->results) {
    EXPECT_EQ(r.mode, mode);
    EXPECT_NEAR(r.force_N, kForce, kRoundOff * kForce) << to_string(mode);
    EXPECT_NEAR(r.ratio, ratio.at(mode), kRoundOff) << to_string(mode);
    EXPECT_NEAR(r.tangential_force_N, ratio.at(mode) * kForce, kRoundOff * kForce) << to_string(mode);
    EXPECT_GT(r.depth_mm, 0);
    EXPECT_FALSE(r.active.empty());
    // ∫ p dA from the multipliers: λ_i over their hats' areas.
    const Eigen::VectorXd& area = setup_->solver->zone().area;
    EXPECT_NEAR(r.lambda.dot(area), r.force_N, kRoundOff * kForce) << to_string(mode);
  }
  EXPECT_EQ(run_->chosen, FrictionMode::coupled);
  EXPECT_EQ(&run_->result(), &run_->results.at(FrictionMode::coupled));
}

TEST_F(Contact, TheBaseOfTheVolumeSolutionCarriesTheIndentersLoadBack) {
  // The skin is pressed down by F and dragged along +x by μF: the base pushes up by F and back by μF.
  const Eigen::Vector3d base = BaseTraction(setup_->skin->mesh, run_->reactions).total_force();
  // The solved skin is the half: it carries half the load.
  const double part = setup_->whole ? 0.5 : 1.0;
  EXPECT_NEAR(base[2], part * kForce, kRoundOff * kForce);
  EXPECT_NEAR(base[0], -part * kMu * kForce, kRoundOff * kForce);
  // (Along y the half's base is not in equilibrium alone: the cut plane y = 0 carries the other half's σ_yy,
  // whose mirror image cancels it in the whole.)
  // The condensed readings (adjoints) equal the full solve's (reactions), a second method.
  EXPECT_LT(run_->readings_condensed_vs_reactions_rel, kRoundOff);
}

TEST_F(Contact, TheSymmetricSceneIsSolvedOnItsHalf) {
  ASSERT_TRUE(setup_->whole != nullptr);
  EXPECT_TRUE(is_half_y(setup_->skin->mesh));
  EXPECT_EQ(symmetry_used(*scene_, *setup_), "mirror y = 0: the half y >= 0 solved");
  // The whole mesh has the mirrored copy of every node off y = 0: each half node is the source of one or two.
  EXPECT_EQ(setup_->source.size(), static_cast<size_t>(setup_->whole->num_nodes()));
  EXPECT_GT(setup_->whole->num_nodes(), setup_->skin->mesh.num_nodes());
  EXPECT_LT(setup_->whole->num_nodes(), 2 * setup_->skin->mesh.num_nodes());
  EXPECT_EQ(setup_->zone_radius, 2);
  EXPECT_EQ(setup_->zone_h, 0.35);
  for (const char* stage : {"mesh", "assemble", "factor", "condense", "contact_solves", "full_solve"})
    EXPECT_TRUE(run_->wall.contains(stage)) << stage;
}

TEST_F(Contact, UncoupledFrictionAddsATractionLinearInMuToTheFrictionlessContact) {
  const contact::ContactResult& none = run_->results.at(FrictionMode::none);
  const contact::ContactResult& un = run_->results.at(FrictionMode::uncoupled);
  // The uncoupled pressure, zone and approach are the frictionless ones.
  EXPECT_EQ(un.active, none.active);
  EXPECT_LT((un.lambda - none.lambda).cwiseAbs().maxCoeff(), kRoundOff * none.lambda.cwiseAbs().maxCoeff());
  EXPECT_NEAR(un.depth_mm, none.depth_mm, kRoundOff * none.depth_mm);
  // Another μ on a second condensation of the same factored skin: the readings' change is linear in μ.
  const double mu2 = 1.3;
  const Scene other = sphere_on_layer(mu2);
  const auto setup2 = contact_setup(other, setup_->skin);
  const contact::ContactResult un2 = setup2->solver->solve(FrictionMode::uncoupled);
  const contact::ContactResult none2 = setup2->solver->solve(FrictionMode::none);
  const Eigen::VectorXd change = un.readings - none.readings, change2 = un2.readings - none2.readings;
  ASSERT_GT(change.cwiseAbs().maxCoeff(), 0);
  EXPECT_LT((change2 - (mu2 / kMu) * change).cwiseAbs().maxCoeff(),
            kRoundOff * change2.cwiseAbs().maxCoeff());
  EXPECT_LT((none2.readings - none.readings).cwiseAbs().maxCoeff(),
            kRoundOff * none.readings.cwiseAbs().maxCoeff());
}

TEST_F(Contact, TheSummarySaysTheTypedRun) {
  const nlohmann::json j = contact_json(*scene_, *run_);
  const contact::ContactResult& r = run_->result();
  const contact::ContactMetrics& m = run_->metric();
  EXPECT_EQ(j.at("friction"), "coupled");
  EXPECT_EQ(j.at("path"), "3d");
  EXPECT_EQ(j.at("indenter"), "sphere");
  EXPECT_EQ(j.at("force_N").get<double>(), r.force_N);
  EXPECT_NEAR(j.at("indentation_um").get<double>(), 1e3 * r.depth_mm, 1e-12 * 1e3 * r.depth_mm);
  EXPECT_NEAR(j.at("p0_kPa").get<double>(), 1e3 * m.p0_MPa, 1e-12 * 1e3 * m.p0_MPa);
  EXPECT_EQ(j.at("contact_radius_mm").get<double>(), m.contact_radius_mm);
  EXPECT_EQ(j.at("active_multipliers").get<size_t>(), r.active.size());
  EXPECT_NEAR(j.at("max_penetration_um").get<double>(), 1e3 * run_->max_penetration_mm, 1e-9);
  EXPECT_EQ(j.at("symmetry"), symmetry_used(*scene_, *setup_));
  EXPECT_EQ(j.at("dofs").get<int>(), setup_->model->solver().free_dofs());
  EXPECT_EQ(j.at("nodes").get<int>(), setup_->mesh().num_nodes());
  EXPECT_EQ(j.at("zone").at("multipliers").get<int>(), setup_->solver->zone().size());
  EXPECT_EQ(j.at("zone").at("multipliers_solved").get<int>(), setup_->condensed->zone.size());
  for (const auto& [mode, res] : run_->results) {
    const nlohmann::json& jm = j.at("modes").at(to_string(mode));
    EXPECT_EQ(jm.at("force_N").get<double>(), res.force_N);
    EXPECT_EQ(jm.at("contact_radius_mm").get<double>(), run_->metrics.at(mode).contact_radius_mm);
  }
  // Coupled − uncoupled, per sensor in kPa, and the shifts along the sliding direction (+x here).
  const nlohmann::json& cu = j.at("coupled_minus_uncoupled");
  const Eigen::VectorXd& a = run_->results.at(FrictionMode::coupled).readings;
  const Eigen::VectorXd& b = run_->results.at(FrictionMode::uncoupled).readings;
  ASSERT_EQ(cu.at("sensors").size(), scene_->sensors.positions.size());
  for (size_t k = 0; k < scene_->sensors.positions.size(); ++k) {
    const nlohmann::json& s = cu.at("sensors")[k];
    EXPECT_EQ(s.at("sensor").get<size_t>(), k + 1);
    EXPECT_EQ(s.at("x_mm").get<double>(), scene_->sensors.positions[k][0]);
    EXPECT_NEAR(s.at("dsigma_z_kPa").get<double>(), 1e3 * (a[2 * k] - b[2 * k]), 1e-9);
    EXPECT_NEAR(s.at("dsigma_x_kPa").get<double>(), 1e3 * (a[2 * k + 1] - b[2 * k + 1]), 1e-9);
  }
  const contact::ContactMetrics &mc = run_->metrics.at(FrictionMode::coupled),
                                &mu = run_->metrics.at(FrictionMode::uncoupled);
  EXPECT_EQ(cu.at("pressure_centroid_shift_mm").get<double>(),
            mc.pressure_centroid[0] - mu.pressure_centroid[0]);
  EXPECT_EQ(cu.at("zone_centroid_shift_mm").get<double>(), mc.zone_centroid[0] - mu.zone_centroid[0]);
  EXPECT_EQ(cu.at("mu").get<double>(), kMu);
}

TEST_F(Contact, TheCondensationSaysHowItWasMade) {
  // Block solves of a plain factorization, or the bordered factorization's Schur complement (no solve).
  const nlohmann::json j = condensation_json(*setup_);
  const int rhs = setup_->condensed->block_solves;
  EXPECT_EQ(j.at("block_solves").get<int>(), rhs);
  EXPECT_EQ(j.at("method"), rhs > 0 ? "block solves" : "bordered factorization");
  const std::string said = condensation_said(*setup_);
  EXPECT_TRUE(said.rfind(rhs > 0 ? std::to_string(rhs) + " rhs" : "from a bordered factorization", 0) == 0)
      << said;
  const auto& choice = setup_->model->solver().border_choice();
  EXPECT_EQ(j.contains("choice"), choice.has_value());
  if (choice) {
    EXPECT_EQ(j.at("choice").at("bordered").get<bool>(), choice->bordered);
    EXPECT_EQ(choice->bordered, rhs == 0);  // the choice made is the one used
    EXPECT_EQ(j.at("choice").at("plain_factor_flops").get<double>(), choice->plain_flops);
  }
  // A skin given already factored, plain, is condensed by block solves: one per condensed column.
  const auto plain = contact_setup(*scene_, skin_setup(*scene_, MeshPart::half_y));
  EXPECT_GT(plain->condensed->block_solves, 0);
  EXPECT_EQ(condensation_json(*plain).at("method"), "block solves");
  EXPECT_EQ(condensation_said(*plain).rfind(std::to_string(plain->condensed->block_solves) + " rhs", 0), 0u);
  // The same contact either way: the condensations agree to round-off.
  const contact::ContactResult a = plain->solver->solve(FrictionMode::coupled);
  const contact::ContactResult& b = run_->results.at(FrictionMode::coupled);
  EXPECT_NEAR(a.depth_mm, b.depth_mm, kRoundOff * b.depth_mm);
  EXPECT_LT((a.readings - b.readings).cwiseAbs().maxCoeff(), kRoundOff * b.readings.cwiseAbs().maxCoeff());
}

TEST_F(Contact, FrictionModesAreNamedAsTheCommandLineNamesThem) {
  EXPECT_EQ(friction_mode_named(*scene_, ""), FrictionMode::coupled);  // the scene's
  EXPECT_EQ(friction_mode_named(*scene_, "scene"), FrictionMode::coupled);
  EXPECT_EQ(friction_mode_named(*scene_, "none"), FrictionMode::none);
  EXPECT_EQ(friction_mode_named(*scene_, "static"), FrictionMode::static_residual);
  EXPECT_EQ(friction_mode_named(*scene_, "uncoupled"), FrictionMode::uncoupled);
  EXPECT_EQ(friction_mode_named(*scene_, "coupled"), FrictionMode::coupled);
  try {
    friction_mode_named(*scene_, "sticky");
    ADD_FAILURE() << "'sticky' accepted";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("sticky"), std::string::npos) << e.what();
  }
}

TEST_F(Contact, AContactReachingTheZonesEdgeIsRefusedNamingTheZone) {
  // The same force in a zone smaller than the contact: the active set reaches its outer ring.
  Scene small = sphere_on_layer();
  small.contact->zone_radius = 0.7;
  const auto setup = std::shared_ptr<const ContactSetup>(contact_setup(small, setup_->skin));
  try {
    contact_run(small, setup, FrictionMode::none);
    ADD_FAILURE() << "a contact cut short by its zone was accepted";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("contact.zone_radius"), std::string::npos) << e.what();
  }
}

TEST_F(Contact, AStageWithoutAContactSectionSaysSo) {
  Scene s = sphere_on_layer();
  s.contact.reset();
  for (const auto& call : {std::function<void()>([&] { require_contact(s); }),
                           std::function<void()>([&] { friction_mode_named(s, "none"); }),
                           std::function<void()>([&] { contact_skin(s); })}) {
    try {
      call();
      ADD_FAILURE() << "a scene without a contact was accepted";
    } catch (const SceneError& e) {
      EXPECT_NE(std::string(e.what()).find("contact: missing"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace skinfem::pipeline
