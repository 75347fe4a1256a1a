// The laser rules (common/map/laser_rules.h) on their own, at and around the laser's
// height; ramp_stairs_test.cpp and the ray and slice tests check them in use.
#include <gtest/gtest.h>

#include <cmath>

#include "common/map/laser_rules.h"
#include "common/map/ramp.h"
#include "common/raycast/ray_rules.h"
#include "common/slicing/map_slice.h"

namespace fleetmap {
namespace {

Segment seg(double h) { return {{0, 0}, {1, 0}, h, 0, "", ""}; }

TEST(LaserRules, WallsStopAtOrAboveTheLaser) {
  EXPECT_TRUE(stops_laser(0.3, 0.3));  // level with it: stops
  EXPECT_TRUE(stops_laser(2.0, 0.3));
  EXPECT_FALSE(stops_laser(std::nextafter(0.3, 0.0), 0.3));
  EXPECT_FALSE(stops_laser(0.0, 0.3));
  EXPECT_TRUE(stops_laser(0.0, 0.0));  // a laser on the floor sees even null-height walls
}

TEST(LaserRules, StairsClosingSegmentIsTheNullHeightOne) {
  EXPECT_TRUE(is_stairs_closing(seg(0)));
  EXPECT_FALSE(is_stairs_closing(seg(0.15)));
}

TEST(LaserRules, StairsStepsStopOnlyWhenHigherThanTheLaser) {
  EXPECT_FALSE(stairs_step_stops_laser(seg(0.3), 0.3));  // level: passed, unlike a wall
  EXPECT_TRUE(stairs_step_stops_laser(seg(std::nextafter(0.3, 1.0)), 0.3));
  EXPECT_FALSE(stairs_step_stops_laser(seg(0.15), 0.3));
  EXPECT_TRUE(stairs_step_stops_laser(seg(0.45), 0.3));
  // The closing segment never stops a ray, whatever the laser's height.
  EXPECT_FALSE(stairs_step_stops_laser(seg(0), 0.0));
}

TEST(LaserRules, RampStopsWhereTheSurfaceReachesTheLaser) {
  EXPECT_TRUE(ramp_stops_laser(0.3, 0.3));
  EXPECT_TRUE(ramp_stops_laser(0.5, 0.3));
  EXPECT_FALSE(ramp_stops_laser(std::nextafter(0.3, 0.0), 0.3));
  // On a ramp rising 0.125 m per metre along x from a foot at x = 10, the surface
  // reaches hL = 0.25 at x = 12.
  const RampSurface s = parse_ramp_surface("ramp,normal=-0.125:0:1,foot=10:5");
  EXPECT_FALSE(ramp_stops_laser(s.height_at({11.9, 0}), 0.25));
  EXPECT_TRUE(ramp_stops_laser(s.height_at({12, 7}), 0.25));
}

// The ray caster's rule and the slice's agree on every step: a staircase of steps at
// 0.15, 0.30, 0.45 (x = 1, 2, 3) closed at x = 4 by h = 0, seen at hL = 0.30.
TEST(LaserRules, RayRuleAndSliceKeepTheSameSteps) {
  Obstacle stairs{1, ShapeType::Stairs, "stairs", {}, {}};
  const double heights[] = {0.15, 0.30, 0.45};
  for (int i = 1; i <= 3; ++i) stairs.segments.push_back({{double(i), 0}, {double(i), 1}, heights[i - 1], 0, "", ""});
  stairs.segments.push_back({{4, 1}, {4, 0}, 0, 0, "", ""});
  const StairsRule rule(stairs, 0.30);
  EXPECT_TRUE(rule.can_stop());
  // From x = 0 along +x: the 0.15 and 0.30 steps are passed, the 0.45 one at x = 3 stops.
  EXPECT_DOUBLE_EQ(rule.distance({0, 0.5}, {1, 0}), 3.0);
  Map m;
  m.border = Border::from_rect({-1, -1, 6, 2});
  m.obstacles.push_back(stairs);
  const Map slice = slice_at_height(m, 0.30);
  ASSERT_EQ(slice.obstacles.size(), 1u);
  ASSERT_EQ(slice.obstacles[0].segments.size(), 2u);  // the 0.45 step and the closing segment
  EXPECT_EQ(slice.obstacles[0].segments[0].h, 0.45);
  EXPECT_EQ(slice.obstacles[0].segments[1].h, 0.0);
  // At hL = 0.45 no step is higher: the staircase vanishes from both.
  EXPECT_FALSE(StairsRule(stairs, 0.45).can_stop());
  EXPECT_TRUE(slice_at_height(m, 0.45).obstacles.empty());
}

}  // namespace
}  // namespace fleetmap
