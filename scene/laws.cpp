#include "skinfem/scene/laws.hpp"

#include <iterator>

namespace skinfem {

namespace {

const FrictionModeKind kModes[] = {
    {FrictionMode::none, "none", false, false, true},  // frictionless
    // the plate at rest: the law's traction scaled by static_ratio/mu
    {FrictionMode::static_residual, "static", true, true, true},
    // the frictionless pressure, then the sliding traction added (the paper's assumption)
    {FrictionMode::uncoupled, "uncoupled", true, false, false},
    // the sliding traction acting while pressure and zone are solved
    {FrictionMode::coupled, "coupled", true, false, true},
};

const FrictionLawKind kLaws[] = {
    {FrictionLaw::coulomb, "coulomb", true, false},                // p_t = mu p
    {FrictionLaw::shear_strength, "shear_strength", false, true},  // p_t = tau0 wherever the skin touches
    {FrictionLaw::mixed, "mixed", true, true},                     // p_t = tau0 + mu p
};

const InterfaceLawKind kInterfaces[] = {
    {InterfaceLaw::hard, "hard", false, false, 2},              // no interpenetration
    {InterfaceLaw::linear, "linear", true, false, 1},           // p = K max(0, -gap): asperities as springs
    {InterfaceLaw::exponential, "exponential", true, true, 0},  // p = p_ref exp(-gap/u0), any sign of gap
};

template <class Kind, size_t N, class Id>
const Kind& find(const Kind (&table)[N], Id id, Id Kind::*key) {
  for (const Kind& k : table)
    if (k.*key == id) return k;
  return table[0];  // every enumerator has its row: unreachable
}

template <class Kind, size_t N, class Id>
std::optional<Id> named(const Kind (&table)[N], std::string_view name, Id Kind::*key) {
  for (const Kind& k : table)
    if (name == k.name) return k.*key;
  return std::nullopt;
}

template <class Kind, size_t N>
std::vector<std::string> names(const Kind (&table)[N]) {
  std::vector<std::string> out;
  for (const Kind& k : table) out.push_back(k.name);
  return out;
}

}  // namespace

const FrictionModeKind& kind(FrictionMode mode) { return find(kModes, mode, &FrictionModeKind::mode); }
const FrictionLawKind& kind(FrictionLaw law) { return find(kLaws, law, &FrictionLawKind::law); }
const InterfaceLawKind& kind(InterfaceLaw law) { return find(kInterfaces, law, &InterfaceLawKind::law); }

std::optional<FrictionMode> friction_mode_named(std::string_view name) {
  return named(kModes, name, &FrictionModeKind::mode);
}
std::optional<FrictionLaw> friction_law_named(std::string_view name) {
  return named(kLaws, name, &FrictionLawKind::law);
}
std::optional<InterfaceLaw> interface_law_named(std::string_view name) {
  return named(kInterfaces, name, &InterfaceLawKind::law);
}

std::vector<std::string> friction_mode_names() { return names(kModes); }
std::vector<std::string> friction_law_names() { return names(kLaws); }
std::vector<std::string> interface_law_names() { return names(kInterfaces); }

std::string choice_list(const std::vector<std::string>& names, bool quote) {
  const std::string q = quote ? "\"" : "";
  std::string s;
  for (const std::string& n : names) s += (s.empty() ? "" : ", ") + q + n + q;
  return s;
}

double solved_ratio(const ContactLoad& c, FrictionMode mode) {
  const FrictionModeKind& k = kind(mode);
  if (!k.traction || !k.coupled) return 0.0;
  return k.at_rest ? c.static_ratio : c.mu;
}

double coulomb_ratio(const ContactLoad& c, FrictionMode mode) {
  return kind(c.law).proportional ? solved_ratio(c, mode) : 0.0;
}

}  // namespace skinfem
