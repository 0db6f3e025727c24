// The sensor-reading seam: what a sensor measures, as one type that every path asks for its weights — the
// 3D adjoint Green maps (green/fe_green.hpp), the condensed contact's sensor rows (contact/condensed.hpp),
// the forward reading of a solved field, and the meridian path (green/meridian.hpp), which takes a site
// whose traits say it is a body of revolution about its centre.
//
// A reading is a linear functional of the base reactions R (3N vector, N): value = w·R (MPa). By
// Maxwell–Betti its adjoint is the displacement field with the base displaced by −w and no load, so one
// weight vector serves both the forward reading and the Green map (docs/theory.md §Reciprocity).
// Two kinds: the mean base traction over a disc (diameter 0: its centre value), and a post (a rigid cylinder
// standing on the base, bonded to the skin: mesh/surface.hpp's cavity, marked kPost), which reads the force
// on it over its cross-section. Both as σ_z = t_z, σ_x = −t_x with t the traction the support exerts on the
// skin (docs/theory.md §Conventions): the post's w is 1/area on its nodes' reactions, and its adjoint
// displaces the post rigidly with the rest of the base held.
#pragma once

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <memory>
#include <vector>

#include "skinfem/fem/base_traction.hpp"
#include "skinfem/fem/mixed_solver.hpp"
#include "skinfem/mesh/tet_mesh.hpp"
#include "skinfem/scene/scene.hpp"

namespace skinfem {

struct ReadingSite {
  SensorModel model = SensorModel::disc;  // a disc of the base, or a post standing on it
  Vec2 center{0, 0};                      // mm, on the base
  double diameter = 0;     // mm: the disc the traction is averaged over (0 reads the value at the centre), or
                           // the post's
  double post_height = 0;  // mm, a post's (the mesh must have it)
  MembraneSprings support{};  // a post's: rigid, or the springs its gauges read (see SensorReadings)
  bool post() const { return model == SensorModel::post; }
  // Traits. The reading is unchanged by rotations about the vertical axis through its centre, so on a body
  // of revolution about that axis σ_z is a mode-0 and σ_x a mode-1 meridian problem.
  bool axisymmetric() const { return true; }
  // Its image under y → −y is the same kind of site at (x, −y) reading the same σ_z and σ_x: a site on
  // y = 0 is its own image (pipeline/symmetry.hpp solves such scenes on the half y ≥ 0).
  bool on_mirror_plane() const { return center[1] == 0; }
};

// A disc of the base (diameter 0: the value at its centre). A post of height > 0 and diameter > 0
// (std::invalid_argument otherwise): a post of no height is the disc under its outline, disc_site's.
ReadingSite disc_site(Vec2 center, double diameter);
ReadingSite post_site(Vec2 center, double diameter, double height, MembraneSprings support = {});

// The sites of a scene's sensors, in their order; point: each disc sensor's centre value instead of its disc
// (a post has no centre value: its site is the post either way).
std::vector<ReadingSite> reading_sites(const Sensors& sensors, bool point = false);

// Sites on one mesh: their weights, factored once for all of them (the base mass matrix).
//
// Posts on membrane springs. The gauges read the force the springs carry. With every post held, a load
// gives each post's generalized force on the skin P₀ (forces and the moments about its foot's centre: the
// rigid modes x, y, z, tilt about x, tilt about y). Let the posts move by U against springs K_s: the skin
// then feels P₀ + K U, K the skin's stiffness against the posts' rigid motions (all posts together: they
// interact through the skin), and each post's equilibrium is P₀ + K U + K_s U = 0. The springs carry
// K_s U = −K_s (K + K_s)⁻¹ P₀, so the reading is T P₀ with T = K_s (K + K_s)⁻¹: still a linear functional of
// the held posts' reactions, whose weights are T's rows over the rigid modes. K comes from one adjoint
// solve per mode (a post displaced rigidly, everything else held): K_ij = φ_i · R(φ_j).
class SensorReadings {
 public:
  // Keeps a reference to mesh, which must outlive it. Throws std::out_of_range when a site leaves the base.
  // supports: the factored skin, needed when a post stands on springs (std::invalid_argument without it).
  SensorReadings(const TetMesh& mesh, std::vector<ReadingSite> sites, const MixedSolver* supports = nullptr);
  SensorReadings(TetMesh&&, std::vector<ReadingSite>) = delete;
  ~SensorReadings();
  SensorReadings(SensorReadings&&) noexcept;

  int size() const { return static_cast<int>(sites_.size()); }
  const ReadingSite& site(int k) const { return sites_.at(k); }
  // w (3N) of site k's component 'z' (σ_z) or 'x' (σ_x).
  Eigen::VectorXd weights(int k, char component) const;
  // All weights, 3N × 2·size: column 2k is site k's σ_z, 2k + 1 its σ_x.
  Eigen::MatrixXd weight_block() const;
  // The forward reading of site k from a solved field's reactions (3N), w·R.
  SensorReading read(int k, const Eigen::VectorXd& reactions) const;
  // Posts on springs: the skin's stiffness against the posts' rigid modes (K above; N/mm, N, N·mm/rad) and
  // T = K_s (K + K_s)⁻¹, M×M over the modes in order (posts in site order, each x, y, z, tilt x, tilt y; a
  // half post on the mirror plane x, z, tilt y only). Empty for rigid posts.
  const Eigen::MatrixXd& post_stiffness() const { return K_; }
  const Eigen::MatrixXd& spring_transfer() const { return T_; }

 private:
  struct Mode {
    int site;
    char kind;  // 'x', 'y', 'z', 'u' (tilt about x), 'v' (tilt about y)
  };
  struct Post {
    std::vector<int> nodes;  // its wall, top and the outline they share with the base (its foot)
    // By node: on the foot. A node there carries the reaction of the wall and of the base beside it; at the
    // corner the skin's stress is the pressure alone (both faces held), which pushes the wall sideways and
    // the base down. So the foot's tangential reaction is the post's and its normal one the base's: either
    // other way the reading takes in, or leaves out, p × the node's area, an O(h) error (σ_z converged at
    // order 1.2 with the foot wholly the post's); this way the error left is O(h²) (docs/theory.md, "The
    // post's foot").
    std::vector<bool> on_foot;
    bool cut = false;  // a half post on the mirror plane (a half mesh holds half of it)
  };
  Post find_post(int k) const;
  int same_post(int k) const;  // the first site standing for site k's post (a list may name a post twice)
  Eigen::VectorXd mode_vector(const Mode& m) const;  // φ (3N): the rigid mode on its post's nodes
  const TetMesh& mesh_;
  std::vector<ReadingSite> sites_;
  std::vector<Post> posts_;  // by site (empty for a disc), found once
  std::unique_ptr<ReadingFunctionals> functional_;
  std::vector<Mode> modes_;
  std::vector<Eigen::SparseVector<double>> phi_;  // each mode's φ
  Eigen::MatrixXd K_, T_;
};

}  // namespace skinfem
