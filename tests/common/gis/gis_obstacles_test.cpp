#include "common/gis/gis_obstacles.h"

#include <gtest/gtest.h>

#include "common/map/map_validation.h"

namespace fleetmap {
namespace {

// Free space is right of a segment seen from its start (seed 000 section 3: left to
// right seen from free space): a point just right of each segment's middle must be free.
void expect_free_on_the_right(const Obstacle& o, const Chain& ring, bool free_inside) {
  for (const Segment& s : o.segments) {
    const Point d = s.b - s.a;
    const Point mid = 0.5 * (s.a + s.b);
    const Point right = mid + (1e-3 / norm(d)) * Point{d.y, -d.x};
    // brute force: crossings of a ray to +x
    bool inside = false;
    for (size_t i = 0; i + 1 < ring.size(); ++i) {
      const Point a = ring[i], b = ring[i + 1];
      if ((a.y > right.y) != (b.y > right.y) && right.x < a.x + (right.y - a.y) * (b.x - a.x) / (b.y - a.y))
        inside = !inside;
    }
    EXPECT_EQ(inside, free_inside) << "segment (" << s.a.x << "," << s.a.y << ")-(" << s.b.x << "," << s.b.y << ")";
  }
}

TEST(GisObstacles, ClockwiseBuildingTurnsCounterClockwise) {
  const Chain cw{{0, 0}, {0, 2}, {3, 2}, {3, 0}, {0, 0}};
  auto o = closed_obstacle(cw, false, {4, 1, "building"});
  ASSERT_TRUE(o);
  EXPECT_EQ(o->type, ShapeType::ClosedPolygon);
  EXPECT_EQ(o->segments.size(), 4u);
  expect_free_on_the_right(*o, cw, false);
  EXPECT_EQ(o->segments[0].h, 4);
  EXPECT_FALSE(check_shape(*o));
}

TEST(GisObstacles, HoleAndRoomTurnClockwise) {
  const Chain ccw{{0, 0}, {3, 0}, {3, 2}, {0, 2}, {0, 0}};
  auto o = closed_obstacle(ccw, true, {});
  ASSERT_TRUE(o);
  expect_free_on_the_right(*o, ccw, true);
  EXPECT_FALSE(check_shape(*o));
}

TEST(GisObstacles, RepeatedVerticesDroppedAndDegenerateRingsRefused) {
  Chain c{{0, 0}, {0, 0}, {1, 0}, {1, 1}, {1, 1}, {0, 0}};
  EXPECT_EQ(drop_repeated_vertices(c), 2u);
  EXPECT_EQ(c.size(), 4u);
  auto o = closed_obstacle(Chain{{0, 0}, {1, 0}, {1, 0}, {1, 1}, {0, 0}}, false, {});
  ASSERT_TRUE(o);
  EXPECT_EQ(o->segments.size(), 3u);
  EXPECT_FALSE(closed_obstacle(Chain{{0, 0}, {1, 0}, {2, 0}, {0, 0}}, false, {}));  // flat
  EXPECT_FALSE(closed_obstacle(Chain{{0, 0}, {1, 0}, {0, 0}}, false, {}));
  EXPECT_FALSE(open_obstacle(Chain{{2, 2}, {2, 2}}, {}));
  auto line = open_obstacle(Chain{{0, 0}, {5, 0}, {5, 0}, {5, 5}}, {1.5, 1, "wall"});
  ASSERT_TRUE(line);
  EXPECT_EQ(line->type, ShapeType::OpenPolygon);
  EXPECT_EQ(line->segments.size(), 2u);
}

TEST(GisObstacles, StairsFollowSeedFigureOne) {
  // 3 m up the y axis at 0.3 m a step: 10 steps and the closing segment.
  auto o = stairs_obstacle(Chain{{1, 0}, {1, 1.2}, {1, 3}}, {0.17, 0.3, 2, 1, "steps"});
  ASSERT_TRUE(o);
  EXPECT_EQ(o->type, ShapeType::Stairs);
  ASSERT_EQ(o->segments.size(), 11u);
  EXPECT_FALSE(check_shape(*o)) << *check_shape(*o);
  // first step at the bottom, seen from below (looking up +y): left (x = 0) to right (x = 2)
  EXPECT_EQ(o->segments[0].a.x, 0);
  EXPECT_EQ(o->segments[0].b.x, 2);
  EXPECT_NEAR(o->segments[0].h, 0.17, 1e-12);
  EXPECT_NEAR(o->segments[9].h, 1.7, 1e-12);
  EXPECT_NEAR(o->segments[9].a.y, 2.7, 1e-12);
  EXPECT_EQ(o->segments[10].h, 0);
  EXPECT_NEAR(o->segments[10].a.y, 3, 1e-12);
  EXPECT_EQ(o->segments[10].a.x, 2);  // the closing segment runs the other way
  EXPECT_FALSE(stairs_obstacle(Chain{{0, 0}, {0, 0.001}}, {}));
}

}  // namespace
}  // namespace fleetmap
