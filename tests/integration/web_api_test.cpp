// The routes of fleetmap-web (server/web/api) against the real test MariaDB, called as
// the transport calls them (web_api_client.h): reads as the web account, writes as the
// operator (or an inspector, whom the database refuses). Every endpoint's answer shape,
// and its errors: unknown names 404, refused goals 422 with no task row, bad bodies 400,
// ?crs=wgs84 on maps with and without a georeference; docs/openapi.json lists every route.
//
// Maps: webapi_gap (written here: 20 m x 10 m, a wall at x = 10 with a 1 m gap, a closed
// box at x 15..17, y 2..4; no georeference) and webapi_room (maps/example-room.map with its
// objects, a small topological graph, georeferenced at 48.1 N 11.5 E). Robots: webapi_r1
// on webapi_gap at (5, 5), webapi_r2 on webapi_room at (13, 6).
#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "common/core/error.h"
#include "server/web/api/api.h"
#include "server/web/api/topology_json.h"
#include "tests/integration/server_fixture.h"
#include "tests/integration/test_db.h"
#include "tests/integration/web_api_client.h"

namespace fleetmap::test {
namespace {

using nlohmann::json;

constexpr const char* kGapMap =
    "border;\n0;10;\n20;0;\n#\n"
    "obstacle;\n1;1;4;wall,south;\n#\n"
    "9.9;0;\n10.1;0;\n2;0;wall;\n#\n10.1;0;\n10.1;4.5;\n2;0;wall;\n#\n"
    "10.1;4.5;\n9.9;4.5;\n2;0;wall;\n#\n9.9;4.5;\n9.9;0;\n2;0;wall;\n#\n"
    "obstacle;\n2;1;4;wall,north;\n#\n"
    "9.9;5.5;\n10.1;5.5;\n2;0;wall;\n#\n10.1;5.5;\n10.1;10;\n2;0;wall;\n#\n"
    "10.1;10;\n9.9;10;\n2;0;wall;\n#\n9.9;10;\n9.9;5.5;\n2;0;wall;\n#\n"
    "obstacle;\n3;1;4;box;\n#\n"
    "15;2;\n17;2;\n1;0;box;\n#\n17;2;\n17;4;\n1;0;box;\n#\n17;4;\n15;4;\n1;0;box;\n#\n15;4;\n15;2;\n1;0;box;\n#\n";

// Nodes in free space of the example room: a named dock, two door nodes (one near the
// dock), a room node. Types: 0 room (room beats corridor), 1 and 2 door, 3 room.
constexpr const char* kRoomGraph = R"({
  "nodes": [{"id": 0, "loc": {"x": 13, "y": 7}, "name": "dock"},
            {"id": 1, "loc": {"x": 11, "y": 2}},
            {"id": 2, "loc": {"x": 7.5, "y": 1}},
            {"id": 3, "loc": {"x": 3, "y": 6}}],
  "edges": [{"s0_id": 0, "s1_id": 1},
            {"s0_id": 1, "s1_id": 2, "has_door": true},
            {"s0_id": 0, "s1_id": 3, "type": "room"}]
})";

void fleetmap_ok(const std::string& args) {
  const RunResult r = run("fleetmap", args);
  ASSERT_EQ(r.exit_code, 0) << "fleetmap " << args << ": " << r.out << r.err;
}

class WebApi : public ::testing::Test {
 protected:
  // The tests change robots and tasks only (SetUp resets those), never the maps.
  static void SetUpTestSuite() { once_per_instance("webapi", import_maps_and_robots); }
  static void import_maps_and_robots() {
    write_file(temp_path("webapi_gap.map"), kGapMap);
    fleetmap_ok("map import " + temp_path("webapi_gap.map") + " --name webapi_gap --replace --drop all");
    fleetmap_ok("map georef webapi_gap --clear");
    fleetmap_ok("map import " + source_path("maps/example-room.map") + " --name webapi_room --replace --drop all");
    fleetmap_ok("objects import webapi_room " + source_path("maps/example-room.geojson") + " --replace");
    write_file(temp_path("webapi_room.navigation.json"), kRoomGraph);
    fleetmap_ok("topo import webapi_room " + temp_path("webapi_room.navigation.json") + " --replace");
    fleetmap_ok("map georef webapi_room 48.1 11.5");
    add_robot("webapi_r1", "webapi_gap");
    add_robot("webapi_r2", "webapi_room");
  }

  void SetUp() override {
    // Robots added again keep their rows: known poses, default profiles, no open task.
    admin()->query("UPDATE robots SET x = 5, y = 5, theta = 0.25, v = 0, ini_x = NULL, ini_y = NULL, "
                   "ini_theta = NULL, radius = NULL, body_height = NULL, state = 'offline' "
                   "WHERE db_user = 'webapi_r1'").execute();
    admin()->query("UPDATE robots SET x = 13, y = 6, theta = 0, v = 0, ini_x = NULL, ini_y = NULL, "
                   "radius = NULL, body_height = NULL, state = 'offline' WHERE db_user = 'webapi_r2'").execute();
    admin()->query("UPDATE tasks SET state = 'done' WHERE robot_id IN (SELECT id FROM robots WHERE db_user "
                   "LIKE 'webapi\\_%') AND state IN ('assigned', 'acknowledged', 'active')").execute();
    r1_ = std::to_string(scalar("SELECT id FROM robots WHERE db_user = 'webapi_r1'"));
  }

