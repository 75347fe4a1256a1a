// stitch_scans (client/localization/stitched_scan.h): scans taken at known poses, joined
// by exact odometry, give the points the true scans put on the map, seen from the last.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "client/localization/distance_field.h"
#include "client/sim/laser_simulator.h"
#include "client/localization/stitched_scan.h"
#include "common/raycast/grid_ray_caster.h"
#include "tests/client/test_maps.h"

namespace fleetmap::localization {
namespace {

TEST(StitchedScan, PointsLandWhereTheTrueScansHit) {
  const Map m = test::room_map();
  const auto world = std::make_shared<GridRayCaster>(m, RayCasterOptions{0.3, 15.0});
  LaserSimulator laser(world, {}, 1);
  const std::vector<Pose> truth{{2, 2, 0.3}, {3, 2.5, 0.8}, {3.5, 3.5, 1.6}};
  std::vector<std::vector<double>> scans;
  std::vector<Odometry> odometry{{}};
  for (size_t k = 0; k < truth.size(); ++k) {
    scans.push_back(laser.true_scan(truth[k]));
    if (k > 0) odometry.push_back(between(truth[k - 1], truth[k]));
  }
  std::vector<const std::vector<double>*> ptrs;
  for (const auto& s : scans) ptrs.push_back(&s);
  const StitchedScan s = stitch_scans(ptrs, odometry, laser.beam_angles(), 15.0);
  ASSERT_EQ(s.poses.size(), 3u);
  EXPECT_NEAR(s.poses[2].x, 0, 1e-12);
  const Pose first = compose(truth[2], {s.poses[0].x, s.poses[0].y, s.poses[0].theta});
  EXPECT_NEAR(first.x, truth[0].x, 1e-9);
  EXPECT_NEAR(first.y, truth[0].y, 1e-9);
  // Every stitched point, placed from the last true pose, lies on a wall of the room.
  const DistanceField walls(m, {0.05, 2.0, 0.3});
  // The room is closed: every beam hits but the odd one through a corner's joint.
  ASSERT_GE(s.ranges.size(), 3 * laser.beam_angles().size() - 10);
  for (size_t i = 0; i < s.ranges.size(); ++i) {
    const double a = truth[2].theta + s.angles[i];
    const Point p{truth[2].x + s.ranges[i] * std::cos(a), truth[2].y + s.ranges[i] * std::sin(a)};
    EXPECT_LT(walls.distance(p), 0.08) << "point " << i;
  }
  // Newest scan first: the first NL points are the last scan itself.
  EXPECT_NEAR(s.ranges[0], scans[2][0], 1e-9);
  EXPECT_EQ(stitch_scans(ptrs, odometry, laser.beam_angles(), 15.0, 100).ranges.size(), 100u);
}

}  // namespace
}  // namespace fleetmap::localization
