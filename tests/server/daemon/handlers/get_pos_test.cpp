// GetPosIni and GetPosEnd (SPEC 5.2): the operator's initial pose, the open task's goal.
#include <gtest/gtest.h>

#include "tests/server/daemon/fake_stores.h"

namespace fleetmap::fakes {
namespace {

TEST(GetPosIni, AnswersTheInitialPoseWithItsThetaWhenSet) {
  Bench b;
  EXPECT_EQ(error_code(b.send("GetPosIni", "{}")), "no_pose");
  b.robot().ini_x = 3;
  b.robot().ini_y = 4;
  RequestWrites w = b.send("GetPosIni", "{}");
  ASSERT_EQ(w.answers.size(), 1u);
  EXPECT_EQ(w.answers[0].op, AnswerOp::SetPosIni);
  EXPECT_EQ(w.answers[0].params, Json::parse(R"({"x": 3.0, "y": 4.0})"));
  b.robot().ini_theta = 1.5;
  w = b.send("GetPosIni", "{}");
  EXPECT_EQ(w.answers.at(0).params, Json::parse(R"({"x": 3.0, "y": 4.0, "theta": 1.5})"));
  EXPECT_EQ(error_code(b.send("GetPosIni", "5")), "bad_json");
}

TEST(GetPosEnd, AnswersTheOpenTasksGoal) {
  Bench b;
  EXPECT_EQ(error_code(b.send("GetPosEnd", "{}")), "no_goal");
  b.served.open_task = task(3, 7, TaskState::Assigned, 12.5, 8);
  const RequestWrites w = b.send("GetPosEnd", "{}");
  ASSERT_EQ(w.answers.size(), 1u);
  EXPECT_EQ(w.answers[0].op, AnswerOp::SetPosEnd);
  EXPECT_EQ(w.answers[0].params, Json::parse(R"({"x": 12.5, "y": 8.0})"));
  EXPECT_TRUE(b.records.task_states.empty());  // asking is no acknowledgement
  EXPECT_EQ(error_code(b.send("GetPosEnd", "[]")), "bad_json");
}

}  // namespace
}  // namespace fleetmap::fakes
