// The contact's physics kinds (scene/laws.hpp): every kind has its row, its name reads back as itself, no two
// share a name, and a friction law's parts are what its traction says (p_t = τ0 + μp for mixed, μp for
// Coulomb, τ0 for a shear strength).
#include <gtest/gtest.h>

#include <set>

#include "skinfem/scene/laws.hpp"

namespace skinfem {
namespace {

TEST(Laws, EveryModeNameReadsBackAsItsMode) {
  std::set<std::string> seen;
  for (FrictionMode m :
       {FrictionMode::none, FrictionMode::static_residual, FrictionMode::uncoupled, FrictionMode::coupled}) {
    EXPECT_EQ(kind(m).mode, m);
    EXPECT_EQ(friction_mode_named(to_string(m)), m);
    EXPECT_TRUE(seen.insert(to_string(m)).second) << to_string(m);
  }
  EXPECT_EQ(friction_mode_names().size(), seen.size());
  EXPECT_FALSE(friction_mode_named("kinetic"));
  EXPECT_FALSE(friction_mode_named(""));
}

TEST(Laws, EveryLawNameReadsBackAsItsLaw) {
  for (FrictionLaw l : {FrictionLaw::coulomb, FrictionLaw::shear_strength, FrictionLaw::mixed}) {
    EXPECT_EQ(kind(l).law, l);
    EXPECT_EQ(friction_law_named(to_string(l)), l);
  }
  for (InterfaceLaw l : {InterfaceLaw::hard, InterfaceLaw::linear, InterfaceLaw::exponential}) {
    EXPECT_EQ(kind(l).law, l);
    EXPECT_EQ(interface_law_named(to_string(l)), l);
  }
  EXPECT_EQ(friction_law_names().size(), 3u);
  EXPECT_EQ(interface_law_names().size(), 3u);
  EXPECT_FALSE(friction_law_named("tresca"));
  EXPECT_FALSE(interface_law_named("soft"));
}

// What the solver builds from them (contact/contact_solver.cpp): the frictionless mode has no traction, only
// the static mode is at rest, only the uncoupled mode solves the pressure without it (the paper's
// assumption).
TEST(Laws, ModesSayWhatTheirTractionDoes) {
  EXPECT_FALSE(kind(FrictionMode::none).traction);
  EXPECT_TRUE(kind(FrictionMode::static_residual).at_rest);
  EXPECT_FALSE(kind(FrictionMode::coupled).at_rest);
  EXPECT_FALSE(kind(FrictionMode::uncoupled).coupled);
  EXPECT_TRUE(kind(FrictionMode::coupled).coupled);
}

TEST(Laws, FrictionLawPartsAreTheirTractions) {
  EXPECT_TRUE(kind(FrictionLaw::coulomb).proportional);
  EXPECT_FALSE(kind(FrictionLaw::coulomb).shear_strength);
  EXPECT_FALSE(kind(FrictionLaw::shear_strength).proportional);
  EXPECT_TRUE(kind(FrictionLaw::shear_strength).shear_strength);
  EXPECT_TRUE(kind(FrictionLaw::mixed).proportional && kind(FrictionLaw::mixed).shear_strength);
  // The edge exponents of the closed forms the contact tests converge to (contact/layer_hertz.hpp and
  // contact/layer_hertz_interface.hpp): √(a − r) hard, (a − r) through a linear interface.
  EXPECT_EQ(kind(InterfaceLaw::hard).edge_q, 2);
  EXPECT_EQ(kind(InterfaceLaw::linear).edge_q, 1);
  EXPECT_TRUE(kind(InterfaceLaw::exponential).smooth);
  EXPECT_FALSE(kind(InterfaceLaw::hard).compliant);
}

TEST(Laws, ChoiceListsQuoteOrNot) {
  EXPECT_EQ(choice_list({"a", "b"}), "\"a\", \"b\"");
  EXPECT_EQ(choice_list({"a", "b"}, false), "a, b");
  EXPECT_EQ(choice_list(friction_mode_names()), R"("none", "static", "uncoupled", "coupled")");
}

}  // namespace
}  // namespace skinfem
