#pragma once
// A planned path: the robot's centre moves along straight lines between waypoints, from
// the first (the start) to the last (the goal).
#include <vector>

#include "common/geometry/geometry.h"

namespace fleetmap {

using Path = std::vector<Point>;

inline double path_length(const Path& path) {
  double len = 0;
  for (size_t i = 1; i < path.size(); ++i) len += distance(path[i - 1], path[i]);
  return len;
}

}  // namespace fleetmap
