// SendPos (SPEC 5.2): a trajectory point, the pose in the robot's row, moving or ready;
// an acknowledged task becomes active when the robot moves.
#include <cmath>

#include <gtest/gtest.h>

#include "tests/server/daemon/fake_stores.h"

namespace fleetmap::fakes {
namespace {

TEST(SendPos, RecordsThePoseWithoutAnAnswer) {
  Bench b;
  const RequestWrites w = b.send("SendPos", R"({"x": 1.5, "y": 2.5, "theta": 0.3, "v": 0.4, "w": 0.1})");
  EXPECT_TRUE(w.answers.empty());
  ASSERT_EQ(w.poses.size(), 1u);
  EXPECT_EQ(w.poses[0].robot_id, 7u);
  EXPECT_EQ(w.poses[0].pose.x, 1.5);
  EXPECT_EQ(w.poses[0].pose.w, 0.1);
  EXPECT_EQ(w.poses[0].at, "2026-11-28 07:00:01.000000");
  EXPECT_EQ(b.robot().x, 1.5);
  EXPECT_EQ(b.robot().y, 2.5);
  EXPECT_EQ(b.robot().theta, 0.3);
  EXPECT_EQ(b.robot().v, 0.4);
  EXPECT_EQ(b.robot().state, RobotState::Moving);
}

TEST(SendPos, StandingStillAMovingRobotIsReadyAStoppedOneStaysStopped) {
  Bench b;
  b.robot().state = RobotState::Moving;
  b.send("SendPos", R"({"x": 1, "y": 2, "theta": 0, "v": 0})");
  EXPECT_EQ(b.robot().state, RobotState::Ready);
  b.robot().state = RobotState::Stopped;
  b.send("SendPos", R"({"x": 1, "y": 2, "theta": 0, "v": 0})");
  EXPECT_EQ(b.robot().state, RobotState::Stopped);
}

TEST(SendPos, MovingWithAnAcknowledgedTaskMakesItActiveNotAnAssignedOne) {
  Bench b;
  b.served.open_task = task(3, 7, TaskState::Assigned, 5, 5);
  b.send("SendPos", R"({"x": 1, "y": 2, "theta": 0, "v": 0.5})");
  EXPECT_TRUE(b.records.task_states.empty());
  b.served.open_task->state = TaskState::Acknowledged;
  b.send("SendPos", R"({"x": 1, "y": 2, "theta": 0, "v": 0})");  // not moving
  EXPECT_TRUE(b.records.task_states.empty());
  b.send("SendPos", R"({"x": 1, "y": 2, "theta": 0, "v": -0.2})");
  ASSERT_EQ(b.records.task_states.size(), 1u);
  EXPECT_EQ(b.records.task_states[0], std::make_pair(3ull, TaskState::Active));
  EXPECT_EQ(b.served.open_task->state, TaskState::Active);
}

TEST(SendPos, MalformedParamsGetBadParamsAndLeaveThePose) {
  for (const char* params : {R"({"x": 1, "y": 2, "theta": 0})", R"({"x": "1", "y": 2, "theta": 0, "v": 0})",
                             R"({"x": 1, "y": 2, "theta": null, "v": 0})",
                             R"({"x": 1e999, "y": 2, "theta": 0, "v": 0})", R"({"y": 2, "theta": 0, "v": 0})"}) {
    Bench b;
    const RequestWrites w = b.send("SendPos", params);
    EXPECT_EQ(error_code(w), "bad_params") << params;
    EXPECT_TRUE(w.poses.empty()) << params;
    EXPECT_FALSE(b.robot().x) << params;
    EXPECT_EQ(b.robot().state, RobotState::Ready) << params;
  }
}

}  // namespace
}  // namespace fleetmap::fakes
