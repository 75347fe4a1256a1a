// Ready (SPEC 5.2): Start, then SetMap of the whole map or, past max_full_map_segments,
// of a window around the robot's best known position; the session is written last.
#include <gtest/gtest.h>

#include "tests/server/daemon/fake_stores.h"

namespace fleetmap::fakes {
namespace {

TEST(Ready, AnswersStartThenTheWholeMapAndStartsTheSession) {
  Bench b;
  b.robot().magic.reset();  // not registered yet: Ready is the one op allowed
  b.robot().state = RobotState::Offline;
  const RequestWrites w = b.send("Ready", R"({"magic": 77})");
  ASSERT_EQ(w.answers.size(), 2u);
  EXPECT_EQ(w.answers[0].op, AnswerOp::Start);
  EXPECT_EQ(w.answers[0].params["magic"], 77);
  EXPECT_EQ(w.answers[0].params["robot_id"], 7);
  EXPECT_EQ(w.answers[0].params["alive_period_s"], b.config.alive_period_s);
  EXPECT_EQ(w.answers[1].op, AnswerOp::SetMap);
  EXPECT_EQ(w.answers[1].params["segments"], 4);
  EXPECT_EQ(w.answers[1].params["border"], Json::parse("[0, 10, 20, 0]"));
  EXPECT_EQ(w.answers[1].params["encoding"], "seed");
  ASSERT_TRUE(w.answers[1].payload);
  for (const Answer& a : w.answers) EXPECT_EQ(a.request_id, b.next_id);
  ASSERT_EQ(b.maps.requested.size(), 1u);
  EXPECT_FALSE(b.maps.requested[0].window);  // the whole map
  EXPECT_EQ(b.records.sessions.at(7), 77);
  EXPECT_EQ(b.robot().magic, 77);
  EXPECT_EQ(b.robot().state, RobotState::Ready);
}

TEST(Ready, ALargeMapGoesOutAsAWindowAroundTheLastPoseElseTheInitialPoseElseTheCentre) {
  Bench b;
  b.config.max_full_map_segments = 3;  // the room has 4
  b.config.ready_window_m = 4;
  b.send("Ready", R"({"magic": 1})");
  b.robot().ini_x = 15;
  b.robot().ini_y = 8;
  b.send("Ready", R"({"magic": 2})");
  b.robot().x = 3;
  b.robot().y = 2;
  b.send("Ready", R"({"magic": 3})");
  ASSERT_EQ(b.maps.requested.size(), 3u);
  const Rect centre{8, 3, 12, 7}, ini{13, 6, 17, 10}, pose{1, 0, 5, 4};  // clipped to the border
  for (auto [i, r] : {std::pair{0, centre}, std::pair{1, ini}, std::pair{2, pose}}) {
    ASSERT_TRUE(b.maps.requested[i].window) << i;
    const Rect g = *b.maps.requested[i].window;
    EXPECT_DOUBLE_EQ(g.xmin, r.xmin) << i;
    EXPECT_DOUBLE_EQ(g.ymin, r.ymin) << i;
    EXPECT_DOUBLE_EQ(g.xmax, r.xmax) << i;
    EXPECT_DOUBLE_EQ(g.ymax, r.ymax) << i;
  }
}

TEST(Ready, TheMapIsSlicedAtTheProfilesLaserHeight) {
  Bench b;
  b.robot().laser_height = 0.4;
  const RequestWrites w = b.send("Ready", R"({"magic": 1, "encoding": "seed+compress"})");
  ASSERT_EQ(w.answers.size(), 2u);
  EXPECT_EQ(w.answers[1].params["laser_height"], 0.4);
  EXPECT_EQ(w.answers[1].params["encoding"], "seed+compress");
  EXPECT_EQ(b.maps.requested.at(0).laser_height, 0.4);
}

TEST(Ready, MalformedParamsGetBadParamsAndNoSession) {
  for (const char* params : {R"({})", R"({"magic": "x"})", R"({"magic": 1.5})", R"({"magic": 1, "encoding": "zip"})"}) {
    Bench b;
    const RequestWrites w = b.send("Ready", params);
    EXPECT_EQ(error_code(w), "bad_params") << params;
    EXPECT_FALSE(b.records.wrote_anything()) << params;
    EXPECT_EQ(b.robot().magic, 42) << params;
  }
}

TEST(Ready, WithoutAMapTheRequestIsRefusedBeforeTheSessionIsWritten) {
  Bench b;
  b.robot().map_id.reset();
  EXPECT_EQ(error_code(b.send("Ready", R"({"magic": 5})")), "internal");
  b.robot().map_id = 9;  // deleted
  EXPECT_EQ(error_code(b.send("Ready", R"({"magic": 5})")), "internal");
  EXPECT_TRUE(b.records.sessions.empty());
  EXPECT_EQ(b.robot().magic, 42);
}

}  // namespace
}  // namespace fleetmap::fakes
