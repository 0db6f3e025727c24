// mesh.vtu written by write_vtu reads back through VTK's own XML reader with quadratic cells.
#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <filesystem>

#include "mesh/build.hpp"
#include "mesh/vtu.hpp"

namespace skinfem {
namespace {

TEST(VtuReadback, QuadraticTetsPointsAndMarkersSurviveTheRoundTrip) {
  Scene s;
  s.geometry.kind = GeometryKind::flat;
  s.geometry.flat = {1.0, 2.0};
  s.sensors.positions = {{0.0, 0.0}};
  s.mesh.h_min = 0.5;
  s.mesh.h_max = 1.0;
  const TetMesh m = build_mesh(s);
  std::filesystem::create_directories(SKINFEM_TEST_TMP);
  const std::string path = std::string(SKINFEM_TEST_TMP) + "/readback.vtu";
  DataArray ux{"displacement_mm", 3, std::vector<double>(3 * m.num_nodes(), 0.25)};
  write_vtu(path, m, {ux});
  ASSERT_FALSE(std::filesystem::exists(path + ".tmp"));

  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkUnstructuredGrid* g = reader->GetOutput();
  ASSERT_EQ(g->GetNumberOfPoints(), m.num_nodes());
  ASSERT_EQ(g->GetNumberOfCells(), m.num_tets());
  for (vtkIdType c = 0; c < g->GetNumberOfCells(); ++c) ASSERT_EQ(g->GetCellType(c), VTK_QUADRATIC_TETRA);
  double p[3];
  g->GetPoint(m.num_nodes() - 1, p);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(p[k], m.nodes(m.num_nodes() - 1, k));  // double precision kept
  auto* marker = g->GetPointData()->GetArray("boundary_marker");
  ASSERT_NE(marker, nullptr);
  for (int i = 0; i < m.num_nodes(); ++i) ASSERT_EQ(marker->GetTuple1(i), m.node_marker(i));
  ASSERT_NE(g->GetPointData()->GetArray("displacement_mm"), nullptr);
  ASSERT_NE(g->GetCellData()->GetArray("element_volume_mm3"), nullptr);
}

}  // namespace
}  // namespace skinfem
