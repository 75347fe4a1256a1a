// ClearanceChecker (common/planning/clearance_checker.h) and the blocking rules of
// common/planning/planning_obstacles.h: agreement with a brute-force judge on the real maps, and
// what blocks by shape type (ramps, stairs, h = 0 segments, the border).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "common/planning/clearance_checker.h"
#include "common/planning/planning_obstacles.h"
#include "common/io/seed_format.h"
#include "common/geometry/segment_distance.h"
#include "planning_test_util.h"

namespace fleetmap {
namespace {

using planning_test::brute_segment_distance2;
using planning_test::BruteClearance;

const std::string kExample = FLEETMAP_SOURCE_DIR "/maps/example-campus.map";

Obstacle obstacle(int id, ShapeType type, std::vector<std::pair<Point, Point>> segs, double h) {
  Obstacle o{id, type, "test", {}, {}};
  for (auto [a, b] : segs) o.segments.push_back({a, b, h, 0, "wall", ""});
  return o;
}

Map empty_map(double w = 20, double h = 20) {
  Map m;
  m.border = Border::from_rect({0, 0, w, h});
  return m;
}

TEST(SegmentDistance, AgreesWithTheQuadraticMinimum) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-5, 5);
  for (int i = 0; i < 20000; ++i) {
    Point a{u(rng), u(rng)}, b{u(rng), u(rng)}, c{u(rng), u(rng)}, d{u(rng), u(rng)};
    if (i % 4 == 1) d = c + 0.3 * (b - a);  // parallel
    if (i % 4 == 2) c = a + 0.5 * (b - a);  // touching
    EXPECT_NEAR(std::sqrt(segment_distance2(a, b, c, d)), std::sqrt(brute_segment_distance2(a, b, c, d)), 1e-9);
  }
  EXPECT_EQ(segment_distance2({0, 0}, {2, 2}, {0, 2}, {2, 0}), 0);  // crossing
  EXPECT_DOUBLE_EQ(segment_distance2({0, 0}, {1, 0}, {3, 0}, {4, 0}), 4);  // collinear, apart
}

// Random points and motions of every length: the grid must give the brute-force answer
// (pairs within 1e-9 of the radius are skipped: there the two formulas may round apart).
void expect_agreement(const Map& m, double radius, unsigned seed) {
  const ClearanceChecker checker(m, {radius, {}, 0});
  const BruteClearance judge(m);
  std::mt19937_64 rng(seed);
  const Rect b = m.border.rect();
  std::uniform_real_distribution<double> ux(b.xmin - 1, b.xmax + 1), uy(b.ymin - 1, b.ymax + 1), ul(-1, 1);
  size_t blocked = 0, clear = 0;
  for (int i = 0; i < 6000; ++i) {
    const Point p{ux(rng), uy(rng)};
    const double len = std::pow(10.0, 2 * ul(rng) + 0.5);  // 0.03 m to 300 m
    const double ang = 3.14159 * ul(rng);
    const Point q = p + len * Point{std::cos(ang), std::sin(ang)};
    const double dp = judge.clearance(p, p), dm = judge.clearance(p, q);
    if (std::fabs(dp - radius) > 1e-9) {
      EXPECT_EQ(checker.point_clear(p), dp > radius) << p.x << " " << p.y;
    }
    if (std::fabs(dm - radius) > 1e-9) {
      EXPECT_EQ(checker.motion_clear(p, q), dm > radius) << p.x << " " << p.y << " -> " << q.x << " " << q.y;
      ++(dm > radius ? clear : blocked);
    }
  }
  EXPECT_GT(clear, 300u);
  EXPECT_GT(blocked, 300u);
}

TEST(ClearanceChecker, AgreesWithBruteForceOnGdc1) { expect_agreement(planning_test::gdc1(), 0.3, 1); }
TEST(ClearanceChecker, AgreesWithBruteForceOnUtCampus) { expect_agreement(planning_test::ut_campus(), 0.3, 2); }
TEST(ClearanceChecker, AgreesWithBruteForceWithLargeRadius) { expect_agreement(planning_test::gdc1(), 1.7, 3); }
TEST(ClearanceChecker, AgreesWithBruteForceWithZeroRadius) { expect_agreement(planning_test::gdc1(), 0.0, 4); }

