#pragma once
// The odometry motion model (Thrun, Burgard & Fox, Probabilistic Robotics, 2005,
// section 5.4, table 5.6): the filter's prediction step (seed 000 Fig. 4).
//
// An increment (dx, dy, dtheta) is read as three motions: turn rot1 towards the
// displacement, drive trans along it, turn rot2 to the final heading. Each is perturbed
// by zero-mean Gaussian noise whose variance grows with the motion:
//
//   var(rot1)  = alpha1 rot1^2 + alpha2 trans^2
//   var(trans) = alpha3 trans^2 + alpha4 (rot1^2 + rot2^2)
//   var(rot2)  = alpha1 rot2^2 + alpha2 trans^2
//
// Motion backwards (displacement behind the robot) is read as rot1 towards the back and
// a negative trans, so that reversing does not look like two half turns (as Nav2's AMCL
// does). A robot that does not move gets no noise: the filter's roughening
// (ParticleFilterOptions) keeps a stationary cloud from collapsing instead.
#include <random>

#include "client/localization/pose.h"

namespace fleetmap::localization {

struct MotionNoise {
  double alpha1 = 0.02;  // rad^2 of rotation per rad^2 of rotation
  double alpha2 = 0.002;  // rad^2 of rotation per m^2 of translation
  double alpha3 = 0.01;  // m^2 of translation per m^2 of translation
  double alpha4 = 0.001;  // m^2 of translation per rad^2 of rotation
};

// The three motions of an increment and their standard deviations under the noise.
struct OdometryDecomposition {
  double rot1 = 0, trans = 0, rot2 = 0;
  double sd_rot1 = 0, sd_trans = 0, sd_rot2 = 0;
};

class MotionModel {
 public:
  explicit MotionModel(MotionNoise noise = {}) : noise_(noise) {}

  OdometryDecomposition decompose(const Odometry& u) const;

  // A noisy version of the increment u (one draw of table 5.6).
  Odometry sample(const Odometry& u, std::mt19937_64& rng) const;

  // Where a particle at p lands after the measured increment u.
  Pose sample(const Pose& p, const Odometry& u, std::mt19937_64& rng) const { return compose(p, sample(u, rng)); }

  const MotionNoise& noise() const { return noise_; }

 private:
  MotionNoise noise_;
};

}  // namespace fleetmap::localization
