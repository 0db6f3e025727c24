#include "skinfem/contact/indenter.hpp"

#include <algorithm>
#include <cmath>

#include "skinfem/mesh/shape.hpp"

namespace skinfem::contact {

Indenter::Indenter(const Scene& scene, const TetMesh& mesh)
    : kind_(scene.contact->indenter), R_(scene.contact->sphere_R), center_(contact_center(scene)) {
  z_touch_ = -1e300;
  if (SkinShape shape(scene.geometry); shape.exact()) z_touch_ = shape.top_z(center_[0], center_[1]);
  for (int i = 0; i < mesh.num_nodes(); ++i)
    if (mesh.node_marker(i) & kTop)
      z_touch_ = std::max(z_touch_, mesh.nodes(i, 2) - phi(mesh.nodes(i, 0), mesh.nodes(i, 1)));
}

double Indenter::phi(double x, double y) const {
  if (kind_ == IndenterKind::plane) return 0.0;
  const double r2 = (x - center_[0]) * (x - center_[0]) + (y - center_[1]) * (y - center_[1]);
  // R − sqrt(R² − r²) without cancellation; beyond the sphere's equator the indenter is out of reach.
  return r2 < R_ * R_ ? r2 / (R_ + std::sqrt(R_ * R_ - r2)) : R_;
}

}  // namespace skinfem::contact
