// Guided tours (seed 003 §III, docs/topology-tour.md) through the real server, CLI and
// MariaDB: a reference robot (plain SQL) sends SendPos and TourEvent ops, `fleetmap topo
// tour build` builds the graph, and the topology tables hold the nodes Fig. 2 places.
// The map is drawn here, so where the nodes belong is known from its geometry.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "tests/integration/server_fixture.h"
#include "tests/integration/test_db.h"

namespace fleetmap::test {
namespace {

// One wall segment in the seed format (docs/map-format.md).
std::string wall(int id, double x1, double y1, double x2, double y2) {
  auto n = [](double v) { return std::to_string(v); };
  return "obstacle;\n" + std::to_string(id) + ";2;1;wall;\n#\n" + n(x1) + ";" + n(y1) + ";\n" + n(x2) + ";" + n(y2) +
         ";\n2.5;0;wall;\n#\n";
}

// A corridor along x (walls y = 0 and y = 3, centre line y = 1.5), a door in its upper
// wall from x = 10 to x = 11 (centre 10.5), a room above up to y = 8.
std::string tour_map() {
  return "border;\n-0.5;8.5;\n20.5;-0.5;\n#\n" + wall(1, 0, 0, 20, 0) + wall(2, 0, 3, 10, 3) + wall(3, 11, 3, 20, 3) +
         wall(4, 0, 8, 20, 8) + wall(5, 0, 0, 0, 8) + wall(6, 20, 0, 20, 8);
}

class GuidedTour : public ::testing::Test {
 protected:
  void SetUp() override {
    if (scalar("SELECT COUNT(*) FROM maps WHERE name = 'tour_map'") == 0) {
      const std::string file = temp_path("tour_map.map");
      write_file(file, tour_map());
      const RunResult r = run("fleetmap", "map import " + file + " --name tour_map");
      ASSERT_EQ(r.exit_code, 0) << r.err;
    }
    password_ = add_robot("tour_r1", "tour_map");
    admin()->query("DELETE FROM tour_events WHERE robot_id = (SELECT id FROM robots WHERE db_user = 'tour_r1')").execute();
    run("fleetmap", "topo delete tour_map");
    server_ = std::make_unique<ServerProcess>("", "tour_server.log");
    robot_ = std::make_unique<SqlRobot>("tour_r1", password_);
    robot_->send("Ready", R"({"magic": 3})");
    ASSERT_EQ(robot_->receive(2).size(), 2u);
  }
  void TearDown() override {
    server_.reset();
    if (HasFailure()) std::cerr << "server log:\n" << read_file(temp_path("tour_server.log")).substr(0, 20000);
  }
  void at(double x, double y, double theta) {
    robot_->send("SendPos", R"({"x": )" + std::to_string(x) + R"(, "y": )" + std::to_string(y) + R"(, "theta": )" +
                                std::to_string(theta) + R"(, "v": 0.5})");
  }
  void tell(const std::string& params) {
    const auto id = robot_->send("TourEvent", params);
    const auto a = robot_->receive(1);
    ASSERT_EQ(a.size(), 1u) << params;
    EXPECT_EQ(a[0].op, "OpAck") << params << " -> " << a[0].params.dump();
    EXPECT_EQ(a[0].request_id, id);
  }
  std::string password_;
  std::unique_ptr<ServerProcess> server_;
  std::unique_ptr<SqlRobot> robot_;
};

double node_field(const std::string& field, const std::string& where) {
  auto c = admin();
  mysqlpp::Query q = c->query("SELECT " + field + " FROM topo_nodes WHERE map = 'tour_map' AND " + where);
  const mysqlpp::StoreQueryResult r = q.store();
  if (r.size() != 1) return NAN;
  return double(r[0][0]);
}

TEST_F(GuidedTour, EventsBecomeTheMapsGraph) {
  // Before any SendPos (the account is new): no pose to stamp.
  const auto refused = robot_->send("TourEvent", R"({"event": "crossing"})");
  const auto a = robot_->receive(1);
  ASSERT_EQ(a.size(), 1u);
  EXPECT_EQ(a[0].request_id, refused);
  EXPECT_EQ(a[0].op, "Error");
  EXPECT_EQ(a[0].params.value("code", std::string()), "no_pose");

  const double up = std::numbers::pi / 2;
  at(2, 0.8, 0);
  tell(R"({"event": "place", "name": "dock"})");             // at the pose
  at(5, 2.4, 0);
  tell(R"({"event": "corridor"})");                          // centred: (5, 1.5)
  at(10.3, 2.4, up);
  tell(R"({"event": "door"})");                              // between the posts: (10.5, 3)
  at(10.4, 5, up);
  tell(R"({"event": "room"})");                              // at the pose
  tell(R"({"event": "place", "name": "desk", "x": 15, "y": 6, "theta": 0})");
  at(10.7, 3.4, -up);
  tell(R"({"event": "door"})");                              // the same door again
  tell(R"({"event": "crossing", "tour": "other"})");         // another tour: not in this one

  const RunResult dry = run("fleetmap", "topo tour build tour_map --robot tour_r1 --dry-run");
  ASSERT_EQ(dry.exit_code, 0) << dry.err;
  EXPECT_NE(dry.out.find("\"nodes\""), std::string::npos);
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM topo_nodes WHERE map = 'tour_map'"), 0) << "--dry-run stored something";

  const RunResult b = run("fleetmap", "topo tour build tour_map --robot tour_r1");
  ASSERT_EQ(b.exit_code, 0) << b.err;
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM topo_nodes WHERE map = 'tour_map'"), 5);
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM topo_edges WHERE map = 'tour_map'"), 5);
  EXPECT_NEAR(node_field("x", "name = 'dock'"), 2.0, 1e-9);
  EXPECT_NEAR(node_field("y", "name = 'dock'"), 0.8, 1e-9);
  EXPECT_NEAR(node_field("x", "name = 'desk'"), 15.0, 1e-9);
  // The corridor node on the centre line, the door node between the posts.
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM topo_nodes WHERE map = 'tour_map' AND ABS(y - 1.5) < 0.1 AND ABS(x - 5) < 0.1"),
            1);
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM topo_nodes WHERE map = 'tour_map' AND ABS(y - 3) < 0.1 AND ABS(x - 10.5) < 0.1"),
            1);
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM topo_edges WHERE map = 'tour_map' AND type = 'corridor'"), 2);
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM topo_edges WHERE map = 'tour_map' AND type = 'door'"), 1);
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM topo_edges WHERE map = 'tour_map' AND type = 'room'"), 2);