  long long tasks_of(const std::string& robot) {
    return scalar("SELECT COUNT(*) FROM tasks t JOIN robots r ON r.id = t.robot_id WHERE r.db_user = '" + robot + "'");
  }

  // An error answer: status, code, and the message holding `what`.
  static void expect_error(const Answer& a, int status, const std::string& code, const std::string& what) {
    EXPECT_EQ(a.status, status) << a.body.dump();
    ASSERT_TRUE(a.body.contains("error")) << a.body.dump();
    const json& e = a.body["error"];
    EXPECT_EQ(e["status"], status);
    EXPECT_EQ(e["code"], code) << e.dump();
    EXPECT_TRUE(e["exit_code"].is_number_integer());
    EXPECT_NE(e["message"].get<std::string>().find(what), std::string::npos) << e.dump();
  }

  TestApiContext ctx_;
  std::string r1_;
};

const json* feature_with(const json& fc, const std::string& key, const json& value) {
  for (const json& f : fc["features"])
    if (f["properties"].contains(key) && f["properties"][key] == value) return &f;
  return nullptr;
}

// --- maps -------------------------------------------------------------------------------

TEST_F(WebApi, MapsListsEveryMapWithBoundsCountsAndGeoreference) {
  const Answer a = call(ctx_, "GET", "/api/maps");
  ASSERT_EQ(a.status, 200) << a.body.dump();
  ASSERT_TRUE(a.body.is_array());
  json gap, room;
  for (const json& m : a.body) {
    if (m["name"] == "webapi_gap") gap = m;
    if (m["name"] == "webapi_room") room = m;
  }
  ASSERT_FALSE(gap.is_null()) << a.body.dump();
  ASSERT_FALSE(room.is_null()) << a.body.dump();
  EXPECT_EQ(gap["bounds"], json({0.0, 0.0, 20.0, 10.0}));
  EXPECT_EQ(gap["obstacles"], 3);
  EXPECT_EQ(gap["segments"], 12);
  EXPECT_EQ(gap["georeferenced"], false);
  EXPECT_TRUE(gap["crs"].is_null());
  EXPECT_GE(gap["revision"].get<int>(), 1);
  EXPECT_EQ(room["bounds"], json({-0.5, -0.5, 15.5, 15.5}));
  EXPECT_EQ(room["georeferenced"], true);
  EXPECT_TRUE(room["crs"].is_string() && !room["crs"].get<std::string>().empty()) << room.dump();
}

TEST_F(WebApi, MapIsGeoJsonOfItsWallsInTheMapFrame) {
  const Answer a = call(ctx_, "GET", "/api/maps/webapi_gap");
  ASSERT_EQ(a.status, 200) << a.body.dump();
  EXPECT_EQ(a.content_type, "application/geo+json");
  EXPECT_EQ(a.body["type"], "FeatureCollection");
  size_t segments = 0;
  for (const json& f : a.body["features"]) {
    if (f["properties"]["kind"] != "segment") continue;
    ++segments;
    EXPECT_EQ(f["geometry"]["type"], "LineString");
    EXPECT_TRUE(f["properties"]["obstacle"].is_number_integer()) << f.dump();
    EXPECT_TRUE(f["properties"]["type"].is_string()) << f.dump();
    EXPECT_TRUE(f["properties"]["h"].is_number()) << f.dump();
  }
  EXPECT_EQ(segments, 12u);
  // The box (obstacle 3, a closed polygon 1 m high): its first segment from (15, 2) to (17, 2).
  const json* box = feature_with(a.body, "obstacle", 3);
  ASSERT_NE(box, nullptr);
  EXPECT_EQ((*box)["properties"]["type"], "closed polygon");
  EXPECT_EQ((*box)["properties"]["h"], 1.0);
  EXPECT_EQ((*box)["geometry"]["coordinates"], json({{15.0, 2.0}, {17.0, 2.0}}));
}

TEST_F(WebApi, MapInWgs84NeedsAGeoreference) {
  // Georeferenced at 48.1 N 11.5 E, the map origin there: the room is a few metres east
  // and north of it.
  const Answer a = call(ctx_, "GET", "/api/maps/webapi_room", nullptr, {{"crs", "wgs84"}});
  ASSERT_EQ(a.status, 200) << a.body.dump();
  size_t checked = 0;
  for (const json& f : a.body["features"]) {
    if (f["properties"]["kind"] != "segment") continue;
    for (const json& p : f["geometry"]["coordinates"]) {
      EXPECT_NEAR(p[0].get<double>(), 11.5001, 0.0003) << f.dump();
      EXPECT_NEAR(p[1].get<double>(), 48.1001, 0.0002) << f.dump();
      ++checked;
    }
  }
  EXPECT_GT(checked, 0u);
  // Without a georeference: the message of `fleetmap map export --format geojson`.
  const RunResult cli = run("fleetmap", "map export webapi_gap --format geojson");
  ASSERT_NE(cli.exit_code, 0);
  const Answer b = call(ctx_, "GET", "/api/maps/webapi_gap", nullptr, {{"crs", "wgs84"}});
  expect_error(b, 400, "bad_input", "map 'webapi_gap' has no georeference");
  EXPECT_NE(cli.err.find(b.body["error"]["message"].get<std::string>()), std::string::npos) << cli.err;
  EXPECT_EQ(b.body["error"]["exit_code"], cli.exit_code);
  expect_error(call(ctx_, "GET", "/api/maps/webapi_room", nullptr, {{"crs", "utm"}}), 400, "bad_input", "crs:");
}

