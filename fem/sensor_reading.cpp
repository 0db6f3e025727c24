#include "skinfem/fem/sensor_reading.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace skinfem {

ReadingSite disc_site(Vec2 center, double diameter) {
  ReadingSite s;
  s.center = center, s.diameter = diameter;
  return s;
}

ReadingSite post_site(Vec2 center, double diameter, double height, MembraneSprings support) {
  if (!(diameter > 0) || !(height > 0))
    throw std::invalid_argument("post_site: a post needs a diameter and a height > 0, got " +
                                std::to_string(diameter) + " and " + std::to_string(height) + " mm");
  ReadingSite s;
  s.model = SensorModel::post;
  s.center = center, s.diameter = diameter, s.post_height = height, s.support = support;
  return s;
}

std::vector<ReadingSite> reading_sites(const Sensors& sensors, bool point) {
  std::vector<ReadingSite> sites;
  for (const Vec2& p : sensors.positions)
    sites.push_back(sensors.model == SensorModel::post
                        ? post_site(p, sensors.post.diameter, sensors.post.height, sensors.post.support)
                        : disc_site(p, point ? 0.0 : sensors.disc_diameter));
  return sites;
}

SensorReadings::SensorReadings(const TetMesh& mesh, std::vector<ReadingSite> sites,
                               const MixedSolver* supports)
    : mesh_(mesh),
      sites_(std::move(sites)),
      posts_(sites_.size()),
      functional_(std::make_unique<ReadingFunctionals>(mesh)) {
  for (int k = 0; k < size(); ++k)
    if (site(k).post()) posts_[k] = same_post(k) == k ? find_post(k) : posts_[same_post(k)];
  for (int k = 0; k < size(); ++k) {
    if (!site(k).post() || site(k).support.rigid() || same_post(k) != k) continue;
    for (char kind : posts_[k].cut ? std::string("xzv") : std::string("xyzuv")) modes_.push_back({k, kind});
  }
  if (modes_.empty()) return;
  if (!supports)
    throw std::invalid_argument("posts on membrane springs need the factored skin for their weights");
  const int M = static_cast<int>(modes_.size());
  for (const Mode& m : modes_) phi_.push_back(mode_vector(m).sparseView());
  K_.resize(M, M);
  for (int j = 0; j < M; ++j) {
    const MixedSolution x =
        supports->solve(Eigen::VectorXd::Zero(3 * mesh_.num_nodes()), Eigen::VectorXd(phi_[j]));
    const Eigen::VectorXd R = supports->reactions(x, {});
    for (int i = 0; i < M; ++i) K_(i, j) = phi_[i].dot(R);
  }
  // A half post on the mirror plane stands on half its membrane.
  Eigen::VectorXd Ks(M);
  for (int i = 0; i < M; ++i) {
    const MembraneSprings& s = site(modes_[i].site).support;
    const char kind = modes_[i].kind;
    Ks[i] = (posts_[modes_[i].site].cut ? 0.5 : 1.0) * (kind == 'z'                  ? s.k_normal
                                                        : kind == 'x' || kind == 'y' ? s.k_tangential
                                                                                     : s.k_tilt);
  }
  const Eigen::MatrixXd KsK = Eigen::MatrixXd(K_) + Eigen::MatrixXd(Ks.asDiagonal());
  // T = K_s (K + K_s)⁻¹, from (K + K_s)ᵀ Tᵀ = K_s (both symmetric).
  T_ = KsK.ldlt().solve(Eigen::MatrixXd(Ks.asDiagonal())).transpose();
}

SensorReadings::~SensorReadings() = default;
SensorReadings::SensorReadings(SensorReadings&&) noexcept = default;

int SensorReadings::same_post(int k) const {
  for (int i = 0; i < k; ++i)
    if (site(i).post() && site(i).center == site(k).center) return i;
  return k;
}

SensorReadings::Post SensorReadings::find_post(int k) const {
  const ReadingSite& s = site(k);
  const double r = 0.5 * s.diameter;
  Post post;
  for (int n = 0; n < mesh_.num_nodes(); ++n) {
    if (!(mesh_.node_marker(n) & kPost)) continue;
    const double d = std::hypot(mesh_.nodes(n, 0) - s.center[0], mesh_.nodes(n, 1) - s.center[1]);
    if (d > r * (1 + 1e-6) || mesh_.nodes(n, 2) > s.post_height * (1 + 1e-6)) continue;
    post.nodes.push_back(n);
    post.on_foot.push_back(mesh_.node_marker(n) & kBase);
    post.cut = post.cut || (mesh_.node_marker(n) & kSymmetry);
  }
  if (post.nodes.empty())
    throw std::out_of_range("no post at (" + std::to_string(s.center[0]) + ", " +
                            std::to_string(s.center[1]) + ") in the mesh");
  return post;
}

Eigen::VectorXd SensorReadings::mode_vector(const Mode& m) const {
  Eigen::VectorXd phi = Eigen::VectorXd::Zero(3 * mesh_.num_nodes());
  const Vec2& c = site(m.site).center;
  const Post& post = posts_[m.site];
  for (size_t i = 0; i < post.nodes.size(); ++i) {
    const int n = post.nodes[i];
    const Eigen::Vector3d r(mesh_.nodes(n, 0) - c[0], mesh_.nodes(n, 1) - c[1], mesh_.nodes(n, 2));
    Eigen::Vector3d u = Eigen::Vector3d::Zero();
    if (m.kind == 'x') u.x() = 1;
    if (m.kind == 'y') u.y() = 1;
    if (m.kind == 'z') u.z() = 1;
    if (m.kind == 'u') u = Eigen::Vector3d::UnitX().cross(r);
    if (m.kind == 'v') u = Eigen::Vector3d::UnitY().cross(r);
    if (post.on_foot[i]) u.z() = 0;  // the foot's normal component is the base's (Post::on_foot)
    phi.segment<3>(3 * n) = u;
  }
  return phi;
}

Eigen::VectorXd SensorReadings::weights(int k, char component) const {
  const ReadingSite& s = site(k);
  if (!s.post()) return (*functional_)(s.center[0], s.center[1], s.diameter, component);
  // The reaction on the post's nodes is the force the post exerts on the skin; a half post carries half its
  // force: read over half the cross-section.
  const Post& post = posts_[k];
  const double r = 0.5 * s.diameter, area = (post.cut ? 0.5 : 1.0) * M_PI * r * r;
  const double sign = component == 'z' ? 1.0 : -1.0;
  if (!s.support.rigid()) {
    // Row `component` of this post's modes in T, over every mode's φ.
    int row = -1;
    for (size_t i = 0; i < modes_.size(); ++i)
      if (modes_[i].site == same_post(k) && modes_[i].kind == component) row = static_cast<int>(i);
    Eigen::VectorXd w = Eigen::VectorXd::Zero(3 * mesh_.num_nodes());
    for (size_t j = 0; j < modes_.size(); ++j) w += (sign * T_(row, j) / area) * phi_[j];
    return w;
  }
  return (sign / area) * mode_vector({k, component});  // the held post's reaction along its rigid mode
}

Eigen::MatrixXd SensorReadings::weight_block() const {
  Eigen::MatrixXd W(3 * mesh_.num_nodes(), 2 * size());
  for (int k = 0; k < size(); ++k)
    for (int b = 0; b < 2; ++b) W.col(2 * k + b) = weights(k, b ? 'x' : 'z');
  return W;
}

SensorReading SensorReadings::read(int k, const Eigen::VectorXd& reactions) const {
  return {weights(k, 'z').dot(reactions), weights(k, 'x').dot(reactions)};
}

}  // namespace skinfem