TEST(ClearanceChecker, ExactAtTheRadius) {
  Map m = empty_map();
  m.obstacles.push_back(obstacle(1, ShapeType::OpenPolygon, {{{5, 5}, {15, 5}}}, 1));
  const ClearanceChecker c(m, {0.5, {}, 0});
  EXPECT_TRUE(c.point_clear({10, 5.5 + 1e-9}));
  EXPECT_FALSE(c.point_clear({10, 5.5}));  // touching counts as a collision
  EXPECT_FALSE(c.point_clear({10, 5.4999}));
  EXPECT_TRUE(c.motion_clear({2, 5.6}, {18, 5.6}));
  EXPECT_FALSE(c.motion_clear({2, 5.4}, {18, 5.4}));
  EXPECT_FALSE(c.motion_clear({10, 2}, {10, 8}));   // across the wall
  EXPECT_TRUE(c.motion_clear({4.4, 2}, {4.4, 8}));  // past its end, 0.6 m away
  EXPECT_FALSE(c.motion_clear({4.6, 2}, {4.6, 8}));
}

TEST(ClearanceChecker, ZeroRadiusStillForbidsCrossingAWall) {
  Map m = empty_map();
  m.obstacles.push_back(obstacle(1, ShapeType::OpenPolygon, {{{5, 5}, {15, 5}}}, 1));
  const ClearanceChecker c(m, {0.0, {}, 0});
  EXPECT_FALSE(c.motion_clear({10, 2}, {10, 8}));
  EXPECT_TRUE(c.motion_clear({10, 5.001}, {12, 5.001}));
}

TEST(ClearanceChecker, BorderBlocks) {
  const Map m = empty_map(10, 10);
  const ClearanceChecker c(m, {0.5, {}, 0});
  EXPECT_TRUE(c.point_clear({5, 5}));
  EXPECT_FALSE(c.point_clear({0.4, 5}));
  EXPECT_FALSE(c.point_clear({-3, 5}));
  EXPECT_FALSE(c.motion_clear({5, 5}, {12, 5}));
  ASSERT_TRUE(c.collision({9.8, 5}));
  EXPECT_EQ(c.collision({9.8, 5})->kind, Collision::Kind::Border);
  // Too large a robot for the map: nowhere to stand.
  const ClearanceChecker big(m, {6, {}, 0});
  EXPECT_FALSE(big.point_clear({5, 5}));
}

TEST(ClearanceChecker, NullHeightSegmentsDoNotBlock) {
  Map m = empty_map();
  m.obstacles.push_back(obstacle(3, ShapeType::OpenPolygon, {{{5, 5}, {15, 5}}}, 0));  // a painted line
  const ClearanceChecker c(m, {0.3, {}, 0});
  EXPECT_TRUE(c.point_clear({10, 5}));
  EXPECT_TRUE(c.motion_clear({10, 2}, {10, 8}));
}

TEST(ClearanceChecker, NamesTheBlockingObstacle) {
  Map m = empty_map();
  m.obstacles.push_back(obstacle(42, ShapeType::ClosedPolygon, {{{5, 5}, {15, 5}}, {{15, 5}, {10, 9}}, {{10, 9}, {5, 5}}}, 2));
  const ClearanceChecker c(m, {0.3, {}, 0});
  const auto hit = c.collision({10, 5.1});
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->kind, Collision::Kind::Segment);
  EXPECT_EQ(hit->obstacle_id, 42);
  EXPECT_FALSE(c.collision({10, 7}));  // inside a closed polygon is not a collision (rooms)
}

// The example map (maps/example-campus.map): a ramp, obstacle 7, outline (8,10)-(12,12);
// stairs, obstacle 6, steps y = 18.5 .. 19.7 and closing segment y = 20 over x = 44 .. 50.
TEST(ClearanceChecker, RampsNeverBlock) {
  const Map m = read_seed_file(kExample);
  for (bool climb : {false, true}) {
    const ClearanceChecker c(m, {0.3, {climb}, 0});
    EXPECT_TRUE(c.point_clear({10, 11}));
    EXPECT_TRUE(c.point_clear({8, 11}));                 // on its outline
    EXPECT_TRUE(c.motion_clear({6, 11}, {14, 11}));      // across it
    EXPECT_TRUE(c.motion_clear({10, 8.5}, {10, 13.5}));
  }
}

