// DistanceField (client/localization/distance_field.h): the exact distance transform of
// the walls that stop the laser, on the room of test_maps.h.
#include <gtest/gtest.h>

#include <cmath>

#include "client/localization/distance_field.h"
#include "tests/client/test_maps.h"

namespace fleetmap::localization {
namespace {

TEST(DistanceField, DistanceToTheNearestWall) {
  const Map m = test::room_map();
  const DistanceField f(m, {0.1, 2.0, 0.3});
  // The room's walls are x = 0, 20 and y = 0, 10; the L wall runs x = 4, y in [2, 6].
  EXPECT_NEAR(f.distance({2.0, 8.0}), 2.0, 0.1);   // the west wall
  EXPECT_NEAR(f.distance({18.0, 5.0}), 2.0, 0.1);  // the east wall
  EXPECT_NEAR(f.distance({5.0, 4.0}), 1.0, 0.1);   // the L's vertical leg
  EXPECT_NEAR(f.distance({9.0, 5.0}), std::hypot(1.0, 1.0), 0.1);  // the L's end (8, 6)
  EXPECT_LT(f.distance({4.0, 3.0}), 0.1);          // on a wall
  EXPECT_NEAR(f.distance({-1.0, 5.0}), 1.0, 0.1);  // in the margin, outside the border
}

TEST(DistanceField, WallsBelowTheLaserDoNotCount) {
  Map m = test::room_map();
  for (Obstacle& o : m.obstacles)
    if (o.id == 2)
      for (Segment& s : o.segments) s.h = 0.2;  // the L, lower than the laser at 0.3 m
  const DistanceField f(m, {0.1, 2.0, 0.3});
  EXPECT_NEAR(f.distance({5.0, 4.0}), 4.0, 0.1);  // now the south wall, 4 m away
}

TEST(DistanceField, CoarsensToFitTheCellBudget) {
  const Map m = test::room_map();
  DistanceFieldOptions o{0.01, 2.0, 0.3};
  o.max_cells = 100000;  // 24 m x 14 m at 1 cm would be 3.4 million cells
  const DistanceField f(m, o);
  EXPECT_LE(static_cast<size_t>(f.width()) * f.height(), 120000u);
  EXPECT_GT(f.resolution(), 0.05);
  EXPECT_NEAR(f.distance({2.0, 8.0}), 2.0, f.resolution());
}

}  // namespace
}  // namespace fleetmap::localization
