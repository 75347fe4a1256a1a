// GridAStar (common/planning/grid_astar.h), the reference planner of the planning tests and of
// bench-planner: its paths keep the clearance exactly (brute-force judge), its lengths are
// near the straight line in open space, and a closed room has no path.
#include <gtest/gtest.h>

#include <cmath>

#include "common/planning/grid_astar.h"
#include "planning_test_util.h"

namespace fleetmap {
namespace {

using planning_test::BruteClearance;

TEST(GridAStar, PathsKeepTheClearanceOnGdc1) {
  const Map& m = planning_test::gdc1();
  const BruteClearance judge(m);
  GridAStar astar(m, {0.1, 0.3, {}});
  const auto pairs = planning_test::reachable_pairs(m, 0.3, 8, 51, 0.1);
  for (const auto& q : pairs) {
    const auto p = astar.solve(q.start, q.goal);
    ASSERT_TRUE(p);
    EXPECT_EQ(p->front(), q.start);
    EXPECT_EQ(p->back(), q.goal);
    EXPECT_GT(judge.path_clearance(*p), 0.3);
    EXPECT_GT(astar.expanded(), 0u);
    // Never shorter than the straight line.
    EXPECT_GE(path_length(*p), distance(q.start, q.goal) - 1e-9);
  }
}

TEST(GridAStar, OpenSpaceLengthIsTheOctileDistance) {
  Map m;
  m.border = Border::from_rect({0, 0, 30, 30});
  GridAStar astar(m, {0.1, 0.3, {}});
  const Point s{2.05, 3.05}, g{22.05, 13.05};  // cell centres: 200 x 100 cells apart
  const auto p = astar.solve(s, g);
  ASSERT_TRUE(p);
  EXPECT_NEAR(path_length(*p), 0.1 * (100 + 100 * std::sqrt(2.0)), 1e-6);
}

TEST(GridAStar, ClosedRoomHasNoPath) {
  Map m;
  m.border = Border::from_rect({0, 0, 40, 40});
  Obstacle room{1, ShapeType::ClosedPolygon, "room", {}, {}};
  const Point c[4] = {{20, 20}, {30, 20}, {30, 30}, {20, 30}};
  for (int i = 0; i < 4; ++i) room.segments.push_back({c[i], c[(i + 1) % 4], 2.0, 0, "wall", ""});
  m.obstacles.push_back(room);
  GridAStar astar(m, {0.2, 0.3, {}});
  EXPECT_FALSE(astar.solve({5, 5}, {25, 25}));
  EXPECT_TRUE(astar.solve({21, 21}, {29, 28}));
  EXPECT_FALSE(astar.solve({20.1, 25}, {5, 5}));  // start on the wall
  EXPECT_FALSE(astar.solve({-5, 5}, {5, 5}));     // start off the map
}

TEST(GridAStar, RejectsBadOptions) {
  Map m;
  m.border = Border::from_rect({0, 0, 40, 40});
  EXPECT_THROW(GridAStar(m, {0, 0.3, {}}), std::invalid_argument);
  EXPECT_THROW(GridAStar(m, {0.1, -1, {}}), std::invalid_argument);
  EXPECT_THROW(GridAStar(m, {1e-4, 0.3, {}}), std::invalid_argument);  // 160 G cells
}

}  // namespace
}  // namespace fleetmap
