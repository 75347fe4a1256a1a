#pragma once
// Several scans of the global phase as one, in the frame of the latest: each scan's
// pose relative to the latest comes from the odometry between them (accurate over the
// few metres of the global phase: 1 % of the distance, motion_model.h), and each return
// becomes a point seen from the latest pose, as a (range, angle) pair. A robot that has
// driven a few metres and turned has seen more of the map than one scan shows; matched
// as a whole (global_search.h), the scans tell apart places that one scan does not
// (one straight wall fits every straight wall).
#include <cstddef>
#include <vector>

#include "client/localization/pose.h"

namespace fleetmap::localization {

struct StitchedScan {
  std::vector<Pose> poses;     // of each scan, in the latest scan's frame (the latest: 0)
  std::vector<double> ranges;  // the returns (< rmax) as seen from the latest pose
  std::vector<double> angles;
};

// scans[k] taken along beam_angles, odometry[k] the motion from scan k-1 to scan k
// (odometry[0] unused). Returns at most max_points points, newest scans first, thinned
// evenly; 0: all.
StitchedScan stitch_scans(const std::vector<const std::vector<double>*>& scans, const std::vector<Odometry>& odometry,
                          const std::vector<double>& beam_angles, double rmax, size_t max_points = 0);

}  // namespace fleetmap::localization
