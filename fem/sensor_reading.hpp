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
#include <memory>
#include <vector>

#include "fem/base_traction.hpp"
#include "mesh/tet_mesh.hpp"
#include "scene/scene.hpp"

namespace skinfem {

struct ReadingSite {
  Vec2 center{0, 0};       // mm, on the base
  double diameter = 0;     // mm: the disc the traction is averaged over (0 reads the value at the centre), or
                           // the post's
  double post_height = 0;  // mm; > 0: a post of this height (the mesh must have it), else a disc
  bool post() const { return post_height > 0; }
  // Traits. The reading is unchanged by rotations about the vertical axis through its centre, so on a body
  // of revolution about that axis σ_z is a mode-0 and σ_x a mode-1 meridian problem.
  bool axisymmetric() const { return true; }
  // Its image under y → −y is the same kind of site at (x, −y) reading the same σ_z and σ_x: a site on
  // y = 0 is its own image (pipeline/symmetry.hpp solves such scenes on the half y ≥ 0).
  bool on_mirror_plane() const { return center[1] == 0; }
};

// The sites of a scene's sensors, in their order; point: each disc sensor's centre value instead of its disc
// (a post has no centre value: its site is the post either way).
std::vector<ReadingSite> reading_sites(const Sensors& sensors, bool point = false);

// Sites on one mesh: their weights, factored once for all of them (the base mass matrix).
class SensorReadings {
 public:
  // Keeps a reference to mesh, which must outlive it. Throws std::out_of_range when a site leaves the base.
  SensorReadings(const TetMesh& mesh, std::vector<ReadingSite> sites);
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

 private:
  const TetMesh& mesh_;
  std::vector<ReadingSite> sites_;
  std::unique_ptr<ReadingFunctionals> functional_;
};

}  // namespace skinfem
