#include "client/sim/differential_drive.h"

#include <cmath>

namespace fleetmap {

Odometry DifferentialDrive::step(double v, double w, double dt) {
  const double d = v * dt, r = w * dt;
  // Exact arc motion of the true robot (midpoint heading).
  const double mid = pose_.theta + r / 2;
  pose_.x += d * std::cos(mid);
  pose_.y += d * std::sin(mid);
  pose_.theta = localization::normalize_angle(pose_.theta + r);
  // The odometry's reading of it, with noise growing with the motion.
  std::normal_distribution<double> n(0, 1);
  const double fd = d + n(rng_) * noise_.forward_per_m * std::abs(d);
  const double fr = r + n(rng_) * (noise_.rotation_per_rad * std::abs(r) + noise_.rotation_per_m * std::abs(d));
  return {fd * std::cos(fr / 2), fd * std::sin(fr / 2), fr};
}

}  // namespace fleetmap
