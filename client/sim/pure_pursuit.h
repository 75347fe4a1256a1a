#pragma once
// Path following by pure pursuit (Coulter 1992): steer along the arc to the point of
// the path one look-ahead distance ahead; slow down near the last waypoint.
#include <vector>

#include "client/sim/differential_drive.h"

namespace fleetmap {

struct PurePursuitOptions {
  double lookahead_m = 1.0;
  double max_speed = 0.8;      // m/s
  double max_turn_rate = 1.2;  // rad/s
  double goal_tolerance_m = 0.2;
  double turn_in_place_rad = localization::kPi / 4;  // 45 degrees: beyond this heading error, v = 0
};

struct Command {
  double v = 0, w = 0;
  bool arrived = false;
};

class PurePursuit {
 public:
  explicit PurePursuit(PurePursuitOptions o = {}) : o_(o) {}
  void set_path(std::vector<Point> waypoints);
  void clear() { path_.clear(); }
  bool has_path() const { return !path_.empty(); }
  Command command(const Pose& pose);

 private:
  PurePursuitOptions o_;
  std::vector<Point> path_;
  size_t next_ = 0;  // first waypoint not yet passed
};

}  // namespace fleetmap
