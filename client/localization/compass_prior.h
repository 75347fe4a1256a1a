#pragma once
// The compass of seed 000 section 4.1: "the orientation of the robot is assumed to be
// initially known with an uncertainty of 3 degrees". Two uses:
//
//  * global initialisation: each particle's heading is drawn uniformly within
//    +-half_width of the reading (the search space (x, y, theta) shrinks to (x, y));
//  * tracking (optional): a weight term, a Gaussian of the heading error with standard
//    deviation half_width, which keeps the cloud's heading from drifting where the
//    laser alone leaves it ambiguous (long corridors).
#include <random>

#include "client/localization/pose.h"

namespace fleetmap::localization {

class CompassPrior {
 public:
  // half_width in radians; 3 degrees by default (seed 000 section 4.1).
  explicit CompassPrior(double half_width = deg2rad(3.0));

  // A heading uniform in [reading - half_width, reading + half_width].
  double sample(double reading, std::mt19937_64& rng) const;

  // log N(theta - reading; 0, half_width), up to a constant: -(d / half_width)^2 / 2.
  double log_likelihood(double theta, double reading) const;

  double half_width() const { return half_width_; }

 private:
  double half_width_;
};

}  // namespace fleetmap::localization
