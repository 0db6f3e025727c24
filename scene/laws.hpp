// The contact's physics kinds, each named and described once: the friction mode a contact is solved in, the
// friction law that says what a sliding plate's traction is made of, and the interface law between plate and
// skin (scene.hpp). Scenes, options, sweeps, outputs and the solver read these tables; a new law is a row
// here, plus its own solver code where its terms are new (contact/contact_solver.hpp).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "skinfem/scene/scene.hpp"

namespace skinfem {

// What each mode does with the plate's tangential traction p_t.
struct FrictionModeKind {
  FrictionMode mode;
  const char* name;  // as scenes and --friction spell it
  bool traction;     // p_t acts at all (every mode but none)
  bool at_rest;      // the plate at rest keeps static_ratio/μ of the sliding traction
  bool coupled;      // pressure and zone are solved with p_t acting (all but uncoupled)
};
// A sliding plate's traction p_t = (shear_strength ? τ0 : 0) + (proportional ? μ p : 0).
struct FrictionLawKind {
  FrictionLaw law;
  const char* name;
  bool proportional;    // μ p
  bool shear_strength;  // τ0 wherever the skin touches
};
// How plate and skin close: hard (no interpenetration), or a rough interface with its parameters.
struct InterfaceLawKind {
  InterfaceLaw law;
  const char* name;
  bool compliant;  // the pressure is a function of the gap (not complementarity alone)
  bool smooth;     // p(gap) > 0 at every gap: the whole zone touches, with a tail and no edge
  int edge_q;      // the pressure vanishes at the contact's edge like (a − r)^(1/q); 0: no edge
};

const FrictionModeKind& kind(FrictionMode mode);
const FrictionLawKind& kind(FrictionLaw law);
const InterfaceLawKind& kind(InterfaceLaw law);
// The Coulomb ratio p_t / p a mode applies while the pressure is solved: static_ratio at rest, μ sliding
// (coupled), 0 frictionless or uncoupled (the uncoupled mode's traction comes after the pressure).
double solved_ratio(const ContactLoad& c, FrictionMode mode);
// Its part that is Coulomb's, p_t = ratio·p: 0 under a law without μp (shear_strength).
double coulomb_ratio(const ContactLoad& c, FrictionMode mode);
inline const char* to_string(FrictionMode mode) { return kind(mode).name; }
inline const char* to_string(FrictionLaw law) { return kind(law).name; }
inline const char* to_string(InterfaceLaw law) { return kind(law).name; }

// The kind a name stands for, or nothing.
std::optional<FrictionMode> friction_mode_named(std::string_view name);
std::optional<FrictionLaw> friction_law_named(std::string_view name);
std::optional<InterfaceLaw> interface_law_named(std::string_view name);
// Every name of a kind, in the table's order (for choices and messages).
std::vector<std::string> friction_mode_names();
std::vector<std::string> friction_law_names();
std::vector<std::string> interface_law_names();
// A choice list for a message: "a", "b", "c" (quote), or a, b, c.
std::string choice_list(const std::vector<std::string>& names, bool quote = true);

}  // namespace skinfem
