// mesh.vtu written by write_vtu reads back through VTK's own XML reader with quadratic cells.
#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <filesystem>

#include "skinfem/mesh/build.hpp"
#include "skinfem/mesh/vtu.hpp"

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

TEST(VtuReadback, TopSurfaceMapReadsBackAsPolyData) {
  Scene s;
  s.geometry.kind = GeometryKind::flat;
  s.geometry.flat = {1.0, 2.0};
  s.mesh.refine_sensors = false;
  s.mesh.h_min = s.mesh.h_max = 0.6;
  const TetMesh m = build_mesh(s);
  std::filesystem::create_directories(SKINFEM_TEST_TMP);
  const std::string path = std::string(SKINFEM_TEST_TMP) + "/top.vtp";
  DataArray g{"g_zz_sensor01_per_mm2", 1, {}};
  for (int i = 0; i < m.num_nodes(); ++i) g.values.push_back(m.nodes(i, 0));  // x as a recognisable field
  write_surface_vtp(path, m, kTop, {g});
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkPolyData* p = reader->GetOutput();
  int top_faces = 0;
  for (int f = 0; f < m.faces.rows(); ++f) top_faces += m.face_marker(f) == kTop;
  EXPECT_EQ(p->GetNumberOfPolys(), 4 * top_faces);  // each quadratic face as four triangles
  auto* arr = p->GetPointData()->GetArray("g_zz_sensor01_per_mm2");
  ASSERT_NE(arr, nullptr);
  for (vtkIdType i = 0; i < p->GetNumberOfPoints(); ++i) {
    double x[3];
    p->GetPoint(i, x);
    EXPECT_EQ(arr->GetTuple1(i), x[0]);
    EXPECT_DOUBLE_EQ(x[2], 1.0);  // all on the top
  }
}

}  // namespace
}  // namespace skinfem
