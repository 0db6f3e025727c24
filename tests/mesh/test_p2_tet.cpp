// Reference-element building blocks: quadrature exactness and the P2 shape functions.
#include <gtest/gtest.h>

#include <cmath>

#include "skinfem/mesh/p2_tet.hpp"

namespace skinfem {
namespace {

double factorial(int n) { return n <= 1 ? 1.0 : n * factorial(n - 1); }

// ∫ ξ^a η^b ζ^c over the reference tet = a! b! c! / (a + b + c + 3)!
void expect_exact_to_degree(const std::vector<p2::QuadPoint>& rule, int degree) {
  for (int a = 0; a <= degree; ++a)
    for (int b = 0; a + b <= degree; ++b)
      for (int c = 0; a + b + c <= degree; ++c) {
        double sum = 0;
        for (const auto& q : rule)
          sum += q.weight * std::pow(q.xi[0], a) * std::pow(q.xi[1], b) * std::pow(q.xi[2], c);
        EXPECT_NEAR(sum, factorial(a) * factorial(b) * factorial(c) / factorial(a + b + c + 3), 1e-15)
            << "monomial " << a << b << c;
      }
}

TEST(P2Tet, QuadratureRulesAreExactToTheirDegree) {
  expect_exact_to_degree(p2::quadrature_degree2(), 2);
  expect_exact_to_degree(p2::quadrature_degree5(), 5);
}

TEST(P2Tet, ShapeFunctionsAreNodalAndPartitionUnity) {
  const double node_xi[10][3] = {{0, 0, 0},   {1, 0, 0},  {0, 1, 0},  {0, 0, 1},   {.5, 0, 0},
                                 {.5, .5, 0}, {0, .5, 0}, {0, 0, .5}, {.5, 0, .5}, {0, .5, .5}};
  for (int a = 0; a < 10; ++a) {
    const p2::Vec10 n = p2::shape(Eigen::Vector3d(node_xi[a][0], node_xi[a][1], node_xi[a][2]));
    for (int b = 0; b < 10; ++b) EXPECT_NEAR(n[b], a == b ? 1.0 : 0.0, 1e-15);
  }
  // Σ N = 1 and Σ ∇N = 0 anywhere; gradients match central differences.
  const Eigen::Vector3d xi(0.2, 0.3, 0.1);
  EXPECT_NEAR(p2::shape(xi).sum(), 1.0, 1e-15);
  EXPECT_LT(p2::shape_gradient(xi).colwise().sum().norm(), 1e-14);
  for (int k = 0; k < 3; ++k) {
    Eigen::Vector3d d = Eigen::Vector3d::Zero();
    d[k] = 1e-6;
    const p2::Vec10 fd = (p2::shape(xi + d) - p2::shape(xi - d)) / 2e-6;
    EXPECT_LT((fd - p2::shape_gradient(xi).col(k)).norm(), 1e-9);
  }
}

}  // namespace
}  // namespace skinfem
