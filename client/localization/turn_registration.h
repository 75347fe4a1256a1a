#pragma once
// The turn between two scans taken from one place. Odometry measures a turn in place
// poorly (the robot's: a few degrees per 60 degree turn, motion_model.h), and a few
// degrees matter when scans are stitched: 2 degrees move a wall 15 m away by 0.5 m.
// Two scans from one point see the same ranges along the same directions, so where their
// fields of view overlap the turn is the rotation that makes their range profiles agree.
//
// Each return of `after` is compared with `before` interpolated along the same direction
// (linearly between neighbouring beams, the nearest beam across a jump in depth); the
// turn minimises the robust squared differences (capped at `cap`) over sigma^2, plus the
// odometry's own term, tried every `step` within `window` of the odometry.
#include <vector>

#include "client/localization/pose.h"

namespace fleetmap::localization {

struct TurnRegistrationOptions {
  double window = deg2rad(12.0);  // searched each side of the odometry's turn
  double step = deg2rad(0.05);
  double sigma = 0.1;             // metres: laser noise of both scans and interpolation
  double cap = 0.5;               // metres: differences beyond count as this (occlusions)
  int min_overlap = 30;           // directions both scans hit (about 40 degrees of 131 beams)
};

// before and after: ranges along beam_angles (ascending, radians, robot frame); returns
// the turn (radians, after's heading minus before's), odometry_turn when the scans
// overlap in fewer than min_overlap directions where both hit.
double register_turn(const std::vector<double>& before, const std::vector<double>& after,
                     const std::vector<double>& beam_angles, double rmax, double odometry_turn, double odometry_sd,
                     const TurnRegistrationOptions& options = {});

}  // namespace fleetmap::localization
