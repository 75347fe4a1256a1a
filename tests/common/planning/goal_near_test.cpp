// common/planning/goal_near.*: goals by meaning. The goal is outside the object, within
// radius + margin of it (and no nearer than the radius), clear for the robot by the
// independent judge of scene_planning_test_util.h, and reached by the path returned; the
// side facing the robot wins; walled-in and unreachable objects are told apart.
#include <gtest/gtest.h>

#include <algorithm>

#include "common/planning/goal_near.h"
#include "common/planning/planning_scene.h"
#include "scene_planning_test_util.h"

namespace fleetmap {
namespace {

using planning_test::SceneJudge;

Polygon rect(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

PlannerOptions deterministic(double radius) {
  PlannerOptions o;
  o.radius = radius;
  o.rrt.max_time = 0;
  o.rrt.max_iterations = 3000;
  return o;
}

Map open_map(double w, double h) {
  Map m;
  m.border = Border::from_rect({0, 0, w, h});
  return m;
}

double distance_to(Point p, const std::vector<Polygon>& footprints) {
  double d = 1e300;
  for (const Polygon& f : footprints) d = std::min(d, distance_to_polygon(p, f));
  return d;
}

std::vector<Polygon> footprints_of(const Scene& s, const std::string& id) {
  for (const EnvObject& o : s.objects)
    if (o.id == id) {
      std::vector<Polygon> out;
      for (const Element& e : o.elements) out.push_back(e.footprint);
      return out;
    }
  ADD_FAILURE() << "no object " << id;
  return {};
}

// What every found goal must satisfy.
void expect_good_goal(const GoalNear& g, const std::vector<Polygon>& footprints, const SceneJudge& judge, Point from,
                      double margin) {
  ASSERT_EQ(g.status, GoalNearStatus::Found) << to_string(g.status);
  const double d = distance_to(g.goal, footprints);
  EXPECT_GT(d, 0) << "inside the object";
  EXPECT_LE(d, judge.radius + margin + 1e-9);
  EXPECT_GE(d, judge.radius + margin - 1e-6);
  EXPECT_TRUE(judge.comfortably_clear(g.goal, 0)) << g.goal.x << " " << g.goal.y;
  ASSERT_TRUE(g.plan.path);
  EXPECT_EQ(g.plan.path->front(), from);
  EXPECT_EQ(g.plan.path->back(), g.goal);
  EXPECT_EQ(judge.check_path(*g.plan.path), "");
  EXPECT_GE(g.free, 1u);
  EXPECT_LE(g.free, g.candidates);
  EXPECT_GE(g.planned, 1u);
}

TEST(GoalNear, PointsBesideAreAtTheOffsetAllRound) {
  const std::vector<Polygon> box{rect(2, 2, 3, 4)};
  const std::vector<Point> pts = points_beside(box, 0.5, 0.05);
  // Perimeter 6 m plus a half-metre circle: about 9.1 m at 5 cm.
  EXPECT_GE(pts.size(), 150u);
  for (Point p : pts) EXPECT_NEAR(distance_to(p, box), 0.5, 1e-9);
  // All four sides and corners are there.
  EXPECT_TRUE(std::any_of(pts.begin(), pts.end(), [](Point p) { return p.x < 1.6 && p.y > 2 && p.y < 4; }));
  EXPECT_TRUE(std::any_of(pts.begin(), pts.end(), [](Point p) { return p.x > 3.4 && p.y > 2 && p.y < 4; }));
  EXPECT_TRUE(std::any_of(pts.begin(), pts.end(), [](Point p) { return p.y > 4.4 && p.x > 2 && p.x < 3; }));
  EXPECT_TRUE(std::any_of(pts.begin(), pts.end(), [](Point p) { return p.x > 3.2 && p.y > 4.2; }));  // NE arc
  // Clockwise rings and several parts: never nearer than the offset to any part.
  std::vector<Polygon> parts{rect(0, 0, 1, 1), rect(1.2, 0, 2, 1)};
  std::reverse(parts[1].begin(), parts[1].end());
  for (Point p : points_beside(parts, 0.3, 0.05)) EXPECT_NEAR(distance_to(p, parts), 0.3, 1e-9);
  // An L shape (a reflex corner).
  const std::vector<Polygon> ell{{{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 3}, {0, 3}}};
  const std::vector<Point> lp = points_beside(ell, 0.2, 0.05);
  for (Point p : lp) EXPECT_NEAR(distance_to(p, ell), 0.2, 1e-9);
  EXPECT_TRUE(std::any_of(lp.begin(), lp.end(), [](Point p) { return distance(p, {1.2, 1.2}) < 0.06; }));
  EXPECT_THROW(points_beside({}, 0.3, 0.1), std::invalid_argument);
  EXPECT_THROW(points_beside(box, 0, 0.1), std::invalid_argument);
}

TEST(GoalNear, ChargingStationInTheExampleRoom) {
  const Map& m = planning_test::example_room_map();
  const Scene& s = planning_test::example_room_scene();
  const PlannerOptions o = deterministic(0.3);
  const MapPlanner planner(m, planning_obstacles(m, s, 0.5, o.robot), o);
  const SceneJudge judge(m, s, 0.5, 0.3);
  const std::vector<Polygon> station = footprints_of(s, "charger-1");  // x 14.7..15 against the east wall
  for (Point from : {Point{7.5, 3}, Point{3, 13}, Point{13, 6}}) {
    SCOPED_TRACE(::testing::Message() << "from " << from.x << " " << from.y);
    const GoalNear g = choose_goal_beside(planner, station, from);
    expect_good_goal(g, station, judge, from, 0.1);
    // West of the station's east face: the wall is right behind it.
    EXPECT_LE(g.goal.x, 15 - 0.3);
  }
}

TEST(GoalNear, TheSideFacingTheRobotWins) {
  const Map m = open_map(20, 20);
  Scene s;
  s.objects.push_back({"box-1", "box", {{rect(9, 9, 11, 11), HeightRange{0, 0.5}}}, false});
  const PlannerOptions o = deterministic(0.3);
  const MapPlanner planner(m, planning_obstacles(m, s, 1, o.robot), o);
  const SceneJudge judge(m, s, 1, 0.3);
  const std::vector<Polygon> box = footprints_of(s, "box-1");
  struct Case {
    Point from;
    bool (*side)(Point);
  };
  const Case cases[] = {{{2, 10}, [](Point p) { return p.x < 9; }},
                        {{18, 10}, [](Point p) { return p.x > 11; }},
                        {{10, 2}, [](Point p) { return p.y < 9; }},
                        {{10, 18}, [](Point p) { return p.y > 11; }}};
  for (const Case& c : cases) {
    const GoalNear g = choose_goal_beside(planner, box, c.from);
    expect_good_goal(g, box, judge, c.from, 0.1);
    EXPECT_TRUE(c.side(g.goal)) << g.goal.x << " " << g.goal.y;
    // In the open, the shortest way is the straight line to the nearest spot (7 m less
    // the 0.4 m offset), up to the spacing of the candidates.
    EXPECT_NEAR(g.plan.length, 7 - 0.4, 0.1);
    EXPECT_LT(g.planned, g.free) << "the search should stop early";
  }
}

TEST(GoalNear, AnObjectUnderAnAvoidedAreaHasNoFreeSpot) {
  const Map m = open_map(20, 20);
  Scene s;
  s.objects.push_back({"box-1", "box", {{rect(9, 9, 10, 10), std::nullopt}}, false});
  s.avoided.push_back({"zone", rect(8, 8, 11, 11)});
  const PlannerOptions o = deterministic(0.3);
  const MapPlanner planner(m, planning_obstacles(m, s, 1, o.robot), o);
  const GoalNear g = choose_goal_beside(planner, footprints_of(s, "box-1"), {2, 2});
  EXPECT_EQ(g.status, GoalNearStatus::NoFreeSpot);
  EXPECT_GT(g.candidates, 0u);
  EXPECT_EQ(g.free, 0u);
  EXPECT_EQ(g.planned, 0u);
}

TEST(GoalNear, AnObjectInAClosedRoomHasNoPath) {
  Map m = open_map(20, 20);
  Obstacle room{1, ShapeType::ClosedPolygon, "room", {}, {}};
  const Polygon r = rect(12, 12, 18, 18);
  for (size_t i = 0; i < r.size(); ++i) room.segments.push_back({r[i], r[(i + 1) % r.size()], 2, 0, "wall", ""});
  m.obstacles.push_back(room);
  Scene s;
  s.objects.push_back({"box-1", "box", {{rect(14, 14, 15, 15), HeightRange{0, 1}}}, false});
  PlannerOptions o = deterministic(0.3);
  o.rrt.max_iterations = 500;
  const MapPlanner planner(m, planning_obstacles(m, s, 1, o.robot), o);
  GoalNearOptions go;
  go.max_plans = 5;
  const GoalNear g = choose_goal_beside(planner, footprints_of(s, "box-1"), {2, 2}, go);
  EXPECT_EQ(g.status, GoalNearStatus::NoPath);
  EXPECT_GT(g.free, 5u);
  EXPECT_EQ(g.planned, 5u);
  EXPECT_EQ(g.plan.status, PlanStatus::NoPath);
}

TEST(GoalNear, ABlockedStartIsReported) {
  const Map m = open_map(20, 20);
  Scene s;
  s.objects.push_back({"box-1", "box", {{rect(9, 9, 10, 10), std::nullopt}}, false});
  const PlannerOptions o = deterministic(0.3);
  const MapPlanner planner(m, planning_obstacles(m, s, 1, o.robot), o);
  const GoalNear g = choose_goal_beside(planner, footprints_of(s, "box-1"), {9.5, 9.5});
  EXPECT_EQ(g.status, GoalNearStatus::StartBlocked);
  ASSERT_TRUE(g.plan.collision);
  EXPECT_EQ(g.plan.collision->kind, Collision::Kind::Area);
  GoalNearOptions bad;
  bad.margin = 0;
  EXPECT_THROW(choose_goal_beside(planner, footprints_of(s, "box-1"), {2, 2}, bad), std::invalid_argument);
}

}  // namespace
}  // namespace fleetmap
