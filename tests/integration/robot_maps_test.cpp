// Each robot is served the map its laser sees (seed 004 section III.A): robots with different laser
// heights on the example room (maps/example-room.map + .geojson) ask for the same window
// and read their answers with plain SQL from their own sa_mine; "2.5d" mode; a profile
// changed with `robot set`; SetObject observations in the maps and their expiry; a robot
// without a profile gets what it got before. Real fleetmap-server, real MariaDB.
#include <tuple>
#include <thread>

#include <gtest/gtest.h>

#include "common/slicing/map_slice.h"
#include "common/map/map_window.h"
#include "common/io/scene_geojson.h"
#include "common/slicing/scene_laser.h"
#include "common/io/seed_format.h"
#include "protocol/connection.h"
#include "tests/integration/server_fixture.h"
#include "tests/integration/test_db.h"

namespace fleetmap::test {
namespace {

using nlohmann::json;

const char* kMap = "rm_room";

// The map a laser at h sees of the example room, cut to the window: the reference.
Map expected_view(double h, const std::optional<Rect>& r) {
  const Map file = read_seed_file(source_path("maps/example-room.map"));
  const Scene scene = read_scene_geojson(read_file(source_path("maps/example-room.geojson")));
  const Map seen = slice_at_height(with_objects_at_height(file, scene, h), h);
  return r ? clip_map(seen, *r) : seen;
}

class RobotMaps : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    // A fresh map every run: its scene and every earlier observation are dropped with the old one.
    RunResult r = run("fleetmap", "map import " + source_path("maps/example-room.map") + " --name " + kMap +
                                      " --replace --drop all");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    r = run("fleetmap", std::string("objects import ") + kMap + " " + source_path("maps/example-room.geojson"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  void SetUp() override {
    low_pw_ = add_robot("rm_low", kMap);
    high_pw_ = add_robot("rm_high", kMap);
    plain_pw_ = add_robot("rm_plain", kMap);
    set_profile("rm_low", "--laser-height 0.3");
    set_profile("rm_high", "--laser-height 0.9");
    server_ = std::make_unique<ServerProcess>("--object-ttl 1", "rm_server.log");
    low_ = std::make_unique<SqlRobot>("rm_low", low_pw_);
    high_ = std::make_unique<SqlRobot>("rm_high", high_pw_);
    plain_ = std::make_unique<SqlRobot>("rm_plain", plain_pw_);
  }
  void TearDown() override {
    server_.reset();
    // This suite's observations go now, not when a sweep comes by.
    execute(*admin(), std::string("DELETE o FROM env_objects o JOIN maps m ON m.id = o.map_id WHERE m.name = '") + kMap +
                          "' AND o.source = 'observed'");
    if (HasFailure()) std::cerr << "server log:\n" << read_file(temp_path("rm_server.log")).substr(0, 20000);
  }
  static void set_profile(const std::string& robot, const std::string& options) {
    const RunResult r = run("fleetmap", "robot set " + robot + " " + options);
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  static std::vector<SqlAnswer> ask(SqlRobot& robot, const std::string& op, const std::string& params, size_t n) {
    const auto id = robot.send(op, params);
    auto got = robot.receive(n);
    EXPECT_EQ(got.size(), n) << op << " " << params;
    for (const auto& a : got) EXPECT_EQ(a.request_id, id) << op;
    return got;
  }
  static void ready(SqlRobot& robot) { ASSERT_EQ(ask(robot, "Ready", R"({"magic": 1})", 2).size(), 2u); }

  // Sends a request and waits until its answer is in the robot's sa_mine (not deleted);
  // returns the answer's id.
  static unsigned long long send_and_wait(SqlRobot& robot, const std::string& op, const std::string& params) {
    const auto req = robot.send(op, params);
    for (int i = 0; i < 1000; ++i) {
      mysqlpp::Query q = robot.connection().query("SELECT id FROM sa_mine WHERE request_id = " + std::to_string(req));
      auto r = q.store();
      if (!r.empty()) return std::stoull(std::string(r[0][0]));
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    ADD_FAILURE() << "no answer to " << op;
    return 0;
  }
  // One value from the robot's own connection: what a robot with nothing but SQL reads.
  static std::string sql(SqlRobot& robot, const std::string& query) {
    mysqlpp::Query q = robot.connection().query(query);
    auto r = q.store();
    if (r.empty() || r[0][0].is_null()) return "NULL";
    return std::string(r[0][0].data(), r[0][0].length());
  }
  static void forget(SqlRobot& robot, unsigned long long answer) {
    robot.connection().query("DELETE FROM sa_mine WHERE id = " + std::to_string(answer)).execute();
  }
  // How many obstacles of the answer's seed text carry "object:<tag>:" (plain SQL).
  static std::string count_sql(unsigned long long answer, const std::string& tag) {
    const std::string needle = "'object:" + tag + ":'";
    return "SELECT (LENGTH(payload) - LENGTH(REPLACE(payload, " + needle + ", ''))) DIV LENGTH(" + needle +
           ") FROM sa_mine WHERE id = " + std::to_string(answer);
  }

  std::string low_pw_, high_pw_, plain_pw_;
  std::unique_ptr<ServerProcess> server_;
  std::unique_ptr<SqlRobot> low_, high_, plain_;
};

// Boxes (2.5D, 0-0.4, 0-0.5 and 0-0.6 m) near the south-west corner, and the big table
// with four chairs in the middle of the room: worked out by hand from the GeoJSON.
TEST_F(RobotMaps, DifferentLaserHeightsGetDifferentMapsOfTheSameWindow) {
  ready(*low_);
  ready(*high_);
  // x 0.5..3.5, y 0.5..2.5: no wall, three boxes.
  const std::string boxes = R"({"x": 2, "y": 1.5, "w": 3, "h": 2})";
  const auto lo = send_and_wait(*low_, "GetMap", boxes);
  const auto hi = send_and_wait(*high_, "GetMap", boxes);
  EXPECT_EQ(sql(*low_, "SELECT op FROM sa_mine WHERE id = " + std::to_string(lo)), "SetMap");
  EXPECT_EQ(sql(*low_, count_sql(lo, "box")), "3");  // the laser at 0.3 m meets every box
  EXPECT_EQ(sql(*high_, count_sql(hi, "box")), "0");  // at 0.9 m it passes over them
  EXPECT_EQ(sql(*low_, "SELECT JSON_EXTRACT(params, '$.obstacles') FROM sa_mine WHERE id = " + std::to_string(lo)), "3");
  EXPECT_EQ(sql(*high_, "SELECT JSON_EXTRACT(params, '$.obstacles') FROM sa_mine WHERE id = " + std::to_string(hi)), "0");
  EXPECT_EQ(sql(*low_, "SELECT JSON_EXTRACT(params, '$.laser_height') FROM sa_mine WHERE id = " + std::to_string(lo)), "0.3");
  EXPECT_EQ(sql(*high_, "SELECT JSON_EXTRACT(params, '$.laser_height') FROM sa_mine WHERE id = " + std::to_string(hi)), "0.9");
  // Each robot sees only its own answers.
  EXPECT_EQ(sql(*low_, "SELECT COUNT(*) FROM sa_mine WHERE id = " + std::to_string(hi)), "0");
  const Rect box_window{0.5, 0.5, 3.5, 2.5};
  EXPECT_EQ(read_seed(sql(*low_, "SELECT payload FROM sa_mine WHERE id = " + std::to_string(lo)), "SetMap", MapKind::Window),
            expected_view(0.3, box_window));
  forget(*low_, lo);
  forget(*high_, hi);

  // x 6..9, y 6..9: the table's four legs (0-0.72) and top (0.72-0.76); each chair's four
  // legs (0-0.43), seat (0.43-0.47) and backrest (0.47-0.9).
  const std::string table = R"({"x": 7.5, "y": 7.5, "w": 3, "h": 3})";
  const auto lo2 = send_and_wait(*low_, "GetMap", table);
  const auto hi2 = send_and_wait(*high_, "GetMap", table);
  EXPECT_EQ(sql(*low_, count_sql(lo2, "table")), "4");    // legs
  EXPECT_EQ(sql(*low_, count_sql(lo2, "chair")), "16");   // legs
  EXPECT_EQ(sql(*high_, count_sql(hi2, "table")), "0");   // over the top
  EXPECT_EQ(sql(*high_, count_sql(hi2, "chair")), "4");   // the backrests' tops
  const Rect table_window{6, 6, 9, 9};
  for (auto [robot, answer, h] : {std::tuple{low_.get(), lo2, 0.3}, std::tuple{high_.get(), hi2, 0.9}}) {
    const std::string payload = sql(*robot, "SELECT payload FROM sa_mine WHERE id = " + std::to_string(answer));
    EXPECT_EQ(read_seed(payload, "SetMap", MapKind::Window), expected_view(h, table_window)) << h;
    EXPECT_EQ(payload, write_seed(expected_view(h, table_window))) << h;
  }
}

TEST_F(RobotMaps, ReadyGivesTheSliceAtTheRobotsHeight) {
  const auto a = ask(*low_, "Ready", R"({"magic": 3})", 2);
  ASSERT_EQ(a.size(), 2u);
  EXPECT_EQ(a[1].op, "SetMap");
  EXPECT_EQ(a[1].params["laser_height"], 0.3);
  EXPECT_FALSE(a[1].params.contains("mode"));
  ASSERT_TRUE(a[1].payload);
  // The same text as the operator's slice of the stored map and its objects.
  const RunResult slice = run("fleetmap", std::string("map slice ") + kMap + " --height 0.3");
  ASSERT_EQ(slice.exit_code, 0) << slice.err;
  EXPECT_EQ(*a[1].payload, slice.out);
  EXPECT_EQ(read_seed(*a[1].payload, "SetMap", MapKind::Window), expected_view(0.3, std::nullopt));
  const Map file = read_seed_file(source_path("maps/example-room.map"));
  EXPECT_GT(a[1].params["obstacles"].get<size_t>(), file.obstacles.size());  // walls and columns, plus objects
}

TEST_F(RobotMaps, RobotWithoutProfileGetsTheStoredMapAsBefore) {
  const auto a = ask(*plain_, "Ready", R"({"magic": 4})", 2);
  ASSERT_EQ(a.size(), 2u);
  const std::string file_text = read_file(source_path("maps/example-room.map"));
  EXPECT_EQ(*a[1].payload, file_text);
  EXPECT_FALSE(a[1].params.contains("laser_height"));
  EXPECT_FALSE(a[1].params.contains("mode"));
  EXPECT_EQ(a[1].params.size(), 4u) << a[1].params.dump();  // border, obstacles, segments, encoding
  const auto g = ask(*plain_, "GetMap", R"({"x": 7.5, "y": 7.5, "w": 6, "h": 6})", 1);
  ASSERT_EQ(g.size(), 1u);
  const Map file = read_seed_file(source_path("maps/example-room.map"));
  EXPECT_EQ(*g[0].payload, write_seed(clip_map(file, Rect{4.5, 4.5, 10.5, 10.5})));
  EXPECT_EQ(g[0].params.size(), 4u) << g[0].params.dump();
  // "mode": "2d" is the default, spelled out.
  const auto d = ask(*plain_, "GetMap", R"({"x": 7.5, "y": 7.5, "w": 6, "h": 6, "mode": "2d"})", 1);
  EXPECT_EQ(d[0].payload, g[0].payload);
  EXPECT_EQ(d[0].params, g[0].params);
}

TEST_F(RobotMaps, TwoAndAHalfDModeGivesSegmentsAndObjectsWithTheirRanges) {
  ready(*high_);
  // x 4.5..10.5, y 4.5..10.5: four columns (segments), the big table and four chairs.
  const auto id = send_and_wait(*high_, "GetMap", R"({"x": 7.5, "y": 7.5, "w": 6, "h": 6, "mode": "2.5d"})");
  const std::string row = " FROM sa_mine WHERE id = " + std::to_string(id);
  EXPECT_EQ(sql(*high_, "SELECT JSON_VALUE(params, '$.mode')" + row), "2.5d");
  EXPECT_EQ(sql(*high_, "SELECT JSON_EXISTS(params, '$.laser_height')" + row), "0");
  // The segments unsliced: the stored window, as a robot without a profile gets it.
  const Map file = read_seed_file(source_path("maps/example-room.map"));
  EXPECT_EQ(sql(*high_, "SELECT payload" + row), write_seed(clip_map(file, Rect{4.5, 4.5, 10.5, 10.5})));
  EXPECT_EQ(sql(*high_, count_sql(id, "chair")), "0");
  // The scene: GeoJSON in params, read with JSON_TABLE.
  const std::string features =
      " FROM sa_mine, JSON_TABLE(params, '$.scene.features[*]' COLUMNS (kind VARCHAR(16) PATH '$.properties.kind',"
      " fid VARCHAR(64) PATH '$.properties.id', tag VARCHAR(64) PATH '$.properties.tag')) f WHERE sa_mine.id = " +
      std::to_string(id);
  EXPECT_EQ(sql(*high_, "SELECT GROUP_CONCAT(fid ORDER BY fid)" + features + " AND kind = 'object'"),
            "big-table,chair-1,chair-2,chair-3,chair-4");
  EXPECT_EQ(sql(*high_, "SELECT GROUP_CONCAT(fid ORDER BY fid)" + features + " AND kind = 'avoid'"),
            "column-1,column-2,column-3,column-4");
  EXPECT_EQ(sql(*high_, "SELECT COUNT(*)" + features + " AND kind = 'bounds'"), "1");
  // The table's ranges: four legs and the top.
  const std::string z = sql(*high_, "SELECT JSON_EXTRACT(params, '$.scene.features[1].properties.z')" + row);
  EXPECT_EQ(json::parse(z), json::parse("[[0,0.72],[0,0.72],[0,0.72],[0,0.72],[0.72,0.76]]")) << z;
  EXPECT_EQ(sql(*high_, "SELECT JSON_VALUE(params, '$.scene.features[1].properties.id')" + row), "big-table");
  // The project's reader takes it back.
  const Scene scene = read_scene_geojson(sql(*high_, "SELECT JSON_EXTRACT(params, '$.scene')" + row));
  EXPECT_EQ(scene.objects.size(), 5u);
  EXPECT_EQ(scene.objects[0].elements.size(), 5u);
  forget(*high_, id);

  for (const char* bad : {R"({"x": 7.5, "y": 7.5, "w": 6, "h": 6, "mode": "3d"})",
                          R"({"x": 7.5, "y": 7.5, "w": 6, "h": 6, "mode": 2})"}) {
    const auto e = ask(*high_, "GetMap", bad, 1);
    ASSERT_EQ(e.size(), 1u);
    EXPECT_EQ(e[0].op, "Error");
    EXPECT_EQ(e[0].params["code"], "bad_params");
    EXPECT_NE(e[0].params["message"].get<std::string>().find("mode"), std::string::npos) << e[0].params.dump();
  }
}

TEST_F(RobotMaps, RobotSetChangesTheNextAnswer) {
  ready(*low_);
  const std::string boxes = R"({"x": 2, "y": 1.5, "w": 3, "h": 2})";
  auto id = send_and_wait(*low_, "GetMap", boxes);
  EXPECT_EQ(sql(*low_, count_sql(id, "box")), "3");
  forget(*low_, id);
  set_profile("rm_low", "--laser-height 0.55");  // over box-1 (0.5) and box-2 (0.4), under box-3 (0.6)
  id = send_and_wait(*low_, "GetMap", boxes);
  EXPECT_EQ(sql(*low_, count_sql(id, "box")), "1");
  EXPECT_NE(sql(*low_, "SELECT LOCATE('object:box:box-3', payload) FROM sa_mine WHERE id = " + std::to_string(id)), "0");
  forget(*low_, id);
  set_profile("rm_low", "--laser-height default");  // back to the stored map: no objects
  id = send_and_wait(*low_, "GetMap", boxes);
  EXPECT_EQ(sql(*low_, count_sql(id, "box")), "0");
  EXPECT_EQ(sql(*low_, "SELECT JSON_EXISTS(params, '$.laser_height') FROM sa_mine WHERE id = " + std::to_string(id)), "0");
  forget(*low_, id);
}

TEST_F(RobotMaps, ObservedObjectsJoinEveryMapAndExpire) {
  ready(*low_);
  ready(*high_);
  const long long robot = scalar("SELECT id FROM robots WHERE db_user = 'rm_low' AND removed_at IS NULL");
  const std::string where = " FROM v_objects WHERE map = 'rm_room' AND source = 'observed' AND robot = 'rm_low'";
  const std::string reports = "SELECT COUNT(*) FROM observed_objects WHERE robot_id = " + std::to_string(robot);
  const long long reported = scalar(reports);  // a robot added again keeps its history
  const auto ack = ask(*low_, "SetObject", R"({"x": 12, "y": 2, "object": "box"})", 1);
  ASSERT_EQ(ack.size(), 1u);
  EXPECT_EQ(ack[0].op, "OpAck");
  EXPECT_EQ(scalar("SELECT COUNT(*)" + where + " AND label = 'box' AND tag = 'box' AND dynamic = 1"), 1);
  EXPECT_EQ(scalar(reports), reported + 1);  // the report itself, as before

  // A 2D square of 0.2 m (docs/semantic-layer.md): every laser height meets it.
  const std::string near = R"({"x": 12, "y": 2, "w": 2, "h": 2})";
  const auto lo = send_and_wait(*low_, "GetMap", near);
  const auto hi = send_and_wait(*high_, "GetMap", near);
  EXPECT_EQ(sql(*low_, count_sql(lo, "box")), "1");
  EXPECT_EQ(sql(*high_, count_sql(hi, "box")), "1");
  EXPECT_NE(sql(*high_, "SELECT LOCATE('object:box:rm_low/box/', payload) FROM sa_mine WHERE id = " + std::to_string(hi)), "0");
  EXPECT_EQ(sql(*low_, "SELECT JSON_EXTRACT(params, '$.segments')" " FROM sa_mine WHERE id = " + std::to_string(lo)), "4");
  forget(*low_, lo);
  forget(*high_, hi);
  // 2.5d shows it too, as a dynamic object without a range.
  const auto s = send_and_wait(*high_, "GetMap", R"({"x": 12, "y": 2, "w": 2, "h": 2, "mode": "2.5d"})");
  EXPECT_EQ(sql(*high_, "SELECT JSON_EXTRACT(params, '$.scene.features[1].properties.dynamic') FROM sa_mine WHERE id = " +
                            std::to_string(s)),
            "true");
  forget(*high_, s);

  // --object-ttl 1: gone from the views and the maps one second after the sighting, and
  // deleted by the housekeeping sweep (every 2 s) soon after.
  std::this_thread::sleep_for(std::chrono::milliseconds(1300));
  EXPECT_EQ(scalar("SELECT COUNT(*)" + where), 0);
  const auto lo2 = send_and_wait(*low_, "GetMap", near);
  EXPECT_EQ(sql(*low_, count_sql(lo2, "box")), "0");
  EXPECT_EQ(sql(*low_, "SELECT JSON_EXTRACT(params, '$.obstacles') FROM sa_mine WHERE id = " + std::to_string(lo2)), "0");
  long long stored = -1;
  for (int i = 0; i < 60 && stored != 0; ++i) {
    stored = scalar("SELECT COUNT(*) FROM env_objects WHERE source = 'observed' AND robot_id = " + std::to_string(robot));
    if (stored != 0) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  EXPECT_EQ(stored, 0);
  EXPECT_EQ(scalar(reports), reported + 1);  // reports do not expire
  // Imported objects never expire.
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM v_objects WHERE map = 'rm_room' AND source = 'imported' AND object_key = 'box-1'"), 1);
}

TEST_F(RobotMaps, LongObjectNamesAreStoredWhole) {
  ready(*low_);
  // 255 bytes, the most SetObject takes; the key holds 200 of them, which would cut an "é".
  std::string name = "a";
  for (int i = 0; i < 127; ++i) name += "\xc3\xa9";
  const auto ack = ask(*low_, "SetObject", json{{"x", 5}, {"y", 12}, {"object", name}}.dump(), 1);
  ASSERT_EQ(ack.size(), 1u);
  EXPECT_EQ(ack[0].op, "OpAck") << ack[0].params.dump();
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM v_objects WHERE map = 'rm_room' AND robot = 'rm_low' AND LENGTH(label) = 255"), 1);
}

TEST_F(RobotMaps, SeenAgainKeepsAnObservationAlive) {
  ready(*low_);
  const std::string where = " FROM v_objects WHERE map = 'rm_room' AND source = 'observed' AND robot = 'rm_low'";
  for (int i = 0; i < 4; ++i) {  // 4 x 0.4 s: longer than the TTL, never 1 s apart
    const auto ack = ask(*low_, "SetObject", R"({"x": 3, "y": 12, "object": "trolley"})", 1);
    ASSERT_EQ(ack.size(), 1u);
    EXPECT_EQ(scalar("SELECT COUNT(*)" + where + " AND label = 'trolley'"), 1) << i;
    std::this_thread::sleep_for(std::chrono::milliseconds(400));
  }
  const auto id = send_and_wait(*low_, "GetMap", R"({"x": 3, "y": 12, "w": 2, "h": 2})");
  EXPECT_EQ(sql(*low_, count_sql(id, "trolley")), "1");
  forget(*low_, id);
}

}  // namespace
}  // namespace fleetmap::test
