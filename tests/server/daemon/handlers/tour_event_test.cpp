// TourEvent (docs/protocol.md; seed 003 §III): the guide's event recorded with the pose
// of the robot's last SendPos, or the pose the params give; OpAck.
#include <gtest/gtest.h>

#include "tests/server/daemon/fake_stores.h"

namespace fleetmap::fakes {
namespace {

TEST(TourEvent, StampsTheLastSendPosPose) {
  Bench b;
  ASSERT_EQ(b.send("SendPos", R"({"x": 2.5, "y": 3, "theta": 1.25, "v": 0.4})").answers.size(), 0u);
  const RequestWrites w = b.send("TourEvent", R"({"event": "door", "tour": "east"})");
  ASSERT_EQ(w.answers.size(), 1u);
  EXPECT_EQ(w.answers[0].op, AnswerOp::OpAck);
  ASSERT_EQ(b.records.tour_events.size(), 1u);
  const auto& r = b.records.tour_events[0];
  EXPECT_EQ(r.robot_id, 7u);
  EXPECT_EQ(r.map_id, 1u);
  EXPECT_EQ(r.tour, "east");
  EXPECT_EQ(r.event.kind, TourEventKind::Door);
  EXPECT_EQ(r.event.pose, (TourPose{2.5, 3, 1.25}));
  EXPECT_FALSE(r.at.empty());
}

TEST(TourEvent, APoseInTheParamsWins) {
  Bench b;
  b.send("SendPos", R"({"x": 2.5, "y": 3, "theta": 1.25, "v": 0})");
  b.send("TourEvent", R"({"event": "place", "name": "dock", "x": -1, "y": 4, "theta": 0.5})");
  ASSERT_EQ(b.records.tour_events.size(), 1u);
  EXPECT_EQ(b.records.tour_events[0].event.pose, (TourPose{-1, 4, 0.5}));
  EXPECT_EQ(b.records.tour_events[0].event.name, "dock");
}

TEST(TourEvent, WithoutAPoseItIsRefused) {
  Bench b;
  b.robot().x.reset();
  b.robot().y.reset();
  b.robot().theta.reset();
  EXPECT_EQ(error_code(b.send("TourEvent", R"({"event": "crossing"})")), "no_pose");
  EXPECT_FALSE(b.records.wrote_anything());
}

TEST(TourEvent, MalformedParamsGetBadParamsAndRecordNothing) {
  for (const char* params : {R"({})", R"({"event": "lift"})", R"({"event": "place"})", R"({"event": "door", "x": 1})"}) {
    Bench b;
    EXPECT_EQ(error_code(b.send("TourEvent", params)), "bad_params") << params;
    EXPECT_FALSE(b.records.wrote_anything()) << params;
  }
}

}  // namespace
}  // namespace fleetmap::fakes
