// register_turn (client/localization/turn_registration.h): two scans from one point of
// the room, taken 60 degrees apart, give back the turn from an odometry reading several
// degrees off; without overlap the odometry's turn is kept.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "client/sim/laser_simulator.h"
#include "client/localization/turn_registration.h"
#include "common/raycast/grid_ray_caster.h"
#include "tests/client/test_maps.h"

namespace fleetmap::localization {
namespace {

struct TurnInPlace : ::testing::Test {
  Map room = test::room_map();
  std::shared_ptr<GridRayCaster> world = std::make_shared<GridRayCaster>(room, RayCasterOptions{0.3, 15.0});
};

TEST_F(TurnInPlace, TheScansCorrectAnOdometryTurnDegreesOff) {
  LaserSimulator laser(world, {}, 7);  // sigma_L 5 cm
  const std::vector<double>& beams = laser.beam_angles();
  for (const Pose at : {Pose{2, 2, 0.3}, Pose{9, 3, -2.0}, Pose{17, 8, 2.9}}) {
    for (double odometry_error : {-8.0, -3.0, 4.0, 9.0}) {
      const double turn = deg2rad(60.0);
      const Pose after{at.x, at.y, normalize_angle(at.theta + turn)};
      const double found = register_turn(laser.scan(at), laser.scan(after), beams, 15.0,
                                         turn + deg2rad(odometry_error), deg2rad(5.0));
      // The beams are 1.4 degrees apart; the profiles still pin the turn far closer.
      EXPECT_NEAR(rad2deg(angle_diff(found, turn)), 0.0, 0.5)
          << "at (" << at.x << ", " << at.y << "), odometry " << odometry_error << " deg off";
    }
  }
}

TEST_F(TurnInPlace, WithoutOverlapTheOdometryStands) {
  LaserSimulator laser(world, {}, 7);
  const std::vector<double>& beams = laser.beam_angles();
  const Pose at{9, 3, 0.0};
  // Turned 180 degrees the two half circles share no direction.
  const double odometry = deg2rad(183.0);
  const double found = register_turn(laser.scan(at), laser.scan({9, 3, kPi}), beams, 15.0, odometry, deg2rad(5.0));
  EXPECT_DOUBLE_EQ(found, normalize_angle(odometry));
  // Nothing hit in the first scan: nothing to compare.
  const std::vector<double> empty(beams.size(), 15.0);
  EXPECT_DOUBLE_EQ(register_turn(empty, laser.scan(at), beams, 15.0, 0.5, 0.1), 0.5);
}

}  // namespace
}  // namespace fleetmap::localization
