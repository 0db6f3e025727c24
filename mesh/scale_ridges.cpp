#include "skinfem/mesh/scale_ridges.hpp"

#include <algorithm>

#include "skinfem/mesh/build.hpp"
#include "skinfem/mesh/quality.hpp"
#include "skinfem/mesh/shape.hpp"

namespace skinfem {

TetMesh scale_ridges(TetMesh mesh, const Geometry& geometry, double factor) {
  const SkinShape shape(geometry);
  const double depth = geometry.ridges.period;
  for (int i = 0; i < mesh.num_nodes(); ++i) {
    const double x = mesh.nodes(i, 0), y = mesh.nodes(i, 1), r = shape.ridge_z(x, y);
    if (r == 0) continue;
    // Shift by (factor − 1)·ridge at the top, fading to none a ridge period below it (within half the skin):
    // the elements that follow the ridges move with them and the coarse ones below are not sheared.
    const double top = shape.top_z(x, y), fade = std::min(depth, 0.5 * shape.mean_top_z(x, y));
    const double u = std::max(0.0, 1 - (top - mesh.nodes(i, 2)) / fade);
    mesh.nodes(i, 2) += (factor - 1) * r * u * u;
  }
  // The map curves elements that build_mesh straightened (their mid-edge nodes leave the chord): the same
  // remedy again.
  straighten_folded_elements(mesh);
  check_no_inverted_element(mesh);
  return mesh;
}

}  // namespace skinfem
