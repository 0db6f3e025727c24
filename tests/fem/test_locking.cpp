// Rung 3 of the verification ladder (docs/theory.md §Elements): ν → 0.5 continuity of the Taylor–Hood P2–P1
// solution (no locking), contrasted with a pure-displacement P1 solve of the same problem, which does lock.
#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>
#include <cmath>
#include <cstdio>
#include <map>
#include <vector>

#include "fixtures.hpp"
#include "skinfem/fem/assembly.hpp"
#include "skinfem/fem/elastic_model.hpp"
#include "skinfem/mesh/surface_quadrature.hpp"

namespace skinfem {
namespace {

using testing::box_mesh;

constexpr double kE = 3.0;      // MPa
constexpr double kThick = 1.5;  // mm, layer thickness
constexpr double kHalf = 3.0;   // mm, half-width of the layer
constexpr double kSize = 0.5;   // mm, target element size
constexpr double kBump = 1.5;   // mm, radius of the pressure bump
constexpr double kForce = 1.0;  // N, total downward force of the bump

// Smooth (C¹) pressure bump q(r) = q₀ (1 − r²/a²)² on r < a, pressing down on the top surface.
// ∫ q dA = q₀ π a² / 3, so q₀ = 3F / (π a²) puts a total force F on the skin.
Eigen::Vector3d bump_traction(const Eigen::Vector3d& x, const Eigen::Vector3d&) {
  const double s = 1.0 - (x.x() * x.x() + x.y() * x.y()) / (kBump * kBump);
  const double q0 = 3.0 * kForce / (M_PI * kBump * kBump);
  return Eigen::Vector3d(0, 0, s > 0 ? -q0 * s * s : 0.0);
}

const TetMesh& layer() {
  static const TetMesh m = box_mesh(kThick, kHalf, kSize);
  return m;
}

// Taylor–Hood solve through ElasticModel on layer(): base bonded, sides free, the bump on the top.
// Cached per ν (each costs one factorization).
const MixedSolution& solve_mixed(double nu) {
  static std::map<double, MixedSolution> cache;
  auto it = cache.find(nu);
  if (it == cache.end()) {
    const ElasticModel model(layer(), Material{kE, nu}, SideCondition::free, {});
    it = cache.emplace(nu, model.solve(traction_load(layer(), kTop, bump_traction), {}).solution).first;
  }
  return it->second;
}

// Consistent P1 load: the same traction integrated against the P1 hat functions of the top faces
// with the same face rule. Written in the P2 face basis, L_i = N_i + ½ Σ_{edges e ∋ i} N_e (P1 ⊂ P2,
// edge nodes 3: 01, 4: 12, 5: 20), so both loads carry exactly the same total force Σ_q w_q t(x_q).
Eigen::VectorXd p1_load(const TetMesh& m) {
  Eigen::VectorXd F = Eigen::VectorXd::Zero(3 * m.num_vertices);
  for (int f = 0; f < m.faces.rows(); ++f) {
    if (!(m.face_marker(f) & kTop)) continue;
    for (const auto& q : face_quadrature(m, f)) {
      const double L[3] = {q.N[0] + 0.5 * (q.N[3] + q.N[5]), q.N[1] + 0.5 * (q.N[3] + q.N[4]),
                           q.N[2] + 0.5 * (q.N[4] + q.N[5])};
      const Eigen::Vector3d t = bump_traction(q.x, q.normal);
      for (int a = 0; a < 3; ++a) F.segment<3>(3 * m.faces(f, a)) += q.weight * L[a] * t;
    }
  }
  return F;
}

// Pure-displacement linear tetrahedra on the corner nodes: K = ∫ 2μ ε(u):ε(v) + λ div u div v, one
// constant gradient per element; base vertices fixed; SimplicialLDLT on the free block. Returns 3·Nv.
Eigen::VectorXd solve_p1(const TetMesh& m, double nu) {
  const Lame lame = Lame::from(kE, nu);
  const double mu = lame.mu, lambda = 1.0 / lame.inv_lambda;  // ν < 0.5 only
  const int nv = m.num_vertices;
  std::vector<int> index(3 * nv, -1);
  int nfree = 0;
  for (int i = 0; i < nv; ++i)
    if (!(m.node_marker(i) & kBase))
      for (int c = 0; c < 3; ++c) index[3 * i + c] = nfree++;
  std::vector<Eigen::Triplet<double>> trip;
  for (int t = 0; t < m.num_tets(); ++t) {
    Eigen::Matrix3d D;  // columns x_k − x_0
    for (int k = 0; k < 3; ++k)
      D.col(k) = (m.nodes.row(m.tets(t, k + 1)) - m.nodes.row(m.tets(t, 0))).transpose();
    const double vol = D.determinant() / 6.0;
    Eigen::Matrix<double, 4, 3> G;  // ∇λ_a, rows
    G.bottomRows<3>() = D.inverse();
    G.row(0) = -G.bottomRows<3>().colwise().sum();
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) {
            const int r = index[3 * m.tets(t, a) + i], c = index[3 * m.tets(t, b) + j];
            if (r < 0 || c < 0) continue;
            // 2μ ε(λ_a e_i):ε(λ_b e_j) = μ(δ_ij ∇λ_a·∇λ_b + ∂_jλ_a ∂_iλ_b); div: ∂_iλ_a ∂_jλ_b
            const double k = mu * ((i == j ? G.row(a).dot(G.row(b)) : 0.0) + G(a, j) * G(b, i)) +
                             lambda * G(a, i) * G(b, j);
            trip.emplace_back(r, c, vol * k);
          }
  }
  SparseMatrixd K(nfree, nfree);
  K.setFromTriplets(trip.begin(), trip.end());
  const Eigen::VectorXd F = p1_load(m);
  Eigen::VectorXd f(nfree);
  for (int d = 0; d < 3 * nv; ++d)
    if (index[d] >= 0) f[index[d]] = F[d];
  Eigen::SimplicialLDLT<SparseMatrixd> ldlt(K);
  EXPECT_EQ(ldlt.info(), Eigen::Success);
  const Eigen::VectorXd x = ldlt.solve(f);
  EXPECT_LT((K * x - f).norm(), 1e-10 * f.norm());
  Eigen::VectorXd u = Eigen::VectorXd::Zero(3 * nv);
  for (int d = 0; d < 3 * nv; ++d)
    if (index[d] >= 0) u[d] = x[index[d]];
  return u;
}

// Largest |u| over the top-surface vertices: the same point set for the P1 and the P2 fields.
double top_max(const TetMesh& m, const Eigen::VectorXd& u) {
  double best = 0;
  for (int i = 0; i < m.num_vertices; ++i)
    if (m.node_marker(i) & kTop) best = std::max(best, u.segment<3>(3 * i).norm());
  return best;
}

TEST(Locking, MixedSolutionIsContinuousAsNuTendsToOneHalf) {
  // Reference: the continuous problem. Its solution is analytic in (μ, 1/λ) at 1/λ = 0 (the
  // incompressible limit is a regular perturbation: σ = 2με − pI, div u + p/λ = 0), and so is the
  // Taylor–Hood one, whose saddle-point operator stays uniformly invertible (discrete inf-sup) when
  // the −(1/λ)M_p block is added. From ν = 0.5 to 0.49999: μ/λ = (1 − 2ν)/(2ν) = 2e-5 and μ changes
  // by 1e-5/1.5 ≈ 7e-6 relative, so u and p move by C·2e-5 relative. C is O(1) here because the
  // load radius is comparable to the thickness (it grows like (radius/thickness)² only for thin,
  // confined layers); 1e-4 allows C ≤ 5. A locking element would instead change by O(1).
  const TetMesh& m = layer();
  const MixedSolution a = solve_mixed(0.5), b = solve_mixed(0.49999);
  const double du = (a.u - b.u).norm() / a.u.norm(), dp = (a.p - b.p).norm() / a.p.norm();
  std::printf("mixed nu 0.5 vs 0.49999: |du|/|u| %.3e, |dp|/|p| %.3e, top max %.5e vs %.5e mm\n", du, dp,
              top_max(m, a.u), top_max(m, b.u));
  EXPECT_LT(du, 1e-4);
  EXPECT_LT(dp, 1e-4);
}

TEST(Locking, PureDisplacementP1LocksNearIncompressibilityAndMixedDoesNot) {
  // Reference: locking theory (Babuška–Suri). At ν = 0.49999, λ/μ = 2ν/(1 − 2ν) ≈ 5e4, so the
  // energy is minimised only by fields with div u ≈ 0 in every element. Continuous P1 has one
  // constant divergence per tet and about 5–6 tets per vertex (3 DOFs per vertex): the constraints
  // outnumber the free DOFs and nearly only u ≈ 0 satisfies them, so the P1 surface deflection is a
  // small fraction of the true one (and the gap does not close with λ/μ → ∞). Taylor–Hood imposes
  // div u = 0 only against P1 pressures (one constraint per vertex) and is inf-sup stable.
  const TetMesh& m = layer();
  const double mixed = top_max(m, solve_mixed(0.49999).u);
  const double p1 = top_max(m, solve_p1(m, 0.49999));
  std::printf("nu 0.49999: top max mixed %.5e mm, P1 %.5e mm, ratio %.3f\n", mixed, p1, p1 / mixed);
  EXPECT_LT(p1, 0.5 * mixed);
  EXPECT_GT(p1, 0.0);
}

TEST(Locking, PureDisplacementP1IsFineAtModerateNu) {
  // Control: the same P1 code at ν = 0.3 (λ/μ = 1.5) is merely a coarse conforming method. Its
  // energy error is O(h |u|₂), so its compliance (and peak deflection) falls short by O((h/ℓ)²) with
  // ℓ = 1.5 mm the scale of the load and of the layer and h ≈ 0.5 mm: ~10 %, times an O(1) constant.
  // 30 % is a loose bound on that, far from the locked ratio above: the contrast is locking, not
  // a wrong P1 stiffness or load. P1 is conforming and so stiffer than the exact solution (and than the
  // O(h²)-accurate P2 one): it must also not exceed the mixed deflection by more than that.
  const TetMesh& m = layer();
  const double mixed = top_max(m, solve_mixed(0.3).u);
  const double p1 = top_max(m, solve_p1(m, 0.3));
  std::printf("nu 0.3: top max mixed %.5e mm, P1 %.5e mm, ratio %.3f\n", mixed, p1, p1 / mixed);
  EXPECT_NEAR(p1 / mixed, 1.0, 0.3);
}

TEST(Locking, P1AndP2LoadsCarryTheSameForce) {
  // Reference: both loads integrate the same traction with the same face rule, and the P1 hats and
  // the P2 face functions are both partitions of unity, so Σ_i f1_i = Σ_a f2_a = Σ_q w_q t(x_q) to
  // round-off: the two discretizations see the same applied force (locking is not a load artefact).
  const TetMesh& m = layer();
  const Eigen::VectorXd f2 = traction_load(m, kTop, bump_traction), f1 = p1_load(m);
  for (int c = 0; c < 3; ++c) {
    double s1 = 0, s2 = 0;
    for (int i = 0; i < m.num_vertices; ++i) s1 += f1[3 * i + c];
    for (int i = 0; i < m.num_nodes(); ++i) s2 += f2[3 * i + c];
    EXPECT_NEAR(s1, s2, 1e-13 * kForce) << "component " << c;
  }
}

}  // namespace
}  // namespace skinfem
