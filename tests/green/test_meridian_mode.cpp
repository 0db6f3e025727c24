// One Fourier mode of the meridian (green/meridian_mode.hpp): the top's W compliance returned by the
// factorization as a Schur complement, against the second method it replaces, one solve per node of the
// same mode factored whole; and a factorization with compliance nodes still solves the whole system.
#include <gtest/gtest.h>

#include <vector>

#include "skinfem/green/meridian.hpp"
#include "skinfem/green/meridian_mode.hpp"

namespace skinfem {
namespace {

TEST(MeridianMode, ComplianceFromTheSchurComplementIsTheSolvesOne) {
  // A 3 mm layer to 12 mm, its top nodes within 2 mm of the axis as compliance nodes (the axis node's W is
  // free in mode 0), the base held.
  const MeridianMesh m =
      meridian_mesh([](double) { return 3.0; }, 12.0, MeridianSizes::for_thickness(3.0, 2.0));
  std::vector<int> zone;
  for (int k : m.top)
    if (m.nodes(k, 0) <= 2.0) zone.push_back(k);
  ASSERT_GT(zone.size(), 5u);
  const MeridianMode whole(m, 0, 0.5, 1.0, SideCondition::free, m.base);
  const MeridianMode bordered(m, 0, 0.5, 1.0, SideCondition::free, m.base, zone);
  EXPECT_EQ(whole.compliance().size(), 0);
  ASSERT_EQ(bordered.compliance().rows(), static_cast<Eigen::Index>(zone.size()));
  const int n = static_cast<int>(m.nodes.rows()), nz = static_cast<int>(zone.size());
  MeridianMode::Fields load;
  load.W = Eigen::MatrixXd::Zero(n, nz);
  for (int j = 0; j < nz; ++j) load.W(zone[j], j) = 1.0;
  const MeridianMode::Fields u = whole.solve({}, load, nz);
  Eigen::MatrixXd G(nz, nz);
  for (int i = 0; i < nz; ++i) G.row(i) = u.W.row(zone[i]);
  const double scale = G.cwiseAbs().maxCoeff();
  EXPECT_LT((bordered.compliance() - G).cwiseAbs().maxCoeff(), 1e-10 * scale);
  EXPECT_LT((bordered.compliance() - bordered.compliance().transpose()).cwiseAbs().maxCoeff(), 1e-12 * scale);
  // A load off the compliance nodes (on the top beyond them and inside the layer), through both.
  MeridianMode::Fields other;
  other.U = Eigen::MatrixXd::Zero(n, 1);
  other.W = Eigen::MatrixXd::Zero(n, 1);
  other.W(m.top.back(), 0) = -1.0;
  other.U(n / 2, 0) = 0.5;
  other.W(zone[1], 0) = 2.0;
  const MeridianMode::Fields a = whole.solve({}, other, 1), b = bordered.solve({}, other, 1);
  const double size = a.W.cwiseAbs().maxCoeff() + a.U.cwiseAbs().maxCoeff();
  EXPECT_LT((a.W - b.W).cwiseAbs().maxCoeff(), 1e-10 * size);
  EXPECT_LT((a.U - b.U).cwiseAbs().maxCoeff(), 1e-10 * size);
  EXPECT_LT((a.P - b.P).cwiseAbs().maxCoeff(), 1e-10 * a.P.cwiseAbs().maxCoeff());
}

}  // namespace
}  // namespace skinfem
