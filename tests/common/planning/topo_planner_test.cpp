// TopoPlanner (common/planning/topo_planner.h): the graph route respects the robot's edge
// rules (stairs), the route is a chain of the graph's edges, and the path is clear for
// the robot's radius, judged by brute force over every wall (planning_test_util.h), on
// a hand map and on the campus.
#include <gtest/gtest.h>

#include <optional>
#include <random>
#include <vector>

#include "common/io/topo_json.h"
#include "common/planning/topo_planner.h"
#include "planning_test_util.h"

namespace fleetmap {
namespace {

using planning_test::BruteClearance;

Obstacle block(int id, double x0, double y0, double x1, double y1) {
  Obstacle o{id, ShapeType::ClosedPolygon, "wall", {}, {}};
  const std::vector<Point> p{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
  for (size_t i = 0; i < 4; ++i) o.segments.push_back({p[i], p[(i + 1) % 4], 2, 0, "wall", ""});
  return o;
}

// A wall at x 12..19 across a 31 x 20 m room with two tunnels through it: y 1..3 (south)
// and y 17..19 (north). The graph reaches the south tunnel by stairs edges only. Neither
// tunnel's middle node is in sight of the trips' ends, (5, 8) and (26, 8), nor of the
// nodes beside it: the legs into the tunnels need RRT-Connect.
Map walled() {
  Map m;
  m.border = Border::from_rect({0, 0, 31, 20});
  m.obstacles.push_back(block(1, 12, 0, 19, 1));
  m.obstacles.push_back(block(2, 12, 3, 19, 17));
  m.obstacles.push_back(block(3, 12, 19, 19, 20));
  return m;
}

TopoGraph walled_graph() {
  TopoGraph g;
  g.add_node({0, {10, 5}, "west"});
  g.add_node({1, {15.5, 2}, "south tunnel"});
  g.add_node({2, {21, 5}, "east"});
  g.add_node({3, {10, 15}, ""});
  g.add_node({4, {15.5, 18}, "north tunnel"});
  g.add_node({5, {21, 15}, ""});
  g.add_edge({.a = 0, .b = 1, .type = EdgeType::Stairs});
  g.add_edge({.a = 1, .b = 2, .type = EdgeType::Stairs});
  g.add_edge({.a = 0, .b = 3, .type = EdgeType::Corridor});
  g.add_edge({.a = 3, .b = 4, .type = EdgeType::Door});
  g.add_edge({.a = 4, .b = 5, .type = EdgeType::Door});
  g.add_edge({.a = 5, .b = 2, .type = EdgeType::Corridor});
  return g;
}

PlannerOptions options(bool stairs) {
  PlannerOptions o;
  o.radius = 0.3;
  o.robot.can_climb_stairs = stairs;
  o.rrt.max_time = 0;  // deterministic
  o.rrt.max_iterations = 20000;
  return o;
}

// The route is a chain: edges[i] joins nodes[i] and nodes[i + 1].
void expect_chain(const TopoGraph& g, const TopoRoute& r) {
  ASSERT_EQ(r.edges.size() + 1, r.nodes.size());
  for (size_t i = 0; i < r.edges.size(); ++i) {
    const TopoEdge& e = g.edges().at(r.edges[i]);
    const bool joins = (e.a == r.nodes[i] && e.b == r.nodes[i + 1]) || (e.b == r.nodes[i] && e.a == r.nodes[i + 1]);
    EXPECT_TRUE(joins) << "edge " << r.edges[i] << " does not join " << r.nodes[i] << " and " << r.nodes[i + 1];
  }
}

void expect_clear_path(const Map& m, const TopoPlanResult& r, Point start, Point goal, double radius) {
  ASSERT_TRUE(r.path) << to_string(r.status);
  ASSERT_GE(r.path->size(), 2u);
  EXPECT_EQ(r.path->front(), start);
  EXPECT_EQ(r.path->back(), goal);
  EXPECT_GT(BruteClearance(m).path_clearance(*r.path), radius);
  EXPECT_NEAR(r.length, path_length(*r.path), 1e-9);
}

TEST(TopoPlanner, WheeledRobotAvoidsStairsEdges) {
  const Map m = walled();
  const TopoGraph g = walled_graph();
  const MapPlanner planner(m, options(false));
  const Point start{5, 8}, goal{26, 8};
  const TopoPlanResult r = TopoPlanner(planner, g).plan(start, goal);
  expect_clear_path(m, r, start, goal, 0.3);
  // From the nodes each end sees (0 and 3; 2 and 5), the shortest without stairs.
  EXPECT_EQ(r.route.nodes, (std::vector<int>{3, 4, 5}));
  EXPECT_GE(r.rrt_legs, 1u);
  expect_chain(g, r.route);
  for (size_t e : r.route.edges) EXPECT_NE(g.edges()[e].type, EdgeType::Stairs);
  // Through the north tunnel: the path climbs above y = 17 at the wall.
  double max_y = 0;
  for (Point p : *r.path) max_y = std::max(max_y, p.y);
  EXPECT_GT(max_y, 17);
}

TEST(TopoPlanner, ClimbingRobotTakesTheShorterStairsRoute) {
  const Map m = walled();
  const TopoGraph g = walled_graph();
  const MapPlanner planner(m, options(true));
  const Point start{5, 8}, goal{26, 8};
  const TopoPlanResult r = TopoPlanner(planner, g).plan(start, goal);
  expect_clear_path(m, r, start, goal, 0.3);
  EXPECT_EQ(r.route.nodes, (std::vector<int>{0, 1, 2}));
  expect_chain(g, r.route);
  for (Point p : *r.path) EXPECT_LT(p.y, 10);
}

TEST(TopoPlanner, StraightLineNeedsNoRoute) {
  const Map m = walled();
  const TopoGraph g = walled_graph();
  const MapPlanner planner(m, options(false));
  const TopoPlanResult r = TopoPlanner(planner, g).plan({2, 5}, {10, 12});
  ASSERT_TRUE(r.path);
  EXPECT_EQ(r.path->size(), 2u);
  EXPECT_TRUE(r.route.nodes.empty());
}

TEST(TopoPlanner, BlockedEndsAndNoRoute) {
  const Map m = walled();
  TopoGraph g = walled_graph();
  const MapPlanner planner(m, options(false));
  EXPECT_EQ(TopoPlanner(planner, g).plan({12.1, 10}, {26, 8}).status, PlanStatus::StartBlocked);
  EXPECT_EQ(TopoPlanner(planner, g).plan({5, 8}, {18.9, 10}).status, PlanStatus::GoalBlocked);
  // Without the north side, a wheeled robot has no route: NoPath (the caller falls back
  // to whole-map RRT), though the map itself has a way.
  TopoGraph south;
  for (int id : {0, 1, 2}) south.add_node(g.node(id));
  south.add_edge({.a = 0, .b = 1, .type = EdgeType::Stairs});
  south.add_edge({.a = 1, .b = 2, .type = EdgeType::Stairs});
  EXPECT_EQ(TopoPlanner(planner, south).plan({5, 8}, {26, 8}).status, PlanStatus::NoPath);
}

// The real campus and its navigation graph: long trips between points a few metres off
// two graph nodes (in sight of them, so a route surely exists), each path clear by brute
// force and each route a chain of usable edges.
TEST(TopoPlanner, LongCampusTripsAreClear) {
  const Map& m = planning_test::ut_campus();
  const TopoGraph g = read_topo_json_file(FLEETMAP_REAL_MAPS "/UT_Campus.navigation.json");
  const MapPlanner planner(m, options(false));
  const TopoPlanner tp(planner, g);
  const BruteClearance judge(m);
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<size_t> pick(0, g.nodes().size() - 1);
  std::uniform_real_distribution<double> off(-4, 4);
  auto near_node = [&](const TopoNode& n) -> std::optional<Point> {
    const Point p{n.pos.x + off(rng), n.pos.y + off(rng)};
    if (judge.clearance(n.pos, p) <= 0.5) return std::nullopt;
    return p;
  };
  int trips = 0;
  for (int tries = 0; trips < 3 && tries < 1000; ++tries) {
    const TopoNode &a = g.nodes()[pick(rng)], &b = g.nodes()[pick(rng)];
    if (!g.route(a.id, b.id, tp.route_options())) continue;  // the graph joins them without stairs
    const std::optional<Point> s = near_node(a), t = near_node(b);
    if (!s || !t || distance(*s, *t) < 150) continue;
    ++trips;
    const TopoPlanResult r = tp.plan(*s, *t);
    expect_clear_path(m, r, *s, *t, 0.3);
    expect_chain(g, r.route);
    EXPECT_FALSE(r.route.nodes.empty());
    for (size_t e : r.route.edges) EXPECT_TRUE(g.usable(e, tp.route_options()));
    EXPECT_GE(r.length, distance(*s, *t) - 1e-9);
  }
  EXPECT_EQ(trips, 3);
}

}  // namespace
}  // namespace fleetmap
