#pragma once
// Slacks shared by the sweeps (sweep_kernels.h): how much wider than exact a wall's or
// a stair's angular interval is taken, so that rounding never drops a beam it can stop.
#include <cmath>

#include "common/raycast/ray_rules.h"
#include "common/raycast/ray_segment.h"

namespace fleetmap {

// A wall nearer the origin than this is tested against every beam: the angle it
// subtends is then ill-conditioned (and it may hold the origin).
inline constexpr double kSweepNear = 1e-3;  // metres
// Slack on a wall's angular interval, in pseudo-angle units (at least radians): far
// above rounding, and above the kRayTolerance / kSweepNear = 1e-6 rad by which the exact
// test widens a wall's ends.
inline constexpr double kSweepAngleSlack = 1e-5;

// Stairs and ramps stop rays only inside their bounding box: the beams within the angle
// its circumscribed circle subtends (a pseudo-angle moves no faster than the angle).
struct SpecialCone {
  Point centre;  // of the box, from the origin
  double radius = 0, dist = 0;
  double half_angle() const { return std::asin(radius / dist) + kSweepAngleSlack; }
  double nearest() const { return dist - radius - 2 * kRayTolerance; }
};

inline SpecialCone special_cone(const SpecialObstacle& sp, Point o) {
  const Rect& b = sp.bounds;
  SpecialCone c;
  c.centre = Point{(b.xmin + b.xmax) / 2, (b.ymin + b.ymax) / 2} - o;
  c.radius = std::hypot(b.xmax - b.xmin, b.ymax - b.ymin) / 2 + kRayTolerance;
  c.dist = norm(c.centre);
  return c;
}

}  // namespace fleetmap
