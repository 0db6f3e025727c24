#include "skinfem/green/kernel_grid.hpp"

#include <hdf5.h>
#include <vtkDoubleArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnsignedCharArray.h>
#include <vtkXMLImageDataWriter.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "skinfem/green/calibration.hpp"

namespace skinfem::green {

std::vector<double> grid_lines(double lo, double hi, double dx) {
  if (!(dx > 0) || !(hi >= lo)) throw std::invalid_argument("grid_lines: need dx > 0 and hi >= lo");
  const int n = static_cast<int>(std::floor((hi - lo) / dx * (1 + 1e-12))) + 1;
  const double start = 0.5 * (lo + hi) - 0.5 * (n - 1) * dx;
  std::vector<double> v(n);
  for (int i = 0; i < n; ++i) v[i] = start + i * dx;
  return v;
}

KernelGrid kernel_grid(const DiscMap& map, const Sensors& sensors, double x_lo, double x_hi, double y_lo,
                       double y_hi, double dx) {
  KernelGrid grid;
  grid.x = grid_lines(x_lo, x_hi, dx);
  grid.y = grid_lines(y_lo, y_hi, dx);
  grid.dx = dx;
  grid.sensors = sensors.positions;
  grid.disc_diameter = sensors.disc_diameter;
  const size_t nx = grid.x.size(), ny = grid.y.size(), ns = sensors.positions.size();
  grid.on_skin.assign(nx * ny, 0);
  grid.values.resize(ns);
  for (auto& per_sensor : grid.values)
    for (auto& v : per_sensor) v.assign(nx * ny, 0.0);
  for (size_t j = 0; j < ny; ++j)
    for (size_t i = 0; i < nx; ++i)
      for (size_t s = 0; s < ns; ++s) {
        GreenSample g;
        if (!map(static_cast<int>(s), grid.x[i], grid.y[j], g)) break;
        grid.on_skin[j * nx + i] = 1;
        for (size_t c = 0; c < 4; ++c) grid.values[s][c][j * nx + i] = component(g, kComponents[c]);
      }
  return grid;
}

namespace {

constexpr const char* kConvention =
    "g_ab(X) is sensor's mean reading b over its disc (MPa) per unit force a (N) at the top point above X = "
    "(x_mm, y_mm); offset = X - sensor position_mm. Force along z presses into the skin (-e_z), along x is "
    "+e_x. Reading z: sigma_z = -sigma_zz > 0 when the skin presses on the sensor; reading x: sigma_x = "
    "sigma_xz > 0 when the skin drags it toward +x. Model: sigma_b(sensor) = sum over grid of (p_x g_xb + "
    "p_z g_zb) dx^2 with p in MPa.";

// Thin RAII guard over an HDF5 identifier.
struct H5 {
  hid_t id;
  herr_t (*close)(hid_t);
  H5(hid_t i, herr_t (*c)(hid_t), const char* what) : id(i), close(c) {
    if (id < 0) throw std::runtime_error(std::string("HDF5: cannot create ") + what);
  }
  ~H5() { close(id); }
  H5(const H5&) = delete;
  H5& operator=(const H5&) = delete;
};

void check(herr_t status, const std::string& what) {
  if (status < 0) throw std::runtime_error("HDF5: cannot write " + what);
}

void string_attribute(hid_t where, const char* name, const std::string& value) {
  H5 type(H5Tcopy(H5T_C_S1), H5Tclose, "string type");
  check(H5Tset_size(type.id, value.size()), name);
  H5 space(H5Screate(H5S_SCALAR), H5Sclose, "dataspace");
  H5 attr(H5Acreate2(where, name, type.id, space.id, H5P_DEFAULT, H5P_DEFAULT), H5Aclose, name);
  check(H5Awrite(attr.id, type.id, value.c_str()), name);
}

void double_attribute(hid_t where, const char* name, const std::vector<double>& value) {
  const hsize_t n = value.size();
  H5 space(H5Screate_simple(1, &n, nullptr), H5Sclose, "dataspace");
  H5 attr(H5Acreate2(where, name, H5T_IEEE_F64LE, space.id, H5P_DEFAULT, H5P_DEFAULT), H5Aclose, name);
  check(H5Awrite(attr.id, H5T_NATIVE_DOUBLE, value.data()), name);
}

void dataset(hid_t where, const char* name, hid_t file_type, hid_t mem_type, const void* data,
             std::vector<hsize_t> dims, const std::string& units) {
  H5 space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), H5Sclose, "dataspace");
  H5 props(H5Pcreate(H5P_DATASET_CREATE), H5Pclose, "dataset properties");
  check(H5Pset_obj_track_times(props.id, false), name);
  H5 set(H5Dcreate2(where, name, file_type, space.id, H5P_DEFAULT, props.id, H5P_DEFAULT), H5Dclose, name);
  check(H5Dwrite(set.id, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), name);
  if (!units.empty()) string_attribute(set.id, "units", units);
}

}  // namespace

