#pragma once
// A robot pose in the map frame and the odometry increment between two poses.
//
// Pose: (x, y) in metres, theta in radians counter-clockwise from +x, kept in (-pi, pi].
// Odometry: the motion between two readings expressed in the frame of the robot at the
// first one (dx forward, dy to the left, dtheta), as wheel encoders report it; it does
// not depend on where the robot is, which is what lets every particle apply it.
//
// Everything of the onboard localization lives in fleetmap::localization, so that its
// names (Pose, normalize_angle, ...) do not meet the simulated robot's (client/sim).
#include <cmath>

#include "common/geometry/geometry.h"

namespace fleetmap::localization {

inline constexpr double kPi = 3.14159265358979323846;

inline double deg2rad(double d) { return d * kPi / 180; }
inline double rad2deg(double r) { return r * 180 / kPi; }

// The same angle in [-pi, pi].
inline double normalize_angle(double a) { return std::remainder(a, 2 * kPi); }

// a - b as the shortest signed turn, in [-pi, pi].
inline double angle_diff(double a, double b) { return normalize_angle(a - b); }

struct Pose {
  double x = 0;
  double y = 0;
  double theta = 0;
  Point point() const { return {x, y}; }
  friend bool operator==(const Pose&, const Pose&) = default;
};

struct Odometry {
  double dx = 0;
  double dy = 0;
  double dtheta = 0;
  friend bool operator==(const Odometry&, const Odometry&) = default;
};

// The pose reached from p by the increment u (u in p's frame).
inline Pose compose(const Pose& p, const Odometry& u) {
  const double c = std::cos(p.theta), s = std::sin(p.theta);
  return {p.x + c * u.dx - s * u.dy, p.y + s * u.dx + c * u.dy, normalize_angle(p.theta + u.dtheta)};
}

// The increment that takes a to b: compose(a, between(a, b)) == b.
inline Odometry between(const Pose& a, const Pose& b) {
  const double c = std::cos(a.theta), s = std::sin(a.theta);
  const double ex = b.x - a.x, ey = b.y - a.y;
  return {c * ex + s * ey, -s * ex + c * ey, angle_diff(b.theta, a.theta)};
}

inline double distance(const Pose& a, const Pose& b) { return std::hypot(b.x - a.x, b.y - a.y); }

}  // namespace fleetmap::localization
