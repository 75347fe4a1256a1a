// The pure decisions of housekeeping (server/daemon/housekeeping.h): what a task needs
// pushed, when a silent robot is lost, when passes and the expiry sweep run.
#include "server/daemon/housekeeping.h"

#include <gtest/gtest.h>

namespace fleetmap {
namespace {

TaskRow open_task(std::optional<unsigned long long> answer, bool abort_requested,
                  std::optional<unsigned long long> abort_answer, TaskState state = TaskState::Assigned) {
  TaskRow t;
  t.id = 1;
  t.state = state;
  t.answer_id = answer;
  t.abort_requested = abort_requested;
  t.abort_answer_id = abort_answer;
  return t;
}

TEST(PushAction, ANewTaskGetsItsGoalPushedOnce) {
  EXPECT_EQ(push_action(open_task(std::nullopt, false, std::nullopt)), PushAction::SendGoal);
  EXPECT_EQ(push_action(open_task(10, false, std::nullopt)), PushAction::None);
}

TEST(PushAction, AnAbortIsPushedOnceAndOnlyWhenTheRobotWasToldOfTheGoal) {
  EXPECT_EQ(push_action(open_task(10, true, std::nullopt, TaskState::Active)), PushAction::SendAbort);
  EXPECT_EQ(push_action(open_task(10, true, 11, TaskState::Active)), PushAction::None);
  EXPECT_EQ(push_action(open_task(std::nullopt, true, std::nullopt)), PushAction::AbortUnsent);
}

TEST(PushAction, AFinishedTaskNeedsNothing) {
  for (TaskState s : {TaskState::Done, TaskState::Aborted, TaskState::Failed}) {
    EXPECT_EQ(push_action(open_task(std::nullopt, false, std::nullopt, s)), PushAction::None);
    EXPECT_EQ(push_action(open_task(10, true, std::nullopt, s)), PushAction::None);
  }
}

TEST(LostAfter, IsTheAlivePeriodTimesThePeriodsAllowed) {
  ServerConfig c;
  EXPECT_DOUBLE_EQ(lost_after_s(c), 5.0);  // defaults: 1 s x 5
  c.alive_period_s = 0.2;
  c.lost_after_periods = 3;
  EXPECT_DOUBLE_EQ(lost_after_s(c), 0.6);
}

TEST(HousekeepingSchedule, RunsAtOnceThenEveryPeriodAndSweepsEveryNthPass) {
  using namespace std::chrono_literals;
  HousekeepingSchedule s(100ms, 3);
  const auto t0 = std::chrono::steady_clock::time_point{} + 1h;
  auto first = s.due(t0);
  ASSERT_TRUE(first);
  EXPECT_TRUE(first->expire_observations);  // the first pass sweeps
  EXPECT_FALSE(s.due(t0 + 99ms));
  auto second = s.due(t0 + 100ms);
  ASSERT_TRUE(second);
  EXPECT_FALSE(second->expire_observations);
  EXPECT_FALSE(s.due(t0 + 150ms));
  // Late: the next pass is a period after this one, not after the one missed.
  auto third = s.due(t0 + 450ms);
  ASSERT_TRUE(third);
  EXPECT_FALSE(third->expire_observations);
  EXPECT_FALSE(s.due(t0 + 500ms));
  auto fourth = s.due(t0 + 550ms);
  ASSERT_TRUE(fourth);
  EXPECT_TRUE(fourth->expire_observations);  // pass 4 of every 3rd: 1, 4, 7, ...
}

}  // namespace
}  // namespace fleetmap
