// The operator's list commands for scripts (README "Operator commands"): `--json` on
// robots, robot list, tasks, map list, objects list|near and avoid list, checked against
// the database read here with plain SQL; `robots --watch` to a pipe; deleting one object
// or one avoided area, with exit 4 for a key that is not there.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "tests/integration/server_fixture.h"
#include "tests/integration/test_db.h"

namespace fleetmap::test {
namespace {

using nlohmann::json;

class CliLists : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    RunResult r = run("fleetmap", "map import " + source_path("maps/example-room.map") + " --name cl_room --replace --drop all");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    r = run("fleetmap", "objects import cl_room " + source_path("maps/example-room.geojson"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    add_robot("cl_r1", "cl_room");
    admin()->query("UPDATE robots SET x = 7.5, y = 3, theta = 0.5, v = 0 WHERE db_user = 'cl_r1'").execute();
  }
  static json parsed(const RunResult& r) {
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return json::parse(r.out);
  }
  static std::string map_id() { return std::to_string(scalar("SELECT id FROM maps WHERE name = 'cl_room'")); }
};

TEST_F(CliLists, RobotsAndRobotListAsJson) {
  const json robots = parsed(run("fleetmap", "robots --json"));
  ASSERT_TRUE(robots.is_array());
  EXPECT_EQ(static_cast<long long>(robots.size()), scalar("SELECT COUNT(*) FROM v_robot_status"));
  const json* mine = nullptr;
  for (const json& r : robots)
    if (r["robot"] == "cl_r1") mine = &r;
  ASSERT_NE(mine, nullptr) << robots.dump();
  EXPECT_EQ((*mine)["x"], 7.5);
  EXPECT_EQ((*mine)["y"], 3.0);
  EXPECT_EQ((*mine)["theta"], 0.5);
  EXPECT_EQ((*mine)["state"], "offline");
  const json list = parsed(run("fleetmap", "robot list --json"));
  bool found = false;
  for (const json& r : list)
    if (r["name"] == "cl_r1") {
      found = true;
      EXPECT_EQ(r["map"], "cl_room");
      EXPECT_TRUE(r["radius"].is_null());  // the server's default
      EXPECT_EQ(r["ramps"], true);
    }
  EXPECT_TRUE(found) << list.dump();
}

TEST_F(CliLists, TasksAsJsonNewestFirst) {
  ASSERT_EQ(run("fleetmap", "goal cl_r1 7.5 12").exit_code, 0);
  const json tasks = parsed(run("fleetmap", "tasks --robot cl_r1 --limit 1 --json"));
  ASSERT_EQ(tasks.size(), 1u);
  EXPECT_EQ(tasks[0]["id"], scalar("SELECT MAX(t.id) FROM tasks t JOIN robots r ON r.id = t.robot_id WHERE r.db_user = 'cl_r1'"));
  EXPECT_EQ(tasks[0]["goal"], json({7.5, 12.0}));
  EXPECT_EQ(tasks[0]["state"], "assigned");
}

TEST_F(CliLists, MapListAsJson) {
  const json maps = parsed(run("fleetmap", "map list --json"));
  bool found = false;
  for (const json& m : maps)
    if (m["name"] == "cl_room") {
      found = true;
      EXPECT_EQ(m["border"], json({-0.5, 15.5, 15.5, -0.5}));  // maps/example-room.map's border
      EXPECT_EQ(m["segments"], scalar("SELECT segments FROM maps WHERE name = 'cl_room'"));
    }
  EXPECT_TRUE(found) << maps.dump();
}

TEST_F(CliLists, ObjectsAndAvoidedAreasAsJson) {
  const json objects = parsed(run("fleetmap", "objects list cl_room --json"));
  EXPECT_EQ(static_cast<long long>(objects.size()),
            scalar("SELECT COUNT(*) FROM env_objects WHERE map_id = " + map_id()));
  const json near = parsed(run("fleetmap", "objects near cl_room 14 2 --tag charging_station --json"));
  ASSERT_EQ(near.size(), 1u);
  EXPECT_EQ(near[0]["key"], "charger-1");
  EXPECT_NEAR(near[0]["distance"].get<double>(), 0.7, 1e-9);  // from x = 14 to the footprint's x = 14.7
  const json areas = parsed(run("fleetmap", "avoid list cl_room --json"));
  EXPECT_EQ(static_cast<long long>(areas.size()),
            scalar("SELECT COUNT(*) FROM avoided_areas WHERE map_id = " + map_id()));
}

TEST_F(CliLists, RobotsWatchToAPipeAppendsEachRefresh) {
  const RunResult r = run("fleetmap", "robots --watch 0.1 --count 3");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  size_t headers = 0;
  for (size_t at = r.out.find("ROBOT "); at != std::string::npos; at = r.out.find("ROBOT ", at + 1)) ++headers;
  EXPECT_EQ(headers, 3u) << r.out;
  EXPECT_NE(r.out.find("every 0.1 s"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("\033["), std::string::npos);  // no screen control codes into a pipe
  const RunResult j = run("fleetmap", "robots --watch 0.1 --count 2 --json");
  ASSERT_EQ(j.exit_code, 0) << j.err;
  std::istringstream lines(j.out);
  std::string line;
  size_t arrays = 0;
  while (std::getline(lines, line)) {
    EXPECT_TRUE(json::parse(line).is_array()) << line;
    ++arrays;
  }
  EXPECT_EQ(arrays, 2u);
  EXPECT_EQ(run("fleetmap", "robots --count 2").exit_code, 64);  // --count needs --watch
}

TEST_F(CliLists, RemoveOneObjectAndOneAvoidedArea) {
  const std::string objects = "SELECT COUNT(*) FROM env_objects WHERE map_id = " + map_id();
  const std::string areas = "SELECT COUNT(*) FROM avoided_areas WHERE map_id = " + map_id();
  const long long o = scalar(objects), a = scalar(areas);
  ASSERT_GT(scalar(objects + " AND object_key = 'box-1'"), 0);
  RunResult r = run("fleetmap", "objects remove cl_room box-1");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(scalar(objects), o - 1);
  EXPECT_EQ(scalar(objects + " AND object_key = 'box-1'"), 0);
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM object_elements e LEFT JOIN env_objects o ON o.id = e.object_id "
                   "WHERE o.id IS NULL"),
            0);  // its elements went with it
  r = run("fleetmap", "objects remove cl_room box-1");
  EXPECT_EQ(r.exit_code, 4);
  EXPECT_NE(r.err.find("no object 'box-1'"), std::string::npos) << r.err;
  r = run("fleetmap", "avoid remove cl_room keepout-1");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(scalar(areas), a - 1);
  EXPECT_EQ(run("fleetmap", "avoid remove cl_room keepout-1").exit_code, 4);
  EXPECT_EQ(run("fleetmap", "avoid remove no_such_map keepout-1").exit_code, 4);
  // Put them back for the other tests of this suite.
  r = run("fleetmap", "objects import cl_room " + source_path("maps/example-room.geojson") + " --replace");
  EXPECT_EQ(r.exit_code, 0) << r.err;
}

}  // namespace
}  // namespace fleetmap::test
