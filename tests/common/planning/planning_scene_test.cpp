// common/planning/planning_scene.*: objects and avoided areas as planning obstacles
// (seed 002 section 3.3).
// A table whose top is above a short robot's body and below a tall one's, scenes made by
// hand; then avoided areas never entered, on the example room and on random scenes, 200
// start/goal pairs each, every path checked by the independent judge of
// scene_planning_test_util.h (not the planner's own checker).
#include <gtest/gtest.h>

#include <numbers>
#include <random>

#include "common/planning/map_planner.h"
#include "common/planning/planning_scene.h"
#include "scene_planning_test_util.h"

namespace fleetmap {
namespace {

using planning_test::SceneJudge;

Polygon rect(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

PlannerOptions deterministic(double radius, uint64_t seed = 1) {
  PlannerOptions o;
  o.radius = radius;
  o.seed = seed;
  o.rrt.max_time = 0;
  o.rrt.max_iterations = 5000;
  return o;
}

Map open_map(double w, double h) {
  Map m;
  m.border = Border::from_rect({0, 0, w, h});
  return m;
}

// A 2 m x 2 m table at x, y 4..6 with 0.1 m legs at its corners (0..0.72 m) and a top
// 0.72..0.76 m: a robot lower than 0.72 m drives under it between the legs.
Scene table_scene() {
  EnvObject table{"table-1", "table", {}, false};
  for (Point c : {Point{4, 4}, Point{5.9, 4}, Point{5.9, 5.9}, Point{4, 5.9}})
    table.elements.push_back({rect(c.x, c.y, c.x + 0.1, c.y + 0.1), HeightRange{0, 0.72}});
  table.elements.push_back({rect(4, 4, 6, 6), HeightRange{0.72, 0.76}});
  Scene s;
  s.objects.push_back(table);
  return s;
}

MapPlanner planner_for(const Map& m, const Scene& s, double body_height, const PlannerOptions& o) {
  return MapPlanner(m, planning_obstacles(m, s, body_height, o.robot), o);
}

TEST(PlanningScene, ShortRobotPassesUnderTheTableTop) {
  const Map m = open_map(10, 10);
  const Scene s = table_scene();
  const MapPlanner short_robot = planner_for(m, s, 0.5, deterministic(0.3));
  // Straight through, between the legs (0.9 m from each).
  const PlanResult r = short_robot.plan({1, 5}, {9, 5});
  ASSERT_EQ(r.status, PlanStatus::Found);
  EXPECT_EQ(r.path->size(), 2u);
  EXPECT_DOUBLE_EQ(r.length, 8);
  EXPECT_EQ(short_robot.plan({1, 5}, {5, 5}).status, PlanStatus::Found);  // a goal under the top
  // The legs block: a goal on a leg, or within the radius of one.
  const PlanResult on_leg = short_robot.plan({1, 5}, {4.05, 4.05});
  EXPECT_EQ(on_leg.status, PlanStatus::GoalBlocked);
  ASSERT_TRUE(on_leg.collision);
  EXPECT_EQ(on_leg.collision->kind, Collision::Kind::Area);
  EXPECT_EQ(short_robot.checker().obstacles().names.at(on_leg.collision->obstacle_id), "object:table:table-1");
  EXPECT_EQ(short_robot.plan({1, 5}, {4.3, 4.1}).status, PlanStatus::GoalBlocked);  // 0.2 m from a leg
  EXPECT_EQ(SceneJudge(m, s, 0.5, 0.3).check_path(*r.path), "");
}

TEST(PlanningScene, TallRobotGoesRoundTheTable) {
  const Map m = open_map(10, 10);
  const Scene s = table_scene();
  const MapPlanner tall_robot = planner_for(m, s, 1.0, deterministic(0.3));
  const PlanResult r = tall_robot.plan({1, 5}, {9, 5});
  ASSERT_EQ(r.status, PlanStatus::Found);
  EXPECT_GT(r.length, 8.5);  // round the top
  EXPECT_EQ(SceneJudge(m, s, 1.0, 0.3).check_path(*r.path), "");
  // Deep under the top, far from its edges: blocked, not only near the outline.
  EXPECT_EQ(tall_robot.plan({1, 5}, {5, 5}).status, PlanStatus::GoalBlocked);
  EXPECT_EQ(tall_robot.plan({5, 5}, {1, 5}).status, PlanStatus::StartBlocked);
}

TEST(PlanningScene, BodyHeightAtTheTopPassesUnderIt) {
  // Element::blocks_body: the range must start below the body's top; 0.72 m fits under 0.72.
  const Map m = open_map(10, 10);
  EXPECT_EQ(planner_for(m, table_scene(), 0.72, deterministic(0.3)).plan({1, 5}, {5, 5}).status, PlanStatus::Found);
  EXPECT_EQ(planner_for(m, table_scene(), 0.7201, deterministic(0.3)).plan({1, 5}, {5, 5}).status,
            PlanStatus::GoalBlocked);
}

TEST(PlanningScene, AvoidedAreasBlockEveryRobotInsideAndAlongTheEdge) {
  const Map m = open_map(20, 10);
  Scene s;
  s.avoided.push_back({"zone", rect(5, -1, 15, 8)});  // leaves a 2 m gap at y 8..10
  // 2D objects block every body; an object high above does not block a 1 m robot.
  s.objects.push_back({"lamp-1", "lamp", {{rect(9, 8.5, 11, 9.5), HeightRange{2, 3}}}, false});
  for (double body : {0.1, 1.0, 5.0}) {
    const MapPlanner p = planner_for(m, s, body, deterministic(0.3));
    const PlanResult deep = p.plan({10, 3}, {1, 1});  // 2 m inside: far from any edge
    EXPECT_EQ(deep.status, PlanStatus::StartBlocked);
    ASSERT_TRUE(deep.collision);
    EXPECT_EQ(deep.collision->kind, Collision::Kind::Area);
    EXPECT_EQ(p.checker().obstacles().names.at(deep.collision->obstacle_id), "avoid:zone");
    EXPECT_EQ(p.plan({1, 1}, {10, 3}).status, PlanStatus::GoalBlocked);
    const PlanResult round = p.plan({1, 1}, {19, 1});
    if (body < 2) {  // over the gap at y 8..10, above the lamp's range
      ASSERT_EQ(round.status, PlanStatus::Found) << body;
      EXPECT_EQ(SceneJudge(m, s, body, 0.3).check_path(*round.path), "") << body;
    } else {
      EXPECT_EQ(round.status, PlanStatus::NoPath) << body;  // the lamp closes the gap for a 5 m body
    }
  }
}

TEST(PlanningScene, RefusesMalformedFootprintsAndHeights) {
  const Map m = open_map(10, 10);
  Scene s;
  s.objects.push_back({"bad-1", "box", {{{{1, 1}, {2, 2}, {1, 2}, {2, 1}}, std::nullopt}}, false});  // a bow tie
  try {
    planning_obstacles(m, s, 1, {});
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("object:box:bad-1: expected a simple ring"), std::string::npos) << e.what();
  }
  EXPECT_THROW(planning_obstacles(m, {}, -1, {}), std::invalid_argument);
  EXPECT_THROW(planning_obstacles(m, {}, std::nan(""), {}), std::invalid_argument);
}

TEST(PlanningScene, SceneIdsFollowTheMapsAndWallsStillBlock) {
  const Map& m = planning_test::example_room_map();
  const Scene& s = planning_test::example_room_scene();
  const PlanningObstacles o = planning_obstacles(m, s, 0.5, {});
  int largest = 0;
  for (const Obstacle& ob : m.obstacles) largest = std::max(largest, ob.id);
  ASSERT_FALSE(o.names.empty());
  EXPECT_EQ(o.names.begin()->first, largest + 1);
  EXPECT_EQ(o.names.size(), o.areas.size());  // the example map has no stairs
  EXPECT_GT(o.segments.size(), prepare_planning_obstacles(m, {}).segments.size());
}

// Random starts and goals the judge calls clear; every path found is checked by the
// judge; returns how many were found.
size_t plan_and_judge(const Map& m, const Scene& s, double body, double radius, Rect where, size_t pairs,
                      std::mt19937_64& rng, uint64_t seed) {
  const SceneJudge judge(m, s, body, radius);
  const MapPlanner planner = planner_for(m, s, body, deterministic(radius, seed));
  std::uniform_real_distribution<double> ux(where.xmin, where.xmax), uy(where.ymin, where.ymax);
  size_t found = 0;
  for (size_t k = 0; k < pairs;) {
    const Point a{ux(rng), uy(rng)}, b{ux(rng), uy(rng)};
    if (!judge.comfortably_clear(a) || !judge.comfortably_clear(b)) continue;
    ++k;
    const PlanResult r = planner.plan(a, b);
    EXPECT_NE(r.status, PlanStatus::StartBlocked) << a.x << " " << a.y;
    EXPECT_NE(r.status, PlanStatus::GoalBlocked) << b.x << " " << b.y;
    if (!r.path) continue;
    ++found;
    EXPECT_EQ(r.path->front(), a);
    EXPECT_EQ(r.path->back(), b);
    EXPECT_EQ(judge.check_path(*r.path), "") << "(" << a.x << ", " << a.y << ") -> (" << b.x << ", " << b.y << ")";
    EXPECT_EQ(judge.check_path(r.raw), "") << "raw path";
  }
  return found;
}

// The judge is no rubber stamp: paths planned without the scene cross the keep-out zone
// and the tables, and it says so.
TEST(PlanningScene, JudgeCatchesPathsPlannedWithoutTheScene) {
  const Map& m = planning_test::example_room_map();
  const SceneJudge judge(m, planning_test::example_room_scene(), 0.5, 0.25);
  EXPECT_EQ(judge.check_motion({1, 10.5}, {5, 10.5}), "crosses avoided area 9");  // through keepout-1
  EXPECT_NE(judge.check_motion({6, 7.08}, {9, 7.08}), "");  // through the big table's legs
  EXPECT_EQ(judge.check_motion({6, 7.5}, {9, 7.5}), "");    // under its top, between the legs
  const PlanResult r = MapPlanner(m, deterministic(0.25)).plan({1, 10.5}, {5, 10.5});
  ASSERT_TRUE(r.path);
  EXPECT_NE(judge.check_path(*r.path), "");
}

TEST(PlanningScene, AvoidedAreasNeverEnteredInTheExampleRoom) {
  std::mt19937_64 rng(801);
  const size_t found = plan_and_judge(planning_test::example_room_map(), planning_test::example_room_scene(), 0.5,
                                      0.25, {0, 0, 15, 15}, 200, rng, 81);
  // The room is one space for a 0.25 m robot, except pockets such as between a
  // shelf's side panels.
  EXPECT_GE(found, 195u);  // 200 found
}

// A scene of random rectangles and star-shaped polygons: 2D, 2.5D and 3D objects with
// random ranges, and avoided areas, one of them a large turned square.
Scene random_scene(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0, 1);
  auto shape = [&](Point c, double size) {
    if (u(rng) < 0.5) {
      const double angle = 2 * std::numbers::pi * u(rng), h = size * (0.3 + u(rng)), w = size * (0.3 + u(rng));
      return rectangle_footprint(c, w, h, angle);
    }
    Polygon star;  // vertices at increasing angles round c: always simple
    const int n = 3 + static_cast<int>(u(rng) * 6);
    for (int i = 0; i < n; ++i) {
      const double t = 2 * std::numbers::pi * (i + 0.8 * u(rng)) / n, r = size * (0.2 + 0.8 * u(rng));
      star.push_back({c.x + r * std::cos(t), c.y + r * std::sin(t)});
    }
    return star;
  };
  auto centre = [&] { return Point{1 + 18 * u(rng), 1 + 18 * u(rng)}; };
  // Every draw in its own statement, last argument first: argument evaluation order is
  // unspecified (g++ goes right to left, clang++ left to right), and both compilers must
  // build the same scenes.
  Scene s;
  for (int i = 0; i < 10; ++i) {
    EnvObject o{"o-" + std::to_string(i), "thing", {}, false};
    const Point c = centre();
    const int parts = 1 + static_cast<int>(u(rng) * 3);
    for (int k = 0; k < parts; ++k) {
      const double size = 0.3 + 1.2 * u(rng);
      const Point at{c.x + u(rng) - 0.5, c.y + u(rng) - 0.5};
      Element e{shape(at, size), std::nullopt};
      if (u(rng) < 0.8) {
        const double zmin = 1.5 * u(rng);
        e.z = HeightRange{zmin, zmin + 0.05 + u(rng)};
      }
      o.elements.push_back(std::move(e));
    }
    s.objects.push_back(std::move(o));
  }
  const double angle = u(rng), h = 4 + 3 * u(rng), w = 4 + 3 * u(rng);
  const Point big = centre();
  s.avoided.push_back({"big", rectangle_footprint(big, w, h, angle)});
  for (int i = 0; i < 3; ++i) {
    const double size = 0.5 + 1.5 * u(rng);
    const Point c = centre();
    s.avoided.push_back({"a-" + std::to_string(i), shape(c, size)});
  }
  return s;
}

TEST(PlanningScene, AvoidedAreasNeverEnteredInRandomScenes) {
  std::mt19937_64 rng(802);
  std::uniform_real_distribution<double> u(0, 1);
  Map m = open_map(20, 20);
  // One wall with a gap, so that some paths must find a way round.
  Obstacle wall{1, ShapeType::OpenPolygon, "wall", {}, {}};
  wall.segments.push_back({{10, 0}, {10, 8}, 2, 0, "wall", ""});
  wall.segments.push_back({{10, 10}, {10, 20}, 2, 0, "wall", ""});
  m.obstacles.push_back(wall);
  size_t found = 0, inside = 0;
  for (int scene = 0; scene < 20; ++scene) {
    const Scene s = random_scene(rng);
    const double body = 0.3 + 1.2 * u(rng), radius = 0.1 + 0.3 * u(rng);
    found += plan_and_judge(m, s, body, radius, {0, 0, 20, 20}, 10, rng, 900 + scene);
    // Any point inside an avoided area, however deep, is refused as start and goal.
    const MapPlanner p = planner_for(m, s, body, deterministic(radius));
    const Rect b = polygon_bounds(s.avoided[0].area);
    std::uniform_real_distribution<double> ux(b.xmin, b.xmax), uy(b.ymin, b.ymax);
    for (int k = 0; k < 20; ++k) {
      const Point q{ux(rng), uy(rng)};
      if (!point_in_polygon(q, s.avoided[0].area)) continue;
      ++inside;
      EXPECT_EQ(p.plan(q, {0.5, 0.5}).status, PlanStatus::StartBlocked);
      EXPECT_EQ(p.plan({0.5, 0.5}, q).status, PlanStatus::GoalBlocked);
    }
  }
  EXPECT_GE(found, 180u) << "of 200 pairs";  // random scenes may cut the room in parts (198 found)
  EXPECT_GE(inside, 100u);
}

}  // namespace
}  // namespace fleetmap
