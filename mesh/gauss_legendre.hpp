// Gauss–Legendre rules on [0, 1]: n points, exact for polynomials of degree ≤ 2n − 1.
#pragma once

#include <array>
#include <vector>

namespace skinfem {

struct GaussRule1d {
  std::vector<double> x, w;  // nodes in (0, 1), weights summing to 1
};

// Newton on the Legendre recurrence from Chebyshev-like initial guesses; nodes to 1e-15.
GaussRule1d gauss_legendre01(int n);

// Mean over a disc of the given radius: nr Gauss radii × nt uniform angles, points (dx, dy, weight)
// about the centre, weights summing to 1 (∫∫ f r dr dθ / (πa²)).
std::vector<std::array<double, 3>> uniform_disc_rule(double radius, int nr, int nt);

}  // namespace skinfem
