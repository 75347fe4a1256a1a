// GetMap (SPEC 5.2, 5.4): the w x h window centred on (x, y), capped to max_window_m,
// clipped to the border; "2.5d" adds the scene.
#include <gtest/gtest.h>

#include "tests/server/daemon/fake_stores.h"

namespace fleetmap::fakes {
namespace {

TEST(GetMap, AnswersTheWindowClippedToTheBorder) {
  Bench b;
  const RequestWrites w = b.send("GetMap", R"({"x": 18, "y": 5, "w": 6, "h": 2})");
  ASSERT_EQ(w.answers.size(), 1u);
  EXPECT_EQ(w.answers[0].op, AnswerOp::SetMap);
  EXPECT_EQ(w.answers[0].params["border"], Json::parse("[15, 6, 20, 4]"));  // x 15..21 cut at 20
  EXPECT_EQ(w.answers[0].params["segments"], 0);  // the wall is at x = 10
  EXPECT_FALSE(w.answers[0].params.contains("mode"));
  ASSERT_EQ(b.maps.requested.size(), 1u);
  EXPECT_DOUBLE_EQ(b.maps.requested[0].window->xmax, 20);
}

TEST(GetMap, TheSidesAreCappedByConfiguration) {
  Bench b;
  b.config.max_window_m = 2;
  const RequestWrites w = b.send("GetMap", R"({"x": 10, "y": 4, "w": 100, "h": 100})");
  ASSERT_EQ(w.answers.size(), 1u);
  EXPECT_EQ(w.answers[0].params["border"], Json::parse("[9, 5, 11, 3]"));
  EXPECT_EQ(w.answers[0].params["segments"], 2);  // the wall's two long sides, cut at y = 3..5
}

TEST(GetMap, AWindowOutsideTheBorderIsBadParams) {
  Bench b;
  EXPECT_EQ(error_code(b.send("GetMap", R"({"x": 50, "y": 50, "w": 4, "h": 4})")), "bad_params");
}

TEST(GetMap, TwoAndAHalfDCarriesTheSceneAndTheUnslicedMap) {
  Bench b;
  b.robot().laser_height = 0.3;
  const RequestWrites w = b.send("GetMap", R"({"x": 10, "y": 5, "w": 4, "h": 4, "mode": "2.5d"})");
  ASSERT_EQ(w.answers.size(), 1u);
  EXPECT_EQ(w.answers[0].params["mode"], "2.5d");
  EXPECT_TRUE(w.answers[0].params.contains("scene"));
  EXPECT_FALSE(b.maps.requested.at(0).laser_height);  // unsliced
}

TEST(GetMap, MalformedParamsGetBadParams) {
  for (const char* params : {R"({"x": 1, "y": 1, "w": 0, "h": 1})", R"({"x": 1, "y": 1, "w": -2, "h": 1})",
                             R"({"x": 1, "y": 1, "w": 2})", R"({"x": 1, "y": 1, "w": 2, "h": 2, "mode": "3d"})"}) {
    Bench b;
    EXPECT_EQ(error_code(b.send("GetMap", params)), "bad_params") << params;
    EXPECT_TRUE(b.maps.requested.empty()) << params;
  }
}

}  // namespace
}  // namespace fleetmap::fakes
