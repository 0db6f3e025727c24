// The report's finite-deformation section (pipeline/finite_deformation.hpp) on a plate sliding over a small
// cap. Reference: the linear skin itself, a second method. The first correction of finite over linear
// elasticity is quadratic in the displacement gradient, so every relative change the section reports
// (finite over linear, same mesh) is of the order of the strain a/R, and must fall with the force as the
// strain does: a ∝ F^(1/3) on a half-space, F^(1/6) on a thin bonded incompressible layer (F ∝ a⁶/(R³h³)),
// so an 8× smaller force divides each change by at least 8^(1/6) = 1.41. A mismatched case, a reading
// scale applied twice or two different meshes would leave a change that does not fall. The zone along the
// tangential load: the finite path's states in order of ratio, ending at the sliding state itself, and the
// linear path ending at the linear sliding contact.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "../common/plate_on_cap.hpp"
#include "skinfem/pipeline/contact_setup.hpp"
#include "skinfem/pipeline/finite_deformation.hpp"
#include "skinfem/validation/text.hpp"

namespace skinfem::pipeline {
namespace {

Scene swept_cap(double force) {
  Scene s = testing::plate_on_cap(6.0, 2.0);
  s.name = "swept_cap";
  s.material.model = MaterialModel::neo_hookean;
  s.sensors.positions = {{0.0, 0.0}, {1.0, 0.0}};
  s.contact->force = force;
  s.contact->static_ratio = 0.3;
  s.contact->friction = FrictionMode::coupled;
  s.contact->sweep = HoleSweep{{-0.4, 0.0}, {0.4, 0.0}, 3, 0.5};
  s.contact->sweep->h = 0.5;
  return s;
}

// The section as the report builds it: the linear skin's defect run, then the finite one beside it.
FiniteDeformation section(const Scene& scene) {
  Scene linear = scene;
  linear.material.model = MaterialModel::linear;
  ContactSkin skin = chain_skin(linear, HolePath::as_scene);
  const std::shared_ptr<const ContactSetup> setup(contact_setup(linear, std::move(skin)));
  return finite_deformation(scene, defect_run(linear, setup), false);  // the scene's law alone
}

// |finite/linear − 1| of the sliding case's indentation, largest pressure, each sensor's σ_z and the
// largest hole amplitude (ς_z of the sensor where the linear one is largest).
std::vector<double> changes(const nlohmann::json& j) {
  const nlohmann::json& c = j.at("cases").at("sliding");
  std::vector<double> out;
  for (const char* key : {"indentation_um", "p_max_kPa"})
    out.push_back(std::abs(c.at("contact").at(key).at("change_rel").get<double>()));
  for (const auto& r : c.at("readings"))
    out.push_back(std::abs(r.at("sigma_z_kPa").at("change_rel").get<double>()));
  double largest = 0, ratio = 1;
  for (const auto& a : c.at("hole_amplitudes"))
    if (a.at("z").at("linear_kPa").get<double>() > largest)
      largest = a.at("z").at("linear_kPa").get<double>(), ratio = a.at("z").at("ratio").get<double>();
  out.push_back(std::abs(ratio - 1));
  return out;
}

TEST(FiniteDeformation, EveryChangeFallsWithTheStrainAsTheForceFalls) {
  const double force = 0.3;
  const Scene full = swept_cap(force), small = swept_cap(force / 8);
  const FiniteDeformation f = section(full), g = section(small);
  EXPECT_TRUE(f.same_mesh);
  EXPECT_TRUE(g.same_mesh);
  const nlohmann::json jf = finite_deformation_json(full, f, nullptr),
                       jg = finite_deformation_json(small, g, nullptr);
  const std::vector<double> a = changes(jf), b = changes(jg);
  ASSERT_EQ(a.size(), b.size());
  const char* names[] = {"indentation", "p_max", "sigma_z #1", "sigma_z #2", "largest hole amplitude"};
  for (size_t i = 0; i < a.size(); ++i) {
    std::printf("%-22s |change| %.3e at %.3g N, %.3e at %.3g N: falls x%.2f (exponent %.2f)\n", names[i],
                a[i], force, b[i], force / 8, a[i] / b[i], std::log(a[i] / b[i]) / std::log(8.0));
    EXPECT_GT(a[i], 0) << names[i];
    EXPECT_GT(a[i] / b[i], std::pow(8.0, 1.0 / 6)) << names[i];
  }
  // The zone along the tangential load: the finite path's states by ratio, ending at the sliding state; the
  // linear path from 0 to μ, ending at the linear sliding contact.
  const double mu = full.contact->mu;
  std::vector<double> ratios;
  for (const FinitePathPoint& p : f.run.path) ratios.push_back(p.ratio);
  const std::vector<double> expected{0.0, full.contact->static_ratio, mu / kSlidingStations,
                                     mu * 2 / kSlidingStations, mu};
  ASSERT_EQ(ratios.size(), expected.size());
  for (size_t i = 0; i < ratios.size(); ++i) EXPECT_NEAR(ratios[i], expected[i], 1e-15) << i;
  const FiniteContactRun& sliding = f.run.cases.at(1).state;
  EXPECT_EQ(f.run.path.back().material.area_mm2, sliding.reference.area_mm2);
  EXPECT_EQ(f.run.path.back().spatial.front_mm, sliding.current.front_mm);
  EXPECT_EQ(f.run.path.back().depth_mm, sliding.result.depth_mm);
  ASSERT_EQ(f.linear_path.size(), static_cast<size_t>(kLinearPathPoints));
  EXPECT_NEAR(f.linear_path.back().ratio, mu, 1e-15);
  EXPECT_NEAR(f.linear_path.back().depth_mm, f.linear[1].depth_mm, 1e-12 * f.linear[1].depth_mm);
  EXPECT_NEAR(f.linear_path.back().tangential_force_N, mu * force, 1e-12 * force);
  // The answer is said from the typed numbers.
  const contact::ContactMetrics &lm = f.linear_metrics[1], &fm = f.run.cases.at(1).metrics;
  const std::string answer = jf.at("answer");
  EXPECT_NE(answer.find(validation::fmt("%+.1f %%", 100 * (fm.contact_radius_mm / lm.contact_radius_mm - 1))),
            std::string::npos)
      << answer;
  EXPECT_NE(answer.find(validation::fmt("%.3f", fm.contact_radius_mm) + " mm"), std::string::npos) << answer;
}

}  // namespace
}  // namespace skinfem::pipeline
