#include "skinfem/fem/neo_hookean.hpp"

#include <cmath>
#include <stdexcept>

namespace skinfem {

NeoHookeanPoint neo_hookean(const Eigen::Matrix3d& F, double p, double mu) {
  NeoHookeanPoint out;
  const double J = F.determinant();
  if (!(J > 0)) throw std::domain_error("neo-Hookean point: det F = " + std::to_string(J) + " (inverted)");
  const Eigen::Matrix3d Finv = F.inverse();
  const Eigen::Matrix3d FinvT = Finv.transpose();
  out.J = J;
  out.energy = 0.5 * mu * (F.squaredNorm() - 3) - mu * std::log(J) - p * (J - 1);
  out.dJ_dF = J * FinvT;
  out.dP_dp = -out.dJ_dF;
  // P = μ F − (μ + pJ) F⁻ᵀ, with ∂(F⁻ᵀ)_iJ/∂F_kL = −F⁻¹_Jk F⁻¹_Li and ∂J/∂F_kL = J F⁻ᵀ_kL.
  out.P = mu * F - (mu + p * J) * FinvT;
  for (int i = 0; i < 3; ++i)
    for (int a = 0; a < 3; ++a)
      for (int k = 0; k < 3; ++k)
        for (int b = 0; b < 3; ++b)
          out.A(3 * i + a, 3 * k + b) = (i == k && a == b ? mu : 0.0) - p * J * FinvT(k, b) * FinvT(i, a) +
                                        (mu + p * J) * Finv(a, k) * Finv(b, i);
  return out;
}

}  // namespace skinfem
