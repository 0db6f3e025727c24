#include "skinfem/contact/pressure_map.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "skinfem/mesh/vtu.hpp"

namespace skinfem::contact {

namespace {
// The zone's faces with every corner a multiplier: elsewhere the gap is not a constraint and is not known.
std::vector<int> corner_faces(const TetMesh& m, const MortarZone& zone) {
  std::vector<char> in_zone(m.num_nodes(), 0);
  for (int v : zone.vertices) in_zone[v] = 1;
  std::vector<int> faces;
  for (int f : zone.faces)
    if (in_zone[m.faces(f, 0)] && in_zone[m.faces(f, 1)] && in_zone[m.faces(f, 2)]) faces.push_back(f);
  return faces;
}

// A P1 field's values at the faces' mid-edge nodes: the mean of the edge's two vertices.
void mid_edge_means(const TetMesh& m, const std::vector<int>& faces, std::vector<double>& v) {
  for (int f : faces)
    for (int e = 0; e < 3; ++e) v[m.faces(f, 3 + e)] = 0.5 * (v[m.faces(f, e)] + v[m.faces(f, (e + 1) % 3)]);
}

// A 0/1 flag at the mid-edge nodes: 1 where both vertices have it.
void mid_edge_both(const TetMesh& m, const std::vector<int>& faces, std::vector<double>& v) {
  for (int f : faces)
    for (int e = 0; e < 3; ++e) v[m.faces(f, 3 + e)] = v[m.faces(f, e)] * v[m.faces(f, (e + 1) % 3)];
}

// Multiplier i's mean gap over its hat to the indenter's face, mm (a bulge's solve holds the weighted gap
// to the receded surface: its opening is taken back out).
double face_gap(const ContactResult& r, const MortarZone& zone, int i) {
  return (r.gap[i] - (r.opening.size() ? r.opening[i] : 0.0)) / zone.area[i];
}
}  // namespace

HoleClearance hole_clearance(const TetMesh& m, const ContactSolver& solver, const ContactResult& r,
                             const std::vector<Hole>& holes) {
  HoleClearance out;
  const MortarZone& zone = solver.zone();
  for (int i = 0; i < zone.size(); ++i)
    if (const int k = hole_holding(m, zone.vertices[i], holes); k >= 0) {
      const double gap = face_gap(r, zone, i);
      if (gap + holes[k].depth < out.clearance_mm) out = {k, gap + holes[k].depth, -gap};
    }
  return out;
}

void check_hole_clearance(const TetMesh& m, const ContactSolver& solver, const ContactResult& r,
                          const std::vector<Hole>& holes, const std::string& field) {
  const HoleClearance c = hole_clearance(m, solver, r, holes);
  if (c.clearance_mm > 0) return;
  const std::string name =
      field == "contact.sweep" ? field + ".hole_depth" : field + "[" + std::to_string(c.hole) + "].depth";
  char line[400];
  std::snprintf(line, sizeof line,
                "%s = %g: the skin rises %.3g um into the hole, %s its bottom (%s friction); the contact is "
                "solved for a hole whose bottom the skin does not touch: give a deeper hole",
                name.c_str(), holes[c.hole].depth, 1e3 * c.rise_mm, c.clearance_mm < 0 ? "past" : "to",
                to_string(r.mode));
  throw SceneError(line);
}

void write_pressure_vtp(const std::string& path, const TetMesh& m, const ContactSolver& solver,
                        const ContactResult& r, const std::vector<Hole>& holes) {
  const int N = m.num_nodes();
  const MortarZone& zone = solver.zone();
  std::vector<double> p(N, 0.0), gap(N, 0.0), in(N, 0.0), pt(N, 0.0), in_hole(N, 0.0);
  for (int i : r.active) in[zone.vertices[i]] = 1.0;  // an exponential interface's λ > 0 everywhere
  for (int i = 0; i < zone.size(); ++i) {
    const int v = zone.vertices[i];
    p[v] = 1e3 * std::max(0.0, r.lambda[i]);
    pt[v] = r.ratio * p[v] + (r.shear.size() ? 1e3 * r.shear[i] : 0.0);
    gap[v] = 1e3 * r.gap[i] / zone.area[i];
    if (const int k = hole_holding(m, v, holes); k >= 0) {
      gap[v] = 1e3 * (face_gap(r, zone, i) + holes[k].depth);
      in_hole[v] = 1;
    }
  }
  const std::vector<int> faces = corner_faces(m, zone);
  for (auto* values : {&p, &pt, &gap}) mid_edge_means(m, faces, *values);
  for (auto* flags : {&in, &in_hole}) mid_edge_both(m, faces, *flags);
  DataArray traction{"traction_kPa", 3, std::vector<double>(3 * N, 0.0)};
  for (int j = 0; j < N; ++j) {
    traction.values[3 * j] = solver.direction().x() * pt[j];
    traction.values[3 * j + 1] = solver.direction().y() * pt[j];
  }
  write_faces_vtp(
      path, m, faces,
      {{"pressure_kPa", 1, p}, traction, {"gap_um", 1, gap}, {"in_hole", 1, in_hole}, {"in_contact", 1, in}});
}

void write_finite_pressure_vtp(const std::string& path, const TetMesh& m, const MortarZone& zone,
                               const FiniteContactResult& r, const Eigen::Vector2d& direction, double ratio) {
  const int N = m.num_nodes();
  std::vector<double> p(N, 0.0), gap(N, 0.0), in(N, 0.0), shear(N, 0.0);
  for (int i : r.active) in[zone.vertices[i]] = 1.0;
  for (int i = 0; i < zone.size(); ++i) {
    const int v = zone.vertices[i];
    p[v] = 1e3 * std::max(0.0, r.lambda[i]);
    gap[v] = 1e3 * r.gap[i] / zone.area[i];
    if (r.shear.size()) shear[v] = 1e3 * r.shear[i];
  }
  const std::vector<int> faces = corner_faces(m, zone);
  mid_edge_means(m, faces, p);
  mid_edge_means(m, faces, gap);
  mid_edge_means(m, faces, shear);
  mid_edge_both(m, faces, in);
  const Eigen::Vector2d t = direction.normalized();
  DataArray traction{"traction_kPa", 3, std::vector<double>(3 * N, 0.0)};
  for (int j = 0; j < N; ++j) {
    traction.values[3 * j] = t.x() * (ratio * p[j] + shear[j]);
    traction.values[3 * j + 1] = t.y() * (ratio * p[j] + shear[j]);
  }
  const DataArray displacement{"displacement_mm", 3,
                               std::vector<double>(r.solution.u.data(), r.solution.u.data() + 3 * N)};
  write_faces_vtp(
      path, m, faces,
      {{"pressure_kPa", 1, p}, traction, {"gap_um", 1, gap}, {"in_contact", 1, in}, displacement});
}

}  // namespace skinfem::contact
