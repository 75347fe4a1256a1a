#include "client/localization/compass_prior.h"

#include <stdexcept>

namespace fleetmap::localization {

CompassPrior::CompassPrior(double half_width) : half_width_(half_width) {
  if (!(half_width > 0)) throw std::invalid_argument("CompassPrior half_width: expected > 0 radians");
}

double CompassPrior::sample(double reading, std::mt19937_64& rng) const {
  std::uniform_real_distribution<double> u(-half_width_, half_width_);
  return normalize_angle(reading + u(rng));
}

double CompassPrior::log_likelihood(double theta, double reading) const {
  const double d = angle_diff(theta, reading) / half_width_;
  return -0.5 * d * d;
}

}  // namespace fleetmap::localization
