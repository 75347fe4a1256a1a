#pragma once
// The operator's side of robots and tasks (SPEC 4, 5.3): registering robot accounts
// (through the robot_add / robot_remove procedures, sql/40_robot_accounts.sql), goals,
// initial poses, aborts, and what the status views show.
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <mysql++/mysql++.h>

#include "common/core/error.h"
#include "protocol/fleet_states.h"

namespace fleetmap {

class RobotNotFound : public NotFound {
 public:
  explicit RobotNotFound(const std::string& name) : NotFound("no robot named '" + name + "'") {}
};

struct RobotStatus {
  unsigned id = 0;
  std::string name, map, last_seen;
  RobotState state = RobotState::Offline;
  std::optional<double> x, y, theta, v;
  std::optional<unsigned long long> task_id;
  std::optional<TaskState> task_state;  // with task_id
  std::optional<double> goal_x, goal_y;
};

// A robot's profile (seed 004 section III.A; columns of robots): what its maps and plans
// depend on. nullopt: the server's default (robot_radius_m, body_height_m in
// [server]); without a laser height the server sends the stored map unsliced
// (server/daemon/robot_map_source.h).
struct RobotProfile {
  std::optional<double> laser_height;  // m over the floor, [0, 1000]
  std::optional<double> radius;        // m, (0, 100]
  std::optional<double> body_height;   // m, (0, 1000]
  bool can_stairs = false, can_ramps = true;
  friend bool operator==(const RobotProfile&, const RobotProfile&) = default;
};

// What `robot add` / `robot set` change: an absent field stays as it is; a field given
// as nullopt goes back to the server's default.
struct RobotProfileChange {
  std::optional<std::optional<double>> laser_height, radius, body_height;
  std::optional<bool> can_stairs, can_ramps;
  bool empty() const { return !laser_height && !radius && !body_height && !can_stairs && !can_ramps; }
};

// Throws std::invalid_argument naming the field ("laser_height: expected ...") for a value
// out of its range or not finite.
void check_profile(const RobotProfileChange& change);

struct TaskInfo {
  unsigned long long id = 0;
  std::string robot;
  TaskState state = TaskState::Assigned;
  std::string reason, created_at, updated_at;
  double goal_x = 0, goal_y = 0;
};

struct TrajectoryPoint {
  std::string t;  // as the session's time zone shows it ('2026-12-02 01:36:02.123456')
  double x = 0, y = 0, theta = 0, v = 0;
  // The same instant in ISO 8601 UTC ('2026-12-02T00:36:02.123456Z'), whatever the
  // session's or the server's time zone: from the stored TIMESTAMP, which is UTC.
  std::string t_utc;
};

// A task read as "SELECT id, robot, goal_x, goal_y, state, COALESCE(reason, ''),
// created_at, updated_at FROM v_tasks": the one way a row of v_tasks becomes a TaskInfo.
TaskInfo task_from_row(const mysqlpp::Row& r);

class FleetStore {
 public:
  explicit FleetStore(mysqlpp::Connection& c) : c_(c) {}

  // Creates the account and the robots row; returns the robot id. Throws
  // std::invalid_argument with the database's reason (bad name, short password, no map, exists).
  unsigned add_robot(const std::string& name, const std::string& password, const std::string& map, int max_connections);
  // Changes a robot's profile (check_profile first); throws RobotNotFound.
  void set_profile(const std::string& name, const RobotProfileChange& change);
  RobotProfile profile(const std::string& name);  // throws RobotNotFound
  std::map<std::string, RobotProfile> profiles();  // every robot not removed, by name
  void remove_robot(const std::string& name);
  std::vector<RobotStatus> status();
  unsigned robot_id(const std::string& name);  // throws RobotNotFound

  // A new goal replaces the robot's open task, which becomes aborted ("replaced by task N",
  // TaskEvent::Replaced) without an Abort push: the new SetPosEnd is what the robot acts on.
  unsigned long long assign_goal(const std::string& robot, double x, double y);
  // Asks the server to push Abort for the robot's open task; false when it has none.
  bool request_abort(const std::string& robot, const std::string& reason);
  void set_initial_pose(const std::string& robot, double x, double y, std::optional<double> theta);
  std::vector<TaskInfo> tasks(const std::optional<std::string>& robot, size_t limit);
  // since: a timestamp ('2026-11-28 07:00:00') or an age ('90s', '10m', '2h', '1d').
  std::vector<TrajectoryPoint> trajectory(const std::string& robot, const std::optional<std::string>& since);

 private:
  mysqlpp::Connection& c_;
};

}  // namespace fleetmap
