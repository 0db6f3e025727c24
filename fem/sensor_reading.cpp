#include "fem/sensor_reading.hpp"

namespace skinfem {

std::vector<ReadingSite> reading_sites(const Sensors& sensors, bool point) {
  std::vector<ReadingSite> sites;
  for (const Vec2& p : sensors.positions) sites.push_back({p, point ? 0.0 : sensors.disc_diameter});
  return sites;
}

SensorReadings::SensorReadings(const TetMesh& mesh, std::vector<ReadingSite> sites)
    : sites_(std::move(sites)), functional_(std::make_unique<ReadingFunctionals>(mesh)) {}

SensorReadings::~SensorReadings() = default;
SensorReadings::SensorReadings(SensorReadings&&) noexcept = default;

Eigen::VectorXd SensorReadings::weights(int k, char component) const {
  const ReadingSite& s = site(k);
  return (*functional_)(s.center[0], s.center[1], s.diameter, component);
}

Eigen::MatrixXd SensorReadings::weight_block() const {
  if (sites_.empty()) return {};
  Eigen::MatrixXd W(weights(0, 'z').size(), 2 * size());
  for (int k = 0; k < size(); ++k)
    for (int b = 0; b < 2; ++b) W.col(2 * k + b) = weights(k, b ? 'x' : 'z');
  return W;
}

SensorReading SensorReadings::read(int k, const Eigen::VectorXd& reactions) const {
  return {weights(k, 'z').dot(reactions), weights(k, 'x').dot(reactions)};
}

}  // namespace skinfem
