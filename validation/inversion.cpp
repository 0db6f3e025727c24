#include "skinfem/validation/inversion.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "skinfem/scene/parallel.hpp"
#include "skinfem/scene/random.hpp"

namespace skinfem::validation {

Eigen::VectorXd nnls(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, int max_iterations) {
  // AᵀA by a symmetric rank update: half the product's flops.
  Eigen::MatrixXd G = Eigen::MatrixXd::Zero(A.cols(), A.cols());
  G.selfadjointView<Eigen::Lower>().rankUpdate(A.transpose());
  G.triangularView<Eigen::StrictlyUpper>() = G.transpose();
  return nnls_gram(G, A.transpose() * b, max_iterations);
}

Eigen::VectorXd nnls_gram(const Eigen::MatrixXd& G, const Eigen::VectorXd& c, int max_iterations) {
  const int n = static_cast<int>(G.cols());
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
  std::vector<char> in(n, 0);
  const double tol = 1e-10 * std::max(1.0, c.cwiseAbs().maxCoeff());
  const int limit = max_iterations > 0 ? max_iterations : 3 * n;
  // The passive set's least squares, the others at zero.
  const auto solve = [&](Eigen::VectorXd& z) {
    std::vector<int> P;
    for (int j = 0; j < n; ++j)
      if (in[j]) P.push_back(j);
    Eigen::MatrixXd GP(P.size(), P.size());
    Eigen::VectorXd cP(P.size());
    for (size_t a = 0; a < P.size(); ++a) {
      cP[a] = c[P[a]];
      for (size_t b2 = 0; b2 < P.size(); ++b2) GP(a, b2) = G(P[a], P[b2]);
    }
    const Eigen::VectorXd zP = GP.ldlt().solve(cP);
    z.setZero(n);
    for (size_t a = 0; a < P.size(); ++a) z[P[a]] = zP[a];
  };
  for (int it = 0;; ++it) {
    if (it >= limit) throw std::runtime_error("nnls: no convergence in " + std::to_string(limit) + " steps");
    const Eigen::VectorXd w = c - G * x;
    int t = -1;
    for (int j = 0; j < n; ++j)
      if (!in[j] && w[j] > tol && (t < 0 || w[j] > w[t])) t = j;
    if (t < 0) return x;
    in[t] = 1;
    Eigen::VectorXd z;
    solve(z);
    // Back along the segment x → z until every passive entry is positive.
    for (int inner = 0; inner < n; ++inner) {
      double alpha = 1;
      bool negative = false;
      for (int j = 0; j < n; ++j)
        if (in[j] && z[j] <= 0) {
          negative = true;
          alpha = std::min(alpha, x[j] / (x[j] - z[j]));
        }
      if (!negative) break;
      x += alpha * (z - x);
      for (int j = 0; j < n; ++j)
        if (in[j] && x[j] <= tol * 1e-6) in[j] = 0, x[j] = 0;
      solve(z);
    }
    x = z;
  }
}

int site_column(const HoleResponses& r, double s) {
  for (size_t k = 0; k < r.sites.size(); ++k)
    if (std::abs(r.sites[k] - s) < 1e-6) return static_cast<int>(k);
  return -1;
}

namespace {
// An atom whose whitened response is below this fraction of the largest is not identifiable (invert_scan).
constexpr double kIdentifiable = 1e-6;

std::vector<int> sites_for(const std::vector<double>& sensors, const HoleResponses& r, double offset) {
  std::vector<int> k;
  for (double x : sensors) {
    k.push_back(site_column(r, x - offset));
    if (k.back() < 0)
      throw std::invalid_argument("invert_scan: no response for a sensor at " + std::to_string(x - offset) +
                                  " mm in the contact's frame (offset " + std::to_string(offset) + " mm)");
  }
  return k;
}

// R of column col at x, linear between the grid's points, 0 outside.
double response_at(const HoleResponses& r, int col, double x) {
  const double m = (x - r.x0) / r.dx;
  const int i = static_cast<int>(std::floor(m));
  if (i < 0 || i + 1 >= r.R.rows())
    return (i == r.R.rows() - 1 && std::abs(m - i) < 1e-9) ? r.R(i, col) : 0.0;
  const double t = m - i;
  return (1 - t) * r.R(i, col) + t * r.R(i + 1, col);
}

// Per component of a sensor, 1/σ of the mean of N passages.
double weight(const SensorNoise& n, int component) {
  return std::sqrt(double(n.passages)) / (component == 0 ? n.sigma_z_kPa : n.sigma_x_kPa);
}
}  // namespace

Eigen::MatrixXd simulated_signals(const std::vector<double>& u, const std::vector<double>& sensors,
                                  const HoleResponses& r, const std::vector<Feature>& features,
                                  double offset) {
  const std::vector<int> k = sites_for(sensors, r, offset);
  Eigen::MatrixXd y = Eigen::MatrixXd::Zero(static_cast<int>(u.size()), 2 * static_cast<int>(sensors.size()));
  for (const Feature& f : features)
    for (size_t i = 0; i < u.size(); ++i)
      for (size_t s = 0; s < sensors.size(); ++s)
        for (int c = 0; c < 2; ++c)
          y(i, 2 * s + c) += f.amplitude * response_at(r, 2 * k[s] + c, f.position_mm - offset + u[i]);
  return y;
}

Inversion invert_scan(const ScanSignals& sig, const HoleResponses& r, const SensorNoise& noise,
                      const std::vector<double>& offsets, double p_fa, int single_sensor) {
  const int nu = static_cast<int>(sig.u.size()), ns = static_cast<int>(sig.sensors.size());
  if (nu < 2 || sig.y.rows() != nu || sig.y.cols() != 2 * ns)
    throw std::invalid_argument("invert_scan: the signals' shape does not match their positions and sensors");
  const double du = (sig.u.back() - sig.u.front()) / (nu - 1);
  if (std::abs(du - r.dx) > 1e-9 * std::max(1.0, r.dx))
    throw std::invalid_argument("invert_scan: the scan's step must be the dictionary's");
  if (single_sensor >= ns) throw std::invalid_argument("invert_scan: no such sensor");
  std::vector<int> used;
  for (int s = 0; s < ns; ++s)
    if (single_sensor < 0 || s == single_sensor) used.push_back(s);
  // Atom j: a hole at q_j = x0 − u0 + (j − (nu − 1)) dx, whose sample i reads the grid's point j − (nu − 1) +
  // i.
  const int rows = static_cast<int>(r.R.rows()), atoms = rows + nu - 1;
  const auto q_of = [&](int j) { return r.x0 - sig.u[0] + (j - (nu - 1)) * r.dx; };
  Eigen::VectorXd b(nu * 2 * static_cast<int>(used.size()));
  for (int i = 0; i < nu; ++i)
    for (size_t s = 0; s < used.size(); ++s)
      for (int c = 0; c < 2; ++c)
        b[(i * used.size() + s) * 2 + c] = weight(noise, c) * sig.y(i, 2 * used[s] + c);
  // The offsets are independent fits: on the machine's cores, each in its own slot.
  const int n_off = static_cast<int>(offsets.size());
  std::vector<Eigen::VectorXd> amplitudes(n_off);
  std::vector<double> residuals(n_off);
  for (double delta : offsets) sites_for(sig.sensors, r, delta);  // throws on the calling thread
  // The design A (a row per sample (i, sensor, component), a column per atom) is Hankel in each sensor's
  // component: A((i, sc), j) = P(i + j, sc), P the weighted responses padded by nu − 1 zeros on both sides.
  // Its Gram matrix therefore follows along each diagonal, G(j+1, j'+1) = G(j, j') + P(j+nu)·P(j'+nu) −
  // P(j)·P(j'), in O(atoms² · sc) instead of the product's O(atoms² · samples) (computed afresh every
  // kRestart steps, so that the recurrence's round-off stays at a few ulps of the largest entry).
  const int nsc = 2 * static_cast<int>(used.size());
  const auto padded = [&](double delta) {
    const std::vector<int> k = sites_for(sig.sensors, r, delta);
    Eigen::MatrixXd P = Eigen::MatrixXd::Zero(rows + 2 * (nu - 1), nsc);
    for (size_t s = 0; s < used.size(); ++s)
      for (int c = 0; c < 2; ++c)
        P.block(nu - 1, 2 * s + c, rows, 1) = weight(noise, c) * r.R.col(2 * k[used[s]] + c);
    return P;
  };
  const Eigen::Map<const Eigen::MatrixXd> B(b.data(), nsc, nu);  // B(sc, i) = b[i·nsc + sc]
  struct Normal {
    Eigen::MatrixXd G;
    Eigen::VectorXd c;
  };
  const auto normal_equations = [&](const Eigen::MatrixXd& P) {
    constexpr int kRestart = 64;
    Normal ne{Eigen::MatrixXd::Zero(atoms, atoms), Eigen::VectorXd::Zero(atoms)};
    const auto direct = [&](int j, int jj) {
      return (P.middleRows(j, nu).cwiseProduct(P.middleRows(jj, nu))).sum();
    };
    for (int d = 0; d < atoms; ++d)
      for (int j = 0; j + d < atoms; ++j) {
        double& g = ne.G(j + d, j);
        g = j % kRestart == 0 ? direct(j, j + d)
                              : ne.G(j + d - 1, j - 1) + P.row(j + nu - 1).dot(P.row(j + d + nu - 1)) -
                                    P.row(j - 1).dot(P.row(j + d - 1));
        ne.G(j, j + d) = g;
      }
    for (int j = 0; j < atoms; ++j) ne.c[j] = (P.middleRows(j, nu).transpose().cwiseProduct(B)).sum();
    // A hole the scan never brings into the contact gives the FE's round-off (1e-13 of the largest
    // response), not a signal: its amplitude is not identifiable, and the fit would spend it on the noise
    // (amplitudes of 1e10). Such atoms are left out (a zero column never enters NNLS's active set).
    const double floor = kIdentifiable * kIdentifiable * ne.G.diagonal().maxCoeff();
    for (int j = 0; j < atoms; ++j)
      if (ne.G(j, j) <= floor) ne.G.row(j).setZero(), ne.G.col(j).setZero(), ne.c[j] = 0;
    return ne;
  };
  // A a, from the non-zero amplitudes only (samples as in b).
  const auto apply = [&](const Eigen::MatrixXd& P, const Eigen::VectorXd& a) {
    Eigen::MatrixXd Y = Eigen::MatrixXd::Zero(nsc, nu);
    for (int j = 0; j < atoms; ++j)
      if (a[j] != 0) Y += a[j] * P.middleRows(j, nu).transpose();
    return Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(Y.data(), Y.size()));
  };
  for_each_index(n_off, [&](std::size_t o) {
    const Eigen::MatrixXd P = padded(offsets[o]);
    const Normal ne = normal_equations(P);
    amplitudes[o] = nnls_gram(ne.G, ne.c);
    residuals[o] = (b - apply(P, amplitudes[o])).squaredNorm();
  });
  Inversion best;
  best.offsets = offsets;
  best.residuals = residuals;
  int chosen = 0;
  for (int o = 1; o < n_off; ++o)
    if (residuals[o] < residuals[chosen]) chosen = o;
  best.weighted_residual = residuals[chosen];
  best.offset_mm = best.offset_refined_mm = offsets[chosen];
  if (chosen > 0 && chosen + 1 < n_off) {
    const double x0 = offsets[chosen - 1], x1 = offsets[chosen], x2 = offsets[chosen + 1];
    const double f0 = residuals[chosen - 1], f1 = residuals[chosen], f2 = residuals[chosen + 1];
    const double den = (x1 - x0) * (f1 - f2) - (x1 - x2) * (f1 - f0);
    // The vertex lies between the neighbours when the parabola opens upwards (den < 0 for x0 < x1 < x2).
    if (x0 < x1 && x1 < x2 && den < 0)
      best.offset_refined_mm =
          x1 - 0.5 * ((x1 - x0) * (x1 - x0) * (f1 - f2) - (x1 - x2) * (x1 - x2) * (f1 - f0)) / den;
  }
  const Eigen::VectorXd& best_a = amplitudes[chosen];
  const Eigen::MatrixXd best_P = padded(offsets[chosen]);
  // Adjacent non-zero atoms are one feature.
  const double tau = detection_threshold(p_fa);
  for (int j = 0; j < atoms;) {
    if (!(best_a[j] > 0)) {
      ++j;
      continue;
    }
    double sum = 0, moment = 0;
    Eigen::VectorXd run = Eigen::VectorXd::Zero(atoms);
    for (; j < atoms && best_a[j] > 0; ++j) {
      sum += best_a[j];
      moment += best_a[j] * q_of(j);
      run[j] = best_a[j];
    }
    const Eigen::VectorXd signal = apply(best_P, run);
    Feature f;
    f.amplitude = sum;
    f.position_mm = moment / sum + best.offset_mm;
    f.diameter_mm = r.diameter * std::cbrt(sum);
    f.snr = signal.norm();
    if (f.snr >= tau) best.features.push_back(f);
  }
  return best;
}

