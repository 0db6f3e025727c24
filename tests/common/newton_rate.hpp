// Newton's observed rate on a finite contact's load steps (contact/finite_contact.hpp): checks
// log r_{k+1} / log r_k ≥ `least` over pairs of iterates both made with a settled contact set (no multiplier
// entered or left), r_k below 1e-2 and r_{k+1} above round-off (1e-13); returns how many pairs it checked.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "skinfem/contact/finite_contact.hpp"

namespace skinfem::testing {

inline int check_newton_rate(const std::vector<contact::FiniteContactStep>& steps, double least) {
  int pairs = 0;
  for (const contact::FiniteContactStep& s : steps)
    for (size_t k = 1; k < s.residuals.size(); ++k)
      if (s.set_changes[k - 1] == 0 && s.set_changes[k] == 0 && s.residuals[k - 1] < 1e-2 &&
          s.residuals[k] > 1e-13) {
        EXPECT_GE(std::log(s.residuals[k]) / std::log(s.residuals[k - 1]), least)
            << s.residuals[k - 1] << " -> " << s.residuals[k];
        ++pairs;
      }
  return pairs;
}

}  // namespace skinfem::testing