TEST(ClearanceChecker, StairsBlockWheeledRobotsOnly) {
  const Map m = read_seed_file(kExample);
  const ClearanceChecker wheeled(m, {0.3, {false}, 0});
  const ClearanceChecker climber(m, {0.3, {true}, 0});
  const Point between_steps{47, 19.25}, below{47, 17.5}, above{47, 21};
  // A wheeled robot may not stand anywhere on the staircase, even between steps that are
  // further apart than its diameter would allow, nor cross it, from below or above (the
  // h = 0 closing segment is part of the outline of the area).
  ASSERT_TRUE(wheeled.collision(between_steps));
  EXPECT_EQ(wheeled.collision(between_steps)->kind, Collision::Kind::Area);
  EXPECT_EQ(wheeled.collision(between_steps)->obstacle_id, 6);
  EXPECT_TRUE(wheeled.point_clear(below));
  EXPECT_TRUE(wheeled.point_clear(above));
  EXPECT_FALSE(wheeled.motion_clear(below, above));
  EXPECT_FALSE(wheeled.motion_clear({43, 19.25}, {51, 19.25}));  // in from the side
  EXPECT_FALSE(wheeled.point_clear({47, 20.2}));                  // 0.2 m above the closing segment
  // A robot that climbs stairs ignores them.
  EXPECT_TRUE(climber.point_clear(between_steps));
  EXPECT_TRUE(climber.motion_clear(below, above));
  EXPECT_TRUE(climber.motion_clear({43, 19.25}, {51, 19.25}));
}

TEST(ClearanceChecker, StairsAreaIsTheConvexHull) {
  Map m = empty_map();
  // Two steps and a closing segment (seed 000 Fig. 1), steps 1 m apart: a 0.2 m robot
  // would fit between them, but the staircase is one area.
  Obstacle st = obstacle(9, ShapeType::Stairs, {{{5, 5}, {9, 5}}, {{5, 6}, {9, 6}}}, 0.2);
  st.segments[1].h = 0.4;
  st.segments.push_back({{9, 7}, {5, 7}, 0, 0, "step", ""});
  m.obstacles.push_back(st);
  const PlanningObstacles po = prepare_planning_obstacles(m, {false});
  ASSERT_EQ(po.areas.size(), 1u);
  EXPECT_EQ(po.areas[0].ring.size(), 4u);
  EXPECT_TRUE(po.areas[0].contains({7, 5.5}));
  EXPECT_FALSE(po.areas[0].contains({7, 7.5}));
  EXPECT_TRUE(prepare_planning_obstacles(m, {true}).segments.empty());
  const ClearanceChecker c(m, {0.2, {false}, 0});
  EXPECT_FALSE(c.point_clear({7, 5.5}));
  EXPECT_FALSE(c.motion_clear({7, 3}, {7, 9}));
}

TEST(ClearanceChecker, CellSizeDoesNotChangeAnswers) {
  const Map& m = planning_test::gdc1();
  const ClearanceChecker fine(m, {0.3, {}, 0.25}), coarse(m, {0.3, {}, 3.0});
  std::mt19937_64 rng(9);
  const Rect b = m.border.rect();
  std::uniform_real_distribution<double> ux(b.xmin, b.xmax), uy(b.ymin, b.ymax);
  for (int i = 0; i < 5000; ++i) {
    const Point p{ux(rng), uy(rng)}, q{ux(rng), uy(rng)};
    EXPECT_EQ(fine.point_clear(p), coarse.point_clear(p));
    EXPECT_EQ(fine.motion_clear(p, q), coarse.motion_clear(p, q));
  }
}

TEST(ClearanceChecker, RejectsBadOptions) {
  const Map m = empty_map();
  EXPECT_THROW(ClearanceChecker(m, {-1, {}, 0}), std::invalid_argument);
  EXPECT_THROW(ClearanceChecker(m, {NAN, {}, 0}), std::invalid_argument);
  EXPECT_THROW(ClearanceChecker(m, {0.3, {}, -2}), std::invalid_argument);
}

}  // namespace
}  // namespace fleetmap
