#include "client/sim/drive_simulator.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
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

bool WanderDriver::mapped(double heading) const {
  if (options_.min_walls_around <= 0) return true;
  const Point end = pose_.point() + options_.lookahead * Point{std::cos(heading), std::sin(heading)};
  // Remembered per 0.25 m cell (the answer for the cell's first point stands for all of
  // it): the drive asks of the same ground again and again.
  const auto ix = static_cast<uint32_t>(static_cast<int32_t>(std::floor(end.x * 4)));
  const auto iy = static_cast<uint32_t>(static_cast<int32_t>(std::floor(end.y * 4)));
  const uint64_t cell = (uint64_t{ix} << 32) | iy;
  if (const auto it = mapped_cells_.find(cell); it != mapped_cells_.end()) return it->second;
  static const std::vector<double> around = [] {
    std::vector<double> a(36);
    for (int k = 0; k < 36; ++k) a[k] = k * kPi / 18;
    return a;
  }();
  double ranges[36];
  world_->cast_scan(end, 0.0, around, ranges);
  const double rmax = world_->options().rmax;
  const auto walls = std::count_if(ranges, ranges + 36, [&](double r) { return r < rmax; });
  return mapped_cells_[cell] = static_cast<double>(walls) >= options_.min_walls_around * 36;
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
  const auto open_and_mapped = [&](double h) { return clear(h) && mapped(h); };
  const auto open = [&](double h) { return clear(h); };
  if (!open_and_mapped(pose_.theta + turn)) {
    // The smallest turn that clears the way, trying the wander's side first; turning
    // more than max_turn happens in place.
    const double side = wander_ >= 0 ? 1.0 : -1.0;
    const double inc = deg2rad(15.0);
    const auto smallest_turn = [&](const auto& passes) -> std::optional<double> {
      for (int k = 1; k <= 12; ++k) {
        if (passes(pose_.theta + side * k * inc)) return side * k * inc;
        if (passes(pose_.theta - side * k * inc)) return -side * k * inc;
      }
      return std::nullopt;
    };
    std::optional<double> found = smallest_turn(open_and_mapped);
    // Nowhere mapped to go: any open way, the wander's own first.
    if (!found && options_.min_walls_around > 0) found = open(pose_.theta + wander_) ? wander_ : smallest_turn(open);
    turn = found.value_or(kPi);
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