TEST_F(WebApi, UnknownMapIs404) {
  for (const std::string path : {"/api/maps/webapi_nope", "/api/maps/webapi_nope/objects",
                                 "/api/maps/webapi_nope/avoided", "/api/maps/webapi_nope/topology"})
    expect_error(call(ctx_, "GET", path), 404, "not_found", "no map named 'webapi_nope'");
}

// --- objects, avoided areas, topology --------------------------------------------------------

TEST_F(WebApi, ObjectsAndAvoidedAreasAreSeparateLayers) {
  const Answer o = call(ctx_, "GET", "/api/maps/webapi_room/objects");
  ASSERT_EQ(o.status, 200) << o.body.dump();
  EXPECT_EQ(o.content_type, "application/geo+json");
  std::set<std::string> kinds;
  for (const json& f : o.body["features"]) kinds.insert(f["properties"].value("kind", "object"));
  EXPECT_EQ(kinds, std::set<std::string>({"object"}));
  EXPECT_EQ(o.body["features"].size(), 17u);
  const json* charger = feature_with(o.body, "id", "charger-1");
  ASSERT_NE(charger, nullptr) << o.body.dump();
  EXPECT_EQ((*charger)["properties"]["tag"], "charging_station");

  const Answer v = call(ctx_, "GET", "/api/maps/webapi_room/avoided");
  ASSERT_EQ(v.status, 200) << v.body.dump();
  EXPECT_EQ(v.body["features"].size(), 10u);
  for (const json& f : v.body["features"]) EXPECT_EQ(f["properties"]["kind"], "avoid") << f.dump();
  ASSERT_NE(feature_with(v.body, "id", "keepout-1"), nullptr);

  // WGS 84 on the georeferenced room; not on the gap map.
  const Answer w = call(ctx_, "GET", "/api/maps/webapi_room/objects", nullptr, {{"crs", "wgs84"}});
  ASSERT_EQ(w.status, 200) << w.body.dump();
  const json ring = (*feature_with(w.body, "id", "charger-1"))["geometry"]["coordinates"][0];
  EXPECT_NEAR(ring[0][0].get<double>(), 11.5 + 14.7 / (111320 * std::cos(48.1 * M_PI / 180)), 2e-5);
  EXPECT_NEAR(ring[0][1].get<double>(), 48.1 + 1.7 / 111200, 2e-5);
  expect_error(call(ctx_, "GET", "/api/maps/webapi_gap/avoided", nullptr, {{"crs", "wgs84"}}), 400, "bad_input",
               "has no georeference");
}

TEST_F(WebApi, TopologyHasTypedNodesAndEdges) {
  const Answer a = call(ctx_, "GET", "/api/maps/webapi_room/topology");
  ASSERT_EQ(a.status, 200) << a.body.dump();
  ASSERT_EQ(a.body["nodes"].size(), 4u);
  ASSERT_EQ(a.body["edges"].size(), 3u);
  const json& dock = a.body["nodes"][0];
  EXPECT_EQ(dock, json({{"id", 0}, {"name", "dock"}, {"type", "room"}, {"x", 13.0}, {"y", 7.0}}));
  EXPECT_TRUE(a.body["nodes"][1]["name"].is_null());
  EXPECT_EQ(a.body["nodes"][1]["type"], "door");
  EXPECT_EQ(a.body["nodes"][2]["type"], "door");
  EXPECT_EQ(a.body["nodes"][3]["type"], "room");
  EXPECT_EQ(a.body["edges"][0], json({{"from", 0}, {"to", 1}, {"type", "corridor"}}));
  EXPECT_EQ(a.body["edges"][1]["type"], "door");
  EXPECT_EQ(a.body["edges"][2]["type"], "room");
  expect_error(call(ctx_, "GET", "/api/maps/webapi_gap/topology"), 404, "not_found", "no topological graph");
}

// --- robots ---------------------------------------------------------------------------------

