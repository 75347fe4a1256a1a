// GetPath through the topological graph and goals by node, through the real programs
// (SPEC 5.2, 7; seed 003; docs/protocol.md, "SetPath: nodes and edges"): on GDC1 with its
// navigation graph, a long GetPath answer carries the route's nodes and edges, which are
// checked against the navigation file parsed here, and its path is clear (brute force
// over every wall); `fleetmap goal R --node WHAT` by name, by type, refused (exit 3)
// when there is no such node or it cannot be reached, exit 4 without a graph.
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <utility>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/common/planning/planning_test_util.h"
#include "tests/integration/server_fixture.h"
#include "tests/integration/test_db.h"

namespace fleetmap::test {
namespace {

using json = nlohmann::json;

constexpr const char* kMap = "tp_gdc1";
constexpr const char* kRobot = "tp_r1";
const Point kStart{-32.5, 20.1};  // beside node 1, the graph's west end
const Point kGoal{33.3, 8.8};     // beside node 3, its east end: 67 m as the crow flies

// The GDC1 navigation file with names on two nodes (near the robot, so that the goal
// check's whole-map RRT is quick) and one more node, "sealed", on the first wall of the
// vector map (a goal no robot can reach), joined to node 3.
json named_graph() {
  std::ifstream in(real_map("GDC1.navigation.json"));
  json g = json::parse(in);
  for (json& n : g["nodes"]) {
    if (n["id"] == 0) n["name"] = "room 2.302";
    if (n["id"] == 8) n["name"] = "charging station";
  }
  std::ifstream walls(real_map("GDC1.vectormap.txt"));
  double x0, y0, x1, y1;
  char comma;
  walls >> x0 >> comma >> y0 >> comma >> x1 >> comma >> y1;
  g["nodes"].push_back({{"id", 100}, {"name", "sealed"}, {"loc", {{"x", (x0 + x1) / 2}, {"y", (y0 + y1) / 2}}}});
  g["edges"].push_back({{"s0_id", 3}, {"s1_id", 100}, {"has_door", false}, {"has_automated_door", false},
                        {"has_stairs", false}, {"has_elevator", false}, {"max_clearance", 1.0}, {"max_speed", 1.0}});
  return g;
}

class TopoPath : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (scalar("SELECT COUNT(*) FROM maps WHERE name = '" + std::string(kMap) + "'") == 0) {
      const RunResult r = run("fleetmap", "map import " + real_map("GDC1.vectormap.txt") + " --name " + kMap);
      ASSERT_EQ(r.exit_code, 0) << r.err;
    }
    write_file(temp_path("tp_graph.json"), named_graph().dump());
    const RunResult r = run("fleetmap", "topo import " + std::string(kMap) + " " + temp_path("tp_graph.json") + " --replace");
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  void SetUp() override {
    password_ = add_robot(kRobot, kMap);
    admin()->query("UPDATE robots SET x = " + std::to_string(kStart.x) + ", y = " + std::to_string(kStart.y) +
                   ", ini_x = NULL, ini_y = NULL, radius = NULL, body_height = NULL, state = 'offline' "
                   "WHERE db_user = '" + kRobot + "'").execute();
    robot_id_ = std::to_string(scalar("SELECT id FROM robots WHERE db_user = '" + std::string(kRobot) + "'"));
  }
  long long tasks() { return scalar("SELECT COUNT(*) FROM tasks WHERE robot_id = " + robot_id_); }
  std::string password_, robot_id_;
};

TEST_F(TopoPath, ALongGetPathCarriesTheGraphRouteAndIsClear) {
  const json file = named_graph();
  std::map<int, std::pair<Point, std::string>> nodes;  // from the file: id -> position, name
  for (const json& n : file["nodes"])
    nodes[n["id"].get<int>()] = {{n["loc"]["x"].get<double>(), n["loc"]["y"].get<double>()},
                                 n.value("name", std::string())};
  std::set<std::pair<int, int>> edges;
  for (const json& e : file["edges"]) {
    edges.insert({e["s0_id"].get<int>(), e["s1_id"].get<int>()});
    edges.insert({e["s1_id"].get<int>(), e["s0_id"].get<int>()});
  }
  const planning_test::BruteClearance judge(planning_test::gdc1());
  ASSERT_GT(judge.clearance(kStart, kStart), 0.3);
  ASSERT_GT(judge.clearance(kGoal, kGoal), 0.3);

  // No known position when the goal is given: accept_goal then checks only the goal's
  // place (its whole-map RRT over 67 m of this floor can near its time limit on a busy
  // machine, bench-topo-path); the pose comes with SendPos, before GetPath.
  admin()->query("UPDATE robots SET x = NULL, y = NULL WHERE db_user = '" + std::string(kRobot) + "'").execute();
  ServerProcess server(kQuietRobotFlags, "tp_server.log");
  SqlRobot robot(kRobot, password_);
  robot.send("Ready", R"({"magic": 5})");
  ASSERT_EQ(robot.receive(2).size(), 2u);
  const RunResult g = run("fleetmap", "goal " + std::string(kRobot) + " " + std::to_string(kGoal.x) + " " +
                                          std::to_string(kGoal.y));
  ASSERT_EQ(g.exit_code, 0) << g.err;
  auto push = robot.receive(1);
  ASSERT_EQ(push.size(), 1u);
  robot.send("OpAck", json{{"answer_id", push[0].id}}.dump());
  robot.send("SendPos", json{{"x", kStart.x}, {"y", kStart.y}, {"theta", 0}, {"v", 0}}.dump());
  robot.send("GetPath", "{}");
  const auto a = robot.receive(1);
  ASSERT_EQ(a.size(), 1u);
  ASSERT_EQ(a[0].op, "SetPath") << a[0].params.dump();
  const json& p = a[0].params;
  ASSERT_TRUE(p.contains("nodes") && p.contains("edges")) << p.dump();

  // The route: stored nodes with their stored positions and names, joined by stored edges.
  const json& rn = p["nodes"];
  const json& re = p["edges"];
  ASSERT_GE(rn.size(), 2u);
  ASSERT_EQ(re.size() + 1, rn.size());
  for (size_t i = 0; i < rn.size(); ++i) {
    const int id = rn[i]["id"].get<int>();
    ASSERT_TRUE(nodes.count(id)) << id;
    EXPECT_NEAR(rn[i]["x"].get<double>(), nodes[id].first.x, 1e-9);
    EXPECT_NEAR(rn[i]["y"].get<double>(), nodes[id].first.y, 1e-9);
    EXPECT_EQ(rn[i]["name"], nodes[id].second);
  }
  for (size_t i = 0; i < re.size(); ++i) {
    EXPECT_EQ(re[i]["from"], rn[i]["id"]);
    EXPECT_EQ(re[i]["to"], rn[i + 1]["id"]);
    EXPECT_TRUE(edges.count({re[i]["from"].get<int>(), re[i]["to"].get<int>()})) << re[i].dump();
    EXPECT_EQ(re[i]["type"], "corridor");  // GDC1's edges carry no flags
  }
  // Along the corridor from the west part (nodes 0-2) eastwards, never to the sealed node.
  // Which nodes exactly depends on what each end sees (the goal sees node 2 down the long
  // corridor), so only the start's side is checked.
  EXPECT_LT(nodes[rn.front()["id"].get<int>()].first.x, -20);
  for (const json& n : rn) EXPECT_NE(n["id"], 100);

  // The path: from the pose to the goal, every segment clear of every wall by the radius.
  Path path;
  for (const json& w : p["waypoints"]) path.push_back({w[0].get<double>(), w[1].get<double>()});
  ASSERT_GE(path.size(), 2u);
  EXPECT_NEAR(path.front().x, kStart.x, 1e-6);
  EXPECT_NEAR(path.front().y, kStart.y, 1e-6);
  EXPECT_NEAR(path.back().x, kGoal.x, 1e-6);
  EXPECT_NEAR(path.back().y, kGoal.y, 1e-6);
  EXPECT_GT(judge.path_clearance(path), 0.3);
  EXPECT_NEAR(p["length"].get<double>(), path_length(path), 1e-6);
}

TEST_F(TopoPath, GoalByNodeNameOrTypeFromTheCli) {
  const std::string goal = "goal " + std::string(kRobot) + " --node ";
  long long before = tasks();
  RunResult r = run("fleetmap", goal + "'room 2.302'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("goal node 0 'room 2.302'"), std::string::npos) << r.out;
  EXPECT_EQ(tasks(), before + 1);
  const json nodes = named_graph()["nodes"];
  json room;
  for (const json& n : nodes)
    if (n["id"] == 0) room = n;
  const mysqlpp::StoreQueryResult last =
      admin()->query("SELECT goal_x, goal_y FROM tasks WHERE robot_id = " + robot_id_ + " ORDER BY id DESC LIMIT 1").store();
  ASSERT_EQ(last.num_rows(), 1u);
  EXPECT_NEAR(double(last[0][0]), room["loc"]["x"].get<double>(), 1e-6);
  EXPECT_NEAR(double(last[0][1]), room["loc"]["y"].get<double>(), 1e-6);
  // A type: the corridor node nearest the robot, beside node 1 (found here by distance).
  int nearest = -1;
  double best = 1e9;
  for (const json& n : nodes) {
    const double d = std::hypot(n["loc"]["x"].get<double>() - kStart.x, n["loc"]["y"].get<double>() - kStart.y);
    if (n["id"] != 100 && d < best) best = d, nearest = n["id"].get<int>();
  }
  r = run("fleetmap", goal + "corridor");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("goal node " + std::to_string(nearest) + " "), std::string::npos) << r.out;
  // No such node, or one on a wall: refused, exit 3, no task; the API's message.
  before = tasks();
  r = run("fleetmap", goal + "nowhere");
  EXPECT_EQ(r.exit_code, 3) << r.out << r.err;
  EXPECT_NE(r.err.find("no node named 'nowhere' and none of that type in the topological graph of map 'tp_gdc1'"),
            std::string::npos) << r.err;
  r = run("fleetmap", goal + "sealed");
  EXPECT_EQ(r.exit_code, 3) << r.out << r.err;
  EXPECT_NE(r.err.find("refused"), std::string::npos) << r.err;
  EXPECT_EQ(tasks(), before);
  // Exactly one kind of goal.
  EXPECT_EQ(run("fleetmap", goal + "corridor --near dock").exit_code, 64);
  EXPECT_EQ(run("fleetmap", "goal " + std::string(kRobot) + " 1 2 --node corridor").exit_code, 64);
  EXPECT_EQ(tasks(), before);
}

TEST_F(TopoPath, GoalByNodeOnAMapWithoutAGraphIsNotFound) {
  ensure_example_map("tp_plain");
  add_robot("tp_r2", "tp_plain");
  const RunResult r = run("fleetmap", "goal tp_r2 --node corridor");
  EXPECT_EQ(r.exit_code, 4) << r.out << r.err;
  EXPECT_NE(r.err.find("has no topological graph"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace fleetmap::test
