#pragma once
// The life cycle of a task (SPEC 5.3: assigned, acknowledged, active, done, aborted,
// failed) as one pure function: what each event does to a task in each state. Every
// code path that changes tasks.state asks it first: the request handlers (OpAck, GetPath,
// SendPos, Stopped), the server's housekeeping (pushes, lost robots) and the operator's
// `fleetmap goal` (FleetStore::assign_goal). `robot_remove` (sql/40_robot_accounts.sql)
// applies RobotRemoved in SQL, on the same open states.
//
//   assigned --GoalAcknowledged--> acknowledged --RobotMoving--> active --GoalReached--> done
//   assigned, acknowledged --PathPlanned--> active
//   any open state --AbortAcknowledged, AbortedUnsent, Replaced--> aborted
//   any open state --NoPath, RobotLost, RobotRemoved--> failed
//
// done, aborted and failed are final: nothing reopens a task (an Abort acknowledged
// after the robot reached its goal leaves the task done).
#include <optional>
#include <string>
#include <string_view>

#include "protocol/fleet_states.h"

namespace fleetmap {

enum class TaskEvent {
  GoalAcknowledged,   // the robot's OpAck of the task's pushed SetPosEnd
  PathPlanned,        // GetPath answered with a SetPath to the task's goal
  RobotMoving,        // SendPos with v != 0
  GoalReached,        // Stopped within goal_tolerance_m of the goal
  AbortAcknowledged,  // the robot's OpAck of the pushed Abort
  AbortedUnsent,      // an operator's abort before the SetPosEnd was pushed: nothing to tell the robot
  Replaced,           // an operator gave the robot a new goal (its SetPosEnd replaces this one)
  NoPath,             // GetPath found no path to the task's goal: the robot stops, the task fails with why
  RobotLost,          // silent for lost_after_periods Alive periods
  RobotRemoved,       // the operator removed the robot
};

inline constexpr TaskEvent kTaskEvents[] = {
    TaskEvent::GoalAcknowledged, TaskEvent::PathPlanned, TaskEvent::RobotMoving,
    TaskEvent::GoalReached,      TaskEvent::AbortAcknowledged, TaskEvent::AbortedUnsent,
    TaskEvent::Replaced,         TaskEvent::NoPath,      TaskEvent::RobotLost,
    TaskEvent::RobotRemoved};

std::string_view to_string(TaskEvent e);

// assigned, acknowledged, active: the task a robot works on (one at most per robot).
bool is_open(TaskState s);

// The state an event leads to, or a refusal saying why (the event does not apply to a
// task in that state: e.g. a late OpAck of a task already active, or any event of a
// finished task). A refusal is not an error of the caller's: handlers leave the task as
// it is.
class TaskTransition {
 public:
  static TaskTransition to(TaskState next) { return TaskTransition(next, {}); }
  static TaskTransition refused(std::string why) { return TaskTransition(std::nullopt, std::move(why)); }

  bool allowed() const { return next_.has_value(); }
  explicit operator bool() const { return allowed(); }
  TaskState next() const;  // throws std::logic_error when refused
  const std::string& refusal() const { return why_; }  // empty when allowed

 private:
  TaskTransition(std::optional<TaskState> next, std::string why) : next_(next), why_(std::move(why)) {}
  std::optional<TaskState> next_;
  std::string why_;
};

TaskTransition task_transition(TaskState from, TaskEvent event);

}  // namespace fleetmap
