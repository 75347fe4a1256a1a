// Every op through its happy path and its error paths, driven by a reference robot that
// uses plain SQL only, against the real fleetmap-server process and MariaDB.
#include <cmath>
#include <thread>

#include <gtest/gtest.h>

#include "common/map/map_window.h"
#include "common/io/seed_format.h"
#include "tests/integration/server_fixture.h"
#include "tests/integration/test_db.h"

namespace fleetmap::test {
namespace {

using nlohmann::json;

class ReferenceRobot : public ::testing::Test {
 protected:
  void SetUp() override {
    ensure_example_map("proto_map");
    password_ = add_robot("proto_r1", "proto_map");
    robot_id_ = static_cast<unsigned>(scalar("SELECT id FROM robots WHERE db_user = 'proto_r1'"));
    // Observations of earlier tests (SetObject's door) live on in the map's scene, where
    // goals are checked and paths planned: each test starts without them.
    admin()->query("DELETE FROM env_objects WHERE source = 'observed' AND map_id = "
                   "(SELECT id FROM maps WHERE name = 'proto_map')").execute();
    admin()->query("DELETE FROM avoided_areas WHERE area_key = 'proto_late'").execute();
    server_ = std::make_unique<ServerProcess>(server_flags(), "proto_server.log");
    robot_ = std::make_unique<SqlRobot>("proto_r1", password_);
  }
  // The test robot is silent between steps: it must not be lost while a step runs.
  virtual std::string server_flags() const { return kQuietRobotFlags; }
  void TearDown() override {
    server_.reset();
    if (HasFailure()) std::cerr << "server log:\n" << read_file(temp_path("proto_server.log")).substr(0, 20000);
  }
  // Sends one request and returns its answers (expected count n).
  std::vector<SqlAnswer> ask(const std::string& op, const std::string& params, size_t n,
                             const std::optional<std::string>& payload = std::nullopt) {
    const auto id = robot_->send(op, params, payload);
    auto got = robot_->receive(n);
    for (const auto& a : got) EXPECT_EQ(a.request_id, id) << op;
    return got;
  }
  void ready() {
    auto a = ask("Ready", R"({"magic": 7})", 2);
    ASSERT_EQ(a.size(), 2u);
  }
  void expect_error(const std::string& op, const std::string& params, const std::string& code,
                    const std::optional<std::string>& payload = std::nullopt) {
    auto a = ask(op, params, 1, payload);
    ASSERT_EQ(a.size(), 1u) << op << " " << params;
    EXPECT_EQ(a[0].op, "Error") << op << " " << params;
    EXPECT_EQ(a[0].params["code"], code) << op << " " << params << " -> " << a[0].params.dump();
    EXPECT_EQ(a[0].params["request_id"], *a[0].request_id);
    EXPECT_FALSE(a[0].params["message"].get<std::string>().empty());
  }
  std::string password_;
  unsigned robot_id_ = 0;
  std::unique_ptr<ServerProcess> server_;
  std::unique_ptr<SqlRobot> robot_;
};

TEST_F(ReferenceRobot, ReadyGivesStartThenTheWholeMap) {
  auto a = ask("Ready", R"({"magic": 12345})", 2);
  ASSERT_EQ(a.size(), 2u);
  EXPECT_EQ(a[0].op, "Start");
  EXPECT_EQ(a[0].params["magic"], 12345);
  EXPECT_EQ(a[0].params["robot_id"], robot_id_);
  EXPECT_DOUBLE_EQ(a[0].params["alive_period_s"].get<double>(), 0.5);
  EXPECT_EQ(a[1].op, "SetMap");
  ASSERT_TRUE(a[1].payload);
  const Map file = read_seed_file(source_path("maps/example-campus.map"));
  EXPECT_EQ(read_seed(*a[1].payload), file);
  EXPECT_EQ(a[1].params["segments"], file.segment_count());
  EXPECT_EQ(a[1].params["obstacles"], file.obstacles.size());
  EXPECT_EQ(a[1].params["encoding"], "seed");
  EXPECT_EQ(a[1].params["border"], json({0.0, 40.0, 60.0, 0.0}));
  EXPECT_EQ(scalar("SELECT magic FROM robots WHERE db_user = 'proto_r1'"), 12345);
}

TEST_F(ReferenceRobot, CompressedMapReadsBackWithSqlUncompress) {
  robot_->send("Ready", R"({"magic": 1, "encoding": "seed+compress"})");
  std::vector<SqlAnswer> a;
  for (int i = 0; i < 500 && a.size() < 2; ++i) {
    a = robot_->peek();
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ASSERT_EQ(a.size(), 2u);
  EXPECT_EQ(a[1].params["encoding"], "seed+compress");
  const std::string text = read_file(source_path("maps/example-campus.map"));
  EXPECT_LT(a[1].payload->size(), text.size() / 2);
  // The robot (or an inspector) reads the text with SQL alone: MariaDB's own UNCOMPRESS.
  mysqlpp::Query q = robot_->connection().query("SELECT UNCOMPRESS(payload) FROM sa_mine WHERE id = " +
                                                std::to_string(a[1].id));
  auto r = q.store();
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(std::string(r[0][0].data(), r[0][0].length()), text);
}

TEST_F(ReferenceRobot, GetMapReturnsTheClippedWindow) {
  ready();
  auto a = ask("GetMap", R"({"x": 20, "y": 30, "w": 10, "h": 8})", 1);
  ASSERT_EQ(a.size(), 1u);
  EXPECT_EQ(a[0].op, "SetMap");
  const Map file = read_seed_file(source_path("maps/example-campus.map"));
  const Map expected = clip_map(file, window_rect(file.border, {20, 30}, 10, 8));
  EXPECT_EQ(read_seed(*a[0].payload, "SetMap", MapKind::Window), expected);
  EXPECT_EQ(a[0].params["border"], json({15.0, 34.0, 25.0, 26.0}));
  // Clipped to the border: a window over the corner.
  a = ask("GetMap", R"({"x": 0, "y": 0, "w": 10, "h": 10})", 1);
  EXPECT_EQ(a[0].params["border"], json({0.0, 5.0, 5.0, 0.0}));
  expect_error("GetMap", R"({"x": 500, "y": 500, "w": 10, "h": 10})", "bad_params");
  expect_error("GetMap", R"({"x": 1, "y": 1, "w": 0, "h": 10})", "bad_params");
  expect_error("GetMap", R"({"x": 1, "y": 1, "w": -5, "h": 10})", "bad_params");
  expect_error("GetMap", R"({"x": 1, "y": 1, "w": 1e999, "h": 10})", "bad_params");
  expect_error("GetMap", R"({"x": "1", "y": 1, "w": 5, "h": 10})", "bad_params");
  expect_error("GetMap", R"({"y": 1, "w": 5, "h": 10})", "bad_params");
  expect_error("GetMap", R"({"x": 1, "y": 1, "w": 5, "h": 10, "encoding": "zip"})", "bad_params");
}

TEST_F(ReferenceRobot, OpsBeforeReadyAreNotRegistered) {
  for (const char* op : {"Alive", "SendPos", "GetMap", "GetPosIni", "Stopped"})
    expect_error(op, "{}", "not_registered");
}

TEST_F(ReferenceRobot, SendPosBuildsTheTrajectoryAndStatus) {
  ready();
  const long long before = scalar("SELECT COUNT(*) FROM trajectories WHERE robot_id = " + std::to_string(robot_id_));
  for (int i = 0; i < 5; ++i)
    robot_->send("SendPos", json{{"x", 1.0 + i}, {"y", 2.0}, {"theta", 0.1}, {"v", 0.5}}.dump());
  robot_->send("Alive");
  // SendPos and Alive get no answer: wait until the server drained rr.
  for (int i = 0; i < 200 && scalar("SELECT COUNT(*) FROM rr WHERE db_user = 'proto_r1'") > 0; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM trajectories WHERE robot_id = " + std::to_string(robot_id_)), before + 5);
  EXPECT_EQ(scalar("SELECT x FROM robots WHERE id = " + std::to_string(robot_id_)), 5);
  EXPECT_EQ(scalar("SELECT state = 'moving' FROM robots WHERE id = " + std::to_string(robot_id_)), 1);
  EXPECT_TRUE(robot_->peek().empty());
  expect_error("SendPos", R"({"x": 1, "y": 2, "theta": 0})", "bad_params");
  expect_error("SendPos", R"({"x": 1, "y": 2, "theta": 0, "v": true})", "bad_params");
  expect_error("SendPos", R"({"x": 1e300, "y": 2, "theta": 0, "v": 0})", "bad_params");
  expect_error("SendPos", R"([1, 2, 3])", "bad_json");
}

TEST_F(ReferenceRobot, MalformedRequestsGetErrorsAndServingGoesOn) {
  ready();
  expect_error("Dance", "{}", "unknown_op");
  expect_error("ready", R"({"magic": 1})", "unknown_op");  // op names are case-sensitive
  expect_error("Ready", R"({"magic": "x"})", "bad_params");
  expect_error("Ready", R"("just a string")", "bad_json");
  expect_error("OpAck", R"({"answer_id": 424242})", "unknown_answer");
  expect_error("OpAck", R"({})", "bad_params");
  expect_error("GetPosIni", "{}", "no_pose");
  expect_error("GetPosEnd", "{}", "no_goal");
  // Not JSON at all: a robot can switch off the column's CHECK constraint for its session.
  robot_->connection().query("SET SESSION check_constraint_checks = 0").execute();
  expect_error("Alive", "{not json", "bad_json");
  robot_->connection().query("SET SESSION check_constraint_checks = 1").execute();
  // Another robot's id.
  const auto id = robot_->send("Alive", "{}", std::nullopt, robot_id_ + 1000);
  auto a = robot_->receive(1);
  ASSERT_EQ(a.size(), 1u);
  EXPECT_EQ(a[0].request_id, id);
  EXPECT_EQ(a[0].params["code"], "not_your_robot");
  // After all that, a normal request is still served.
  auto g = ask("GetMap", R"({"x": 20, "y": 30, "w": 10, "h": 8})", 1);
  ASSERT_EQ(g.size(), 1u);
  EXPECT_EQ(g[0].op, "SetMap");
}

// The server writes a batch of requests together (protocol/write_batch.h). When the
// database refuses one request's write, only that request gets an Error: the others that
// came in the same batch are answered and stored as if it were not there.
TEST_F(ReferenceRobot, AWriteTheDatabaseRefusesCostsOnlyItsOwnRequest) {
  ready();
  const std::string mine = " WHERE robot_id = " + std::to_string(robot_id_);
  const long long fixes = scalar("SELECT COUNT(*) FROM gps_fixes" + mine);
  const long long poses = scalar("SELECT COUNT(*) FROM trajectories" + mine);
  const long long images = scalar("SELECT COUNT(*) FROM images" + mine);
  // A refusal only the database makes: a trigger of this test's own (the decoder already
  // refuses what no column could hold, so no valid request fails by itself).
  admin()->query("DROP TRIGGER IF EXISTS proto_refuse_image").execute();
  admin()->query("CREATE TRIGGER proto_refuse_image BEFORE INSERT ON images FOR EACH ROW "
                 "IF NEW.format = 'refuse-me' THEN SIGNAL SQLSTATE '45000' SET MESSAGE_TEXT = 'refused'; END IF")
      .execute();
  // One robot transaction: the server sees all five at once, in one batch.
  mysqlpp::Connection& c = robot_->connection();
  c.query("START TRANSACTION").execute();
  const auto gps1 = robot_->send("SendGPS", R"({"lat": 41.0, "lon": 2.0})");
  robot_->send("SendPos", R"({"x": 3, "y": 4, "theta": 0.5, "v": 0})");
  const auto bad = robot_->send("SendImage", R"({"x": 1, "y": 2, "format": "refuse-me"})", std::string("\x89PNG"));
  const auto gps2 = robot_->send("SendGPS", R"({"lat": 41.5, "lon": 2.5})");
  const auto map = robot_->send("GetMap", R"({"x": 20, "y": 30, "w": 10, "h": 8})");
  c.query("COMMIT").execute();

  auto a = robot_->receive(4);
  admin()->query("DROP TRIGGER IF EXISTS proto_refuse_image").execute();
  ASSERT_EQ(a.size(), 4u);
  EXPECT_EQ(a[0].request_id, gps1);
  EXPECT_EQ(a[0].op, "OpAck");
  EXPECT_EQ(a[1].request_id, bad);
  EXPECT_EQ(a[1].op, "Error");
  EXPECT_EQ(a[1].params["code"], "internal") << a[1].params.dump();
  EXPECT_EQ(a[2].request_id, gps2);
  EXPECT_EQ(a[2].op, "OpAck");
  EXPECT_EQ(a[3].request_id, map);
  EXPECT_EQ(a[3].op, "SetMap");
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM gps_fixes" + mine), fixes + 2);
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM trajectories" + mine), poses + 1);
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM images" + mine), images);
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM robots WHERE x = 3 AND y = 4 AND id = " + std::to_string(robot_id_)), 1);
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM rr WHERE db_user = 'proto_r1'"), 0);
}

// images.format is VARCHAR(32): the decoder takes as much as the column holds and answers
// a longer one bad_params, rather than an internal error after a failed batch.
TEST_F(ReferenceRobot, AnImageFormatIsAsLongAsItsColumnHolds) {
  ready();
  const std::string f32(32, 'f');
  const std::string stored =
      "SELECT COUNT(*) FROM images WHERE format = '" + f32 + "' AND robot_id = " + std::to_string(robot_id_);
  const long long before = scalar(stored);
  const auto ok = ask("SendImage", R"({"x": 1, "y": 2, "format": ")" + f32 + R"("})", 1, std::string("IMG"));
  EXPECT_EQ(ok[0].op, "OpAck") << ok[0].params.dump();
  EXPECT_EQ(scalar(stored), before + 1);
  expect_error("SendImage", R"({"x": 1, "y": 2, "format": ")" + std::string(33, 'f') + R"("})", "bad_params");
}

// Requests that arrive together are handled in one batch, the robot's row changed in
// memory and written once: the result must be that of handling them one after another.
TEST_F(ReferenceRobot, RequestsOfOneBatchTakeEffectInOrder) {
  ready();
  const std::string me = " WHERE id = " + std::to_string(robot_id_);
  const std::string points = "SELECT COUNT(*) FROM trajectories WHERE robot_id = " + std::to_string(robot_id_);
  const long long before = scalar(points);
  mysqlpp::Connection& c = robot_->connection();
  auto together = [&](const std::vector<std::pair<std::string, std::string>>& reqs) {
    c.query("START TRANSACTION").execute();
    for (const auto& [op, params] : reqs) robot_->send(op, params);
    c.query("COMMIT").execute();
    ASSERT_TRUE(wait_until([&] { return scalar("SELECT COUNT(*) FROM rr WHERE db_user = 'proto_r1'") == 0; },
                           std::chrono::seconds(10)));
    robot_->receive(1, std::chrono::milliseconds(300));  // the Stopped OpAck, if any
  };
  together({{"SendPos", R"({"x": 5, "y": 6, "theta": 0, "v": 1})"}, {"Stopped", "{}"}});
  EXPECT_EQ(scalar("SELECT state = 'stopped' FROM robots" + me), 1);
  together({{"Stopped", "{}"}, {"SendPos", R"({"x": 7, "y": 8, "theta": 1, "v": 0.5})"}});
  EXPECT_EQ(scalar("SELECT state = 'moving' AND x = 7 AND y = 8 AND theta = 1 FROM robots" + me), 1);
  together({{"SendPos", R"({"x": 9, "y": 10, "theta": 2, "v": 1})"}, {"SendPos", R"({"x": 11, "y": 12, "theta": 3, "v": 0})"}});
  EXPECT_EQ(scalar("SELECT state = 'ready' AND x = 11 AND y = 12 AND v = 0 FROM robots" + me), 1);
  EXPECT_EQ(scalar(points), before + 4);
  // last_seen is the newest request's time, never older than it was.
  EXPECT_EQ(scalar("SELECT last_seen >= (SELECT MAX(t) FROM trajectories WHERE robot_id = " +
                   std::to_string(robot_id_) + ") FROM robots" + me), 1);
}

TEST_F(ReferenceRobot, GpsImageAndObjectAreStoredAndAcknowledged) {
  ready();
  const std::string mine = " WHERE robot_id = " + std::to_string(robot_id_);
  const long long fixes = scalar("SELECT COUNT(*) FROM gps_fixes" + mine);
  auto a = ask("SendGPS", R"({"lat": 41.389, "lon": 2.113})", 1);
  ASSERT_EQ(a.size(), 1u);
  EXPECT_EQ(a[0].op, "OpAck");
  EXPECT_EQ(a[0].params["request_id"], *a[0].request_id);
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM gps_fixes" + mine), fixes + 1);
  EXPECT_EQ(scalar("SELECT lat * 1000 FROM gps_fixes" + mine + " ORDER BY id DESC LIMIT 1"), 41389);
  expect_error("SendGPS", R"({"lat": 91, "lon": 2})", "bad_params");

  const std::string image(1000, '\x7f');
  a = ask("SendImage", R"({"x": 1, "y": 2, "object_id": 5, "format": "png"})", 1, image);
  EXPECT_EQ(a[0].op, "OpAck");
  EXPECT_EQ(scalar("SELECT LENGTH(data) FROM images WHERE robot_id = " + std::to_string(robot_id_) +
                   " ORDER BY id DESC LIMIT 1"),
            1000);
  expect_error("SendImage", R"({"x": 1, "y": 2, "format": "png"})", "bad_params");  // no payload

  const long long doors = scalar("SELECT COUNT(*) FROM v_observed_objects WHERE robot = 'proto_r1' AND object = 'door'");
  a = ask("SetObject", R"({"x": 3, "y": 4, "object": "door"})", 1);
  EXPECT_EQ(a[0].op, "OpAck");
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM v_observed_objects WHERE robot = 'proto_r1' AND object = 'door' AND x = 3"),
            doors + 1);
}

TEST_F(ReferenceRobot, GpsFixesGetMapCoordinatesOnAGeoreferencedMap) {
  ready();
  // Origin at (41.389 N, 2.113 E), map x axis pointing north (heading pi/2).
  ASSERT_EQ(run("fleetmap", "map georef proto_map 41.389 2.113 --heading 1.5707963267948966").exit_code, 0);
  auto a = ask("SendGPS", R"({"lat": 41.390, "lon": 2.113})", 1);
  ASSERT_EQ(a[0].op, "OpAck");
  // 0.001 deg north on the WGS 84 ellipsoid: the meridian's radius of curvature
  // M = a (1 - e2) / (1 - e2 sin^2 phi)^1.5 at the mid latitude, times the angle.
  const double e2 = 0.00669437999014, phi = 41.3895 * M_PI / 180;
  const double m = 6378137 * (1 - e2) / std::pow(1 - e2 * std::sin(phi) * std::sin(phi), 1.5);
  const std::string last = " FROM gps_fixes WHERE robot_id = " + std::to_string(robot_id_) + " ORDER BY id DESC LIMIT 1";
  EXPECT_EQ(scalar("SELECT ROUND(x * 1000)" + last), std::lround(m * 0.001 * M_PI / 180 * 1000));  // north is +x
  EXPECT_EQ(scalar("SELECT ROUND(y * 1000)" + last), 0);
  ASSERT_EQ(run("fleetmap", "map georef proto_map --clear").exit_code, 0);
  ask("SendGPS", R"({"lat": 41.390, "lon": 2.113})", 1);
  EXPECT_EQ(scalar("SELECT x IS NULL" + last), 1);
}

TEST(ReferenceRobotLimits, OversizedImageIsRefused) {
  ensure_example_map("proto_map");
  const std::string pw = add_robot("proto_big", "proto_map");
  ServerProcess server("--max-image-bytes 1000", "proto_big.log");
  SqlRobot robot("proto_big", pw);
  robot.send("Ready", R"({"magic": 1})");
  ASSERT_EQ(robot.receive(2).size(), 2u);
  robot.send("SendImage", R"({"x": 1, "y": 2, "format": "jpg"})", std::string(1001, 'x'));
  auto a = robot.receive(1);
  ASSERT_EQ(a.size(), 1u);
  EXPECT_EQ(a[0].params["code"], "payload_too_large");
}

TEST_F(ReferenceRobot, PosesAndTasksFromTheOperator) {
  ready();
  ASSERT_EQ(run("fleetmap", "pose-ini proto_r1 3 4 1.5").exit_code, 0);
  auto a = ask("GetPosIni", "{}", 1);
  EXPECT_EQ(a[0].op, "SetPosIni");
  EXPECT_EQ(a[0].params, json({{"x", 3.0}, {"y", 4.0}, {"theta", 1.5}}));

  // goal -> SetPosEnd pushed (request_id NULL) -> OpAck -> acknowledged -> moves -> active
  RunResult g = run("fleetmap", "goal proto_r1 10 12");
  ASSERT_EQ(g.exit_code, 0) << g.err;
  const long long task = scalar("SELECT MAX(id) FROM tasks WHERE robot_id = " + std::to_string(robot_id_));
  auto push = robot_->receive(1);
  ASSERT_EQ(push.size(), 1u);
  EXPECT_EQ(push[0].op, "SetPosEnd");
  EXPECT_FALSE(push[0].request_id);
  EXPECT_EQ(push[0].params, json({{"x", 10.0}, {"y", 12.0}}));
  const std::string state = "SELECT state FROM tasks WHERE id = " + std::to_string(task);
  EXPECT_EQ(scalar("SELECT state = 'assigned' FROM tasks WHERE id = " + std::to_string(task)), 1);
  robot_->send("OpAck", json{{"answer_id", push[0].id}}.dump());
  a = ask("GetPosEnd", "{}", 1);  // in order after the OpAck
  EXPECT_EQ(a[0].params, json({{"x", 10.0}, {"y", 12.0}}));
  EXPECT_EQ(scalar("SELECT state = 'acknowledged' FROM tasks WHERE id = " + std::to_string(task)), 1);
  robot_->send("SendPos", R"({"x": 10.1, "y": 11.9, "theta": 0, "v": 0.4})");
  a = ask("Stopped", "{}", 1);
  EXPECT_EQ(a[0].op, "OpAck");
  EXPECT_EQ(scalar("SELECT state = 'done' FROM tasks WHERE id = " + std::to_string(task)), 1);

  // A second goal, aborted on the way: Abort pushed, aborted once acknowledged.
  ASSERT_EQ(run("fleetmap", "goal proto_r1 20 20").exit_code, 0);
  push = robot_->receive(1);
  ASSERT_EQ(push.size(), 1u);
  robot_->send("OpAck", json{{"answer_id", push[0].id}}.dump());
  RunResult ab = run("fleetmap", "abort proto_r1 --reason 'blocked corridor'");
  ASSERT_EQ(ab.exit_code, 0) << ab.err;
  auto abort = robot_->receive(1);
  ASSERT_EQ(abort.size(), 1u);
  EXPECT_EQ(abort[0].op, "Abort");
  EXPECT_EQ(abort[0].params["reason"], "blocked corridor");
  const long long task2 = scalar("SELECT MAX(id) FROM tasks WHERE robot_id = " + std::to_string(robot_id_));
  EXPECT_NE(scalar("SELECT state = 'aborted' FROM tasks WHERE id = " + std::to_string(task2)), 1);
  robot_->send("OpAck", json{{"answer_id", abort[0].id}}.dump());
  robot_->send("Stopped");
  robot_->receive(1);
  EXPECT_EQ(scalar("SELECT state = 'aborted' FROM tasks WHERE id = " + std::to_string(task2)), 1);
  EXPECT_EQ(run("fleetmap", "abort proto_r1").exit_code, 4);  // nothing open any more
}

TEST_F(ReferenceRobot, GetPathPlansFromThePoseToTheGoal) {
  ready();
  expect_error("GetPath", "{}", "no_goal");
  const RunResult g = run("fleetmap", "goal proto_r1 50 12");
  ASSERT_EQ(g.exit_code, 0) << g.err;
  auto push = robot_->receive(1);
  ASSERT_EQ(push.size(), 1u);
  robot_->send("OpAck", json{{"answer_id", push[0].id}}.dump());
  expect_error("GetPath", "{}", "no_pose");  // nothing reported yet
  robot_->send("SendPos", R"({"x": 25, "y": 8, "theta": 0, "v": 0})");
  auto a = ask("GetPath", "{}", 1);
  ASSERT_EQ(a.size(), 1u);
  ASSERT_EQ(a[0].op, "SetPath") << a[0].params.dump();
  const auto& w = a[0].params["waypoints"];
  ASSERT_GE(w.size(), 2u);
  EXPECT_EQ(w.front(), json({25.0, 8.0}));
  EXPECT_EQ(w.back(), json({50.0, 12.0}));
  double length = 0;
  for (size_t i = 1; i < w.size(); ++i)
    length += std::hypot(w[i][0].get<double>() - w[i - 1][0].get<double>(), w[i][1].get<double>() - w[i - 1][1].get<double>());
  EXPECT_NEAR(a[0].params["length"].get<double>(), length, 1e-9);
  EXPECT_GE(length, std::hypot(25.0, 4.0) - 1e-9);
  const long long task = scalar("SELECT MAX(id) FROM tasks WHERE robot_id = " + std::to_string(robot_id_));
  EXPECT_EQ(scalar("SELECT state = 'active' FROM tasks WHERE id = " + std::to_string(task)), 1);
  // A goal inside the closed library (its door is 2.5 m high) is refused by the operator's
  // command: exit 3, no task, the active one stays.
  const RunResult library = run("fleetmap", "goal proto_r1 12 30");
  EXPECT_EQ(library.exit_code, 3) << library.out << library.err;
  EXPECT_NE(library.err.find("inside obstacle 1 (building,library)"), std::string::npos) << library.err;
  EXPECT_EQ(scalar("SELECT MAX(id) FROM tasks WHERE robot_id = " + std::to_string(robot_id_)), task);
  // An avoided area drawn over the goal after it was given: GetPath finds no path, the
  // task fails with the reason, and the robot has no open task left.
  ASSERT_EQ(run("fleetmap", "avoid add proto_map --id proto_late --wkt 'POLYGON((49 11, 51 11, 51 13, 49 13, 49 11))'")
                .exit_code,
            0);
  std::this_thread::sleep_for(std::chrono::milliseconds(400));  // RobotMapSource::kRecheck
  expect_error("GetPath", "{}", "no_path");
  EXPECT_EQ(run("fleetmap", "avoid remove proto_map proto_late").exit_code, 0);
  EXPECT_EQ(scalar("SELECT state = 'failed' FROM tasks WHERE id = " + std::to_string(task)), 1);
  auto c = admin();
  const std::string reason =
      std::string(c->query("SELECT reason FROM tasks WHERE id = " + std::to_string(task)).store()[0][0]);
  EXPECT_NE(reason.find("no path to (50.000000, 12.000000): the goal is inside avoid:proto_late"), std::string::npos)
      << reason;
  expect_error("GetPath", "{}", "no_goal");
}

// A server that loses a silent robot soon, as losing it is what the test checks.
class SilentReferenceRobot : public ReferenceRobot {
 protected:
  std::string server_flags() const override { return "--alive-period 0.5 --lost-after 4"; }
};

TEST_F(SilentReferenceRobot, IsLostItsTaskFailsAndItComesBack) {
  ready();
  ASSERT_EQ(run("fleetmap", "goal proto_r1 5 5").exit_code, 0);
  const long long task = scalar("SELECT MAX(id) FROM tasks WHERE robot_id = " + std::to_string(robot_id_));
  ASSERT_EQ(robot_->receive(1).size(), 1u);  // SetPosEnd
  // Alive period 0.5 s, lost after 4 periods: silent for 3 s is lost.
  std::this_thread::sleep_for(std::chrono::seconds(3));
  EXPECT_EQ(scalar("SELECT state = 'lost' FROM robots WHERE id = " + std::to_string(robot_id_)), 1);
  EXPECT_EQ(scalar("SELECT state = 'failed' FROM tasks WHERE id = " + std::to_string(task)), 1);
  robot_->send("Alive");
  for (int i = 0; i < 200 && scalar("SELECT state = 'lost' FROM robots WHERE id = " + std::to_string(robot_id_)); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  EXPECT_EQ(scalar("SELECT state = 'ready' FROM robots WHERE id = " + std::to_string(robot_id_)), 1);
}

}  // namespace
}  // namespace fleetmap::test
