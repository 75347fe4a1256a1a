#include "client/sim/drive_simulator.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace fleetmap::localization {

WanderDriver::WanderDriver(std::shared_ptr<const RayCaster> world, const Pose& start, DriveOptions options,
                           uint64_t seed)
    : world_(std::move(world)), options_(options), odometry_(options.odometry), pose_(start), rng_(seed) {}

bool WanderDriver::clear(double heading) const {
  const Point u{std::cos(heading), std::sin(heading)}, v{-u.y, u.x};
  const Point o = pose_.point();
  for (double side : {-1.0, 0.0, 1.0}) {
    const Point from = o + side * options_.robot_radius * v;
    if (world_->cast_direction(from, u) < options_.lookahead + options_.robot_radius) return false;
  }
  return true;
}

DriveStep WanderDriver::step() {
  if (steps_++ < options_.look_around_steps) {
    const Pose before = pose_;
    pose_ = compose(pose_, {0, 0, options_.look_around_turn});
    return {pose_, odometry_.sample(between(before, pose_), rng_), 0.0};
  }
  std::normal_distribution<double> jitter(0.0, options_.max_turn / 3);
  wander_ = std::clamp(wander_ + jitter(rng_), -options_.max_turn, options_.max_turn);
  double turn = wander_, forward = options_.step;
  if (!clear(pose_.theta + turn)) {
    // The smallest turn that clears the way, trying the wander's side first; turning
    // more than max_turn happens in place.
    const double side = wander_ >= 0 ? 1.0 : -1.0;
    const double inc = deg2rad(15.0);
    turn = kPi;
    for (int k = 1; k <= 12; ++k) {
      if (clear(pose_.theta + side * k * inc)) { turn = side * k * inc; break; }
      if (clear(pose_.theta - side * k * inc)) { turn = -side * k * inc; break; }
    }
    if (std::fabs(turn) > options_.max_turn) {
      turn = std::clamp(turn, -deg2rad(45.0), deg2rad(45.0));
      forward = 0;
      wander_ = 0;
    }
  }
  const Pose before = pose_;
  pose_ = compose(compose(pose_, {0, 0, turn}), {forward, 0, 0});
  return {pose_, odometry_.sample(between(before, pose_), rng_), forward};
}

Pose pick_start_pose(const FreeSpace& free_space, const RayCaster& world, const std::vector<double>& beams,
                     double min_hit_fraction, double clearance, std::mt19937_64& rng, int max_tries) {
  std::uniform_real_distribution<double> heading(-kPi, kPi);
  const double rmax = world.options().rmax;
  std::vector<double> ranges(beams.size());
  for (int t = 0; t < max_tries; ++t) {
    const Point p = free_space.sample(rng);
    if (!free_space.contains(p)) continue;
    bool roomy = true;
    for (int k = 0; k < 36 && roomy; ++k) roomy = world.cast(p, k * kPi / 18) >= clearance;
    if (!roomy) continue;
    const double theta = heading(rng);
    world.cast_scan(p, theta, beams, ranges.data());
    const auto hits = std::count_if(ranges.begin(), ranges.end(), [&](double r) { return r < rmax; });
    if (hits >= min_hit_fraction * static_cast<double>(beams.size())) return {p.x, p.y, theta};
  }
  throw std::runtime_error("pick_start_pose: no pose with the requested clearance and hits in " +
                           std::to_string(max_tries) + " tries");
}

}  // namespace fleetmap::localization
