#include "skinfem/validation/paper_model.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "skinfem/fem/face_index.hpp"
#include "skinfem/mesh/gauss_legendre.hpp"
#include "skinfem/mesh/surface_quadrature.hpp"

namespace skinfem::validation {

GreenKernel rescaled_halfspace_kernel(std::vector<double> thickness, double k) {
  return [h = std::move(thickness), k](int sensor, double ox, double oy) {
    return green::rescaled_green(ox, oy, h.at(sensor), k);
  };
}

GreenKernel layer_exact_kernel(double h, double nu, double reach, double step) {
  // g_zz, g_zx, g_xz depend on r (times x/r); g_xx = C0(r) − cos2θ·C2(r): the values on the x axis and on
  // the y axis give all four.
  const green::LayerGreen layer(h, nu);
  const int n = static_cast<int>(std::ceil(reach / step)) + 1;
  auto on_x = std::make_shared<std::vector<green::GreenSample>>(n);
  auto on_y = std::make_shared<std::vector<double>>(n);
  for (int i = 0; i < n; ++i) {
    const double r = i * step;
    (*on_x)[i] = layer.at(std::max(r, 1e-9), 0);
    (*on_y)[i] = layer.at(0, std::max(r, 1e-9)).xx;
  }
  return [on_x, on_y, step, n, reach](int, double ox, double oy) {
    const double r = std::hypot(ox, oy);
    if (r > reach) throw std::out_of_range("layer_exact_kernel: offset beyond the tabulated reach");
    const double f = r / step;
    const int i = std::min(static_cast<int>(f), n - 2);
    const double t = f - i;
    const auto lerp = [t](double a, double b) { return (1 - t) * a + t * b; };
    const green::GreenSample &a = (*on_x)[i], &b = (*on_x)[i + 1];
    const double zz = lerp(a.zz, b.zz), zx_r = lerp(a.zx, b.zx), xz_r = lerp(a.xz, b.xz);
    const double xx_x = lerp(a.xx, b.xx), xx_y = lerp((*on_y)[i], (*on_y)[i + 1]);
    const double c = r > 0 ? ox / r : 0, cos2 = r > 0 ? (ox * ox - oy * oy) / (r * r) : 0;
    green::GreenSample g;
    g.zz = zz;
    g.zx = c * zx_r;
    g.xz = c * xz_r;
    // On the x axis xx = C0 − C2, on the y axis C0 + C2.
    g.xx = 0.5 * (xx_x + xx_y) - cos2 * 0.5 * (xx_y - xx_x);
    return g;
  };
}

GreenKernel fe_kernel(const green::FeGreen& fe) {
  return [&fe](int sensor, double ox, double oy) {
    return fe.at(sensor, true, ox, oy, green::LayerLoad::point, 0);
  };
}

double Tractions::force() const {
  double f = 0;
  for (const auto& p : points) f += p[2];
  return f;
}

Tractions axisymmetric_tractions(std::function<double(double)> p_of_r, const Vec2& center, double a,
                                 double ratio, double shear, int n_theta, int n_phi) {
  Tractions t;
  t.pressure = [p_of_r, center, a](double x, double y) {
    const double r = std::hypot(x - center[0], y - center[1]);
    return r < a ? p_of_r(r) : 0.0;
  };
  t.tangential = [p_of_r, center, a, ratio, shear](double x, double y) {
    const double r = std::hypot(x - center[0], y - center[1]);
    return r < a ? ratio * p_of_r(r) + shear : 0.0;
  };
  const GaussRule1d g = gauss_legendre01(n_theta);
  for (int i = 0; i < n_theta; ++i) {
    const double theta = 0.5 * M_PI * g.x[i];
    const double r = a * std::sin(theta), dr = a * std::cos(theta) * 0.5 * M_PI * g.w[i];
    const double w = r * dr * 2 * M_PI / n_phi, pr = p_of_r(r) * w;
    for (int j = 0; j < n_phi; ++j) {
      const double phi = 2 * M_PI * (j + 0.5) / n_phi;
      t.points.push_back(
          {center[0] + r * std::cos(phi), center[1] + r * std::sin(phi), pr, ratio * pr + shear * w});
    }
  }
  return t;
}

Tractions hertz_tractions(const contact::HertzHalfspace& hertz, const Vec2& center, double ratio,
                          double shear) {
  const double a = hertz.a_mm, p0 = hertz.p0_MPa;
  return axisymmetric_tractions(
      [a, p0](double r) { return p0 * std::sqrt(std::max(0.0, 1 - r * r / (a * a))); }, center, a, ratio,
      shear);
}

Tractions layer_hertz_tractions(const contact::LayerHertzResult& layer, const Vec2& center, double ratio,
                                double shear) {
  return axisymmetric_tractions([layer](double r) { return layer.pressure_MPa(r); }, center, layer.a_mm,
                                ratio, shear);
}

namespace {
// The nodal pressure λ and traction ratio·λ + shear of the zone's multipliers, 0 elsewhere.
std::pair<std::vector<double>, std::vector<double>> zone_nodal_tractions(const contact::MortarZone& zone,
                                                                         const TetMesh& mesh,
                                                                         const Eigen::VectorXd& lambda,
                                                                         double ratio,
                                                                         const Eigen::VectorXd& shear) {
  std::pair<std::vector<double>, std::vector<double>> v{std::vector<double>(mesh.num_nodes(), 0.0),
                                                        std::vector<double>(mesh.num_nodes(), 0.0)};
  for (int i = 0; i < zone.size(); ++i) {
    v.first[zone.vertices[i]] = lambda[i];
    v.second[zone.vertices[i]] = ratio * lambda[i] + (shear.size() ? shear[i] : 0.0);
  }
  return v;
}

// Linear in the face's corners (the multipliers' shape functions).
double on_face(const TetMesh& mesh, const std::vector<double>& v, int f, double s, double t) {
  return (1 - s - t) * v[mesh.faces(f, 0)] + s * v[mesh.faces(f, 1)] + t * v[mesh.faces(f, 2)];
}
}  // namespace

Tractions fe_tractions(const contact::MortarZone& zone, const TetMesh& mesh, const Eigen::VectorXd& lambda,
                       double ratio, const Eigen::VectorXd& shear) {
  Tractions t;
  auto [p_nodal, t_nodal] = zone_nodal_tractions(zone, mesh, lambda, ratio, shear);
  auto nodal = std::make_shared<std::vector<double>>(std::move(p_nodal));
  auto nodal_t = std::make_shared<std::vector<double>>(std::move(t_nodal));
  for (int f : zone.faces)
    for (const FacePoint& q : face_quadrature(mesh, f)) {
      const double p = on_face(mesh, *nodal, f, q.s, q.t), pt = on_face(mesh, *nodal_t, f, q.s, q.t);
      if (p != 0 || pt != 0) t.points.push_back({q.x.x(), q.x.y(), q.weight_xy * p, q.weight_xy * pt});
    }
  // The face index is built on the first pointwise query only: sweeps convolve many of these and never ask.
  auto top = std::make_shared<std::unique_ptr<PlanarFaceIndex>>();
  const auto pointwise = [top, &mesh](std::shared_ptr<std::vector<double>> v) {
    return [top, &mesh, v](double x, double y) {
      if (!*top) *top = std::make_unique<PlanarFaceIndex>(mesh, kTop);
      double s = 0, tt = 0;
      const int f = (*top)->find(x, y, s, tt);
      return f < 0 ? 0.0 : on_face(mesh, *v, f, s, tt);
    };
  };
  t.pressure = pointwise(nodal);
  t.tangential = pointwise(nodal_t);
  return t;
}

Eigen::VectorXd convolve(const Tractions& t, const GreenKernel& g, const Sensors& sensors) {
  const int ns = static_cast<int>(sensors.positions.size());
  Eigen::VectorXd out = Eigen::VectorXd::Zero(2 * ns);
  for (int k = 0; k < ns; ++k)
    for (const auto& p : t.points) {
      const green::GreenSample G = g(k, p[0] - sensors.positions[k][0], p[1] - sensors.positions[k][1]);
      out[2 * k] += p[2] * G.zz + p[3] * G.xz;
      out[2 * k + 1] += p[2] * G.zx + p[3] * G.xx;
    }
  return out;
}

FeConvolution::FeConvolution(const contact::MortarZone& zone, const TetMesh& mesh, const GreenKernel& g,
                             const Sensors& sensors)
    : zone_(zone), mesh_(mesh), sensors_(static_cast<int>(sensors.positions.size())) {
  std::vector<Vec2> xy;
  for (int f : zone.faces)
    for (const FacePoint& q : face_quadrature(mesh, f)) {
      points_.push_back({f, q.s, q.t, q.weight_xy});
      xy.push_back({q.x.x(), q.x.y()});
    }
  g_.reserve(sensors_ * points_.size());
  for (int k = 0; k < sensors_; ++k)
    for (const Vec2& x : xy)
      g_.push_back(g(k, x[0] - sensors.positions[k][0], x[1] - sensors.positions[k][1]));
}

Eigen::VectorXd FeConvolution::operator()(const Eigen::VectorXd& lambda, double ratio,
                                          const Eigen::VectorXd& shear) const {
  const auto [nodal, nodal_t] = zone_nodal_tractions(zone_, mesh_, lambda, ratio, shear);
  // fe_tractions's points: those where the pressure or the traction is not zero, each with its weight.
  std::vector<std::array<double, 2>> w(points_.size());
  std::vector<char> on(points_.size());
  for (size_t q = 0; q < points_.size(); ++q) {
    const Point& pt = points_[q];
    const double p = on_face(mesh_, nodal, pt.face, pt.s, pt.t),
                 tt = on_face(mesh_, nodal_t, pt.face, pt.s, pt.t);
    on[q] = p != 0 || tt != 0;
    w[q] = {pt.weight_xy * p, pt.weight_xy * tt};
  }
  Eigen::VectorXd out = Eigen::VectorXd::Zero(2 * sensors_);
  for (int k = 0; k < sensors_; ++k)
    for (size_t q = 0; q < points_.size(); ++q) {
      if (!on[q]) continue;
      const green::GreenSample& G = g_[k * points_.size() + q];
      out[2 * k] += w[q][0] * G.zz + w[q][1] * G.xz;
      out[2 * k + 1] += w[q][0] * G.zx + w[q][1] * G.xx;
    }
  return out;
}

Eigen::MatrixXd first_order_hole(const Tractions& t, const GreenKernel& g, const Sensors& sensors,
                                 const std::vector<Vec2>& centers, double hole_area) {
  const int ns = static_cast<int>(sensors.positions.size());
  Eigen::MatrixXd out(centers.size(), 2 * ns);
  for (size_t i = 0; i < centers.size(); ++i) {
    const double pz = t.pressure(centers[i][0], centers[i][1]),
                 px = t.tangential(centers[i][0], centers[i][1]);
    for (int k = 0; k < ns; ++k) {
      const green::GreenSample G =
          g(k, centers[i][0] - sensors.positions[k][0], centers[i][1] - sensors.positions[k][1]);
      out(i, 2 * k) = -(px * G.xz + pz * G.zz) * hole_area;
      out(i, 2 * k + 1) = -(px * G.xx + pz * G.zx) * hole_area;
    }
  }
  return out;
}

}  // namespace skinfem::validation
