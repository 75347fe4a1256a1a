#pragma once
// Whether a goal is one the robot can reach, asked before a task exists (SPEC 5.3: a
// task is what the robot acts on, so a goal it cannot reach is refused at once, not
// left to fail later). One implementation for every front door: `fleetmap goal X Y`
// now, the HTTP API later (422), both through accept_goal.
//
//   1. the robot: not lost (its last pose is stale and nothing would be pushed to it:
//      the goal is refused, not queued; give it again once the robot reports);
//   2. the goal inside the map's border;
//   3. the planner GetPath uses for this robot (its profile, the server's defaults, the
//      map's live scene, server/core/planner_cache.h): the goal clear of obstacles,
//      objects its body cannot pass and avoided areas; and not inside a closed obstacle
//      whose every segment blocks (a building without an open door: the planner would
//      only find out by searching until its time limit), unless the robot is inside it too;
//   4. from the robot's last pose (else its initial pose) a path to the goal. With
//      neither, only 2 and 3 are checked (GoalAcceptance::from is empty): GetPath will
//      plan once the robot reports a pose, and a no_path then fails the task.
//
// A refusal is GoalRefused (a NoPath: exit 3), its message names the robot, the goal and
// why; no task row is written.
#include <optional>
#include <string>

#include <mysql++/mysql++.h>

#include "common/geometry/geometry.h"
#include "common/core/error.h"
#include "common/planning/map_planner.h"
#include "common/planning/topo_graph.h"
#include "protocol/robot_whereabouts.h"
#include "server/core/planner_cache.h"
#include "server/core/server_config.h"

namespace fleetmap {

class GoalRefused : public NoPath {
 public:
  using NoPath::NoPath;
};

struct GoalAcceptance {
  std::optional<Point> from;  // where the path was planned from; empty: no known position
  double path_length = 0;     // metres, with from (RRT-Connect's path, unsmoothed)
};

struct AcceptedGoal {
  unsigned long long task = 0;
  GoalAcceptance check;
};

// The robot's planning profile: its own values, else the server's defaults.
PlannerProfile planner_profile(const RobotWhereabouts& w, const ServerConfig& defaults);

// The server's planning defaults (robot_radius_m, body_height_m) as an operator's
// program sees them: the [server] section of this config file (or the one
// find_config_file finds), else ServerConfig's. Other keys are the server's business.
ServerConfig planning_defaults(const std::optional<std::string>& config_file);

// Step 1: throws GoalRefused when the robot is lost; `goal` names the goal ("goal (1, 2)").
void refuse_if_lost(const RobotWhereabouts& w, const std::string& robot, const std::string& goal);

// Steps 2-4 on a planner already built (no database): throws GoalRefused. With the map's
// topological graph, a goal whole-map RRT does not reach is tried through the graph too
// (common/planning/topo_planner.h), as GetPath may plan it.
GoalAcceptance check_goal_on(const MapPlanner& planner, const Map& map, const std::string& robot,
                             const std::string& map_name, std::optional<Point> from, Point goal,
                             const TopoGraph* graph = nullptr);

// The closed obstacle (ST 1 or 3) whose every segment blocks (h > 0) and whose inside
// holds p, or nullptr.
const Obstacle* enclosing_obstacle(const Map& map, Point p);

// Steps 1-4 for a stored robot; throws GoalRefused, RobotNotFound, NotFound (no map).
GoalAcceptance check_goal(mysqlpp::Connection& c, const std::string& robot, Point goal, const ServerConfig& defaults);

// check_goal, then the task (FleetStore::assign_goal: the open task is replaced).
AcceptedGoal accept_goal(mysqlpp::Connection& c, const std::string& robot, Point goal, const ServerConfig& defaults);

}  // namespace fleetmap
