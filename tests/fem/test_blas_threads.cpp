// The BLAS's thread controls (fem/blas_threads.hpp): making OpenBLAS's idle threads sleep changes no number
// a threaded factorization gives, and leaves a timeout the environment set alone.
#include <dlfcn.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "skinfem/fem/blas_threads.hpp"
#include "skinfem/fem/mumps_ldlt.hpp"

namespace skinfem {
namespace {

// One dense front of order n (n·I plus the Hilbert matrix, SPD, stored sparse): MUMPS factors it with the
// BLAS's dgemm, threaded at this size. Solved with two BLAS threads, against a fixed right-hand side.
Eigen::VectorXd solve_with_two_threads(int n) {
  std::vector<Eigen::Triplet<double>> t;
  for (int j = 0; j < n; ++j)
    for (int i = j; i < n; ++i) t.emplace_back(i, j, (i == j ? n : 0) + 1.0 / (1 + i + j));
  Eigen::SparseMatrix<double> K(n, n);
  K.setFromTriplets(t.begin(), t.end());
  const BlasThreads two(2);
  const MumpsLdlt ldlt(K);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0);
  return ldlt.solve(b);
}

TEST(BlasThreads, SleepingWhenIdleChangesNoNumberAndKeepsTheUsersTimeout) {
  const char* given = std::getenv("OPENBLAS_THREAD_TIMEOUT");
  const std::string users = given ? given : "";
  unsetenv("OPENBLAS_THREAD_TIMEOUT");
  const Eigen::VectorXd before = solve_with_two_threads(600);
  blas_threads_sleep_when_idle();
  // OpenBLAS (which Debian's MUMPS calls through libblas.so.3 by default) takes the shortest timeout;
  // another BLAS is left as it is.
  const bool openblas = dlsym(RTLD_DEFAULT, "openblas_read_env") != nullptr;
  const char* now = std::getenv("OPENBLAS_THREAD_TIMEOUT");
  if (openblas) {
    ASSERT_NE(now, nullptr);
    EXPECT_EQ(std::string(now), "4");
  } else {
    EXPECT_EQ(now, nullptr);
  }
  // The pool, ended by the call, starts again: the same solution to the last bit.
  const Eigen::VectorXd after = solve_with_two_threads(600);
  ASSERT_EQ(after.size(), before.size());
  EXPECT_EQ((after - before).cwiseAbs().maxCoeff(), 0.0);
  // A timeout the environment sets stands.
  setenv("OPENBLAS_THREAD_TIMEOUT", "9", 1);
  blas_threads_sleep_when_idle();
  EXPECT_EQ(std::string(std::getenv("OPENBLAS_THREAD_TIMEOUT")), "9");
  if (given)
    setenv("OPENBLAS_THREAD_TIMEOUT", users.c_str(), 1);
  else
    unsetenv("OPENBLAS_THREAD_TIMEOUT");
}

}  // namespace
}  // namespace skinfem
