// The feed's objects (server/web/api/fleet_json.h, shared with REST) and its diff
// (fleet_feed.h), without a
// database: what is null, how times read, and that only changed robots go out.
#include "server/web/http/fleet_feed.h"

#include <gtest/gtest.h>

#include "server/web/api/fleet_json.h"
#include "server/web/api/utc_session.h"

namespace fleetmap::web {
namespace {

TEST(FeedJson, TimesAsIso8601Utc) {
  EXPECT_EQ(iso8601_utc("2026-12-02 04:10:08.123456"), "2026-12-02T04:10:08.123456Z");
  EXPECT_EQ(iso8601_utc("2026-12-02 04:10:08"), "2026-12-02T04:10:08Z");
  EXPECT_EQ(iso8601_utc(""), "");
}

TEST(FeedJson, UnknownsAreNull) {
  RobotStatus s;
  s.name = "r1";
  const nlohmann::json j = robot_state_json(s, std::nullopt);
  for (const char* key : {"map", "x", "y", "theta", "v", "lonlat", "task", "goal", "last_seen"})
    EXPECT_TRUE(j.at(key).is_null()) << key << ": " << j.dump();
  EXPECT_EQ(j["state"], "offline");
}

TEST(FeedJson, AKnownRobot) {
  RobotStatus s;
  s.name = "r1";
  s.map = "campus";
  s.state = RobotState::Moving;
  s.x = 1.5, s.y = -2, s.theta = 0.25, s.v = 0.5;
  s.task_id = 42, s.task_state = TaskState::Active;
  s.goal_x = 10, s.goal_y = 20;
  s.last_seen = "2026-12-02 04:10:08.5";
  const nlohmann::json j = robot_state_json(s, LonLat{4.8, 45.7});
  EXPECT_EQ(j["map"], "campus");
  EXPECT_EQ(j["state"], "moving");
  EXPECT_EQ(j["x"], 1.5);
  EXPECT_EQ(j["lonlat"], nlohmann::json::array({4.8, 45.7}));
  EXPECT_EQ(j["task"], (nlohmann::json{{"id", 42}, {"state", "active"}}));
  EXPECT_EQ(j["goal"], nlohmann::json::array({10, 20}));
  EXPECT_EQ(j["last_seen"], "2026-12-02T04:10:08.5Z");

  TaskInfo t{7, "r1", TaskState::Done, "", "2026-12-02 04:00:00.000001", "2026-12-02 04:01:00.000002", 3, 4};
  const nlohmann::json tj = task_json(t);
  EXPECT_EQ(tj["goal"], nlohmann::json::array({3, 4}));
  EXPECT_EQ(tj["state"], "done");
  EXPECT_EQ(tj["updated_at"], "2026-12-02T04:01:00.000002Z");
}

TEST(RobotDiff, OnlyChangedRobots) {
  RobotDiff d;
  const nlohmann::json a{{"name", "a"}, {"x", 1}}, b{{"name", "b"}, {"x", 2}};
  EXPECT_EQ(d.changed({a, b}).size(), 2u) << "the first poll: every robot";
  EXPECT_TRUE(d.changed({a, b}).empty());
  nlohmann::json b2 = b;
  b2["x"] = 3;
  const auto changed = d.changed({a, b2});
  ASSERT_EQ(changed.size(), 1u);
  EXPECT_EQ(changed[0], b2);
}

}  // namespace
}  // namespace fleetmap::web
