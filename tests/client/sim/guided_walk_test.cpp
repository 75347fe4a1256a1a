// The simulated guided tour (client/sim/guided_walk.h) and what the tour builder makes
// of it on GDC1 (seed 003 §III-IV): the tour generated from the hand-made navigation
// graph (common/planning/tour_plan.h), walked by the guide and followed by the robot,
// must give back most of the hand-made nodes. Distances are measured here against the
// navigation file as parsed by the test, not by the code under test.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <vector>

#include "client/sim/guided_walk.h"
#include "common/io/amrl_import.h"
#include "common/io/topo_json.h"
#include "common/io/tour_json.h"
#include "common/planning/tour_builder.h"
#include "common/planning/tour_plan.h"

namespace fleetmap {
namespace {

std::vector<TourEvent> walk(const std::vector<TourWaypoint>& tour, GuidedWalkOptions o = {}) {
  GuidedWalk w(tour, o);
  std::vector<TourEvent> events;
  while (!w.done())
    for (TourEvent& e : w.step()) events.push_back(std::move(e));
  return events;
}

TEST(GuidedWalk, TheRobotReportsEveryEventPointItReaches) {
  // An L: out along x, a dead end, back, and up.
  std::vector<TourWaypoint> tour = {
      {{0, 0}, TourEventKind::Place, "dock", -1}, {{5, 0}, std::nullopt, "", -1},
      {{10, 0}, TourEventKind::Crossing, "", -1}, {{10, 6}, TourEventKind::EnterCorridor, "", -1},
      {{10, 0}, TourEventKind::Crossing, "", -1}, {{14, 0}, TourEventKind::Place, "end", -1}};
  const std::vector<TourEvent> events = walk(tour);
  ASSERT_EQ(events.size(), 5u);
  const Point where[] = {{0, 0}, {10, 0}, {10, 6}, {10, 0}, {14, 0}};
  for (size_t i = 0; i < events.size(); ++i) {
    EXPECT_NEAR(events[i].pose.x, where[i].x, 0.15) << i;
    EXPECT_NEAR(events[i].pose.y, where[i].y, 0.15) << i;
    if (i) {
      EXPECT_GT(events[i].t, events[i - 1].t);
    }
  }
  EXPECT_EQ(events[0].name, "dock");
  EXPECT_EQ(events[4].name, "end");
  EXPECT_EQ(events[2].kind, TourEventKind::EnterCorridor);
  // Heading: up the corridor at (10, 6)'s approach.
  EXPECT_NEAR(std::remainder(events[2].pose.theta - M_PI / 2, 2 * M_PI), 0, 0.35);
  // Followed at the robot's pace, not teleported: 26 m of trail take at least 26 / 0.8 s.
  EXPECT_GT(events.back().t, 26 / 0.8);
}

TEST(GuidedWalk, TourFilesRoundTrip) {
  const std::vector<TourWaypoint> tour = {{{1.5, -2}, TourEventKind::Place, "dock", -1},
                                          {{3, 4}, std::nullopt, "", -1},
                                          {{3, 9}, TourEventKind::Door, "", -1}};
  EXPECT_EQ(read_tour_json(write_tour_json(tour)), tour);
  EXPECT_THROW(read_tour_json(R"([{"x": 1}])"), TourFormatError);
  EXPECT_THROW(read_tour_json(R"([{"x": 1, "y": 2, "event": "lift"}])"), TourFormatError);
  EXPECT_THROW(read_tour_json(R"([{"x": 1, "y": 2, "event": "place"}])"), TourFormatError);
  EXPECT_THROW(read_tour_json(R"({"x": 1, "y": 2})"), TourFormatError);
}

TEST(GuidedWalk, Gdc1TourGivesBackTheHandMadeNodes) {
  const std::string maps = FLEETMAP_REAL_MAPS;
  const Map map = read_amrl_file(maps + "/GDC1.vectormap.txt", AmrlOptions{});
  const TopoGraph hand = read_topo_json_file(maps + "/GDC1.navigation.json");
  const std::vector<TourWaypoint> tour = tour_of_graph(hand, hand.nodes().front().id);
  const TourGraph built = build_tour_graph(map, walk(tour), {.merge_distance = 1.5});

  // The hand-made nodes, read from the file by the test.
  std::ifstream in(maps + "/GDC1.navigation.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  size_t matched = 0, total = 0;
  for (const auto& n : j.at("nodes")) {
    const Point p{n.at("loc").at("x").get<double>(), n.at("loc").at("y").get<double>()};
    double nearest = std::numeric_limits<double>::infinity();
    for (const TopoNode& a : built.graph.nodes()) nearest = std::min(nearest, std::hypot(a.pos.x - p.x, a.pos.y - p.y));
    matched += nearest <= 1.5;
    ++total;
  }
  EXPECT_GE(matched * 10, total * 9) << matched << " of " << total << " within 1.5 m";
  // Revisited crossings merged: no more nodes than the hand-made graph has.
  EXPECT_LE(built.graph.nodes().size(), total);
  EXPECT_EQ(built.graph.components(), 1u);
}

}  // namespace
}  // namespace fleetmap
