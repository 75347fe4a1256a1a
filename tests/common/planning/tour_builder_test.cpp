// Tour builder (common/planning/tour_builder.h, tour_placement.h): node placement of seed 003
// Fig. 2 on synthetic corridors and doorways, merging and edge types. Expected centres
// come from the synthetic geometry written here, not from the code.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "common/map/map.h"
#include "common/planning/tour_builder.h"
#include "common/planning/tour_placement.h"
#include "common/planning/tour_plan.h"
#include "common/raycast/seed_ray_caster.h"

namespace fleetmap {
namespace {

constexpr double kPi = std::numbers::pi;

Obstacle wall(int id, std::vector<Point> pts) {
  Obstacle o;
  o.id = id;
  o.type = ShapeType::OpenPolygon;
  for (size_t i = 0; i + 1 < pts.size(); ++i) o.segments.push_back({pts[i], pts[i + 1], 2.0, 0, "", ""});
  return o;
}

Map with_walls(std::vector<Obstacle> walls) {
  Map m;
  m.border = Border::from_rect({-50, -50, 50, 50});
  m.obstacles = std::move(walls);
  m.compute_bounds();
  return m;
}

// A corridor along x from -20 to 20, walls at y = -1 and y = 1.5 (centre line y = 0.25).
Map corridor() { return with_walls({wall(1, {{-20, -1}, {20, -1}}), wall(2, {{20, 1.5}, {-20, 1.5}})}); }

// A wall along y = 0 with a doorway from x = 2.0 to x = 2.9 (centre 2.45), walls drawn as
// single lines; a room above (y up to 5), a corridor below (down to y = -2).
Map doorway() {
  return with_walls({wall(1, {{-10, 0}, {2.0, 0}}), wall(2, {{2.9, 0}, {10, 0}}), wall(3, {{-10, 5}, {10, 5}}),
                     wall(4, {{-10, -2}, {10, -2}}), wall(5, {{-10, -2}, {-10, 5}}), wall(6, {{10, -2}, {10, 5}})});
}

SeedRayCaster caster(const Map& m) { return SeedRayCaster(m, {.laser_height = 0.3, .rmax = 8.0}); }

TEST(TourPlacement, CorridorNodeIsCentredBetweenTheWalls) {
  const Map m = corridor();
  const auto c = caster(m);
  // Off centre, heading along the corridor.
  Placement p = centre_in_corridor(c, {3.0, 1.0, 0.0});
  EXPECT_TRUE(p.measured);
  EXPECT_NEAR(p.pos.y, 0.25, 0.1);
  EXPECT_NEAR(p.pos.x, 3.0, 0.1);
  EXPECT_NEAR(p.width, 2.5, 0.05);
  // Near the other wall, heading 35° off the corridor's direction.
  p = centre_in_corridor(c, {-4.0, -0.7, 35 * kPi / 180});
  EXPECT_TRUE(p.measured);
  EXPECT_NEAR(p.pos.y, 0.25, 0.1);
  EXPECT_NEAR(p.width, 2.5, 0.05);
  // Heading backwards.
  p = centre_in_corridor(c, {0.0, 1.2, kPi});
  EXPECT_NEAR(p.pos.y, 0.25, 0.1);
}

TEST(TourPlacement, AngledCorridor) {
  // The same corridor turned by 30° about the origin: the centre line is the turned y = 0.25.
  const double a = 30 * kPi / 180, ca = std::cos(a), sa = std::sin(a);
  auto turn = [&](Point p) { return Point{ca * p.x - sa * p.y, sa * p.x + ca * p.y}; };
  const Map m = with_walls({wall(1, {turn({-20, -1}), turn({20, -1})}), wall(2, {turn({20, 1.5}), turn({-20, 1.5})})});
  const auto c = caster(m);
  const Point start = turn({5.0, -0.5});
  const Placement p = centre_in_corridor(c, {start.x, start.y, a + 0.2});
  ASSERT_TRUE(p.measured);
  // Back into the corridor's frame: y' is the offset from the walls.
  const double y_in_corridor = -sa * p.pos.x + ca * p.pos.y;
  EXPECT_NEAR(y_in_corridor, 0.25, 0.1);
}

TEST(TourPlacement, OpenSideFallsBackToThePose) {
  const Map m = with_walls({wall(1, {{-20, -1}, {20, -1}})});
  const Placement p = centre_in_corridor(caster(m), {1.0, 0.5, 0.0});
  EXPECT_FALSE(p.measured);
  EXPECT_EQ(p.pos, (Point{1.0, 0.5}));
}

TEST(TourPlacement, DoorNodeIsCentredBetweenThePosts) {
  const Map m = doorway();
  const auto c = caster(m);
  // Just below the doorway, off its centre, heading into the room.
  Placement p = centre_in_doorway(c, {2.2, -0.6, kPi / 2});
  ASSERT_TRUE(p.measured);
  EXPECT_NEAR(p.pos.x, 2.45, 0.1);
  EXPECT_NEAR(p.pos.y, 0.0, 0.1);
  EXPECT_NEAR(p.width, 0.9, 0.05);
  // Already through, in the room, heading a little askew.
  p = centre_in_doorway(c, {2.7, 0.5, kPi / 2 + 0.3});
  ASSERT_TRUE(p.measured);
  EXPECT_NEAR(p.pos.x, 2.45, 0.1);
  EXPECT_NEAR(p.pos.y, 0.0, 0.1);
  // Leaving the room, heading down.
  p = centre_in_doorway(c, {2.5, 0.8, -kPi / 2});
  EXPECT_NEAR(p.pos.x, 2.45, 0.1);
  EXPECT_NEAR(p.pos.y, 0.0, 0.1);
}

TEST(TourPlacement, ThickDoorPosts) {
  // Posts 0.2 m deep (closed rectangles), gap from x = -0.4 to x = 0.5 (centre 0.05).
  Obstacle left = wall(1, {{-6, 0}, {-0.4, 0}, {-0.4, 0.2}, {-6, 0.2}});
  Obstacle right = wall(2, {{0.5, 0}, {6, 0}, {6, 0.2}, {0.5, 0.2}});
  const Map m = with_walls({left, right, wall(3, {{-6, -3}, {6, -3}}), wall(4, {{-6, 4}, {6, 4}})});
  const Placement p = centre_in_doorway(caster(m), {0.3, -0.9, kPi / 2 - 0.2});
  ASSERT_TRUE(p.measured);
  EXPECT_NEAR(p.pos.x, 0.05, 0.1);
  EXPECT_NEAR(p.pos.y, 0.1, 0.15);
  EXPECT_NEAR(p.width, 0.9, 0.05);
}

TEST(TourPlacement, AWallAheadIsNoDoor) {
  // Facing a wall 0.8 m ahead in a 3 m wide dead end: a short chord along that wall is
  // no gap; the narrowest free one is the dead end's cross-section, centred at x = 0.
  const Map m = with_walls({wall(1, {{-1.5, -5}, {-1.5, 0.8}, {1.5, 0.8}, {1.5, -5}})});
  const Placement p = centre_in_doorway(caster(m), {0.4, 0.0, kPi / 2});
  ASSERT_TRUE(p.measured);
  EXPECT_NEAR(p.width, 3.0, 0.05);
  EXPECT_NEAR(p.pos.x, 0.0, 0.1);
  EXPECT_LT(p.pos.y, 0.7);
  // Nothing within reach at all: the pose.
  const Map open = with_walls({wall(1, {{-20, 30}, {20, 30}})});
  const Placement q = centre_in_doorway(caster(open), {0.4, 0.0, kPi / 2});
  EXPECT_FALSE(q.measured);
  EXPECT_EQ(q.pos, (Point{0.4, 0.0}));
}

TEST(TourPlacement, CrossingNodeIsCentredBetweenTheCorners) {
  // Corridors along x (walls y = ±1) and y (walls x = ±1) crossing at the origin, whose
  // corners (±1, ±1) are nearest the middle.
  const Map m = with_walls({wall(1, {{-10, 1}, {-1, 1}, {-1, 10}}), wall(2, {{1, 10}, {1, 1}, {10, 1}}),
                            wall(3, {{10, -1}, {1, -1}, {1, -10}}), wall(4, {{-1, -10}, {-1, -1}, {-10, -1}})});
  const Placement p = centre_in_crossing(caster(m), {0.5, -0.4, 0.3});
  ASSERT_TRUE(p.measured);
  EXPECT_NEAR(p.pos.x, 0.0, 0.1);
  EXPECT_NEAR(p.pos.y, 0.0, 0.1);
  EXPECT_NEAR(p.width, 2 * std::sqrt(2.0), 0.1);
}

TourEvent ev(TourEventKind k, double x, double y, double theta, std::string name = "") {
  return {k, {x, y, theta}, std::move(name), 0};
}

const TopoEdge* find_edge(const TopoGraph& g, int a, int b) {
  for (const TopoEdge& e : g.edges())
    if ((e.a == a && e.b == b) || (e.a == b && e.b == a)) return &e;
  return nullptr;
}

TEST(TourBuilder, CorridorDoorRoomTour) {
  // Corridor below the doorway of doorway() (y from -2 to 0, centre line y = -1), the room above.
  const Map m = doorway();
  const std::vector<TourEvent> events = {
      ev(TourEventKind::Place, -8, -1.5, 0, "dock"),          // 0: at the pose, named
      ev(TourEventKind::EnterCorridor, -5, -0.4, 0),          // 1: centred, y = -1
      ev(TourEventKind::Door, 2.3, -0.5, kPi / 2),            // 2: between the posts (2.45, 0)
      ev(TourEventKind::EnterRoom, 2.5, 1.5, kPi / 2),        // 3: at the pose
      ev(TourEventKind::Place, 6, 3, 0, "desk"),              // 4
  };
  const TourGraph t = build_tour_graph(m, events);
  const TopoGraph& g = t.graph;
  ASSERT_EQ(g.nodes().size(), 5u);
  EXPECT_EQ(g.node(0).name, "dock");
  EXPECT_EQ(g.node(0).pos, (Point{-8, -1.5}));
  EXPECT_NEAR(g.node(1).pos.y, -1.0, 0.1);
  EXPECT_NEAR(g.node(2).pos.x, 2.45, 0.1);
  EXPECT_NEAR(g.node(2).pos.y, 0.0, 0.1);
  EXPECT_EQ(g.node(3).pos, (Point{2.5, 1.5}));
  EXPECT_EQ(g.node(4).name, "desk");
  EXPECT_EQ(t.kinds[2], TourEventKind::Door);
  EXPECT_TRUE(t.measured[1]);
  EXPECT_TRUE(t.measured[2]);
  EXPECT_FALSE(t.measured[3]);
  ASSERT_EQ(g.edges().size(), 4u);
  // Seed 003: each event announces the type of the next edge.
  EXPECT_EQ(find_edge(g, 0, 1)->type, EdgeType::Corridor);  // first_edge
  EXPECT_EQ(find_edge(g, 1, 2)->type, EdgeType::Corridor);
  EXPECT_EQ(find_edge(g, 2, 3)->type, EdgeType::Door);
  EXPECT_EQ(find_edge(g, 3, 4)->type, EdgeType::Room);
  EXPECT_EQ(g.components(), 1u);
}

TEST(TourBuilder, APlacePassedAgainMerges) {
  const Map m = corridor();
  const std::vector<TourEvent> events = {
      ev(TourEventKind::Crossing, 0, 0, 0),      // 0
      ev(TourEventKind::EnterCorridor, 8, 1.0, 0),  // 1
      ev(TourEventKind::Crossing, 15, 0, 0),     // 2
      ev(TourEventKind::EnterCorridor, 8.9, -0.5, kPi),  // back past 1: same node (0.9 m)
      ev(TourEventKind::Crossing, 1.0, 0.8, kPi),  // back at 0 (1.28 m away): same node
      ev(TourEventKind::Crossing, 15.5, 0.3, 0),   // a jump to 2: an edge 0-2, new
      ev(TourEventKind::Crossing, 0.2, 0.1, kPi),  // and 2-0 again: no second edge
      ev(TourEventKind::Place, 0.1, 0, 0, "a"),   // a place near the crossing: its own node
  };
  const TourGraph t = build_tour_graph(m, events, {.merge_distance = 1.5});
  const TopoGraph& g = t.graph;
  EXPECT_EQ(g.nodes().size(), 4u);
  EXPECT_EQ(t.event_nodes, (std::vector<int>{0, 1, 2, 1, 0, 2, 0, 3}));
  // Edges 0-1, 1-2, 0-2, 0-3; 2-1 and 1-0 again, 2-0 again not duplicated.
  EXPECT_EQ(g.edges().size(), 4u);
  EXPECT_NE(find_edge(g, 0, 2), nullptr);
  EXPECT_NE(find_edge(g, 0, 3), nullptr);

  // A tighter merge distance keeps the revisits apart.
  const TourGraph strict = build_tour_graph(m, events, {.merge_distance = 0.5});
  EXPECT_GT(strict.graph.nodes().size(), 4u);
}

TEST(TourBuilder, NamedPlacesMergeByName) {
  const Map m = corridor();
  const TourGraph t = build_tour_graph(m, {ev(TourEventKind::Place, 0, 0, 0, "dock"), ev(TourEventKind::Place, 5, 0, 0),
                                           ev(TourEventKind::Place, 0.5, 0, 0, "desk"),
                                           ev(TourEventKind::Place, 5.4, 0.2, 0, "printer"),
                                           ev(TourEventKind::Place, 0.3, 0, 0, "dock")});
  // desk is 0.5 m from dock but another name: its own node; printer names the unnamed 1.
  ASSERT_EQ(t.graph.nodes().size(), 3u);
  EXPECT_EQ(t.event_nodes, (std::vector<int>{0, 1, 2, 1, 0}));
  EXPECT_EQ(t.graph.node(1).name, "printer");
}

TEST(TourPlan, EveryEdgeIsWalkedOutAndBackWithEventsFromTheDegree) {
  // A T: 0 - 1 - 2 along x, 1 - 3 up; node 1 is the crossing, 0, 2, 3 dead ends.
  TopoGraph g;
  g.add_node({0, {0, 0}, ""});
  g.add_node({1, {5, 0}, ""});
  g.add_node({2, {10, 0}, "lab"});
  g.add_node({3, {5, 5}, ""});
  g.add_edge({.a = 0, .b = 1});
  g.add_edge({.a = 1, .b = 2});
  g.add_edge({.a = 1, .b = 3});
  const std::vector<TourWaypoint> t = tour_of_graph(g, 0);
  std::vector<int> nodes;
  for (const TourWaypoint& w : t) nodes.push_back(w.node);
  EXPECT_EQ(nodes, (std::vector<int>{0, 1, 2, 1, 3, 1, 0}));
  EXPECT_EQ(t[0].event, TourEventKind::Place);
  EXPECT_EQ(t[0].name, "node 0");
  EXPECT_EQ(t[1].event, TourEventKind::Crossing);
  EXPECT_EQ(t[2].name, "lab");
  EXPECT_EQ(t[2].p, (Point{10, 0}));

  // Keeping right 0.5 m: walking +x, right is -y; walking up (+y) to node 3, right is +x.
  const std::vector<TourWaypoint> r = keep_right(t, 0.5);
  EXPECT_NEAR(r[1].p.y, -0.5, 1e-12);
  EXPECT_NEAR(r[4].p.x, 5.5, 1e-12);
  EXPECT_NEAR(r[0].p.y, -0.5, 1e-12);  // the first: right of the way it leaves in
}

TEST(TourBuilder, KindsRoundTripTheirWords) {
  for (auto k : {TourEventKind::EnterCorridor, TourEventKind::EnterRoom, TourEventKind::Door, TourEventKind::Crossing,
                 TourEventKind::Place})
    EXPECT_EQ(tour_event_kind_from_string(to_string(k)), k);
  EXPECT_EQ(tour_event_kind_from_string("hall"), std::nullopt);
  EXPECT_EQ(to_string(TourEventKind::EnterRoom), "room");
}

}  // namespace
}  // namespace fleetmap
