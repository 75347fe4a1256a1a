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

#include <Eigen/Core>

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

// R(theta): from the robot's frame at heading theta to the map frame.
inline Eigen::Matrix2d rotation(double theta) {
  const double c = std::cos(theta), s = std::sin(theta);
  return (Eigen::Matrix2d() << c, -s, s, c).finished();
}

inline Eigen::Vector2d position(const Pose& p) { return {p.x, p.y}; }

// The pose reached from p by the increment u (u in p's frame): p + R(theta) u. Summed
// column by column, so that every particle moves by the same bits as before Eigen.
inline Pose compose(const Pose& p, const Odometry& u) {
  const Eigen::Matrix2d r = rotation(p.theta);
  const Eigen::Vector2d xy = position(p) + r.col(0) * u.dx + r.col(1) * u.dy;
  return {xy.x(), xy.y(), normalize_angle(p.theta + u.dtheta)};
}

// The increment that takes a to b: compose(a, between(a, b)) == b, R(theta_a)^T (b - a).
inline Odometry between(const Pose& a, const Pose& b) {
  const Eigen::Vector2d d = rotation(a.theta).transpose() * (position(b) - position(a));
  return {d.x(), d.y(), angle_diff(b.theta, a.theta)};
}

inline double distance(const Pose& a, const Pose& b) { return std::hypot(b.x - a.x, b.y - a.y); }

}  // namespace fleetmap::localization
