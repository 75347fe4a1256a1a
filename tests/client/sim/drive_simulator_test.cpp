// WanderDriver and pick_start_pose (client/sim/drive_simulator.h): the simulated
// robot keeps clear of walls, drives, and its odometry is noisy but close to its motion.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>

#include "client/sim/drive_simulator.h"
#include "common/raycast/grid_ray_caster.h"
#include "tests/client/test_maps.h"

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

TEST(WanderDriver, LooksAroundInPlaceBeforeDriving) {
  const Map m = test::room_map();
  const auto world = std::make_shared<GridRayCaster>(m, RayCasterOptions{0.3, 15.0});
  DriveOptions o;
  o.look_around_steps = 6;
  o.look_around_turn = deg2rad(60.0);
  const Pose start{10, 8, 0.4};
  WanderDriver driver(world, start, o, 3);
  for (int k = 1; k <= 6; ++k) {
    const DriveStep s = driver.step();
    EXPECT_EQ(s.driven, 0.0) << k;
    EXPECT_DOUBLE_EQ(s.truth.x, start.x);
    EXPECT_DOUBLE_EQ(s.truth.y, start.y);
    EXPECT_NEAR(angle_diff(s.truth.theta, start.theta + k * deg2rad(60.0)), 0.0, 1e-9) << k;
    // Odometry reports the turn with its noise (a few degrees), no drive.
    EXPECT_NEAR(angle_diff(s.odometry.dtheta, deg2rad(60.0)), 0.0, deg2rad(20.0)) << k;
    EXPECT_LT(std::hypot(s.odometry.dx, s.odometry.dy), 0.1) << k;
  }
  // Back where it started, then it drives.
  EXPECT_NEAR(angle_diff(driver.pose().theta, start.theta), 0.0, 1e-9);
  double driven = 0;
  for (int k = 0; k < 4; ++k) driven += driver.step().driven;
  EXPECT_GT(driven, 0.0);
}

// A 10 m x 10 m room open on its east side onto ground with nothing in it. With the rule
// (half the rays around meet a wall within the laser's 15 m), the robot keeps by the room,
// less than a metre out of it; without it, it wanders off into the empty ground.
TEST(WanderDriver, KeepsWhereItsMapIsWhenAsked) {
  const Map m = test::chain_map({-100, -100, 100, 100},
                                {test::wall({10, 0}, {0, 0}), test::wall({0, 0}, {0, 10}), test::wall({0, 10}, {10, 10})});
  const auto world = std::make_shared<GridRayCaster>(m, RayCasterOptions{0.3, 15.0});
  const auto farthest_out = [&](double min_walls) {
    DriveOptions o;
    o.min_walls_around = min_walls;
    WanderDriver driver(world, {5, 5, 0}, o, 11);
    double out = 0, driven = 0;
    for (int k = 0; k < 2000; ++k) {
      const DriveStep st = driver.step();
      const double dx = std::max({0.0, -st.truth.x, st.truth.x - 10}), dy = std::max({0.0, -st.truth.y, st.truth.y - 10});
      out = std::max(out, std::hypot(dx, dy));
      driven += st.driven;
    }
    EXPECT_GT(driven, 300.0) << min_walls;  // it drives, it is not stuck turning
    return out;
  };
  EXPECT_LT(farthest_out(0.5), 1.0);
  EXPECT_GT(farthest_out(0.0), 20.0);
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
