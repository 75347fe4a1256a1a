#include "client/sim/pure_pursuit.h"

#include <gtest/gtest.h>

#include <cmath>

#include "client/sim/differential_drive.h"

namespace fleetmap {
namespace {

TEST(PurePursuit, TurnsOnTheSpotWhileTheHeadingIsFarOff) {
  PurePursuit pursuit;
  pursuit.set_path({{0, 0}, {10, 0}});
  // 60 degrees off a 10 m leg: an arc to a target that far would sweep sideways.
  const Command c = pursuit.command({0, 0, -M_PI / 3});
  EXPECT_EQ(c.v, 0);
  EXPECT_GT(c.w, 0);  // towards the path (counter-clockwise)
  EXPECT_FALSE(c.arrived);
  // Nearly aligned: it drives.
  EXPECT_GT(pursuit.command({0, 0, -0.2}).v, 0);
}

TEST(PurePursuit, FromSixtyDegreesOffItStaysInACorridorAndArrives) {
  // A 2 m corridor along x (|y| < 1), the path down its middle, the robot starting as a
  // look around can leave it: 60 degrees off.
  PurePursuit pursuit;
  pursuit.set_path({{0, 0}, {10, 0}});
  DifferentialDrive body({0, 0, -M_PI / 3}, OdometryNoise{}, 1);
  double widest = 0;
  bool arrived = false;
  for (int i = 0; i < 1000 && !arrived; ++i) {
    const Command c = pursuit.command(body.pose());
    arrived = c.arrived;
    body.step(c.v, c.w, 0.05);
    widest = std::max(widest, std::abs(body.pose().y));
  }
  EXPECT_TRUE(arrived);
  EXPECT_LT(widest, 0.7);  // 0.3 m of the corridor's half width left for the robot's body
}

}  // namespace
}  // namespace fleetmap
