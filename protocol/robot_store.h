#pragma once
// Robots, their tasks and what they report, as the server sees them (tables robots,
// tasks, trajectories, gps_fixes, images, observed_objects). Used inside the caller's
// transaction; a robot's rows are changed only by whoever holds its robots row lock.
#include <optional>
#include <string>
#include <vector>

#include <mysql++/mysql++.h>

#include "protocol/fleet_states.h"
#include "protocol/params.h"

namespace fleetmap {

struct RobotRow {
  unsigned id = 0;
  std::string db_user;
  std::optional<unsigned> map_id;
  RobotState state = RobotState::Offline;
  std::optional<long long> magic;  // of the session; nullopt: no Ready yet
  std::optional<double> x, y, theta, v;
  std::optional<double> ini_x, ini_y, ini_theta;
  bool removed = false;
  // Profile (seed 004: what the robot's laser sees and its plans avoid); nullopt: the
  // server's default.
  std::optional<double> laser_height, radius, body_height;
  bool can_stairs = false, can_ramps = true;
  bool registered() const { return magic.has_value() && !removed; }
};

struct TaskRow {
  unsigned long long id = 0;
  unsigned robot_id = 0;
  double goal_x = 0, goal_y = 0;
  TaskState state = TaskState::Assigned;
  std::optional<unsigned long long> answer_id, abort_answer_id;
  bool abort_requested = false;
  std::string reason;
};

class RobotStore {
 public:
  explicit RobotStore(mysqlpp::Connection& c) : c_(c) {}

  // Claims robots, not rows (SPEC 5.3): locks the robots rows of these accounts that no
  // other server holds (FOR UPDATE SKIP LOCKED). Accounts without a row are not returned.
  // One statement for the lot: the accounts are a bounded list (the caller's share of
  // the queue head), so no row is locked that is not returned; returned in the order given.
  std::vector<RobotRow> claim(const std::vector<std::string>& accounts);
  std::optional<RobotRow> claim(unsigned robot_id);
  // The same claim as SQL and its result, for a caller that sends it with other statements
  // in one round trip (server/daemon/request_loop.cpp); accounts not empty.
  std::string claim_sql(const std::vector<std::string>& accounts);
  std::vector<RobotRow> claimed(const mysqlpp::StoreQueryResult& res, const std::vector<std::string>& accounts);

  void start_session(unsigned id, long long magic);
  void set_state(unsigned id, RobotState state);
  void record_image(unsigned id, const SendImageParams& p, const std::string& data, const std::string& at);
  void record_object(unsigned id, std::optional<unsigned> map_id, const SetObjectParams& p, const std::string& at);

  std::optional<TaskRow> open_task(unsigned robot_id);  // the newest task in an open state (is_open)
  // The open task of each of these robots that has one, in one query.
  std::vector<TaskRow> open_tasks(const std::vector<unsigned>& robot_ids);
  std::string open_tasks_sql(const std::vector<unsigned>& robot_ids);  // likewise; ids not empty
  static std::vector<TaskRow> open_tasks_of(const mysqlpp::StoreQueryResult& res);
  std::optional<TaskRow> task_pushed_as(unsigned robot_id, unsigned long long answer_id);
  // Writes the state as given: the caller asked task_transition (protocol/task_lifecycle.h).
  void set_task_state(unsigned long long task_id, TaskState state, const std::string& reason = "");
  void set_task_answer(unsigned long long task_id, unsigned long long answer_id);
  void set_task_abort_answer(unsigned long long task_id, unsigned long long answer_id);

  // Robots with a task whose SetPosEnd or Abort is still to be pushed.
  std::vector<unsigned> robots_with_pushes(size_t limit, unsigned modulus = 1, unsigned remainder = 0);
  // Registered robots silent for longer than `seconds` with nothing waiting in rr.
  std::vector<unsigned> silent_robots(double seconds, size_t limit, unsigned modulus = 1, unsigned remainder = 0);

 private:
  RobotRow read_robot(const mysqlpp::Row& r);
  mysqlpp::Connection& c_;
};

}  // namespace fleetmap
