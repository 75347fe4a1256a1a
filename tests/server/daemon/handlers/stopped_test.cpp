// Stopped (SPEC 5.2, 5.3): robot state stopped; an active task whose goal is within
// goal_tolerance_m of the last pose is done.
#include <gtest/gtest.h>

#include "tests/server/daemon/fake_stores.h"

namespace fleetmap::fakes {
namespace {

TEST(Stopped, StopsTheRobotAndAcknowledges) {
  Bench b;
  b.robot().state = RobotState::Moving;
  b.robot().v = 0.8;
  const RequestWrites w = b.send("Stopped", "{}");
  ASSERT_EQ(w.answers.size(), 1u);
  EXPECT_EQ(w.answers[0].op, AnswerOp::OpAck);
  EXPECT_EQ(w.answers[0].params["request_id"], b.next_id);
  EXPECT_EQ(b.robot().state, RobotState::Stopped);
  EXPECT_EQ(b.robot().v, 0);
}

TEST(Stopped, AnActiveTaskAtItsGoalIsDone) {
  Bench b;
  b.config.goal_tolerance_m = 0.5;
  b.robot().x = 5.3;
  b.robot().y = 5.3;  // 0.42 m from the goal
  b.served.open_task = task(3, 7, TaskState::Active, 5, 5);
  b.send("Stopped", "{}");
  ASSERT_EQ(b.records.task_states.size(), 1u);
  EXPECT_EQ(b.records.task_states[0], std::make_pair(3ull, TaskState::Done));
  EXPECT_FALSE(b.served.open_task);  // done is no longer open
}

TEST(Stopped, ShortOfTheGoalOrNotActiveTheTaskStaysAsItIs) {
  Bench b;
  b.robot().x = 5.4;
  b.robot().y = 5.4;  // 0.57 m
  b.served.open_task = task(3, 7, TaskState::Active, 5, 5);
  b.send("Stopped", "{}");
  b.robot().x = 5;
  b.robot().y = 5;
  b.served.open_task = task(3, 7, TaskState::Acknowledged, 5, 5);  // never planned nor moved
  b.send("Stopped", "{}");
  EXPECT_TRUE(b.records.task_states.empty());
  ASSERT_TRUE(b.served.open_task);
  EXPECT_EQ(b.served.open_task->state, TaskState::Acknowledged);
}

TEST(Stopped, MalformedParamsLeaveTheRobotMoving) {
  Bench b;
  b.robot().state = RobotState::Moving;
  EXPECT_EQ(error_code(b.send("Stopped", "[1]")), "bad_json");
  EXPECT_EQ(b.robot().state, RobotState::Moving);
}

}  // namespace
}  // namespace fleetmap::fakes
