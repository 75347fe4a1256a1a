#include "protocol/task_lifecycle.h"

#include <stdexcept>

namespace fleetmap {

std::string_view to_string(TaskEvent e) {
  switch (e) {
    case TaskEvent::GoalAcknowledged: return "goal acknowledged";
    case TaskEvent::PathPlanned: return "path planned";
    case TaskEvent::RobotMoving: return "robot moving";
    case TaskEvent::GoalReached: return "goal reached";
    case TaskEvent::AbortAcknowledged: return "abort acknowledged";
    case TaskEvent::AbortedUnsent: return "aborted before it was sent";
    case TaskEvent::Replaced: return "replaced by a new goal";
    case TaskEvent::NoPath: return "no path";
    case TaskEvent::RobotLost: return "robot lost";
    case TaskEvent::RobotRemoved: return "robot removed";
  }
  return "?";
}

bool is_open(TaskState s) {
  return s == TaskState::Assigned || s == TaskState::Acknowledged || s == TaskState::Active;
}

TaskState TaskTransition::next() const {
  if (!next_) throw std::logic_error("refused task transition: " + why_);
  return *next_;
}

TaskTransition task_transition(TaskState from, TaskEvent event) {
  auto refuse = [&](const char* expected) {
    return TaskTransition::refused("'" + std::string(to_string(event)) + "' does not apply to a task " +
                                   std::string(to_string(from)) + " (expected a task " + expected + ")");
  };
  if (!is_open(from)) return refuse("assigned, acknowledged or active: a finished task stays finished");
  switch (event) {
    case TaskEvent::GoalAcknowledged:
      if (from == TaskState::Assigned) return TaskTransition::to(TaskState::Acknowledged);
      return refuse("assigned");
    case TaskEvent::PathPlanned:
      if (from == TaskState::Assigned || from == TaskState::Acknowledged) return TaskTransition::to(TaskState::Active);
      return refuse("assigned or acknowledged");
    case TaskEvent::RobotMoving:
      // Moving before it acknowledged the goal, the robot may still be on its way to the
      // previous one: the task is active once it took this goal.
      if (from == TaskState::Acknowledged) return TaskTransition::to(TaskState::Active);
      return refuse("acknowledged");
    case TaskEvent::GoalReached:
      if (from == TaskState::Active) return TaskTransition::to(TaskState::Done);
      return refuse("active");
    case TaskEvent::AbortAcknowledged:
    case TaskEvent::AbortedUnsent:
    case TaskEvent::Replaced:
      return TaskTransition::to(TaskState::Aborted);
    case TaskEvent::NoPath:
    case TaskEvent::RobotLost:
    case TaskEvent::RobotRemoved:
      return TaskTransition::to(TaskState::Failed);
  }
  return refuse("of a known event");
}

}  // namespace fleetmap