TEST_F(WebApi, RobotStateHasEveryFieldWithUtcTimesAndLonLat) {
  // last_seen stored as 03:04:05 UTC; the reader's session shows another zone, which the
  // API must not leak into its answer (nor keep changed afterwards).
  auto a = admin();
  a->query("SET time_zone = '+00:00'").execute();
  a->query("UPDATE robots SET last_seen = '2026-01-02 03:04:05.250000' WHERE db_user = 'webapi_r2'").execute();
  ctx_.reader().query("SET time_zone = '+05:00'").execute();

  const Answer r = call(ctx_, "GET", "/api/robots/webapi_r2");
  ASSERT_EQ(r.status, 200) << r.body.dump();
  const json& s = r.body;
  EXPECT_EQ(s["name"], "webapi_r2");
  EXPECT_EQ(s["map"], "webapi_room");
  EXPECT_EQ(s["state"], "offline");
  EXPECT_EQ(s["x"], 13.0);
  EXPECT_EQ(s["y"], 6.0);
  EXPECT_EQ(s["theta"], 0.0);
  EXPECT_EQ(s["v"], 0.0);
  EXPECT_EQ(s["last_seen"], "2026-01-02T03:04:05.250000Z");
  ASSERT_TRUE(s["lonlat"].is_array()) << s.dump();
  EXPECT_NEAR(s["lonlat"][0].get<double>(), 11.5 + 13 / (111320 * std::cos(48.1 * M_PI / 180)), 2e-5);
  EXPECT_NEAR(s["lonlat"][1].get<double>(), 48.1 + 6 / 111200.0, 2e-5);
  EXPECT_TRUE(s.contains("task"));
  EXPECT_TRUE(s.contains("goal"));
  EXPECT_EQ(s["profile"], json({{"laser_height", nullptr}, {"radius", nullptr}, {"body_height", nullptr},
                                {"can_stairs", false}, {"can_ramps", true}}));
  mysqlpp::StoreQueryResult tz = ctx_.reader().query("SELECT @@SESSION.time_zone").store();
  EXPECT_EQ(std::string(tz[0][0].data(), tz[0][0].length()), "+05:00");

  const Answer all = call(ctx_, "GET", "/api/robots");
  ASSERT_EQ(all.status, 200) << all.body.dump();
  json r1;
  for (const json& x : all.body)
    if (x["name"] == "webapi_r1") r1 = x;
  ASSERT_FALSE(r1.is_null()) << all.body.dump();
  EXPECT_TRUE(r1["lonlat"].is_null()) << "webapi_gap has no georeference";
  EXPECT_EQ(r1["theta"], 0.25);
  for (const char* key : {"name", "map", "state", "x", "y", "theta", "v", "lonlat", "task", "goal", "last_seen"})
    EXPECT_TRUE(r1.contains(key)) << key;
  EXPECT_FALSE(r1.contains("profile"));
  expect_error(call(ctx_, "GET", "/api/robots/webapi_nobody"), 404, "not_found", "no robot named 'webapi_nobody'");
}

// --- goals ----------------------------------------------------------------------------------

TEST_F(WebApi, GoalByPointIsATaskWithItsPath) {
  const long long before = tasks_of("webapi_r1");
  const Answer a = call(ctx_, "POST", "/api/robots/webapi_r1/goal", {{"x", 15}, {"y", 8}});
  ASSERT_EQ(a.status, 201) << a.body.dump();
  EXPECT_EQ(a.body["robot"], "webapi_r1");
  EXPECT_EQ(a.body["goal"], json({15.0, 8.0}));
  EXPECT_EQ(a.body["from"], json({5.0, 5.0}));
  EXPECT_GT(a.body["path_length"].get<double>(), std::hypot(10.0, 3.0) - 1e-9);
  EXPECT_EQ(tasks_of("webapi_r1"), before + 1);
  const auto task = a.body["task"].get<unsigned long long>();
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM tasks WHERE id = " + std::to_string(task) + " AND robot_id = " + r1_ +
                   " AND goal_x = 15 AND goal_y = 8 AND state = 'assigned'"),
            1);

  // The task list, newest first, and the robot's state now show it.
  const Answer t = call(ctx_, "GET", "/api/tasks", nullptr, {{"robot", "webapi_r1"}, {"limit", "1"}});
  ASSERT_EQ(t.status, 200) << t.body.dump();
  ASSERT_EQ(t.body.size(), 1u);
  EXPECT_EQ(t.body[0]["id"], task);
  EXPECT_EQ(t.body[0]["robot"], "webapi_r1");
  EXPECT_EQ(t.body[0]["state"], "assigned");
  EXPECT_EQ(t.body[0]["goal"], json({15.0, 8.0}));
  EXPECT_EQ(t.body[0]["reason"], "");
  for (const char* key : {"created_at", "updated_at"}) {
    const std::string at = t.body[0][key].get<std::string>();
    EXPECT_EQ(at.size(), std::string("2026-01-02T03:04:05.250000Z").size()) << at;
    EXPECT_EQ(at[10], 'T') << at;
    EXPECT_EQ(at.back(), 'Z') << at;
  }
  const Answer s = call(ctx_, "GET", "/api/robots/webapi_r1");
  EXPECT_EQ(s.body["task"], json({{"id", task}, {"state", "assigned"}}));
  EXPECT_EQ(s.body["goal"], json({15.0, 8.0}));
}

