// VTK XML unstructured-grid output (.vtu) of a 10-node tet mesh with quadratic cells, readable by ParaView.
#pragma once

#include <string>
#include <vector>

#include "skinfem/mesh/tet_mesh.hpp"

namespace skinfem {

struct DataArray {
  std::string name;  // include the unit, e.g. "displacement_mm"
  int components = 1;
  std::vector<double> values;  // tuple-major: size = count × components
};

// Writes the volume mesh as VTK_QUADRATIC_TETRA cells. Always adds point data "boundary_marker"
// (node_marker) and cell data "element_volume_mm3". Writes to path + ".tmp" first, then renames,
// so a failure leaves no half-written file. Throws std::runtime_error on I/O failure.
void write_vtu(const std::string& path, const TetMesh& mesh, const std::vector<DataArray>& point_data = {},
               const std::vector<DataArray>& cell_data = {});

// The boundary faces with `marker` as a surface (.vtp): each quadratic triangle is split into four
// linear ones through its mid-edge nodes (PolyData has no quadratic cells); point data per mesh node
// (arrays sized num_nodes × components; nodes off the surface are dropped).
void write_surface_vtp(const std::string& path, const TetMesh& mesh, int marker,
                       const std::vector<DataArray>& point_data);

// The same for a chosen list of boundary faces (e.g. a contact zone).
void write_faces_vtp(const std::string& path, const TetMesh& mesh, const std::vector<int>& faces,
                     const std::vector<DataArray>& point_data);

// The boundary faces as VTK_QUADRATIC_TRIANGLE cells with cell data "boundary_marker".
void write_boundary_vtu(const std::string& path, const TetMesh& mesh);

}  // namespace skinfem
