#include "client/sim/laser_simulator.h"

#include <algorithm>
#include <cmath>

namespace fleetmap::localization {

LaserSimulator::LaserSimulator(std::shared_ptr<const RayCaster> world, LaserSimulatorOptions options, uint64_t seed)
    : world_(std::move(world)), options_(options), beams_(evenly_spread_angles(options.beams, options.fov)), rng_(seed) {}

std::vector<double> LaserSimulator::true_scan(const Pose& truth) const {
  std::vector<double> r(beams_.size());
  world_->cast_scan(truth.point(), truth.theta, beams_, r.data());
  return r;
}

std::vector<double> LaserSimulator::scan(const Pose& truth) {
  std::vector<double> r = true_scan(truth);
  const double rmax = this->rmax();
  std::normal_distribution<double> noise(0.0, options_.sigma);
  for (double& v : r)
    if (v < rmax) v = std::clamp(v + noise(rng_), 0.0, rmax);
  if (beams_.size() < 2) return r;
  const double step = beams_[1] - beams_[0];
  std::uniform_int_distribution<size_t> any_beam(0, beams_.size() - 1);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  for (int k = 0; k < options_.people; ++k) {
    const size_t c = any_beam(rng_);
    if (r[c] <= options_.min_person_range) continue;
    const double d = options_.min_person_range + u01(rng_) * (r[c] - options_.min_person_range);
    const double half = std::atan2(options_.person_width / 2, d);
    const long reach = static_cast<long>(half / step);
    for (long j = static_cast<long>(c) - reach; j <= static_cast<long>(c) + reach; ++j)
      if (j >= 0 && j < static_cast<long>(r.size())) r[j] = std::min(r[j], d);
  }
  return r;
}

}  // namespace fleetmap::localization