  // What the other topo commands do with it: a route from the dock to the desk.
  const RunResult r = run("fleetmap", "topo route tour_map 2,0.8 15,6");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("length"), std::string::npos);
  // A second build needs --replace.
  EXPECT_NE(run("fleetmap", "topo tour build tour_map --robot tour_r1").exit_code, 0);
  EXPECT_EQ(run("fleetmap", "topo tour build tour_map --robot tour_r1 --replace --tour other").exit_code, 0);
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM topo_nodes WHERE map = 'tour_map'"), 1);
  // An unknown tour is not found (exit 4).
  EXPECT_EQ(run("fleetmap", "topo tour build tour_map --robot tour_r1 --tour none").exit_code, 4);
}

TEST_F(GuidedTour, TheSimulatedRobotFollowsAGuideAndSendsTheEvents) {
  // fleetmap-robot --tour: along the corridor 0.6 m above its centre line, through the
  // door, into the room; the robot reaches each event point and sends TourEvent.
  const std::string tour = temp_path("tour_walk.json");
  write_file(tour, R"([{"x": 2, "y": 2.1, "event": "place", "name": "dock"},
                      {"x": 6, "y": 2.1, "event": "corridor"},
                      {"x": 10.5, "y": 2.1},
                      {"x": 10.5, "y": 2.6, "event": "door"},
                      {"x": 10.5, "y": 5, "event": "room"},
                      {"x": 15, "y": 6, "event": "place", "name": "desk"}])");
  robot_.reset();  // the program registers on its own
  const RunResult r = run("fleetmap-robot", "--config " + std::string(std::getenv("FLEETMAP_CONFIG")) +
                                                " --user tour_r1 --password-file " + temp_path("tour_r1.pw") +
                                                " --tour " + tour + " --tour-fast --tour-name walk");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const RunResult b = run("fleetmap", "topo tour build tour_map --robot tour_r1 --tour walk");
  ASSERT_EQ(b.exit_code, 0) << b.err;
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM tour_events WHERE tour = 'walk'"), 5);
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM topo_nodes WHERE map = 'tour_map'"), 5);
  // Walked 0.6 m off the centre line, the corridor node is on it; the door node between the posts.
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM topo_nodes WHERE map = 'tour_map' AND ABS(y - 1.5) < 0.1 AND ABS(x - 6) < 0.2"),
            1);
  EXPECT_EQ(scalar("SELECT COUNT(*) FROM topo_nodes WHERE map = 'tour_map' AND ABS(y - 3) < 0.1 AND ABS(x - 10.5) < 0.1"),
            1);
  EXPECT_NEAR(node_field("x", "name = 'desk'"), 15.0, 0.15);
}

}  // namespace
}  // namespace fleetmap::test
