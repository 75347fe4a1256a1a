// WanderDriver and pick_start_pose (client/localization/drive_simulator.h): the simulated
// robot keeps clear of walls, drives, and its odometry is noisy but close to its motion.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>

#include "client/localization/drive_simulator.h"
#include "common/grid_ray_caster.h"
#include "test_maps.h"

namespace fleetmap::localization {
namespace {

TEST(WanderDriver, DrivesWithoutTouchingWalls) {
  const Map m = test::room_map();
  const auto world = std::make_shared<GridRayCaster>(m, RayCasterOptions{0.3, 15.0});
  WanderDriver driver(world, {2, 8, 0}, {}, 1);
  double driven = 0, odo_error = 0;
  for (int k = 0; k < 400; ++k) {
    const Pose before = driver.pose();
    const DriveStep s = driver.step();
    driven += s.driven;
    const Odometry truth = between(before, s.truth);
    odo_error = std::max(odo_error, std::hypot(s.odometry.dx - truth.dx, s.odometry.dy - truth.dy));
    // Never closer to a wall than the robot's radius, all around.
    for (int a = 0; a < 36; ++a) ASSERT_GT(world->cast(s.truth.point(), a * kPi / 18), 0.25) << k;
  }
  EXPECT_GT(driven, 60.0);  // mostly driving, some turning in place
  EXPECT_GT(odo_error, 0.0);
  EXPECT_LT(odo_error, 0.1);  // per 0.25 m step
}

TEST(PickStartPose, HasClearanceAndHits) {
  const Map m = test::room_map();
  const auto world = std::make_shared<GridRayCaster>(m, RayCasterOptions{0.3, 15.0});
  const FreeSpace fs(m);
  const std::vector<double> beams = evenly_spread_angles(131, kPi);
  std::mt19937_64 rng(2);
  for (int k = 0; k < 50; ++k) {
    const Pose p = pick_start_pose(fs, *world, beams, 1.0, 0.5, rng);
    EXPECT_TRUE(fs.contains(p.point()));
    EXPECT_GT(p.x, 0.5);
    EXPECT_LT(p.x, 19.5);
    for (int a = 0; a < 36; ++a) EXPECT_GE(world->cast(p.point(), a * kPi / 18), 0.5);
  }
}

}  // namespace
}  // namespace fleetmap::localization
