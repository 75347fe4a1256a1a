// The task life cycle (protocol/task_lifecycle.h) against a table written here from
// SPEC 5.3 and what the server did in SQL before it was a function: every legal
// transition leads where the table says, every other (state, event) pair is refused.
#include "protocol/task_lifecycle.h"

#include <map>
#include <set>
#include <string>
#include <tuple>

#include <gtest/gtest.h>

namespace fleetmap {
namespace {

// (state, event) -> next state, the states as the database spells them
// (tasks.state ENUM, sql/10_schema.sql).
const std::map<std::pair<std::string, TaskEvent>, std::string>& legal() {
  static const std::map<std::pair<std::string, TaskEvent>, std::string> table = {
      // OpAck of SetPosEnd: only a task the robot had not yet taken.
      {{"assigned", TaskEvent::GoalAcknowledged}, "acknowledged"},
      // GetPath: the robot works on it now.
      {{"assigned", TaskEvent::PathPlanned}, "active"},
      {{"acknowledged", TaskEvent::PathPlanned}, "active"},
      // SendPos with v != 0 after the OpAck.
      {{"acknowledged", TaskEvent::RobotMoving}, "active"},
      // Stopped at the goal.
      {{"active", TaskEvent::GoalReached}, "done"},
      // Abort acknowledged, abort before the push, a new goal: aborted from any open state.
      {{"assigned", TaskEvent::AbortAcknowledged}, "aborted"},
      {{"acknowledged", TaskEvent::AbortAcknowledged}, "aborted"},
      {{"active", TaskEvent::AbortAcknowledged}, "aborted"},
      {{"assigned", TaskEvent::AbortedUnsent}, "aborted"},
      {{"acknowledged", TaskEvent::AbortedUnsent}, "aborted"},
      {{"active", TaskEvent::AbortedUnsent}, "aborted"},
      {{"assigned", TaskEvent::Replaced}, "aborted"},
      {{"acknowledged", TaskEvent::Replaced}, "aborted"},
      {{"active", TaskEvent::Replaced}, "aborted"},
      // GetPath's no_path, a lost or removed robot: the open task fails (robot_remove: 'robot removed').
      {{"assigned", TaskEvent::NoPath}, "failed"},
      {{"acknowledged", TaskEvent::NoPath}, "failed"},
      {{"active", TaskEvent::NoPath}, "failed"},
      {{"assigned", TaskEvent::RobotLost}, "failed"},
      {{"acknowledged", TaskEvent::RobotLost}, "failed"},
      {{"active", TaskEvent::RobotLost}, "failed"},
      {{"assigned", TaskEvent::RobotRemoved}, "failed"},
      {{"acknowledged", TaskEvent::RobotRemoved}, "failed"},
      {{"active", TaskEvent::RobotRemoved}, "failed"},
  };
  return table;
}

const char* kAllStates[] = {"assigned", "acknowledged", "active", "done", "aborted", "failed"};

TEST(TaskLifecycle, EveryLegalTransitionLeadsWhereSpec53Says) {
  for (const auto& [from_event, to] : legal()) {
    const auto& [from, event] = from_event;
    const TaskTransition t = task_transition(task_state_from_string(from), event);
    ASSERT_TRUE(t.allowed()) << from << " + " << to_string(event) << ": " << t.refusal();
    EXPECT_EQ(to_string(t.next()), to) << from << " + " << to_string(event);
    EXPECT_TRUE(t.refusal().empty());
  }
}

TEST(TaskLifecycle, EveryOtherStateAndEventPairIsRefused) {
  size_t refused = 0;
  for (const char* from : kAllStates)
    for (TaskEvent event : kTaskEvents) {
      if (legal().count({from, event})) continue;
      const TaskTransition t = task_transition(task_state_from_string(from), event);
      EXPECT_FALSE(t.allowed()) << from << " + " << to_string(event) << " should be refused, goes to "
                                << to_string(t.next());
      // The refusal says which event and which state.
      EXPECT_NE(t.refusal().find(std::string(to_string(event))), std::string::npos) << t.refusal();
      EXPECT_NE(t.refusal().find(from), std::string::npos) << t.refusal();
      EXPECT_THROW(t.next(), std::logic_error);
      ++refused;
    }
  // 6 states x 10 events, 23 legal.
  EXPECT_EQ(refused, 6u * 10u - 23u);
}

TEST(TaskLifecycle, FinishedTasksStayFinished) {
  for (const char* from : {"done", "aborted", "failed"})
    for (TaskEvent event : kTaskEvents) EXPECT_FALSE(task_transition(task_state_from_string(from), event)) << from;
}

TEST(TaskLifecycle, OpenStatesAreTheOnesTheServerWorksOn) {
  const std::set<std::string> open = {"assigned", "acknowledged", "active"};
  for (const char* s : kAllStates) EXPECT_EQ(is_open(task_state_from_string(s)), open.count(s) == 1) << s;
}

TEST(TaskLifecycle, EveryEventHasADistinctName) {
  std::set<std::string> names;
  for (TaskEvent e : kTaskEvents) names.insert(std::string(to_string(e)));
  EXPECT_EQ(names.size(), std::size(kTaskEvents));
  EXPECT_EQ(names.count("?"), 0u);
}

}  // namespace
}  // namespace fleetmap
