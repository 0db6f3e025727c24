// Isotropic linear elasticity constants. Units: MPa.
#pragma once

#include <algorithm>

namespace skinfem {

struct Lame {
  double mu = 0;          // shear modulus E / (2(1 + ν))
  double inv_lambda = 0;  // 1/λ = (1 + ν)(1 − 2ν) / (E ν); 0 at ν = 0.5 (incompressible)

  static Lame from(double E, double nu) {
    Lame l;
    l.mu = E / (2 * (1 + nu));
    // ν = 0 has λ = 0 and an infinite 1/λ (the pressure vanishes): cap it at 1e12/μ, a relative
    // perturbation of 1e-12, so that one code path serves 0 ≤ ν ≤ 0.5.
    l.inv_lambda = nu >= 0.5 ? 0.0 : std::min((1 + nu) * (1 - 2 * nu) / (E * nu), 1e12 / l.mu);
    return l;
  }
};

}  // namespace skinfem