TEST_F(WebApi, RefusedGoalsAre422AndWriteNoTask) {
  const long long before = tasks_of("webapi_r1");
  Answer a = call(ctx_, "POST", "/api/robots/webapi_r1/goal", {{"x", 500}, {"y", 500}});
  expect_error(a, 422, "goal_refused", "outside the map 'webapi_gap'");
  EXPECT_EQ(a.body["error"]["exit_code"], 3);
  // The same message as `fleetmap goal` prints.
  const RunResult cli = run("fleetmap", "goal webapi_r1 500 500");
  EXPECT_EQ(cli.exit_code, 3);
  EXPECT_NE(cli.err.find(a.body["error"]["message"].get<std::string>()), std::string::npos) << cli.err;
  expect_error(call(ctx_, "POST", "/api/robots/webapi_r1/goal", {{"x", 16}, {"y", 3}}), 422, "goal_refused",
               "inside obstacle 3 (box)");
  EXPECT_EQ(tasks_of("webapi_r1"), before);
  expect_error(call(ctx_, "POST", "/api/robots/webapi_nobody/goal", {{"x", 1}, {"y", 1}}), 404, "not_found",
               "no robot named 'webapi_nobody'");
}

TEST_F(WebApi, GoalBodiesAreCheckedFieldByField) {
  const long long before = tasks_of("webapi_r1");
  const std::string goal = "/api/robots/webapi_r1/goal";
  expect_error(call(ctx_, "POST", goal), 400, "bad_input", "body: expected exactly one of");
  expect_error(call(ctx_, "POST", goal, json::object()), 400, "bad_input", "body: expected exactly one of");
  expect_error(call(ctx_, "POST", goal, {{"x", 1}}), 400, "bad_input", "y: expected a number");
  expect_error(call(ctx_, "POST", goal, {{"x", "1"}, {"y", 2}}), 400, "bad_input", "x: expected a number, got string");
  expect_error(call(ctx_, "POST", goal, {{"x", NAN}, {"y", 2}}), 400, "bad_input", "x: expected a finite number");
  expect_error(call(ctx_, "POST", goal, {{"x", 1}, {"y", 2}, {"tag", "door"}}), 400, "bad_input", "exactly one of");
  expect_error(call(ctx_, "POST", goal, {{"tag", 5}}), 400, "bad_input", "tag: expected a string");
  expect_error(call(ctx_, "POST", goal, {{"node", ""}}), 400, "bad_input", "node: expected a non-empty string");
  expect_error(call(ctx_, "POST", goal, {{"x", 1}, {"y", 2}, {"z", 3}}), 400, "bad_input", "z: unknown field");
  expect_error(call(ctx_, "POST", goal, {{"x", 1}, {"y", 2}, {"margin", 1}}), 400, "bad_input", "margin");
  expect_error(call(ctx_, "POST", goal, json::array({1, 2})), 400, "bad_input", "body: expected a JSON object");
  EXPECT_EQ(tasks_of("webapi_r1"), before);
}

TEST_F(WebApi, GoalByTagGoesBesideTheNearestObject) {
  const long long before = tasks_of("webapi_r2");
  const Answer a = call(ctx_, "POST", "/api/robots/webapi_r2/goal", {{"tag", "charging_station"}});
  ASSERT_EQ(a.status, 201) << a.body.dump();
  EXPECT_EQ(a.body["object"], "charger-1");
  EXPECT_EQ(a.body["from"], json({13.0, 6.0}));
  // Beside the station (x 14.7..15, y 1.7..2.3, against the east wall): radius 0.3 m (the
  // server's default) + margin 0.1 m from its footprint, and clear of the wall.
  const double gx = a.body["goal"][0].get<double>(), gy = a.body["goal"][1].get<double>();
  const double dx = std::max({14.7 - gx, 0.0, gx - 15.0}), dy = std::max({1.7 - gy, 0.0, gy - 2.3});
  EXPECT_NEAR(std::hypot(dx, dy), 0.4, 1e-6) << a.body.dump();
  EXPECT_LE(gx, 14.7 + 1e-6) << a.body.dump();
  EXPECT_GT(a.body["path_length"].get<double>(), 3.0);
  EXPECT_EQ(tasks_of("webapi_r2"), before + 1);
  expect_error(call(ctx_, "POST", "/api/robots/webapi_r2/goal", {{"tag", "spaceship"}}), 404, "not_found",
               "no object tagged 'spaceship' on map 'webapi_room'");
  EXPECT_EQ(tasks_of("webapi_r2"), before + 1);
}

