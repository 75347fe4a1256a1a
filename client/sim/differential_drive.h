#pragma once
// The simulated robot's body: a differential-drive robot moving by (v, w) and its
// wheel odometry, which measures each motion with noise (seed 000 section 4.1: the
// filter's motion model sees only the odometry).
#include <random>

#include "client/localization/pose.h"

namespace fleetmap {

using localization::Odometry;
using localization::Pose;

struct OdometryNoise {
  double forward_per_m = 0.02;     // standard deviation of distance error per metre driven
  double rotation_per_rad = 0.02;  // of rotation error per radian turned
  double rotation_per_m = 0.005;   // of rotation error per metre driven
};

class DifferentialDrive {
 public:
  DifferentialDrive(Pose start, OdometryNoise noise, unsigned seed) : pose_(start), noise_(noise), rng_(seed) {}

  // Moves the true pose by v (m/s), w (rad/s) for dt seconds; returns what the odometry
  // measured of that motion, in the robot frame at the start of the step.
  Odometry step(double v, double w, double dt);

  const Pose& pose() const { return pose_; }
  void stop_at(const Pose& p) { pose_ = p; }

 private:
  Pose pose_;
  OdometryNoise noise_;
  std::mt19937_64 rng_;
};

}  // namespace fleetmap
