#pragma once
// Goals by meaning for every front door (`fleetmap goal ROBOT --near TAG`, the web API's
// POST /api/robots/{name}/goal {"tag"}; docs/semantic-layer.md):
//
//   1. the robot's position: its last reported pose, else its initial pose (pose-ini);
//   2. the object with that tag nearest to it (SceneStore::near: live objects, by the
//      distance to their footprints);
//   3. a free point beside it, reachable with the planner GetPath uses for this robot
//      (its profile, the server's defaults; the map's live scene): choose_goal_beside,
//      common/planning/goal_near.h;
//   4. the usual goal: a task assigned (the open one replaced), SetPosEnd pushed by the
//      server.
//
// What can go wrong, by class (app/exit_code_for.h gives the exit code):
//   RobotNotFound                             no such robot (4)
//   GoalRefused                               the robot is lost (3)
//   NoGoalByTag (a NotFound)                  no map, no known position, no object with
//                                             the tag, the object expired (4)
//   GoalByTagRefused (a GoalRefused)          the robot's position is blocked, no free
//                                             point beside the object, none reachable (3)
// No task row is written unless a goal was found.
#include <string>

#include <mysql++/mysql++.h>

#include "common/core/error.h"
#include "common/geometry/geometry.h"
#include "server/core/goal_check.h"
#include "server/core/server_config.h"

namespace fleetmap {

class NoGoalByTag : public NotFound {
 public:
  using NotFound::NotFound;
};

class GoalByTagRefused : public GoalRefused {
 public:
  using GoalRefused::GoalRefused;
};

struct AcceptedGoalByTag {
  unsigned long long task = 0;
  Point goal;                // the free point beside the object
  Point from;                // where the path was planned from (step 1)
  double path_length = 0;    // metres
  std::string tag, object;   // the tag asked for, the key of the object chosen
  double gap = 0;            // metres from the goal to the object's nearest footprint
};

// Steps 1-4 for a stored robot; margin: metres kept between the robot's disc and the
// object (> 0). Throws as the header comment says.
AcceptedGoalByTag accept_goal_by_tag(mysqlpp::Connection& c, const std::string& robot, const std::string& tag,
                                     double margin, const ServerConfig& defaults);

}  // namespace fleetmap
