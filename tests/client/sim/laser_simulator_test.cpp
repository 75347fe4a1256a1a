// LaserSimulator (client/sim/laser_simulator.h): true ranges plus N(0, sigma_L),
// RMAX kept for beams that hit nothing, people: walking discs that shorten the beams they meet.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "client/sim/laser_simulator.h"
#include "common/raycast/grid_ray_caster.h"
#include "tests/client/test_maps.h"

namespace fleetmap::localization {
namespace {

std::shared_ptr<const RayCaster> room_caster() {
  return std::make_shared<GridRayCaster>(test::room_map(), RayCasterOptions{0.3, 15.0});
}

TEST(LaserSimulator, TrueScanIsTheCastersScan) {
  const auto world = room_caster();
  LaserSimulator laser(world, {}, 1);
  ASSERT_EQ(laser.beam_angles().size(), 131u);
  EXPECT_NEAR(laser.beam_angles().front(), -kPi / 2, 1e-12);
  EXPECT_NEAR(laser.beam_angles().back(), kPi / 2, 1e-12);
  // From (2, 2) facing +x the middle beam meets the L's wall at x = 4.
  const std::vector<double> r = laser.true_scan({2, 2.5, 0});
  EXPECT_NEAR(r[65], 2.0, 1e-9);
  EXPECT_NEAR(r[0], 2.5, 1e-9);  // facing -y: the wall y = 0
}

TEST(LaserSimulator, NoiseHasSigmaL) {
  const auto world = room_caster();
  LaserSimulator laser(world, {}, 2);
  const Pose p{10, 3, 0.3};
  const std::vector<double> truth = laser.true_scan(p);
  double sum = 0, sum_sq = 0;
  int n = 0;
  for (int k = 0; k < 200; ++k) {
    const std::vector<double> r = laser.scan(p);
    for (size_t j = 0; j < r.size(); ++j) {
      const double d = r[j] - truth[j];
      sum += d;
      sum_sq += d * d;
      ++n;
    }
  }
  EXPECT_NEAR(sum / n, 0.0, 0.002);
  EXPECT_NEAR(std::sqrt(sum_sq / n), 0.05, 0.002);  // seed 000 section 4.1: sigma_L 5 cm
}

TEST(LaserSimulator, BeamsThatHitNothingReturnRmax) {
  // A single wall: the beams that miss it stay at RMAX exactly.
  const Map m = test::chain_map({-20, -20, 20, 20}, {test::wall({3, -1}, {3, 1})});
  LaserSimulator laser(std::make_shared<GridRayCaster>(m, RayCasterOptions{0.3, 15.0}), {}, 3);
  const std::vector<double> r = laser.scan({0, 0, 0});
  EXPECT_EQ(r[0], 15.0);
  EXPECT_EQ(r[130], 15.0);
  EXPECT_NEAR(r[65], 3.0, 0.3);
}

TEST(LaserSimulator, PeopleShortenBeamsToTheirDiscs) {
  const auto world = room_caster();
  LaserSimulatorOptions o;
  o.sigma = 0;
  o.people = 3;
  LaserSimulator laser(world, o, 4);
  const Pose p{10, 3, kPi / 2};
  const std::vector<double> truth = laser.true_scan(p);
  int shorter = 0;
  for (int k = 0; k < 50; ++k) {
    const std::vector<double> r = laser.scan(p);
    for (size_t j = 0; j < r.size(); ++j) {
      EXPECT_LE(r[j], truth[j] + 1e-12);
      if (r[j] < truth[j] - 1e-9) {
        ++shorter;
        EXPECT_GE(r[j], 0.5);  // min_person_range
        // The reading ends on a person's edge.
        const Point hit = p.point() + r[j] * ray_direction(p.theta + laser.beam_angles()[j]);
        double nearest_edge = INFINITY;
        for (const Person& person : laser.people())
          nearest_edge = std::min(nearest_edge, std::fabs(distance(hit, person.centre) - person.radius));
        EXPECT_LT(nearest_edge, 1e-6) << "beam " << j;
      }
    }
  }
  // A person 0.4-0.6 m wide covers at least one beam (1.4 degrees apart) even at 15 m.
  EXPECT_GT(shorter, 150);
}

TEST(LaserSimulator, PeopleAreHumanSizedInViewClearOfWallsAndWalk) {
  // Realistic people (docs/localization.md "People in the scans"): 0.4-0.6 m across,
  // in the field of view within the laser's range, never inside or against a wall, and
  // walking from scan to scan rather than jumping.
  const auto world = room_caster();
  LaserSimulatorOptions o;
  o.people = 10;
  LaserSimulator laser(world, o, 5);
  Pose robot{3, 8, 0};
  std::vector<Person> before;
  int walked = 0, compared = 0;
  for (int k = 0; k < 100; ++k) {
    robot = {3 + 0.1 * k, 8, 0.02 * k};  // driving and turning slowly
    laser.scan(robot);
    const std::vector<Person>& people = laser.people();
    ASSERT_EQ(people.size(), 10u);
    for (size_t i = 0; i < people.size(); ++i) {
      const Person& q = people[i];
      if (!(q.radius > 0)) continue;
      EXPECT_GE(2 * q.radius, 0.4 - 1e-12);
      EXPECT_LE(2 * q.radius, 0.6 + 1e-12);
      const Point rel = q.centre - robot.point();
      EXPECT_LE(norm(rel) + q.radius, 15.0);
      EXPECT_GE(norm(rel) - q.radius, 0.5);
      EXPECT_LE(std::fabs(angle_diff(std::atan2(rel.y, rel.x), robot.theta)), kPi / 2 + 1e-9);
      for (int a = 0; a < 36; ++a) EXPECT_GE(world->cast(q.centre, a * kPi / 18), q.radius) << "inside a wall";
      EXPECT_NEAR(norm(q.velocity), 1.0, 1e-9);
      if (!before.empty() && before[i].radius == q.radius) {  // the same person, not placed again
        const double moved = distance(before[i].centre, q.centre);
        EXPECT_TRUE(moved < 1e-12 || std::fabs(moved - 0.2) < 1e-9) << moved;  // 1 m/s for 0.2 s, or turning
        ++compared;
        walked += moved > 0.1;
      }
    }
    before = people;
  }
  EXPECT_GT(compared, 500);
  EXPECT_GT(walked, compared / 2);
}

TEST(LaserSimulator, PeopleAllAroundStandBehindTheLaserToo) {
  // people_field 360 degrees: the people stand all around the robot (in its line of sight,
  // within range), many behind the 180 degree laser, and people_in_view counts those in
  // front. The default keeps every person in view.
  const auto world = room_caster();
  LaserSimulatorOptions around;
  around.people = 10;
  around.people_field = 2 * kPi;
  LaserSimulatorOptions in_view = around;
  in_view.people_field = 0;
  LaserSimulator all_around(world, around, 3), in_front(world, in_view, 3);
  size_t placed = 0, behind = 0, shortened = 0;
  for (int k = 0; k < 100; ++k) {
    const Pose robot{9 + 0.02 * k, 3, 0.03 * k};  // open floor on every side, within a few metres of walls
    const std::vector<double> truth = all_around.true_scan(robot);
    const std::vector<double> scan = all_around.scan(robot);
    size_t front = 0;
    for (const Person& q : all_around.people()) {
      if (!(q.radius > 0)) continue;
      ++placed;
      const Point rel = q.centre - robot.point();
      EXPECT_LE(norm(rel) + q.radius, 15.0);
      EXPECT_GE(world->cast(robot.point(), std::atan2(rel.y, rel.x)), norm(rel)) << "out of the robot's sight";
      if (std::fabs(angle_diff(std::atan2(rel.y, rel.x), robot.theta)) > kPi / 2) ++behind;
      else ++front;
    }
    EXPECT_EQ(all_around.people_in_view(robot), front);
    for (size_t j = 0; j < scan.size(); ++j) shortened += scan[j] < truth[j] - 0.3;
    in_front.scan(robot);
    EXPECT_EQ(in_front.people_in_view(robot),
              static_cast<size_t>(std::count_if(in_front.people().begin(), in_front.people().end(),
                                                [](const Person& q) { return q.radius > 0; })));
  }
  EXPECT_GT(placed, 900u);                   // the field has room for the crowd
  EXPECT_GT(behind, placed / 4);             // many stand behind the laser
  EXPECT_LT(behind, 3 * placed / 4);         // and many in front
  EXPECT_GT(shortened, 100u);                // those in front reach the scans
}

TEST(LaserSimulator, PeopleNeverOverlap) {
  // Bodies do not overlap at a laser's height: overlapping discs side by side make a
  // straight front that no real row of people shows. A crowd of 30 in a 20 m x 10 m room,
  // over 150 scans of a robot driving through it: no two people closer than their radii
  // add up to, and the room still holds most of the crowd in every scan.
  LaserSimulatorOptions o;
  o.people = 30;
  LaserSimulator laser(room_caster(), o, 11);
  size_t placed = 0, scans = 0;
  for (int k = 0; k < 150; ++k) {
    const Pose robot{1 + 0.1 * k, 8 - 0.03 * k, -0.2 + 0.01 * k};
    laser.scan(robot);
    const std::vector<Person>& people = laser.people();
    for (size_t i = 0; i < people.size(); ++i) {
      if (!(people[i].radius > 0)) continue;
      ++placed;
      for (size_t j = i + 1; j < people.size(); ++j) {
        if (!(people[j].radius > 0)) continue;
        ASSERT_GE(distance(people[i].centre, people[j].centre), people[i].radius + people[j].radius - 1e-12)
            << "scan " << k << ": people " << i << " and " << j << " overlap";
      }
    }
    ++scans;
  }
  EXPECT_GT(static_cast<double>(placed) / scans, 0.8 * 30);
}

}  // namespace
}  // namespace fleetmap::localization
