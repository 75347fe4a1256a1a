#include "client/sim/pure_pursuit.h"

#include <algorithm>
#include <cmath>

namespace fleetmap {

void PurePursuit::set_path(std::vector<Point> waypoints) {
  path_ = std::move(waypoints);
  next_ = 0;
}

Command PurePursuit::command(const Pose& pose) {
  if (path_.empty()) return {0, 0, true};
  const Point p{pose.x, pose.y};
  const Point goal = path_.back();
  if (distance(p, goal) <= o_.goal_tolerance_m) {
    path_.clear();
    return {0, 0, true};
  }
  // Skip waypoints already within the look-ahead circle.
  while (next_ + 1 < path_.size() && distance(p, path_[next_]) < o_.lookahead_m) ++next_;
  const Point target = path_[next_];
  const double heading = std::atan2(target.y - p.y, target.x - p.x);
  const double alpha = localization::normalize_angle(heading - pose.theta);
  const double ld = std::max(distance(p, target), 1e-6);
  double v = std::min(o_.max_speed, distance(p, goal));       // slow down at the end
  if (std::abs(alpha) > M_PI / 2) v = 0;                      // turn on the spot first
  double w = v > 0 ? 2 * v * std::sin(alpha) / ld : std::copysign(o_.max_turn_rate, alpha);
  w = std::clamp(w, -o_.max_turn_rate, o_.max_turn_rate);
  return {v, w, false};
}

}  // namespace fleetmap
