#include "skinfem/pipeline/symmetry.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "skinfem/scene/texture.hpp"

namespace skinfem::pipeline {

std::string mirror_unavailable(const Scene& scene) {
  const Geometry& g = scene.geometry;
  if (g.kind == GeometryKind::surface) return "an imported surface is not known to be symmetric";
  if (g.ridges.present()) return "ridged tops are meshed whole";
  if (g.kind == GeometryKind::cap && g.cap.apex_y != 0) return "the cap's apex is off y = 0";
  for (size_t i = 0; i < scene.sensors.positions.size(); ++i)
    if (scene.sensors.positions[i][1] != 0) {
      char buf[120];
      std::snprintf(buf, sizeof buf, "sensor %zu is off y = 0 (y = %g mm)", i + 1,
                    scene.sensors.positions[i][1]);
      return buf;
    }
  return "";
}

MeshPart green_mesh_part(const Scene& scene) {
  return scene.symmetry == SymmetryUse::automatic && mirror_unavailable(scene).empty() ? MeshPart::half_y
                                                                                       : MeshPart::whole;
}

std::string contact_mirror_unavailable(const Scene& scene) {
  if (!scene.contact) return "";
  const ContactLoad& c = *scene.contact;
  char buf[160];
  if (contact_center(scene)[1] != 0) {
    std::snprintf(buf, sizeof buf, "the contact's centre is off y = 0 (y = %g mm)", contact_center(scene)[1]);
    return buf;
  }
  if (c.direction[1] != 0) {
    std::snprintf(buf, sizeof buf, "the sliding direction (%g, %g) is not along x", c.direction[0],
                  c.direction[1]);
    return buf;
  }
  for (size_t i = 0; i < c.holes.size(); ++i)
    if (c.holes[i].center[1] != 0) {
      std::snprintf(buf, sizeof buf, "hole %zu is off y = 0 (y = %g mm)", i + 1, c.holes[i].center[1]);
      return buf;
    }
  if (c.sweep && (c.sweep->from[1] != 0 || c.sweep->to[1] != 0)) return "the hole sweep's path is off y = 0";
  // A texture off y = 0 is symmetric when every hole there has its image (x, -y) of the same size: the half
  // then solves each such hole with its image (contact/holes/scan.hpp).
  if (c.texture) {
    const auto& holes = c.texture->holes;
    for (size_t i = 0; i < holes.size(); ++i) {
      const Hole& h = holes[i];
      if (h.center[1] == 0) continue;
      const bool imaged = std::any_of(holes.begin(), holes.end(), [&](const Hole& o) {
        return std::abs(o.center[0] - h.center[0]) <= 1e-9 && std::abs(o.center[1] + h.center[1]) <= 1e-9 &&
               o.diameter == h.diameter && o.length == h.length && o.depth == h.depth;
      });
      if (!imaged) {
        std::snprintf(buf, sizeof buf, "texture %s %zu at (%g, %g) mm has no mirror image at (%g, %g) mm",
                      hole_word(h), i + 1, h.center[0], h.center[1], h.center[0], -h.center[1]);
        return buf;
      }
    }
  }
  return "";
}

MeshPart contact_mesh_part(const Scene& scene) {
  return green_mesh_part(scene) == MeshPart::half_y && contact_mirror_unavailable(scene).empty()
             ? MeshPart::half_y
             : MeshPart::whole;
}

}  // namespace skinfem::pipeline
