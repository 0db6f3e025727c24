#include "scene/scene.hpp"

namespace skinfem {

double nominal_thickness(const Scene& scene) {
  switch (scene.geometry.kind) {
    case GeometryKind::cap:
      return scene.geometry.cap.h;
    case GeometryKind::flat:
      return scene.geometry.flat.h;
    case GeometryKind::surface:
      return 0.0;  // unknown until the surface file is read (see scene.hpp)
  }
  return 0.0;
}

}  // namespace skinfem
