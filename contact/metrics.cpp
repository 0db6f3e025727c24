#include "skinfem/contact/metrics.hpp"

#include <algorithm>
#include <cmath>

#include "skinfem/scene/laws.hpp"
#include "skinfem/scene/texture.hpp"

namespace skinfem::contact {

namespace {
// The inactive vertices outside the contact: those reached from the zone's rim through inactive
// neighbours. The others are enclosed by it (holes, and the rims a hole lifts off), so they are neither
// the contact's edge nor outside its outer boundary.
std::vector<char> outside_contact(const MortarZone& z, const TetMesh& m, const std::vector<char>& touching) {
  std::vector<int> index(m.num_nodes(), -1);
  for (int i = 0; i < z.size(); ++i) index[z.vertices[i]] = i;
  std::vector<std::vector<int>> next(z.size());
  std::vector<char> outside(z.size(), 0);
  std::vector<int> queue;
  for (const int f : z.faces)
    for (int a = 0; a < 3; ++a) {
      const int i = index[m.faces(f, a)];
      if (i < 0 || touching[i]) continue;
      for (int b = 0; b < 3; ++b) {
        const int j = index[m.faces(f, b)];
        if (j < 0 && !outside[i]) outside[i] = 1, queue.push_back(i);  // on the zone's rim
        if (j >= 0 && j != i && !touching[j]) next[i].push_back(j);
      }
    }
  while (!queue.empty()) {
    const int i = queue.back();
    queue.pop_back();
    for (const int j : next[i])
      if (!outside[j]) outside[j] = 1, queue.push_back(j);
  }
  return outside;
}

}  // namespace

ContactMetrics contact_metrics(const ContactSolver& solver, const TetMesh& m, const PlanarFaceIndex& top,
                               const ContactResult& r, const Vec2& center, const std::vector<Hole>& holes) {
  ContactMetrics out;
  const MortarZone& z = solver.zone();
  const Eigen::Vector2d t = solver.direction();
  const auto xy = [&](int i) {
    return Eigen::Vector2d(m.nodes(z.vertices[i], 0), m.nodes(z.vertices[i], 1));
  };
  const Eigen::Vector2d c0(center[0], center[1]);
  // The active set (an exponential interface's λ is > 0 everywhere: its set holds λ ≥ 1e-6 of the peak).
  std::vector<char> touching(z.size(), 0);
  for (int i : r.active) touching[i] = 1;

  double F = 0, area = 0, peak_front = 0, peak_back = 0;
  Eigen::Vector2d moment = Eigen::Vector2d::Zero(), zone_moment = Eigen::Vector2d::Zero();
  for (int i = 0; i < z.size(); ++i) {
    const double p = r.lambda[i];
    if (!touching[i]) continue;
    F += p * z.area[i];
    moment += p * z.area[i] * xy(i);
    area += z.area[i];
    zone_moment += z.area[i] * xy(i);
    out.p_max_MPa = std::max(out.p_max_MPa, p);
    const double ahead = (xy(i) - c0).dot(t);
    (ahead > 0 ? peak_front : peak_back) = std::max(ahead > 0 ? peak_front : peak_back, p);
    out.front_edge_mm = std::max(out.front_edge_mm, ahead);
    out.back_edge_mm = std::min(out.back_edge_mm, ahead);
  }
  if (F <= 0) return out;
  const std::vector<char> outside = outside_contact(z, m, touching);
  double enclosed = 0;
  Eigen::Vector2d enclosed_moment = Eigen::Vector2d::Zero();
  for (int i = 0; i < z.size(); ++i)
    if (!outside[i]) enclosed += z.area[i], enclosed_moment += z.area[i] * xy(i);
  const Eigen::Vector2d pc = moment / F;
  out.pressure_centroid = {pc.x(), pc.y()};
  out.zone_centroid = {zone_moment.x() / area, zone_moment.y() / area};
  out.equivalent_radius_mm = std::sqrt(enclosed / M_PI);
  out.front_back_peak_ratio = peak_back > 0 ? peak_front / peak_back : 0.0;

  for (const Hole& h : holes)
    if (hole_contains(h, center[0], center[1])) out.p0_in_hole = true;
  double s, tt;
  if (const int f = top.find(center[0], center[1], s, tt); !out.p0_in_hole && f >= 0) {
    const double psi[3] = {1 - s - tt, s, tt};
    for (int a = 0; a < 3; ++a)
      for (int i = 0; i < z.size(); ++i)
        if (z.vertices[i] == m.faces(f, a)) out.p0_MPa += psi[a] * std::max(0.0, r.lambda[i]);
  }

  // Edge fit: p^q = α + βr² + γr⁴ over the outer part of the contact, root nearest the last active ring. A
  // hard contact's pressure vanishes like √(a − r) (q = 2); through a linear interface the closure p/K
  // takes up the gap at the edge, so p vanishes like a − r (q = 1; contact/layer_hertz_interface.hpp).
  const bool linear_edge = kind(solver.load().interface.law).edge_q == 1;
  // With holes the pressure centroid leaves the centre (the holes carry nothing): the fit is made about
  // the centroid of the area inside the outer boundary, holes included.
  const Eigen::Vector2d fc = holes.empty() ? pc : Eigen::Vector2d(enclosed_moment / enclosed);
  // An exponential interface has no edge, only a tail: fit the loaded part (λ ≥ 5 % of the peak, the
  // asperities closed to within u0 ln 20 of the mean plane) and extrapolate it to its hard-contact edge.
  const double floor = kind(solver.load().interface.law).smooth ? 0.05 * out.p_max_MPa : 0.0;
  const auto fitted = [&](int i) {
    if (!touching[i] || r.lambda[i] < floor) return false;
    for (const Hole& h : holes)
      if ((xy(i) - Eigen::Vector2d(h.center[0], h.center[1])).norm() < h.diameter) return false;
    return true;
  };
  std::vector<double> radii, p;
  for (int i = 0; i < z.size(); ++i)
    if (fitted(i)) {
      radii.push_back((xy(i) - fc).norm());
      p.push_back(r.lambda[i]);
    }
  // A linear interface's edge zone, where its closure takes up the gap, shrinks as K grows (to a fraction
  // p0/(Kδ) of the radius) and falls below the mesh: its edge takes the exponent that fits the pressure
  // better, so a stiff interface's radius is the hard contact's.
  EdgeFit fit = edge_fit(radii, p, 2);
  if (linear_edge) {
    const EdgeFit lin = edge_fit(radii, p, 1);
    if (lin.radius > 0 && (!(fit.radius > 0) || lin.rms < fit.rms)) fit = lin;
  }
  // Too few rows for the fit: the area-equivalent radius.
  out.contact_radius_mm = fit.radius > 0 ? fit.radius : out.equivalent_radius_mm;
  return out;
}

EdgeFit edge_fit(const std::vector<double>& radii, const std::vector<double>& p, int q) {
  double r_max = 0;
  for (double r : radii) r_max = std::max(r_max, r);
  std::vector<Eigen::Vector3d> rows;
  std::vector<double> rhs, p_rows;
  for (size_t i = 0; i < radii.size(); ++i)
    if (radii[i] >= 0.6 * r_max) {
      const double X = radii[i] * radii[i] / (r_max * r_max);  // scaled for conditioning
      rows.emplace_back(1.0, X, X * X);
      rhs.push_back(q == 1 ? p[i] : p[i] * p[i]);
      p_rows.push_back(p[i]);
    }
  EdgeFit fit;
  if (rows.size() < 6) return fit;
  Eigen::MatrixXd A(rows.size(), 3);
  Eigen::VectorXd b(rows.size());
  for (size_t k = 0; k < rows.size(); ++k) A.row(k) = rows[k].transpose(), b[k] = rhs[k];
  const Eigen::Vector3d co = A.colPivHouseholderQr().solve(b);
  // Root of α + βX + γX² nearest X = 1 (the last active ring).
  double X = -co[0] / co[1];
  if (std::abs(co[2]) > 1e-12 * std::abs(co[1])) {
    const double disc = co[1] * co[1] - 4 * co[2] * co[0];
    if (disc >= 0) {
      const double qq = -0.5 * (co[1] + std::copysign(std::sqrt(disc), co[1]));
      const double X1 = qq / co[2], X2 = co[0] / qq;
      X = std::abs(X1 - 1) < std::abs(X2 - 1) ? X1 : X2;
    }
  }
  if (!(X > 0) || !std::isfinite(X)) return fit;
  fit.radius = r_max * std::sqrt(X);
  // The residual in pressure, the same measure for either exponent.
  double sum = 0;
  for (size_t k = 0; k < rows.size(); ++k) {
    const double v = rows[k].dot(co);
    const double model = q == 1 ? v : std::sqrt(std::max(v, 0.0));
    sum += (model - p_rows[k]) * (model - p_rows[k]);
  }
  fit.rms = std::sqrt(sum / rows.size());
  return fit;
}

double edge_fit_radius(const std::vector<double>& radii, const std::vector<double>& p, double fallback) {
  const EdgeFit fit = edge_fit(radii, p, 2);
  return fit.radius > 0 ? fit.radius : fallback;
}

}  // namespace skinfem::contact
