#pragma once
// A guided tour, simulated (seed 003 §III: "a person is showing the robot around. The
// platform autonomously follows the guide"): a guide walks a waypoint list (tour_plan.h,
// tour_json.h) at a walking pace and waits when the robot falls behind; the robot, a
// differential drive, follows the guide's trail about follow_distance behind by pure
// pursuit of a carrot on the trail, and when it reaches a point where the guide told it
// something (within 0.1 m of it; the carrot waits there until it has) it reports the
// event with its own pose and heading, as a robot sends TourEvent. No sensors, no network: fleetmap-robot
// --tour sends what this produces; bench-tour and the tests build graphs from it.
//
//   GuidedWalk walk(tour, {});
//   while (!walk.done()) for (TourEvent& e : walk.step()) send(e);
#include <vector>

#include "client/sim/differential_drive.h"
#include "common/planning/tour_event.h"
#include "common/planning/tour_plan.h"

namespace fleetmap {

struct GuidedWalkOptions {
  double guide_speed = 1.0;      // m/s, walking pace
  double follow_distance = 1.0;  // metres of trail between the robot and the guide
  double wait_distance = 2.5;    // the guide waits while the robot is this far behind
  double lookahead = 0.5;        // metres: the carrot's lead on the robot
  double max_speed = 0.8;        // m/s, the robot
  double max_turn_rate = 1.5;    // rad/s
  double step_s = 0.05;          // simulation period
  double max_time_s = 3600;      // done() after this much simulated time
};

class GuidedWalk {
 public:
  // Throws std::invalid_argument for an empty tour. The robot starts on the first
  // waypoint, facing the second.
  GuidedWalk(std::vector<TourWaypoint> tour, GuidedWalkOptions o = {});

  // Advances one step_s; returns the events the robot reached during it.
  std::vector<TourEvent> step();
  bool done() const;

  const Pose& robot() const { return drive_.pose(); }
  Point guide() const { return at(guide_s_); }
  double time_s() const { return time_s_; }
  double trail_length() const { return cum_.back(); }

 private:
  Point at(double s) const;  // the point of the trail at arc length s
  double heading_at(double s) const;

  std::vector<TourWaypoint> tour_;
  GuidedWalkOptions o_;
  std::vector<double> cum_;  // arc length at each waypoint
  DifferentialDrive drive_;
  double guide_s_ = 0, carrot_s_ = 0, time_s_ = 0;
  size_t next_event_ = 0;  // index into tour_ of the next waypoint with an event
  double closest_ = 0;     // the robot's closest approach to it so far
  Pose closest_pose_;
  double closest_t_ = 0;
};

}  // namespace fleetmap
