#include "skinfem/green/meridian.hpp"

#include <Eigen/SparseCore>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "skinfem/fem/base_traction.hpp"
#include "skinfem/fem/mumps_ldlt.hpp"
#include "skinfem/green/fe_green.hpp"
#include "skinfem/green/halfspace.hpp"
#include "skinfem/green/meridian_mode.hpp"
#include "skinfem/green/meridian_reading.hpp"
#include "skinfem/mesh/gauss_legendre.hpp"
#include "skinfem/mesh/surface_quadrature.hpp"

namespace skinfem {

MeridianSizes MeridianSizes::for_thickness(double h, double scale) {
  MeridianSizes z;
  z.axis_cell = h / 60 * scale;
  z.growth = std::pow(1.1, scale);
  z.max_cell = 2 * h / 3 * scale;
  z.layers = std::max(2, static_cast<int>(std::lround(36 / scale)));
  return z;
}

MeridianMesh meridian_mesh(const std::function<double(double)>& top, double radius, const MeridianSizes& z) {
  if (!(radius > 0) || !(z.axis_cell > 0) || !(z.growth >= 1) || !(z.max_cell > 0) || z.layers < 1 ||
      z.layer_grading < 0 || z.layer_grading >= 1)
    throw std::invalid_argument(
        "meridian_mesh: need radius, axis_cell, max_cell > 0, growth >= 1, layers >= 1, layer_grading in [0, "
        "1)");
  std::vector<double> rows{0};  // vertex radii
  for (double cell = z.axis_cell; rows.back() < radius * (1 - 1e-9); cell *= z.growth)
    rows.push_back(rows.back() + std::min(cell, z.max_cell));
  for (double& r : rows) r *= radius / rows.back();
  std::vector<double> tau(2 * z.layers + 1);
  for (size_t j = 0; j < tau.size(); ++j) {
    const double t = double(j) / (tau.size() - 1);
    tau[j] = t - z.layer_grading * std::sin(2 * M_PI * t) / (2 * M_PI);
  }
  return meridian_mesh(top, rows, tau);
}

MeridianMesh meridian_mesh(const std::function<double(double)>& top, const std::vector<double>& rows,
                           const std::vector<double>& tau) {
  if (rows.size() < 2 || rows.front() != 0 || tau.size() < 3 || tau.size() % 2 == 0 || tau.front() != 0 ||
      tau.back() != 1)
    throw std::invalid_argument("meridian_mesh: need rows from 0 and an odd number of fractions from 0 to 1");
  for (size_t i = 1; i < rows.size(); ++i)
    if (!(rows[i] > rows[i - 1])) throw std::invalid_argument("meridian_mesh: rows must increase");
  for (size_t j = 1; j < tau.size(); ++j)
    if (!(tau[j] > tau[j - 1])) throw std::invalid_argument("meridian_mesh: fractions must increase");
  const int nr = static_cast<int>(rows.size()) - 1, nz = static_cast<int>(tau.size() / 2);
  const int ni = 2 * nr + 1, nj = 2 * nz + 1;  // the P2 node grid
  MeridianMesh m;
  m.num_vertices = (nr + 1) * (nz + 1);
  m.nodes.resize(ni * nj, 2);
  std::vector<int> id(ni * nj);
  int next_vertex = 0, next_mid = m.num_vertices;
  for (int i = 0; i < ni; ++i)
    for (int j = 0; j < nj; ++j) {
      const int k = (i % 2 == 0 && j % 2 == 0) ? next_vertex++ : next_mid++;
      id[i * nj + j] = k;
      const double r = i % 2 == 0 ? rows[i / 2] : 0.5 * (rows[i / 2] + rows[i / 2 + 1]);
      m.nodes(k, 0) = r;
      m.nodes(k, 1) = top(r) * tau[j];
    }
  const auto at = [&](int i, int j) { return id[i * nj + j]; };
  m.tris.resize(2 * nr * nz, 6);
  int t = 0;
  for (int a = 0; a < nr; ++a)
    for (int b = 0; b < nz; ++b) {
      const int i = 2 * a, j = 2 * b;
      m.tris.row(t++) << at(i, j), at(i + 2, j), at(i + 2, j + 2), at(i + 1, j), at(i + 2, j + 1),
          at(i + 1, j + 1);
      m.tris.row(t++) << at(i, j), at(i + 2, j + 2), at(i, j + 2), at(i + 1, j + 1), at(i + 1, j + 2),
          at(i, j + 1);
    }
  for (int i = 0; i < ni; ++i) {
    m.base.push_back(at(i, 0));
    m.top.push_back(at(i, nj - 1));
  }
  for (int j = 0; j < nj; ++j) {
    m.axis.push_back(at(0, j));
    m.side.push_back(at(ni - 1, j));
  }
  return m;
}

std::vector<double> graded_points(double L, double c0, double c1, double growth, double cap) {
  std::vector<double> x{0};
  const auto cell = [&](double p) {
    return std::min({cap, c0 + (growth - 1) * p, c1 + (growth - 1) * std::max(0.0, L - p)});
  };
  while (x.back() + 1.5 * cell(x.back()) < L) x.push_back(x.back() + cell(x.back()));
  x.push_back(L);
  return x;
}

MeridianMesh meridian_mesh(const std::function<double(double)>& top, double radius, const MeridianSizes& z,
                           const MeridianPost& post) {
  const double a = post.radius, H = post.height, T0 = top(0) - H;
  if (!(a > 0) || !(a < radius) || !(H > 0) || !(T0 > 0) || !(top(radius) > H) || !(z.axis_cell > 0) ||
      !(z.growth >= 1) || !(z.max_cell > 0) || z.layers < 1 || post.rim_cell < 0)
    throw std::invalid_argument(
        "meridian_mesh: need 0 < post radius < radius, 0 < post height < top, cells > 0, growth >= 1");
  const double rim = post.rim_cell > 0 ? post.rim_cell : 7.5 * z.axis_cell * z.axis_cell / top(0);
  // Radial vertex rows: inside the post's radius (above its top) and beyond it, fine at the rim.
  std::vector<double> rows = graded_points(a, z.axis_cell, rim, z.growth, z.axis_cell);
  const int ia = static_cast<int>(rows.size()) - 1;  // the row at r = a
  for (double r : graded_points(radius - a, rim, z.max_cell, z.growth, z.max_cell))
    if (r > 0) rows.push_back(a + r);
  // Heights beside the post (fine at its foot and top) and the fractions τ above its top (fine at the post,
  // at the top as the layer grading's end cells, top(0)/(2·layers)).
  const std::vector<double> low = graded_points(H, rim, rim, z.growth, z.axis_cell);
  std::vector<double> tau =
      graded_points(T0, rim, top(0) / (2 * z.layers), z.growth, 1.5 * top(0) / z.layers);
  for (double& t : tau) t /= T0;
  const int nr = static_cast<int>(rows.size()) - 1, n1 = static_cast<int>(low.size()) - 1;
  const int nz = n1 + static_cast<int>(tau.size()) - 1;
  const int ni = 2 * nr + 1, nj = 2 * nz + 1;  // the P2 node grid
  const auto exists = [&](int i, int j) { return i >= 2 * ia || j >= 2 * n1; };
  const auto half = [](const std::vector<double>& v, int k) {
    return k % 2 == 0 ? v[k / 2] : 0.5 * (v[k / 2] + v[k / 2 + 1]);
  };
  MeridianMesh m;
  m.post_radius = a, m.post_height = H;
  std::vector<int> id(ni * nj, -1);
  int count[2] = {0, 0};
  for (int i = 0; i < ni; ++i)
    for (int j = 0; j < nj; ++j)
      if (exists(i, j)) ++count[i % 2 == 0 && j % 2 == 0 ? 0 : 1];
  m.num_vertices = count[0];
  m.nodes.resize(count[0] + count[1], 2);
  int next_vertex = 0, next_mid = m.num_vertices;
  for (int i = 0; i < ni; ++i)
    for (int j = 0; j < nj; ++j) {
      if (!exists(i, j)) continue;
      const int k = (i % 2 == 0 && j % 2 == 0) ? next_vertex++ : next_mid++;
      id[i * nj + j] = k;
      const double r = half(rows, i);
      m.nodes(k, 0) = r;
      m.nodes(k, 1) = j <= 2 * n1 ? half(low, j) : H + (top(r) - H) * half(tau, j - 2 * n1);
    }
  const auto at = [&](int i, int j) { return id[i * nj + j]; };
  m.tris.resize(2 * (nr * nz - ia * n1), 6);
  int t = 0;
  for (int c = 0; c < nr; ++c)
    for (int b = 0; b < nz; ++b) {
      if (c < ia && b < n1) continue;  // inside the post
      const int i = 2 * c, j = 2 * b;
      m.tris.row(t++) << at(i, j), at(i + 2, j), at(i + 2, j + 2), at(i + 1, j), at(i + 2, j + 1),
          at(i + 1, j + 1);
      m.tris.row(t++) << at(i, j), at(i + 2, j + 2), at(i, j + 2), at(i + 1, j + 1), at(i + 1, j + 2),
          at(i, j + 1);
    }
  for (int i = 2 * ia + 1; i < ni; ++i) m.base.push_back(at(i, 0));
  for (int j = 0; j <= 2 * n1; ++j) m.post.push_back(at(2 * ia, j));
  for (int i = 2 * ia - 1; i >= 0; --i) m.post.push_back(at(i, 2 * n1));
  for (int i = 0; i < ni; ++i) m.top.push_back(at(i, nj - 1));
  for (int j = 2 * n1; j < nj; ++j) m.axis.push_back(at(0, j));
  for (int j = 0; j < nj; ++j) m.side.push_back(at(ni - 1, j));
  return m;
}

namespace {
// One Fourier mode's adjoint solves: (U, V, W) at the top nodes for each column of w. mode 0: u_r = U, u_z =
// W (V = 0); mode 1: u_r = U cos θ, u_θ = V sin θ, u_z = W cos θ, p = P cos θ. w (held nodes × readings):
// the readings' weights on the held nodes (the base and a post's wall and top), imposed as their
// displacement (mode 0: W = −w; mode 1: U = w, V = −w, the x displacement w).
struct ModeField {
  std::vector<std::vector<double>> U, V, W;  // per reading
  int dofs = 0;
};

ModeField solve_mode(const MeridianMesh& m, const std::vector<int>& held, double nu, SideCondition side,
                     int mode, const Eigen::MatrixXd& w, MeridianGreen::Cost& cost) {
  const MeridianMode system(m, mode, nu, 1, side, held);
  MeridianMode::Fields prescribed;
  if (mode == 0) {
    prescribed.W = -w;
  } else {
    prescribed.U = w;
    prescribed.V = -w;
  }
  const int nread = static_cast<int>(w.cols());
  const MeridianMode::Fields u = system.solve(prescribed, {}, nread);
  ModeField f;
  f.dofs = system.dofs();
  f.U.resize(nread), f.V.resize(nread), f.W.resize(nread);
  for (int c = 0; c < nread; ++c)
    for (int k : m.top) {
      f.U[c].push_back(u.U(k, c));
      f.V[c].push_back(mode == 1 ? u.V(k, c) : 0.0);
      f.W[c].push_back(u.W(k, c));
    }
  cost.assemble_s += system.cost().assemble_s;
  cost.factor_s += system.cost().factor_s;
  cost.solve_s += system.cost().solve_s;
  return f;
}
}  // namespace

MeridianGreen::MeridianGreen(const MeridianMesh& m, double nu, SideCondition side,
                             const ReadingSite& sensor) {
  if (!sensor.axisymmetric())
    throw std::invalid_argument("the meridian path reads only sensors that are bodies of revolution");
  const MeridianReading reading = meridian_reading(m, sensor);
  const std::vector<int>& held = reading.held;
  const Eigen::MatrixXd &w = reading.w, &w_z = reading.w_z;
  // σ_z = t_z (the base's traction on the skin, whose outward normal is −e_z): impose −w along z. σ_x = −t_x:
  // impose +w along x.
  const ModeField z = solve_mode(m, held, nu, side, 0, w_z, cost_),
                  x = solve_mode(m, held, nu, side, 1, w, cost_);
  dofs_ = z.dofs + x.dofs;
  for (size_t i = 0; i < m.top.size(); ++i) r_.push_back(m.nodes(m.top[i], 0));
  // Reciprocity (green/fe_green.hpp): g_ab(X) = f_a·y_b(X), f_z = −e_z (pressing), f_x = +e_x.
  for (int c = 0; c < w.cols(); ++c) {
    Maps& f = maps_[c];
    f.zz = z.W[c], f.u0 = z.U[c], f.w1 = x.W[c], f.u1 = x.U[c], f.v1 = x.V[c];
    for (double& v : f.zz) v = -v;
  }
  // A post has no centre value: both readings are the post's.
  if (sensor.post()) maps_[1] = maps_[0];
  has_disc_ = w.cols() == 2 || sensor.post();
}

double MeridianGreen::interpolate(const std::vector<double>& f, double rho) const {
  return meridian_interpolate(
      r_, Eigen::Map<const Eigen::VectorXd>(f.data(), static_cast<Eigen::Index>(f.size())), rho);
}

green::GreenSample MeridianGreen::at(double x, double y, bool disc) const {
  if (disc && !has_disc_) throw std::logic_error("MeridianGreen: built without a disc reading");
  const Maps& f = maps_[disc ? 1 : 0];
  const double rho = std::hypot(x, y);
  const double c = rho > 0 ? x / rho : 1, s = rho > 0 ? y / rho : 0;
  green::GreenSample g;
  g.zz = interpolate(f.zz, rho);
  g.xz = interpolate(f.u0, rho) * c;
  g.zx = -interpolate(f.w1, rho) * c;
  g.xx = interpolate(f.u1, rho) * c * c - interpolate(f.v1, rho) * s * s;
  return g;
}

green::GreenSample MeridianGreen::at(bool disc, double x, double y, green::LayerLoad load,
                                     double radius) const {
  green::GreenSample v;
  for (const auto& q : green::load_rule(load, radius)) {
    const green::GreenSample p = at(x + q[0], y + q[1], disc);
    v.zz += q[2] * p.zz, v.zx += q[2] * p.zx, v.xz += q[2] * p.xz, v.xx += q[2] * p.xx;
  }
  return v;
}

MeridianGreen::Shape MeridianGreen::shape(const std::vector<double>& along_x,
                                          const std::vector<double>& integrand, double angular) const {
  // Each top edge sampled at its Gauss points (integral) and at 16 even steps of its parameter (peak, half
  // width; the map is quadratic in the parameter, so the steps resolve its maximum to O(1/16²) of the edge's
  // variation).
  Shape s;
  const GaussRule1d g = gauss_legendre01(4);
  std::vector<std::pair<double, double>> samples;  // (ρ, g)
  for (size_t e = 0; e + 2 < r_.size(); e += 2) {
    double L[3], dL[3];
    for (size_t k = 0; k < g.x.size(); ++k) {
      meridian_p2_line(g.x[k], L, dL);
      const double r = L[0] * r_[e] + L[1] * r_[e + 1] + L[2] * r_[e + 2];
      const double drdu = dL[0] * r_[e] + dL[1] * r_[e + 1] + dL[2] * r_[e + 2];
      const double f = L[0] * integrand[e] + L[1] * integrand[e + 1] + L[2] * integrand[e + 2];
      s.integral += angular * g.w[k] * f * r * drdu;
    }
    for (int k = 0; k < 16; ++k) {
      meridian_p2_line(k / 16.0, L, dL);
      samples.push_back({L[0] * r_[e] + L[1] * r_[e + 1] + L[2] * r_[e + 2],
                         L[0] * along_x[e] + L[1] * along_x[e + 1] + L[2] * along_x[e + 2]});
    }
  }
  samples.push_back({r_.back(), along_x.back()});
  for (const auto& [r, v] : samples)
    if (std::abs(v) > std::abs(s.peak)) s.peak = v, s.peak_at = r;
  // The outermost crossing of |g| = |peak| / 2, linear between samples.
  const double half = 0.5 * std::abs(s.peak);
  for (size_t i = samples.size() - 1; i > 0; --i)
    if (std::abs(samples[i - 1].second) >= half) {
      const double a = std::abs(samples[i - 1].second), b = std::abs(samples[i].second);
      const double t = b >= half ? 1.0 : (a - half) / (a - b);
      s.half_width = samples[i - 1].first + t * (samples[i].first - samples[i - 1].first);
      break;
    }
  return s;
}

MeridianGreen::Shape MeridianGreen::shape_zz() const {
  if (!has_disc_) throw std::logic_error("MeridianGreen: built without the sensor's own reading");
  return shape(maps_[1].zz, maps_[1].zz, 2 * M_PI);
}

MeridianGreen::Shape MeridianGreen::shape_xx() const {
  if (!has_disc_) throw std::logic_error("MeridianGreen: built without the sensor's own reading");
  // g_xx = u cos² − v sin²: along +x it is u; over the angle it integrates to π(u − v).
  std::vector<double> u_minus_v(maps_[1].u1.size());
  for (size_t i = 0; i < u_minus_v.size(); ++i) u_minus_v[i] = maps_[1].u1[i] - maps_[1].v1[i];
  return shape(maps_[1].u1, u_minus_v, M_PI);
}

}  // namespace skinfem
