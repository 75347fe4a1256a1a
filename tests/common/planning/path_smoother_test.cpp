// PathSmoother (common/planning/path_smoother.h): on RRT-Connect paths of the real maps, every step
// keeps the clearance (brute-force judge of planning_test_util.h) and never lengthens the
// path; on a hand-made corner, the result is close to the known shortest path.
#include <gtest/gtest.h>

#include <cmath>

#include "common/planning/clearance_checker.h"
#include "common/planning/path_smoother.h"
#include "common/planning/planning_obstacles.h"
#include "common/planning/rrt_connect.h"
#include "planning_test_util.h"

namespace fleetmap {
namespace {

using planning_test::BruteClearance;

constexpr double kRadius = 0.3;
constexpr double kPi = 3.14159265358979323846;

void expect_smoothing_safe(const Map& m, double resolution, unsigned seed) {
  const ClearanceChecker checker(m, {kRadius, {}, 0});
  const BruteClearance judge(m);
  const PathSmoother smoother(checker);
  size_t corners = 0, rounded = 0;
  for (const auto& q : planning_test::reachable_pairs(m, kRadius, 10, seed, resolution)) {
    RrtOptions o;
    o.seed = seed;
    o.max_time = 0;
    RrtConnect rrt(checker, o);
    const auto raw = rrt.solve(q.start, q.goal);
    ASSERT_TRUE(raw);
    const Path shortcut = smoother.shortcut(*raw);
    const Path cut = smoother.cut_corners(*raw);
    SmoothingStats st;
    const Path smooth = smoother.smooth(*raw, &st);
    const Path* steps[] = {raw.operator->(), &shortcut, &cut, &smooth};
    for (size_t k = 1; k < 4; ++k) {
      const Path& p = *steps[k];
      EXPECT_EQ(p.front(), q.start);
      EXPECT_EQ(p.back(), q.goal);
      EXPECT_LE(path_length(p), path_length(*steps[k - 1]) + 1e-9) << "step " << k << " lengthened the path";
      EXPECT_GT(judge.path_clearance(p), kRadius) << "step " << k << " came too close to a wall";
    }
    EXPECT_DOUBLE_EQ(st.output_length, path_length(smooth));
    EXPECT_DOUBLE_EQ(st.input_length, path_length(*raw));
    corners += st.corners;
    rounded += st.rounded;
  }
  ::testing::Test::RecordProperty("corners", static_cast<int>(corners));
  ::testing::Test::RecordProperty("rounded", static_cast<int>(rounded));
}

TEST(PathSmoother, KeepsClearanceAndNeverLengthensOnGdc1) { expect_smoothing_safe(planning_test::gdc1(), 0.1, 41); }
TEST(PathSmoother, KeepsClearanceAndNeverLengthensOnUtCampus) {
  expect_smoothing_safe(planning_test::ut_campus(), 0.25, 42);
}

// A 1 m wide wall from (10, 0) up to (10, 10) in a 20 x 20 map: from (5, 2) to (15, 2) the
// shortest path for a disc of radius r goes over the wall's top, wrapping its end at
// distance r: two tangents to the circle of radius r about (10, 10) and the arc between.
TEST(PathSmoother, CornerCuttingApproachesTheShortestPath) {
  Map m;
  m.border = Border::from_rect({0, 0, 20, 20});
  Obstacle wall{1, ShapeType::OpenPolygon, "wall", {}, {}};
  wall.segments.push_back({{10, 0}, {10, 10}, 2.0, 0, "wall", ""});
  m.obstacles.push_back(wall);
  const double r = 0.5;
  const ClearanceChecker checker(m, {r, {}, 0});
  // A clumsy clear path: far up, then down.
  const Path raw{{5, 2}, {5, 18}, {12, 18}, {15, 12}, {15, 2}};
  for (size_t k = 1; k < raw.size(); ++k) ASSERT_TRUE(checker.motion_clear(raw[k - 1], raw[k]));
  SmoothingOptions so;
  so.round_corners = false;
  const Path p = PathSmoother(checker, so).cut_corners(raw);
  // The shortest path hugs the circle of radius r about the wall's top (10, 10): it is the
  // upper part of the convex hull of the two ends and that circle (drawn as a fine inscribed
  // polygon, so a little short: a lower bound).
  double lower = 0;
  {
    std::vector<Point> pts{{5, 2}, {15, 2}};
    for (int i = 0; i < 20000; ++i)
      pts.push_back({10 + r * std::cos(2 * kPi * i / 20000), 10 + r * std::sin(2 * kPi * i / 20000)});
    const std::vector<Point> hull = convex_hull(pts);
    for (size_t i = 0; i < hull.size(); ++i) lower += distance(hull[i], hull[(i + 1) % hull.size()]);
    lower -= 10;  // the chord from (15, 2) back to (5, 2)
  }
  EXPECT_GE(path_length(p), lower - 1e-6);
  EXPECT_LE(path_length(p), lower * 1.01) << "corner cutting stopped 1 % or more above the shortest path";
  EXPECT_LT(path_length(p), path_length(raw));
}

// Rounding: a right-angle corner in open space becomes an arc; next to posts, the arc
// shrinks until it is clear.
TEST(PathSmoother, RoundsCornersWhereThereIsRoom) {
  Map m;
  m.border = Border::from_rect({0, 0, 20, 20});
  const ClearanceChecker checker(m, {0.3, {}, 0});
  SmoothingOptions so;
  so.corner_radius = 2;
  const PathSmoother smoother(checker, so);
  const Path corner{{2, 2}, {10, 2}, {10, 10}};
  size_t rounded = 0;
  const Path p = smoother.round_corners(corner, &rounded);
  EXPECT_EQ(rounded, 1u);
  EXPECT_GT(p.size(), 4u);
  EXPECT_LT(path_length(p), path_length(corner));
  // The arc of radius 2 joins (8, 2) to (10, 4), centred on (8, 4).
  for (size_t k = 1; k + 1 < p.size(); ++k) EXPECT_NEAR(distance(p[k], {8, 4}), 2, 1e-9);
  EXPECT_EQ(p.front(), corner.front());
  EXPECT_EQ(p.back(), corner.back());

  Map tight = m;
  Obstacle post{1, ShapeType::OpenPolygon, "post", {}, {}};
  post.segments.push_back({{10.5, 1.5}, {11, 1}, 1.0, 0, "post", ""});  // just outside the corner
  post.segments.push_back({{9.2, 2.8}, {9.3, 2.7}, 1.0, 0, "post", ""});  // 0.35 m inside it
  tight.obstacles.push_back(post);
  const ClearanceChecker tc(tight, {0.3, {}, 0});
  ASSERT_TRUE(tc.motion_clear(corner[0], corner[1]));
  ASSERT_TRUE(tc.motion_clear(corner[1], corner[2]));
  const Path q = PathSmoother(tc, so).round_corners(corner, &rounded);
  for (size_t k = 1; k < q.size(); ++k) EXPECT_TRUE(tc.motion_clear(q[k - 1], q[k]));
  EXPECT_LE(path_length(q), path_length(corner));
}

}  // namespace
}  // namespace fleetmap
