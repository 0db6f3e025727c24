#include "fem/sensor_reading.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace skinfem {

std::vector<ReadingSite> reading_sites(const Sensors& sensors, bool point) {
  std::vector<ReadingSite> sites;
  for (const Vec2& p : sensors.positions)
    sites.push_back(sensors.model == SensorModel::post
                        ? ReadingSite{p, sensors.post.diameter, sensors.post.height}
                        : ReadingSite{p, point ? 0.0 : sensors.disc_diameter, 0.0});
  return sites;
}

SensorReadings::SensorReadings(const TetMesh& mesh, std::vector<ReadingSite> sites)
    : mesh_(mesh), sites_(std::move(sites)), functional_(std::make_unique<ReadingFunctionals>(mesh)) {}

SensorReadings::~SensorReadings() = default;
SensorReadings::SensorReadings(SensorReadings&&) noexcept = default;

Eigen::VectorXd SensorReadings::weights(int k, char component) const {
  const ReadingSite& s = site(k);
  if (!s.post()) return (*functional_)(s.center[0], s.center[1], s.diameter, component);
  // The post's nodes (its wall, top and the outline they share with the base): the reaction on them is the
  // force the post exerts on the skin. A half mesh holds half a post on its cut (a node on the cut marks
  // it), and half its force: read over half the cross-section.
  const double r = 0.5 * s.diameter;
  std::vector<int> on_post;
  bool cut = false;
  for (int n = 0; n < mesh_.num_nodes(); ++n) {
    if (!(mesh_.node_marker(n) & kPost)) continue;
    const double d = std::hypot(mesh_.nodes(n, 0) - s.center[0], mesh_.nodes(n, 1) - s.center[1]);
    if (d > r * (1 + 1e-6) || mesh_.nodes(n, 2) > s.post_height * (1 + 1e-6)) continue;
    on_post.push_back(n);
    cut = cut || (mesh_.node_marker(n) & kSymmetry);
  }
  if (on_post.empty())
    throw std::out_of_range("no post at (" + std::to_string(s.center[0]) + ", " +
                            std::to_string(s.center[1]) + ") in the mesh");
  const double area = (cut ? 0.5 : 1.0) * M_PI * r * r;
  Eigen::VectorXd w = Eigen::VectorXd::Zero(3 * mesh_.num_nodes());
  for (int n : on_post) w[3 * n + (component == 'z' ? 2 : 0)] = (component == 'z' ? 1.0 : -1.0) / area;
  return w;
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