double position_crb(const ScanSignals& sig, const HoleResponses& r, const SensorNoise& noise, double q,
                    double a, double offset, int single_sensor) {
  const std::vector<int> k = sites_for(sig.sensors, r, offset);
  Eigen::Matrix2d F = Eigen::Matrix2d::Zero();
  const double h = 0.5 * r.dx;
  for (size_t i = 0; i < sig.u.size(); ++i)
    for (size_t s = 0; s < sig.sensors.size(); ++s) {
      if (single_sensor >= 0 && static_cast<int>(s) != single_sensor) continue;
      for (int c = 0; c < 2; ++c) {
        const int col = 2 * k[s] + c;
        const double x = q + sig.u[i];
        const Eigen::Vector2d g(a * (response_at(r, col, x + h) - response_at(r, col, x - h)) / (2 * h),
                                response_at(r, col, x));
        const double w = weight(noise, c);
        F += w * w * g * g.transpose();
      }
    }
  return std::sqrt(F.inverse()(0, 0));
}

Eigen::MatrixXd with_noise(const Eigen::MatrixXd& y, const SensorNoise& noise, std::uint64_t seed) {
  SplitMix64 rng{seed};
  const double root = std::sqrt(static_cast<double>(noise.passages));
  Eigen::MatrixXd out = y;
  for (Eigen::Index i = 0; i < y.rows(); ++i)
    for (Eigen::Index j = 0; j < y.cols(); ++j)
      out(i, j) += (j % 2 ? noise.sigma_x_kPa : noise.sigma_z_kPa) / root * rng.normal();
  return out;
}

InversionScore score_inversion(const std::vector<Feature>& features, const std::vector<double>& truth,
                               double reach) {
  InversionScore s;
  std::vector<double> best(truth.size(), 1e300);
  for (const Feature& f : features) {
    int nearest = -1;
    for (size_t k = 0; k < truth.size(); ++k)
      if (std::abs(f.position_mm - truth[k]) < reach &&
          (nearest < 0 || std::abs(f.position_mm - truth[k]) < std::abs(f.position_mm - truth[nearest])))
        nearest = static_cast<int>(k);
    if (nearest < 0) {
      ++s.false_features;
      continue;
    }
    // A hole's second feature is one too many: it counts as false, the nearer one as the hole's.
    if (best[nearest] < 1e299) ++s.false_features;
    best[nearest] = std::min(best[nearest], std::abs(f.position_mm - truth[nearest]));
  }
  double sum = 0;
  for (double e : best) {
    if (e > 1e299) {
      ++s.missed;
      continue;
    }
    ++s.found;
    sum += e * e;
    s.largest_error_mm = std::max(s.largest_error_mm, e);
  }
  if (s.found > 0) s.rms_error_mm = std::sqrt(sum / s.found);
  return s;
}

}  // namespace skinfem::validation
