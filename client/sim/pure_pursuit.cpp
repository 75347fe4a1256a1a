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
  // The target is the point one look-ahead ahead on the leg being driven (Coulter 1992),
  // not the leg's far end: steering at a waypoint 10 m away turns so gently that the
  // robot drifts sideways across a corridor before it lines up.
  Point target = path_[next_];
  if (next_ > 0) {
    const Point a = path_[next_ - 1], leg = path_[next_] - a;
    const double len = norm(leg);
    if (len > 0) {
      const double along = std::clamp(dot(p - a, leg) / len, 0.0, len);
      target = a + (std::min(len, along + o_.lookahead_m) / len) * leg;
    }
  }
  const double heading = std::atan2(target.y - p.y, target.x - p.x);
  const double alpha = localization::normalize_angle(heading - pose.theta);
  const double ld = std::max(distance(p, target), 1e-6);
  double v = std::min(o_.max_speed, distance(p, goal));       // slow down at the end
  // Turn on the spot first while the heading is far off: an arc from 60 degrees off, to a
  // target metres away, sweeps sideways into a corridor's wall (a robot that localized
  // mid-look-around heads wherever its last turn left it).
  if (std::abs(alpha) > o_.turn_in_place_rad) v = 0;
  double w = v > 0 ? 2 * v * std::sin(alpha) / ld : std::copysign(o_.max_turn_rate, alpha);
  w = std::clamp(w, -o_.max_turn_rate, o_.max_turn_rate);
  return {v, w, false};
}

}  // namespace fleetmap
