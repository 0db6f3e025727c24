// The whole skin from the meshed half of a mirror-symmetric one (MeshPart::half_y): the half and its mirror
// image in the plane y = 0, sharing the cut's nodes. For output (the whole top in ParaView) and as the test
// of the symmetric reduction: a solve on this mesh is the full body's.
#pragma once

#include <vector>

#include "skinfem/mesh/tet_mesh.hpp"

namespace skinfem {

// half: a half_y mesh. Returns a whole mesh: vertices first, every element positively oriented, the cut's
// faces gone. source (optional): for each of its nodes, the half's node it is or mirrors.
TetMesh mirror_half(const TetMesh& half, std::vector<int>* source = nullptr);

}  // namespace skinfem
