#pragma once
// Where an operator's command finds a robot (`fleetmap goal`, server/core/goal_check.h):
// its map, the last pose it reported (robots.x, y), and the initial pose an operator gave
// it (robots.ini_x, ini_y, `fleetmap pose-ini`), its state (a lost robot's last pose is
// stale), and the profile values its plans use.
#include <optional>
#include <string>

#include <mysql++/mysql++.h>

#include "common/geometry/geometry.h"
#include "protocol/fleet_states.h"

namespace fleetmap {

struct RobotWhereabouts {
  unsigned id = 0;
  std::optional<unsigned> map_id;
  std::string map;  // its name; empty without a map
  RobotState state = RobotState::Offline;
  std::string last_seen;  // empty: never
  std::optional<Point> last_pose, initial_pose;
  std::optional<double> radius, body_height;  // nullopt: the server's default
  bool can_stairs = false;
  // The last pose, else the initial pose, else nothing.
  std::optional<Point> known_position() const { return last_pose ? last_pose : initial_pose; }
};

// Throws RobotNotFound (protocol/fleet_store.h) for a name that is no robot, or a removed one.
RobotWhereabouts robot_whereabouts(mysqlpp::Connection& c, const std::string& robot);

}  // namespace fleetmap