TEST_F(WebApi, GoalByNodeNameOrNearestNodeOfAType) {
  Answer a = call(ctx_, "POST", "/api/robots/webapi_r2/goal", {{"node", "dock"}});
  ASSERT_EQ(a.status, 201) << a.body.dump();
  EXPECT_EQ(a.body["node"], 0);
  EXPECT_EQ(a.body["goal"], json({13.0, 7.0}));
  EXPECT_EQ(a.body["from"], json({13.0, 6.0}));
  // Two door nodes: (11, 2) is nearer the robot at (13, 6) than (7.5, 1).
  a = call(ctx_, "POST", "/api/robots/webapi_r2/goal", {{"node", "door"}});
  ASSERT_EQ(a.status, 201) << a.body.dump();
  EXPECT_EQ(a.body["node"], 1);
  EXPECT_EQ(a.body["goal"], json({11.0, 2.0}));
  // From near the other one, the other one.
  admin()->query("UPDATE robots SET x = 7, y = 3 WHERE db_user = 'webapi_r2'").execute();
  a = call(ctx_, "POST", "/api/robots/webapi_r2/goal", {{"node", "door"}});
  ASSERT_EQ(a.status, 201) << a.body.dump();
  EXPECT_EQ(a.body["node"], 2);
  const long long before = tasks_of("webapi_r2");
  expect_error(call(ctx_, "POST", "/api/robots/webapi_r2/goal", {{"node", "elevator"}}), 404, "not_found",
               "no node named 'elevator'");
  expect_error(call(ctx_, "POST", "/api/robots/webapi_r1/goal", {{"node", "dock"}}), 404, "not_found",
               "map 'webapi_gap' has no topological graph");
  EXPECT_EQ(tasks_of("webapi_r2"), before);
}

// --- pose, abort ----------------------------------------------------------------------------

TEST_F(WebApi, PoseSetsTheInitialPose) {
  Answer a = call(ctx_, "POST", "/api/robots/webapi_r1/pose", {{"x", 3}, {"y", 4}, {"theta", 0.5}});
  ASSERT_EQ(a.status, 200) << a.body.dump();
  EXPECT_EQ(a.body, json({{"robot", "webapi_r1"}, {"pose", {3.0, 4.0, 0.5}}}));
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM robots WHERE id = " + r1_ + " AND ini_x = 3 AND ini_y = 4 AND ini_theta = 0.5"),
            1);
  a = call(ctx_, "POST", "/api/robots/webapi_r1/pose", {{"x", 6}, {"y", 7}});
  ASSERT_EQ(a.status, 200) << a.body.dump();
  EXPECT_TRUE(a.body["pose"][2].is_null());
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM robots WHERE id = " + r1_ + " AND ini_x = 6 AND ini_theta IS NULL"), 1);
  expect_error(call(ctx_, "POST", "/api/robots/webapi_r1/pose", {{"x", 3}}), 400, "bad_input", "y:");
  expect_error(call(ctx_, "POST", "/api/robots/webapi_r1/pose", {{"x", 3}, {"y", 4}, {"theta", "up"}}), 400,
               "bad_input", "theta:");
  expect_error(call(ctx_, "POST", "/api/robots/webapi_nobody/pose", {{"x", 3}, {"y", 4}}), 404, "not_found",
               "no robot named");
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM robots WHERE id = " + r1_ + " AND ini_x = 6"), 1);
}

TEST_F(WebApi, AbortNeedsAnOpenTask) {
  expect_error(call(ctx_, "POST", "/api/robots/webapi_r1/abort"), 404, "not_found",
               "robot 'webapi_r1' has no open task");
  const Answer g = call(ctx_, "POST", "/api/robots/webapi_r1/goal", {{"x", 3}, {"y", 3}});
  ASSERT_EQ(g.status, 201) << g.body.dump();
  const Answer a = call(ctx_, "POST", "/api/robots/webapi_r1/abort", {{"reason", "webapi test"}});
  ASSERT_EQ(a.status, 202) << a.body.dump();
  EXPECT_EQ(a.body, json({{"robot", "webapi_r1"}, {"task", g.body["task"]}}));
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM tasks WHERE id = " + g.body["task"].dump() +
                   " AND abort_requested_at IS NOT NULL AND reason = 'webapi test'"),
            1);
  expect_error(call(ctx_, "POST", "/api/robots/webapi_r1/abort", {{"reason", 7}}), 400, "bad_input", "reason:");
  expect_error(call(ctx_, "POST", "/api/robots/webapi_nobody/abort"), 404, "not_found", "no robot named");
}

TEST_F(WebApi, AnInspectorsWritesAreRefusedByTheDatabase) {
  TestApiContext inspector(Role::Inspector);
  const long long before = tasks_of("webapi_r1");
  expect_error(call(inspector, "POST", "/api/robots/webapi_r1/goal", {{"x", 15}, {"y", 8}}), 403, "forbidden",
               "denied");
  expect_error(call(inspector, "POST", "/api/robots/webapi_r1/pose", {{"x", 1}, {"y", 1}}), 403, "forbidden",
               "denied");
  EXPECT_EQ(tasks_of("webapi_r1"), before);
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM robots WHERE id = " + r1_ + " AND ini_x IS NULL"), 1);
  // Reads run on the web account: the same for an inspector.
  EXPECT_EQ(call(inspector, "GET", "/api/robots/webapi_r1").status, 200);
}

// --- tasks, trajectory ----------------------------------------------------------------------

