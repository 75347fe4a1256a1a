// GetPath (SPEC 5.2, 7): a path from the last pose to the open task's goal around the
// map's obstacles, for the robot's profile; the task becomes active.
#include <algorithm>
#include <cmath>
#include <memory>

#include <gtest/gtest.h>

#include "tests/server/daemon/fake_stores.h"

namespace fleetmap::fakes {
namespace {

struct GetPathTest : ::testing::Test {
  Bench b;
  void SetUp() override {
    b.robot().x = 5;
    b.robot().y = 2;
    b.served.open_task = task(3, 7, TaskState::Acknowledged, 15, 2);  // behind the wall
  }
};

// The length of the polyline, and whether it passes the wall (x = 10, y < 6) only above it.
double length(const Json& waypoints) {
  double l = 0;
  for (size_t i = 1; i < waypoints.size(); ++i)
    l += std::hypot(waypoints[i][0].get<double>() - waypoints[i - 1][0].get<double>(),
                    waypoints[i][1].get<double>() - waypoints[i - 1][1].get<double>());
  return l;
}

TEST_F(GetPathTest, PlansAroundTheWallFromThePoseToTheGoalAndTheTaskIsActive) {
  const RequestWrites w = b.send("GetPath", "{}");
  ASSERT_EQ(w.answers.size(), 1u) << w.answers[0].params.dump();
  ASSERT_EQ(w.answers[0].op, AnswerOp::SetPath) << w.answers[0].params.dump();
  const Json& pts = w.answers[0].params["waypoints"];
  ASSERT_GE(pts.size(), 3u);  // not the straight line through the wall
  EXPECT_EQ(pts.front(), Json::parse("[5, 2]"));
  EXPECT_EQ(pts.back(), Json::parse("[15, 2]"));
  // Around the wall's end at y = 6, so at least twice the climb from y = 2 to 6.
  EXPECT_GT(length(pts), 2 * std::hypot(5, 4) - 0.01);
  EXPECT_NEAR(w.answers[0].params["length"].get<double>(), length(pts), 1e-6);
  ASSERT_EQ(b.records.task_states.size(), 1u);
  EXPECT_EQ(b.records.task_states[0], std::make_pair(3ull, TaskState::Active));
}

TEST_F(GetPathTest, PlansForTheRobotsProfileElseTheServersDefaults) {
  b.send("GetPath", "{}");
  b.robot().radius = 0.6;
  b.robot().body_height = 0.5;
  b.robot().can_stairs = true;
  b.send("GetPath", "{}");
  ASSERT_EQ(b.maps.profiles.size(), 2u);
  EXPECT_EQ(b.maps.profiles[0].radius, b.config.robot_radius_m);
  EXPECT_EQ(b.maps.profiles[0].body_height, b.config.body_height_m);
  EXPECT_FALSE(b.maps.profiles[0].can_climb_stairs);
  EXPECT_EQ(b.maps.profiles[1].radius, 0.6);
  EXPECT_EQ(b.maps.profiles[1].body_height, 0.5);
  EXPECT_TRUE(b.maps.profiles[1].can_climb_stairs);
}

TEST_F(GetPathTest, AnActiveTaskStaysActive) {
  b.served.open_task->state = TaskState::Active;
  EXPECT_EQ(b.send("GetPath", "{}").answers.at(0).op, AnswerOp::SetPath);
  EXPECT_TRUE(b.records.task_states.empty());
}

TEST_F(GetPathTest, WithoutATaskNoGoalWithoutAPoseNoPose) {
  b.served.open_task.reset();
  EXPECT_EQ(error_code(b.send("GetPath", "{}")), "no_goal");
  b.served.open_task = task(3, 7, TaskState::Assigned, 15, 2);
  b.robot().x.reset();
  EXPECT_EQ(error_code(b.send("GetPath", "{}")), "no_pose");
  EXPECT_TRUE(b.records.task_states.empty());
}

TEST_F(GetPathTest, AGoalInsideTheWallIsNoPathAndTheTaskFailsWithTheReason) {
  b.served.open_task->goal_x = 10;
  b.served.open_task->goal_y = 3;
  const RequestWrites w = b.send("GetPath", "{}");
  ASSERT_EQ(error_code(w), "no_path");
  const std::string message = w.answers[0].params["message"].get<std::string>();
  EXPECT_NE(message.find("the goal"), std::string::npos) << message;
  // Answered, not refused: the task's failure is a direct write the batch must keep.
  EXPECT_FALSE(w.refused);
  ASSERT_EQ(b.records.task_states.size(), 1u);
  EXPECT_EQ(b.records.task_states[0], std::make_pair(3ull, TaskState::Failed));
  EXPECT_EQ(b.records.task_reasons.at(3), message);
  EXPECT_FALSE(b.served.open_task);  // failed is final: the robot has no open task now
  EXPECT_EQ(error_code(b.send("GetPath", "{}")), "no_goal");
}

TEST_F(GetPathTest, AMapThePlannerCannotTakeIsNoPlanner) {
  b.maps.planner_refuses = true;
  const RequestWrites w = b.send("GetPath", "{}");
  ASSERT_EQ(error_code(w), "no_planner");
  EXPECT_NE(w.answers[0].params["message"].get<std::string>().find("obstacle 7"), std::string::npos);
}

// A graph over the room: west (5, 8) and east (15, 8), one edge above the wall's end
// (stored east to west). The robot at (5, 2) sees west, not east (the wall is in the way);
// the goal (15, 2) sees east.
std::shared_ptr<const TopoGraph> room_graph(EdgeType type = EdgeType::Door) {
  auto g = std::make_shared<TopoGraph>();
  g->add_node({10, {5, 8}, "west"});
  g->add_node({12, {15, 8}, "east"});
  g->add_edge({.a = 12, .b = 10, .type = type});
  return g;
}

// Distance from p to the wall's box (9.9..10.1 x 0..6), written here, not the planner's.
double to_wall(double x, double y) {
  const double dx = std::max({9.9 - x, 0.0, x - 10.1}), dy = std::max({0.0 - y, 0.0, y - 6.0});
  return std::hypot(dx, dy);
}

// Every point of the polyline, sampled every centimetre, keeps the radius from the wall.
double clearance(const Json& pts) {
  double d = 1e9;
  for (size_t i = 1; i < pts.size(); ++i) {
    const double x0 = pts[i - 1][0].get<double>(), y0 = pts[i - 1][1].get<double>();
    const double x1 = pts[i][0].get<double>(), y1 = pts[i][1].get<double>();
    const int n = 1 + static_cast<int>(std::hypot(x1 - x0, y1 - y0) / 0.01);
    for (int k = 0; k <= n; ++k) d = std::min(d, to_wall(x0 + (x1 - x0) * k / n, y0 + (y1 - y0) * k / n));
  }
  return d;
}

TEST_F(GetPathTest, FarEnoughAndWithAGraphTheAnswerCarriesTheRoute) {
  b.maps.graphs[1] = room_graph();
  b.config.topo_path_min_m = 5;  // the trip is 10 m
  const RequestWrites w = b.send("GetPath", "{}");
  ASSERT_EQ(w.answers.size(), 1u);
  ASSERT_EQ(w.answers[0].op, AnswerOp::SetPath) << w.answers[0].params.dump();
  const Json& p = w.answers[0].params;
  EXPECT_EQ(p["nodes"], Json::parse(R"([{"id": 10, "name": "west", "x": 5, "y": 8},
                                          {"id": 12, "name": "east", "x": 15, "y": 8}])"));
  // In travel order, though the edge is stored the other way round.
  EXPECT_EQ(p["edges"], Json::parse(R"([{"from": 10, "to": 12, "type": "door"}])"));
  EXPECT_EQ(p["waypoints"].front(), Json::parse("[5, 2]"));
  EXPECT_EQ(p["waypoints"].back(), Json::parse("[15, 2]"));
  EXPECT_GT(clearance(p["waypoints"]), b.config.robot_radius_m - 0.005);
  EXPECT_NEAR(p["length"].get<double>(), length(p["waypoints"]), 1e-6);
  ASSERT_EQ(b.records.task_states.size(), 1u);
  EXPECT_EQ(b.records.task_states[0], std::make_pair(3ull, TaskState::Active));
}

TEST_F(GetPathTest, ShortTripsNoGraphOrNoRouteArePlannedOnTheWholeMap) {
  b.maps.graphs[1] = room_graph();
  // The default rule: 10 m is too short for the graph.
  Json p = b.send("GetPath", "{}").answers.at(0).params;
  EXPECT_FALSE(p.contains("nodes")) << p.dump();
  EXPECT_FALSE(p.contains("edges"));
  // Far enough, but the graph's only edge is stairs and this robot is wheeled: whole-map RRT.
  b.maps.graphs[1] = room_graph(EdgeType::Stairs);
  b.config.topo_path_min_m = 0;
  const RequestWrites w = b.send("GetPath", "{}");
  ASSERT_EQ(w.answers.at(0).op, AnswerOp::SetPath);
  p = w.answers[0].params;
  EXPECT_FALSE(p.contains("nodes")) << p.dump();
  EXPECT_GT(clearance(p["waypoints"]), b.config.robot_radius_m - 0.005);
  // A map without a graph.
  b.maps.graphs.clear();
  EXPECT_FALSE(b.send("GetPath", "{}").answers.at(0).params.contains("nodes"));
}

TEST_F(GetPathTest, MalformedParamsGetBadJson) {
  EXPECT_EQ(error_code(b.send("GetPath", "[]")), "bad_json");
  EXPECT_TRUE(b.records.task_states.empty());
}

}  // namespace
}  // namespace fleetmap::fakes
