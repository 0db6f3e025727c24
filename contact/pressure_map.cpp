#include "contact/pressure_map.hpp"

#include <algorithm>

#include "mesh/vtu.hpp"

namespace skinfem::contact {

void write_pressure_vtp(const std::string& path, const TetMesh& m, const ContactSolver& solver,
                        const ContactResult& r) {
  const int N = m.num_nodes();
  const MortarZone& zone = solver.zone();
  std::vector<double> p(N, 0.0), gap(N, 0.0), in(N, 0.0), pt(N, 0.0);
  for (int i : r.active) in[zone.vertices[i]] = 1.0;  // an exponential interface's λ > 0 everywhere
  for (int i = 0; i < zone.size(); ++i) {
    const int v = zone.vertices[i];
    p[v] = 1e3 * std::max(0.0, r.lambda[i]);
    pt[v] = r.ratio * p[v] + (r.shear.size() ? 1e3 * r.shear[i] : 0.0);
    gap[v] = 1e3 * r.gap[i] / zone.area[i];
  }
  // Faces with every corner in the zone: elsewhere the gap is not a constraint and is not known here.
  std::vector<char> in_zone(N, 0);
  for (int v : zone.vertices) in_zone[v] = 1;
  std::vector<int> faces;
  for (int f : zone.faces)
    if (in_zone[m.faces(f, 0)] && in_zone[m.faces(f, 1)] && in_zone[m.faces(f, 2)]) faces.push_back(f);
  for (int f : faces)
    for (int e = 0; e < 3; ++e) {
      const int a = m.faces(f, e), b = m.faces(f, (e + 1) % 3), mid = m.faces(f, 3 + e);
      p[mid] = 0.5 * (p[a] + p[b]);
      pt[mid] = 0.5 * (pt[a] + pt[b]);
      gap[mid] = 0.5 * (gap[a] + gap[b]);
      in[mid] = in[a] * in[b];
    }
  DataArray traction{"traction_kPa", 3, std::vector<double>(3 * N, 0.0)};
  for (int j = 0; j < N; ++j) {
    traction.values[3 * j] = solver.direction().x() * pt[j];
    traction.values[3 * j + 1] = solver.direction().y() * pt[j];
  }
  write_faces_vtp(path, m, faces,
                  {{"pressure_kPa", 1, p}, traction, {"gap_um", 1, gap}, {"in_contact", 1, in}});
}

}  // namespace skinfem::contact
