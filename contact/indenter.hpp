// The rigid indenter's lower surface over the (x, y) plane: z = z_touch − depth + φ(x, y), with z_touch
// the height at which it first touches the undeformed skin (scene.hpp, ContactLoad).
#pragma once

#include "skinfem/mesh/tet_mesh.hpp"
#include "skinfem/scene/scene.hpp"

namespace skinfem::contact {

class Indenter {
 public:
  // z_touch: the largest s(x, y) − φ(x, y) over the skin's top nodes and the exact shape at the
  // contact centre (for a plane on a cap, the apex height h).
  Indenter(const Scene& scene, const TetMesh& mesh);
  double phi(double x,
             double y) const;  // mm, ≥ 0: how far the indenter's surface rises above its lowest point
  double z_touch() const { return z_touch_; }
  // The vertical gap from point x (mm) up to the indenter at first touch: z_touch + φ(x, y) − z.
  double gap_at_rest(const Eigen::Vector3d& x) const { return z_touch_ + phi(x.x(), x.y()) - x.z(); }
  const Vec2& center() const { return center_; }
  double R() const { return R_; }  // a sphere's radius, mm (0 for a plane)
  IndenterKind kind() const { return kind_; }

 private:
  IndenterKind kind_;
  double R_ = 0;
  Vec2 center_{0, 0};
  double z_touch_ = 0;
};

}  // namespace skinfem::contact
