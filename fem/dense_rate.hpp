// The flop rate this machine reaches on a dense Cholesky factorization (Eigen, n = 600, best of 3),
// measured once per process (≈ 0.05 s): the scale for turning a factorization's flop count into an
// estimated time (fem/factor_progress.hpp). Only progress messages use it, never a result.
#pragma once

namespace skinfem {

double dense_flop_rate();  // flop/s

}  // namespace skinfem