TEST_F(WebApi, TasksAreNewestFirstAndChecked) {
  for (double x : {2.0, 3.0, 4.0}) ASSERT_EQ(call(ctx_, "POST", "/api/robots/webapi_r1/goal", {{"x", x}, {"y", 2}}).status, 201);
  const Answer a = call(ctx_, "GET", "/api/tasks", nullptr, {{"robot", "webapi_r1"}, {"limit", "3"}});
  ASSERT_EQ(a.status, 200) << a.body.dump();
  ASSERT_EQ(a.body.size(), 3u);
  EXPECT_EQ(a.body[0]["goal"], json({4.0, 2.0}));
  EXPECT_EQ(a.body[2]["goal"], json({2.0, 2.0}));
  EXPECT_GT(a.body[0]["id"].get<unsigned long long>(), a.body[1]["id"].get<unsigned long long>());
  EXPECT_EQ(a.body[1]["state"], "aborted");  // replaced by the next goal
  EXPECT_NE(a.body[1]["reason"].get<std::string>().find("replaced by task"), std::string::npos);
  const Answer all = call(ctx_, "GET", "/api/tasks");
  ASSERT_EQ(all.status, 200);
  EXPECT_LE(all.body.size(), 50u);
  expect_error(call(ctx_, "GET", "/api/tasks", nullptr, {{"limit", "0"}}), 400, "bad_input", "limit:");
  expect_error(call(ctx_, "GET", "/api/tasks", nullptr, {{"limit", "ten"}}), 400, "bad_input", "limit:");
  expect_error(call(ctx_, "GET", "/api/tasks", nullptr, {{"robot", "webapi_nobody"}}), 404, "not_found",
               "no robot named");
}

TEST_F(WebApi, TrajectorySinceAnAgeInTheRobotsMapFrame) {
  auto a = admin();
  a->query("DELETE FROM trajectories WHERE robot_id = " + r1_).execute();
  a->query("INSERT INTO trajectories (robot_id, t, x, y, theta, v, pos) VALUES (" + r1_ +
           ", SYSDATE(6) - INTERVAL 2 HOUR, 1, 1, 0, 0, POINT(1, 1)), (" + r1_ +
           ", SYSDATE(6) - INTERVAL 2 MINUTE, 2, 3, 0.5, 0.4, POINT(2, 3)), (" + r1_ +
           ", SYSDATE(6) - INTERVAL 1 MINUTE, 2.5, 3.5, 0.75, 0.2, POINT(2.5, 3.5))")
      .execute();
  Answer t = call(ctx_, "GET", "/api/robots/webapi_r1/trajectory", nullptr, {{"since", "10m"}});
  ASSERT_EQ(t.status, 200) << t.body.dump();
  EXPECT_EQ(t.content_type, "application/geo+json");
  ASSERT_EQ(t.body["features"].size(), 2u) << t.body.dump();
  const json& first = t.body["features"][0];
  EXPECT_EQ(first["geometry"], json({{"type", "Point"}, {"coordinates", {2.0, 3.0}}}));
  EXPECT_EQ(first["properties"]["theta"], 0.5);
  EXPECT_EQ(first["properties"]["v"], 0.4);
  EXPECT_EQ(first["properties"]["t"].get<std::string>().back(), 'Z');
  t = call(ctx_, "GET", "/api/robots/webapi_r1/trajectory");
  EXPECT_EQ(t.body["features"].size(), 3u);
  expect_error(call(ctx_, "GET", "/api/robots/webapi_r1/trajectory", nullptr, {{"since", "yesterday"}}), 400,
               "bad_input", "since:");
  expect_error(call(ctx_, "GET", "/api/robots/webapi_r1/trajectory", nullptr, {{"crs", "wgs84"}}), 400,
               "bad_input", "map 'webapi_gap' has no georeference");
  expect_error(call(ctx_, "GET", "/api/robots/webapi_nobody/trajectory"), 404, "not_found", "no robot named");

  // On the georeferenced room, in WGS 84.
  const std::string r2 = std::to_string(scalar("SELECT id FROM robots WHERE db_user = 'webapi_r2'"));
  a->query("DELETE FROM trajectories WHERE robot_id = " + r2).execute();
  a->query("INSERT INTO trajectories (robot_id, t, x, y, theta, v, pos) VALUES (" + r2 +
           ", SYSDATE(6), 13, 6, 0, 0, POINT(13, 6))")
      .execute();
  t = call(ctx_, "GET", "/api/robots/webapi_r2/trajectory", nullptr, {{"crs", "wgs84"}, {"since", "1h"}});
  ASSERT_EQ(t.status, 200) << t.body.dump();
  ASSERT_EQ(t.body["features"].size(), 1u);
  const json& p = t.body["features"][0]["geometry"]["coordinates"];
  EXPECT_NEAR(p[0].get<double>(), 11.5 + 13 / (111320 * std::cos(48.1 * M_PI / 180)), 2e-5);
  EXPECT_NEAR(p[1].get<double>(), 48.1 + 6 / 111200.0, 2e-5);
}

// --- errors and the document ----------------------------------------------------------------

