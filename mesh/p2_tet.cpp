#include "skinfem/mesh/p2_tet.hpp"

namespace skinfem::p2 {

namespace {
// The four points (a, a, a), (1 − 3a, a, a), … of a symmetric orbit.
void add_orbit4(std::vector<QuadPoint>& q, double a, double w) {
  const double b = 1 - 3 * a;
  q.push_back({{a, a, a}, w});
  q.push_back({{b, a, a}, w});
  q.push_back({{a, b, a}, w});
  q.push_back({{a, a, b}, w});
}
// The six points with two barycentrics c and two ½ − c.
void add_orbit6(std::vector<QuadPoint>& q, double c, double w) {
  const double d = 0.5 - c;
  const double pts[6][3] = {{c, c, d}, {c, d, c}, {d, c, c}, {c, d, d}, {d, c, d}, {d, d, c}};
  for (const auto& p : pts) q.push_back({{p[0], p[1], p[2]}, w});
}
}  // namespace

const std::vector<QuadPoint>& quadrature_degree2() {
  static const std::vector<QuadPoint> q = [] {
    std::vector<QuadPoint> r;
    add_orbit4(r, 0.1381966011250105, 1.0 / 24.0);
    return r;
  }();
  return q;
}

const std::vector<QuadPoint>& quadrature_degree5() {
  static const std::vector<QuadPoint> q = [] {
    std::vector<QuadPoint> r;
    add_orbit4(r, 0.0927352503108912, 0.0734930431163620 / 6);
    add_orbit4(r, 0.3108859192633006, 0.1126879257180159 / 6);
    add_orbit6(r, 0.0455037041256496, 0.0425460207770815 / 6);
    return r;
  }();
  return q;
}

}  // namespace skinfem::p2