void write_kernel_h5(const std::string& path, const KernelGrid& grid, const std::string& scene_name) {
  const std::string tmp = path + ".tmp";
  {
    H5 file(H5Fcreate(tmp.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose, tmp.c_str());
    string_attribute(file.id, "scene", scene_name);
    string_attribute(file.id, "units", "lengths mm, forces N, stresses MPa, g 1/mm^2 (MPa per N)");
    string_attribute(file.id, "convention", kConvention);
    double_attribute(file.id, "grid_spacing_mm", {grid.dx});
    double_attribute(file.id, "disc_diameter_mm", {grid.disc_diameter});
    const hsize_t nx = grid.x.size(), ny = grid.y.size();
    dataset(file.id, "x_mm", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, grid.x.data(), {nx}, "mm");
    dataset(file.id, "y_mm", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, grid.y.data(), {ny}, "mm");
    dataset(file.id, "on_skin", H5T_STD_U8LE, H5T_NATIVE_UCHAR, grid.on_skin.data(), {ny, nx}, "");
    for (size_t s = 0; s < grid.values.size(); ++s) {
      char name[32];
      std::snprintf(name, sizeof name, "sensor%02zu", s + 1);
      H5 group_props(H5Pcreate(H5P_GROUP_CREATE), H5Pclose, "group properties");
      check(H5Pset_obj_track_times(group_props.id, false), name);
      H5 group(H5Gcreate2(file.id, name, H5P_DEFAULT, group_props.id, H5P_DEFAULT), H5Gclose, name);
      double_attribute(group.id, "position_mm", {grid.sensors[s][0], grid.sensors[s][1]});
      for (size_t c = 0; c < 4; ++c) {
        const std::string set = std::string("g_") + component_name(kComponents[c]) + "_per_mm2";
        dataset(group.id, set.c_str(), H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, grid.values[s][c].data(), {ny, nx},
                "1/mm^2");
      }
    }
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) throw std::runtime_error("cannot write " + path);
}

void write_kernel_vti(const std::string& path, const KernelGrid& grid) {
  const int nx = static_cast<int>(grid.x.size()), ny = static_cast<int>(grid.y.size());
  vtkNew<vtkImageData> image;
  image->SetDimensions(nx, ny, 1);
  image->SetOrigin(grid.x.front(), grid.y.front(), 0.0);
  image->SetSpacing(grid.dx, grid.dx, 1.0);
  vtkNew<vtkUnsignedCharArray> on_skin;
  on_skin->SetName("on_skin");
  on_skin->SetNumberOfValues(nx * ny);
  for (int k = 0; k < nx * ny; ++k) on_skin->SetValue(k, grid.on_skin[k]);
  image->GetPointData()->AddArray(on_skin);
  for (size_t s = 0; s < grid.values.size(); ++s)
    for (size_t c = 0; c < 4; ++c) {
      char name[64];
      std::snprintf(name, sizeof name, "g_%s_sensor%02zu_per_mm2", component_name(kComponents[c]), s + 1);
      vtkNew<vtkDoubleArray> a;
      a->SetName(name);
      a->SetNumberOfValues(nx * ny);
      for (int k = 0; k < nx * ny; ++k) a->SetValue(k, grid.values[s][c][k]);
      image->GetPointData()->AddArray(a);
    }
  const std::string tmp = path + ".tmp";
  vtkNew<vtkXMLImageDataWriter> writer;
  writer->SetFileName(tmp.c_str());
  writer->SetInputData(image);
  writer->SetDataModeToAppended();
  if (writer->Write() != 1) throw std::runtime_error("cannot write " + path);
  if (std::rename(tmp.c_str(), path.c_str()) != 0) throw std::runtime_error("cannot write " + path);
}

}  // namespace skinfem::green
