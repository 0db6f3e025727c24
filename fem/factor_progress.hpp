// Progress of a long sparse factorization, reported from a watcher thread while MUMPS factors: seconds
// elapsed and the estimated fraction done, the analysis's flop count (RINFOG(1)) over a dense-kernel rate
// measured on this machine (fem/dense_rate.hpp). MUMPS has no progress hook, so the fraction is an estimate;
// it is capped below 1 until the factorization returns.
#pragma once

#include <functional>

namespace skinfem {

struct FactorStatus {
  double fraction = 0;         // estimated, in [0, 0.99] while running, 1 when done
  double elapsed_s = 0;        // since the factorization phase began
  double estimated_flops = 0;  // from the analysis
  double estimated_s = 0;      // from estimated_flops and the unknowns at the measured dense rate
};

using FactorProgress = std::function<void(const FactorStatus&)>;

}  // namespace skinfem
