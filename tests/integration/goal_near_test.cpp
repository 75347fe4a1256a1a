// Goals by meaning and planning with objects through the real programs (docs/semantic-layer.md):
// `fleetmap goal ROBOT --near TAG` on the example room with its objects (the goal beside
// the charging station, checked with polygon distances; exit codes), and GetPath keeping
// to the robot's profile and out of the avoided areas, an area added while the server
// runs included.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <thread>

#include "common/planning/goal_near.h"
#include "common/planning/planning_scene.h"
#include "protocol/scene_store.h"
#include "tests/common/planning/scene_planning_test_util.h"
#include "tests/integration/server_fixture.h"
#include "tests/integration/test_db.h"

namespace fleetmap::test {
namespace {

using nlohmann::json;

// The charging station's footprint in maps/example-room.geojson (x 14.7..15 against the
// east wall, y 1.7..2.3).
const Polygon& station() {
  static const Polygon p = [] {
    for (const EnvObject& o : planning_test::example_room_scene().objects)
      if (o.tag == "charging_station") return o.elements.at(0).footprint;
    throw std::runtime_error("no charging station in the example room");
  }();
  return p;
}

double number(const std::string& sql) {
  auto c = admin();
  mysqlpp::StoreQueryResult r = c->query(sql).store();
  if (r.empty() || r[0][0].is_null()) throw std::runtime_error("no value: " + sql);
  return std::stod(std::string(r[0][0].data(), r[0][0].length()));
}

class GoalNear : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    RunResult r = run("fleetmap", "map import " + source_path("maps/example-room.map") + " --name gn_room --replace --drop all");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    r = run("fleetmap", "objects import gn_room " + source_path("maps/example-room.geojson"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  void SetUp() override {
    password_ = add_robot("gn_r1", "gn_room");
    // A robot added again keeps its row: forget poses and profile of earlier runs.
    admin()->query("UPDATE robots SET x = NULL, y = NULL, ini_x = NULL, ini_y = NULL, radius = NULL, "
                   "body_height = NULL WHERE db_user = 'gn_r1'").execute();
    robot_id_ = std::to_string(scalar("SELECT id FROM robots WHERE db_user = 'gn_r1'"));
  }
  Point last_goal() {
    const std::string q = " FROM tasks WHERE robot_id = " + robot_id_ + " ORDER BY id DESC LIMIT 1";
    return {number("SELECT goal_x" + q), number("SELECT goal_y" + q)};
  }
  long long tasks() { return scalar("SELECT COUNT(*) FROM tasks WHERE robot_id = " + robot_id_); }

  std::string password_, robot_id_;
};

// Clear for a disc of radius r among the room's walls, blocking objects (body 1 m, the
// server's default) and avoided areas, by the independent judge.
void expect_free(Point p, double r) {
  const planning_test::SceneJudge judge(planning_test::example_room_map(), planning_test::example_room_scene(), 1.0, r);
  EXPECT_TRUE(judge.comfortably_clear(p, 0)) << p.x << " " << p.y;
}

TEST_F(GoalNear, GoalBesideTheChargingStationFromTheInitialPose) {
  ASSERT_EQ(run("fleetmap", "pose-ini gn_r1 7.5 3").exit_code, 0);
  const long long before = tasks();
  const RunResult r = run("fleetmap", "goal gn_r1 --near charging_station");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("beside charging_station 'charger-1'"), std::string::npos) << r.out;
  EXPECT_EQ(tasks(), before + 1);
  const Point g = last_goal();
  const double d = distance_to_polygon(g, station());
  // Outside it, at the server's default radius 0.3 m + the margin 0.1 m.
  EXPECT_GT(d, 0.3);
  EXPECT_LE(d, 0.4 + 1e-3);  // the printed goal is rounded to the millimetre
  expect_free(g, 0.3);
  EXPECT_EQ(scalar("SELECT state = 'assigned' FROM tasks WHERE robot_id = " + robot_id_ + " ORDER BY id DESC LIMIT 1"), 1);
}

TEST_F(GoalNear, TheProfileAndTheLastPoseCount) {
  ASSERT_EQ(run("fleetmap", "pose-ini gn_r1 7.5 3").exit_code, 0);
  // A reported pose wins over the initial one; a 0.5 m robot stays 0.5 + 0.2 m away.
  admin()->query("UPDATE robots SET x = 13, y = 6, radius = 0.5 WHERE db_user = 'gn_r1'").execute();
  const RunResult r = run("fleetmap", "goal gn_r1 --near charging_station --margin 0.2");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("from (13.000, 6.000)"), std::string::npos) << r.out;
  const Point g = last_goal();
  EXPECT_NEAR(distance_to_polygon(g, station()), 0.7, 1e-3);
  expect_free(g, 0.5);
  // From the north, the goal is on the station's north side or its north-west corner.
  EXPECT_GT(g.y, 2.0);
}

TEST_F(GoalNear, ErrorsAndExitCodes) {
  const long long before = tasks();
  // No pose reported, no initial pose.
  RunResult r = run("fleetmap", "goal gn_r1 --near charging_station");
  EXPECT_EQ(r.exit_code, 4);
  EXPECT_NE(r.err.find("no known position"), std::string::npos) << r.err;
  ASSERT_EQ(run("fleetmap", "pose-ini gn_r1 7.5 3").exit_code, 0);
  // A tag no object on the map has (columns are avoided areas here), and a word that is no tag.
  r = run("fleetmap", "goal gn_r1 --near column");
  EXPECT_EQ(r.exit_code, 4);
  EXPECT_NE(r.err.find("no object tagged 'column'"), std::string::npos) << r.err;
  EXPECT_EQ(run("fleetmap", "goal gn_r1 --near spaceship").exit_code, 4);
  EXPECT_EQ(run("fleetmap", "goal gn_no_such_robot --near charging_station").exit_code, 4);
  EXPECT_EQ(run("fleetmap", "goal gn_r1 --near charging_station --map it_plan").exit_code, 2);
  // The robot's own position inside the keep-out zone.
  admin()->query("UPDATE robots SET x = 2.5, y = 11 WHERE db_user = 'gn_r1'").execute();
  r = run("fleetmap", "goal gn_r1 --near charging_station");
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_NE(r.err.find("avoid:keepout-1"), std::string::npos) << r.err;
  // Usage: X Y or --near, one of them.
  EXPECT_EQ(run("fleetmap", "goal gn_r1").exit_code, 64);
  EXPECT_EQ(run("fleetmap", "goal gn_r1 1 2 --near charging_station").exit_code, 64);
  EXPECT_EQ(tasks(), before);
}

// GetPath plans with the robot's profile among the scene, and sees an avoided area added
// while the server runs.
TEST_F(GoalNear, GetPathKeepsOutOfAvoidedAreas) {
  ServerProcess server(kQuietRobotFlags, "gn_server.log");
  SqlRobot robot("gn_r1", password_);
  robot.send("Ready", R"({"magic": 3})");
  ASSERT_EQ(robot.receive(2).size(), 2u);
  ASSERT_EQ(run("fleetmap", "goal gn_r1 1 12").exit_code, 0);
  auto push = robot.receive(1);
  ASSERT_EQ(push.size(), 1u);
  robot.send("OpAck", json{{"answer_id", push[0].id}}.dump());
  robot.send("SendPos", R"({"x": 1, "y": 8, "theta": 0, "v": 0})");
  auto path_now = [&] {
    robot.send("GetPath", "{}");
    auto a = robot.receive(1);
    EXPECT_EQ(a.size(), 1u);
    return a.empty() ? SqlAnswer{} : a[0];
  };
  auto check = [&](const SqlAnswer& a, const std::string& wkt_area) {
    ASSERT_EQ(a.op, "SetPath") << a.params.dump();
    Path p;
    for (const auto& w : a.params["waypoints"]) p.push_back({w[0].get<double>(), w[1].get<double>()});
    Scene s = planning_test::example_room_scene();
    if (!wkt_area.empty()) s.avoided.push_back({"new", parse_polygon_wkt(wkt_area)});
    const planning_test::SceneJudge judge(planning_test::example_room_map(), s, 1.0, 0.3);
    EXPECT_EQ(judge.check_path(p), "");
  };
  SqlAnswer a = path_now();
  check(a, "");
  const std::string block = "POLYGON((0 9.5,2.4 9.5,2.4 10,0 10,0 9.5))";
  {  // the way it takes now, straight north west of keepout-1, is what the new area closes
    ASSERT_EQ(a.op, "SetPath");
    Path p;
    for (const auto& w : a.params["waypoints"]) p.push_back({w[0].get<double>(), w[1].get<double>()});
    Scene s = planning_test::example_room_scene();
    s.avoided.push_back({"new", parse_polygon_wkt(block)});
    EXPECT_NE(planning_test::SceneJudge(planning_test::example_room_map(), s, 1.0, 0.3).check_path(p), "");
    EXPECT_EQ(p.size(), 2u);
  }
  // A wall of keep-out across the west side, x 0..2.4 at y 9.5..10 (overlapping
  // keepout-1, x 2..4): the way north now goes round east of both.
  ASSERT_EQ(run("fleetmap", "avoid add gn_room --id gn-block --wkt '" + block + "'").exit_code, 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(400));  // RobotMapSource::kRecheck
  a = path_now();
  check(a, block);
  ASSERT_EQ(a.op, "SetPath");
  EXPECT_GT(a.params["length"].get<double>(), 8);
  // A fat robot (1.2 m radius, its profile) cannot stand at the goal, 1 m from the west wall.
  admin()->query("UPDATE robots SET radius = 1.2 WHERE db_user = 'gn_r1'").execute();
  robot.send("SendPos", R"({"x": 7.5, "y": 3, "theta": 0, "v": 0})");
  a = path_now();
  EXPECT_EQ(a.op, "Error");
  EXPECT_EQ(a.params["code"], "no_path") << a.params.dump();
  EXPECT_NE(a.params["message"].get<std::string>().find("the goal is too close to"), std::string::npos)
      << a.params.dump();
  admin()->query("DELETE FROM avoided_areas WHERE area_key = 'gn-block'").execute();
  server.terminate();
  if (HasFailure()) std::cerr << "server log:\n" << read_file(temp_path("gn_server.log")).substr(0, 20000);
}

}  // namespace
}  // namespace fleetmap::test
