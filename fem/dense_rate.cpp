#include "skinfem/fem/dense_rate.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Dense>
#include <algorithm>
#include <chrono>

namespace skinfem {

double dense_flop_rate() {
  static const double rate = [] {
    constexpr int n = 600;
    Eigen::MatrixXd A = Eigen::MatrixXd::Identity(n, n) * n;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) A(i, j) += 1.0 / (1 + i + j);  // SPD: Hilbert + n·I
    double best = 1e300;
    for (int rep = 0; rep < 3; ++rep) {
      const auto t0 = std::chrono::steady_clock::now();
      Eigen::LLT<Eigen::MatrixXd> llt(A);
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      if (llt.info() == Eigen::Success) best = std::min(best, s);
    }
    return static_cast<double>(n) * n * n / 3 / std::max(best, 1e-6);
  }();
  return rate;
}

}  // namespace skinfem
