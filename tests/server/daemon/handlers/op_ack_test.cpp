// OpAck (SPEC 5.2, 5.3): of a pushed SetPosEnd -> acknowledged, of a pushed Abort ->
// aborted; an answer that is none of this robot's pushes -> unknown_answer.
#include <gtest/gtest.h>

#include "tests/server/daemon/fake_stores.h"

namespace fleetmap::fakes {
namespace {

struct OpAckTest : ::testing::Test {
  Bench b;
  void SetUp() override {
    TaskRow t = task(3, 7, TaskState::Assigned, 5, 5);
    t.answer_id = 500;
    b.records.tasks.push_back(t);
    b.served.open_task = t;
  }
};

TEST_F(OpAckTest, OfTheGoalAcknowledgesTheTaskWithoutAnAnswer) {
  const RequestWrites w = b.send("OpAck", R"({"answer_id": 500})");
  EXPECT_TRUE(w.answers.empty());
  ASSERT_EQ(b.records.task_states.size(), 1u);
  EXPECT_EQ(b.records.task_states[0], std::make_pair(3ull, TaskState::Acknowledged));
  EXPECT_EQ(b.served.open_task->state, TaskState::Acknowledged);
}

TEST_F(OpAckTest, OfTheAbortAbortsTheTask) {
  b.records.tasks[0].state = b.served.open_task->state = TaskState::Active;
  b.records.tasks[0].abort_answer_id = 510;
  EXPECT_TRUE(b.send("OpAck", R"({"answer_id": 510})").answers.empty());
  ASSERT_EQ(b.records.task_states.size(), 1u);
  EXPECT_EQ(b.records.task_states[0], std::make_pair(3ull, TaskState::Aborted));
  EXPECT_FALSE(b.served.open_task);
}

TEST_F(OpAckTest, ALateAcknowledgementChangesNothing) {
  b.records.tasks[0].state = b.served.open_task->state = TaskState::Active;
  EXPECT_TRUE(b.send("OpAck", R"({"answer_id": 500})").answers.empty());
  // The robot reached its goal before it acknowledged the Abort: the task stays done.
  b.records.tasks[0].state = TaskState::Done;
  b.records.tasks[0].abort_answer_id = 510;
  b.served.open_task.reset();
  EXPECT_TRUE(b.send("OpAck", R"({"answer_id": 510})").answers.empty());
  EXPECT_TRUE(b.records.task_states.empty());
}

TEST_F(OpAckTest, AnAnswerThatIsNotThisRobotsPushIsUnknown) {
  EXPECT_EQ(error_code(b.send("OpAck", R"({"answer_id": 501})")), "unknown_answer");
  b.records.tasks[0].robot_id = 8;  // another robot's push
  EXPECT_EQ(error_code(b.send("OpAck", R"({"answer_id": 500})")), "unknown_answer");
  EXPECT_TRUE(b.records.task_states.empty());
}

TEST_F(OpAckTest, MalformedParamsGetBadParams) {
  for (const char* params : {R"({})", R"({"answer_id": -1})", R"({"answer_id": "500"})", R"({"answer_id": 5.5})"})
    EXPECT_EQ(error_code(b.send("OpAck", params)), "bad_params") << params;
  EXPECT_TRUE(b.records.task_states.empty());
}

}  // namespace
}  // namespace fleetmap::fakes