TEST(WebApiErrors, ExceptionsBecomeTheirStatusCodeAndExitCode) {
  const auto error = [](const std::exception& e) { return web::error_response(e).body["error"]; };
  EXPECT_EQ(error(web::ApiError(409, "conflict", "x", 1)), json({{"status", 409}, {"code", "conflict"},
                                                                   {"exit_code", 1}, {"message", "x"}}));
  EXPECT_EQ(error(BadInput("b"))["status"], 400);
  EXPECT_EQ(error(std::invalid_argument("b"))["code"], "bad_input");
  EXPECT_EQ(error(NotFound("n"))["exit_code"], 4);
  EXPECT_EQ(error(NoPath("p"))["code"], "no_path");
  EXPECT_EQ(error(std::runtime_error("boom")), json({{"status", 500}, {"code", "internal"}, {"exit_code", 1},
                                                      {"message", "boom"}}));
  EXPECT_EQ(error(mysqlpp::BadQuery("SELECT command denied", 1142))["status"], 403);
  EXPECT_EQ(error(mysqlpp::BadQuery("SELECT command denied", 1142))["code"], "forbidden");
  EXPECT_EQ(error(mysqlpp::BadQuery("Duplicate entry", 1062))["status"], 500);
  EXPECT_EQ(std::string(web::to_string(web::WebRole::Operator)), "operator");
  EXPECT_EQ(std::string(web::to_string(web::WebRole::Inspector)), "inspector");
}

TEST(WebApiTopology, NodeTypesAndGoalNodesWithoutADatabase) {
  TopoGraph g;
  g.add_node({0, {0, 0}, "dock"});
  g.add_node({1, {10, 0}, ""});
  g.add_node({2, {20, 0}, ""});
  g.add_node({3, {30, 0}, "dock"});  // a second node of that name, farther from (12, 0)
  g.add_node({4, {40, 0}, ""});      // no edges
  g.add_edge({.a = 0, .b = 1, .type = EdgeType::Corridor});
  g.add_edge({.a = 1, .b = 2, .type = EdgeType::Stairs});
  g.add_edge({.a = 2, .b = 3, .type = EdgeType::Door});
  const json t = web::topology_json(g);
  EXPECT_EQ(t["nodes"][0]["type"], "corridor");
  EXPECT_EQ(t["nodes"][1]["type"], "stairs");  // stairs beat the corridor
  EXPECT_EQ(t["nodes"][2]["type"], "stairs");  // and the door
  EXPECT_EQ(t["nodes"][3]["type"], "door");
  EXPECT_TRUE(t["nodes"][4]["type"].is_null());
  EXPECT_TRUE(t["nodes"][1]["name"].is_null());
  EXPECT_EQ(web::find_goal_node(g, "dock", Point{12, 0})->id, 0);
  EXPECT_EQ(web::find_goal_node(g, "dock", Point{28, 0})->id, 3);
  EXPECT_EQ(web::find_goal_node(g, "stairs", Point{28, 0})->id, 2);
  EXPECT_EQ(web::find_goal_node(g, "stairs", std::nullopt)->id, 1);  // no position: the first
  EXPECT_EQ(web::find_goal_node(g, "elevator", Point{0, 0}), nullptr);
  EXPECT_EQ(web::find_goal_node(g, "nowhere", Point{0, 0}), nullptr);
}

TEST(WebApiDocument, OpenApiListsEveryRouteWithItsMethod) {
  std::ifstream in(source_path("docs/openapi.json"));
  ASSERT_TRUE(in) << "docs/openapi.json";
  const json doc = json::parse(in);
  EXPECT_EQ(doc["openapi"], "3.0.3");
  ASSERT_TRUE(doc["paths"].is_object());
  const auto lower = [](std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
  };
  std::set<std::pair<std::string, std::string>> seen;
  for (const web::Route& r : web::api_routes()) {
    EXPECT_TRUE(seen.insert({r.method, r.pattern}).second) << "twice: " << r.method << " " << r.pattern;
    ASSERT_TRUE(doc["paths"].contains(r.pattern)) << r.pattern;
    const json& path = doc["paths"][r.pattern];
    ASSERT_TRUE(path.contains(lower(r.method))) << r.method << " " << r.pattern;
    const json& op = path[lower(r.method)];
    EXPECT_TRUE(op.contains("responses")) << r.pattern;
    EXPECT_EQ(op["summary"], r.summary) << r.pattern;  // api.h: "one line, as in docs/openapi.json"
    if (r.write) {
      // A write needs the session and the CSRF token (SPEC 4), and says so.
      ASSERT_TRUE(op.contains("security")) << r.pattern;
      EXPECT_NE(op["security"].dump().find("csrf"), std::string::npos) << r.pattern;
    }
  }
  for (const auto& [method, path] : std::vector<std::pair<std::string, std::string>>{
           {"post", "/api/login"}, {"post", "/api/logout"}, {"get", "/api/session"},
           {"get", "/api/openapi.json"}, {"get", "/api/ws"}})
    EXPECT_TRUE(doc["paths"].contains(path) && doc["paths"][path].contains(method)) << method << " " << path;
  for (const char* schema : {"RobotState", "Task", "Error"})
    EXPECT_TRUE(doc["components"]["schemas"].contains(schema)) << schema;
  EXPECT_TRUE(doc["components"]["securitySchemes"].contains("session"));
  EXPECT_TRUE(doc["components"]["securitySchemes"].contains("csrf"));
}

}  // namespace
}  // namespace fleetmap::test
