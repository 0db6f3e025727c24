#include "skinfem/green/fe_green.hpp"

#include <cmath>
#include <stdexcept>

#include "skinfem/fem/sensor_reading.hpp"
#include "skinfem/mesh/gauss_legendre.hpp"
#include "skinfem/mesh/surface_quadrature.hpp"

namespace skinfem::green {

std::vector<std::array<double, 3>> load_quadrature(LayerLoad load, double a, int nr, int nt) {
  if (load == LayerLoad::point || a <= 0) return {{0.0, 0.0, 1.0}};
  if (load == LayerLoad::uniform) return uniform_disc_rule(a, nr, nt);
  // r = a sin φ removes the edge singularity: ∫ f r dr / (2πa√(a² − r²)) dθ = (1/2π) ∫∫ f sin φ dφ dθ
  const GaussRule1d g = gauss_legendre01(nr);
  std::vector<std::array<double, 3>> pts;
  for (int i = 0; i < nr; ++i)
    for (int j = 0; j < nt; ++j) {
      const double th = 2 * M_PI * (j + 0.5) / nt, phi = 0.5 * M_PI * g.x[i], r = a * std::sin(phi);
      pts.push_back({r * std::cos(th), r * std::sin(th), 0.5 * M_PI * g.w[i] * std::sin(phi) / nt});
    }
  return pts;
}

FeGreen::FeGreen(const ElasticModel& model, const Sensors& sensors,
                 const std::function<void(const std::string&)>& progress)
    : model_(model), sensors_(sensors), top_(model.mesh(), kTop) {
  if (!model.punch_groups().empty())
    throw std::invalid_argument("FeGreen needs a model without punch constraints");
  const TetMesh& m = model.mesh();
  // All 4 readings of every sensor as one block of prescribed base values (the adjoint loads).
  const int ns = static_cast<int>(sensors.positions.size());
  // Site 2s is sensor s's centre value, 2s + 1 its disc mean.
  std::vector<ReadingSite> sites;
  const auto points = reading_sites(sensors, true), discs = reading_sites(sensors);
  for (int s = 0; s < ns; ++s) sites.insert(sites.end(), {points[s], discs[s]});
  const SensorReadings readings(m, sites, &model.solver());
  Eigen::MatrixXd W(3 * m.num_nodes(), 4 * ns);
  for (int s = 0; s < ns; ++s)
    for (bool disc : {false, true})
      for (char reading : {'z', 'x'})
        W.col(4 * s + 2 * disc + (reading == 'x')) = -readings.weights(2 * s + disc, reading);
  // On a half mesh a force at (x, y) stands for itself and its mirror image at (x, −y) (or, on the cut, for
  // twice the half it carries): the reading per unit force is half the half model's.
  if (is_half_y(m)) W *= 0.5;
  if (progress) progress("adjoint solves: " + std::to_string(4 * ns) + " readings as one block");
  const Eigen::MatrixXd Y =
      model.solver().solve_block(Eigen::MatrixXd::Zero(W.rows(), W.cols()), W, &max_residual_);
  for (int j = 0; j < Y.cols(); ++j) adjoint_.push_back(Y.col(j));
}

const Eigen::VectorXd& FeGreen::adjoint(int sensor, char reading, bool disc) const {
  return adjoint_.at(4 * sensor + 2 * disc + (reading == 'x'));
}

Eigen::Vector3d FeGreen::displacement_at_top(const Eigen::VectorXd& y, double x, double yy) const {
  double s, t;
  const int f = top_.find(x, yy, s, t);
  if (f < 0)
    throw std::out_of_range("load point (" + std::to_string(x) + ", " + std::to_string(yy) +
                            ") is off the top");
  const auto N = triangle_shape(s, t);
  Eigen::Vector3d v = Eigen::Vector3d::Zero();
  for (int k = 0; k < 6; ++k) v += N[k] * y.segment<3>(3 * model_.mesh().faces(f, k));
  if (top_.mirrored(yy)) v.y() = -v.y();
  return v;
}

bool FeGreen::disc_map_at(int sensor, double x, double y, GreenSample& g) const {
  double s, t;
  const int f = top_.find(x, y, s, t);  // g_zz … g_xx are even in y
  if (f < 0) return false;
  const auto N = triangle_shape(s, t);
  Eigen::Vector3d vz = Eigen::Vector3d::Zero(), vx = Eigen::Vector3d::Zero();
  const auto& yz = adjoint(sensor, 'z', true);
  const auto& yx = adjoint(sensor, 'x', true);
  for (int k = 0; k < 6; ++k) {
    const int node = model_.mesh().faces(f, k);
    vz += N[k] * yz.segment<3>(3 * node);
    vx += N[k] * yx.segment<3>(3 * node);
  }
  g = {-vz.z(), -vx.z(), vz.x(), vx.x()};
  return true;
}

const std::vector<std::array<double, 3>>& load_rule(LayerLoad load, double radius) {
  thread_local LayerLoad last_load = LayerLoad::point;
  thread_local double last_radius = -1;
  thread_local std::vector<std::array<double, 3>> rule;
  if (load != last_load || radius != last_radius) {
    rule = load_quadrature(load, radius);
    last_load = load, last_radius = radius;
  }
  return rule;
}

GreenSample FeGreen::at(int sensor, bool disc, double ox, double oy, LayerLoad load, double radius) const {
  const auto& yz = adjoint(sensor, 'z', disc);
  const auto& yx = adjoint(sensor, 'x', disc);
  const double cx = sensors_.positions[sensor][0] + ox, cy = sensors_.positions[sensor][1] + oy;
  Eigen::Vector3d vz = Eigen::Vector3d::Zero(), vx = Eigen::Vector3d::Zero();
  for (const auto& q : load_rule(load, radius)) {
    vz += q[2] * displacement_at_top(yz, cx + q[0], cy + q[1]);
    vx += q[2] * displacement_at_top(yx, cx + q[0], cy + q[1]);
  }
  // A force "along z" presses into the skin (−e_z); along x it is +e_x.
  GreenSample g;
  g.zz = -vz.z();
  g.zx = -vx.z();
  g.xz = vz.x();
  g.xx = vx.x();
  return g;
}

}  // namespace skinfem::green
