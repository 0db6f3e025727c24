// Closed boundary surfaces with top / base / side markers: generated for caps and flat layers,
// imported from STL/OBJ/OFF for anything else. Every surface passes the same watertight and
// manifold check (OpenMesh halfedge structure) before it is tetrahedralized.
#pragma once

#include <stdexcept>
#include <string>

#include "skinfem/mesh/footprint.hpp"
#include "skinfem/mesh/shape.hpp"
#include "skinfem/mesh/sizing.hpp"
#include "skinfem/mesh/tet_mesh.hpp"

namespace skinfem {

struct MeshError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Cap or flat layer: a graded footprint triangulation lifted to the exact top (z = s(x, y)) and the
// base (z = 0), joined by a side band of vertical quads split in two. The triangulation follows the
// edge of every punch, so that a rigid punch holds exactly its disc.
SurfaceMesh layer_surface(const Scene& scene, const SizingField& size, MeshPart part = MeshPart::whole);
// The outlines of the scene's post sensors on the base (none for disc sensors).
std::vector<Circle> post_circles(const Scene& scene);

// Reads a closed surface (STL ASCII or binary, OBJ, OFF; mm): points with equal coordinates are merged and
// faces are oriented like their neighbours, then outward. Faces lying on z = 0 (all three vertices within
// 1e-9·diameter, normal −z) become the base, faces with a horizontal normal the side, the rest the top.
// Throws MeshError naming the file when its header declares more than it holds, a vertex is not finite, it
// cannot be read, is not watertight, has an edge of more than two
// faces (naming where), is one-sided or self-intersecting, reaches below z = 0, or has no base face.
SurfaceMesh import_surface(const std::string& path);
// Whether (x, y) lies under one of the surface's top faces (kTop), seen from above.
bool over_top(const SurfaceMesh& s, const Vec2& p);

// The volume a closed surface encloses, mm³ (negative when it is inward oriented).
double signed_volume(const SurfaceMesh& s);

// Throws MeshError (prefixed with `what`) unless the surface is closed, manifold and outward oriented.
void check_watertight(const SurfaceMesh& surface, const std::string& what);

}  // namespace skinfem
