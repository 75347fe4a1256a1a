// FreeSpace (client/localization/free_space.h): the border minus enclosed obstacles.
#include <gtest/gtest.h>

#include <random>

#include "client/localization/free_space.h"
#include "common/map/map_window.h"
#include "tests/client/test_maps.h"

namespace fleetmap::localization {
namespace {

TEST(FreeSpace, ExcludesClosedObstaclesOnly) {
  const Map m = test::room_map();
  const FreeSpace fs(m);
  EXPECT_EQ(fs.solid_count(), 1u);  // the pillar; the room's open chain encloses nothing
  EXPECT_FALSE(fs.contains({14.5, 4.5}));  // inside the pillar
  EXPECT_TRUE(fs.contains({13.9, 4.5}));
  EXPECT_TRUE(fs.contains({2, 2}));
  EXPECT_TRUE(fs.contains({5, 5}));  // inside the L's corner: open
  EXPECT_FALSE(fs.contains({-0.5, 5}));  // outside the border
  EXPECT_NEAR(fs.area(), 20.0 * 10.0 - 1.0, 1e-9);
}

TEST(FreeSpace, SamplesAreFreeAndCoverTheBorder) {
  const Map m = test::room_map();
  const FreeSpace fs(m);
  std::mt19937_64 rng(1);
  int left = 0;
  for (int k = 0; k < 20000; ++k) {
    const Point p = fs.sample(rng);
    ASSERT_TRUE(fs.contains(p));
    left += p.x < 10;
  }
  EXPECT_NEAR(left / 20000.0, 100.0 / 199.0, 0.02);
}

TEST(FreeSpace, CutObstaclesOfAWindowEncloseNothing) {
  const Map m = test::room_map();
  // A window that cuts the pillar in two: what is left is no closed chain.
  const Map w = clip_map(m, window_rect(m.border, {10, 5}, 9, 4));
  const FreeSpace fs(w);
  EXPECT_EQ(fs.solid_count(), 0u);
  EXPECT_TRUE(fs.contains({14.2, 4.5}));
}

}  // namespace
}  // namespace fleetmap::localization
