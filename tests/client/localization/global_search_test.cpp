// GlobalSearch (client/localization/global_search.h): the branch and bound finds what an
// exhaustive scan of every cell and heading finds, and on seeded scans of the real maps
// the true pose's place is among the candidates the filter keeps.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "client/sim/drive_simulator.h"
#include "client/localization/free_space.h"
#include "client/localization/global_search.h"
#include "client/sim/laser_simulator.h"
#include "common/io/amrl_import.h"
#include "common/raycast/grid_ray_caster.h"
#include "tests/client/test_maps.h"

namespace fleetmap::localization {
namespace {

GlobalSearchOptions options_for(double rmax) {
  GlobalSearchOptions o;
  o.field.margin = rmax;
  return o;
}

TEST(GlobalSearch, BestCandidateIsTheTruthInTheRoom) {
  const Map m = test::room_map();
  const auto world = std::make_shared<GridRayCaster>(m, RayCasterOptions{0.3, 15.0});
  const GlobalSearch search(m, options_for(15.0));
  LaserSimulator laser(world, {}, 7);
  for (const Pose truth : {Pose{2.3, 7.1, 0.2}, Pose{16.4, 2.2, 2.0}, Pose{9.6, 3.3, -1.2}}) {
    const std::vector<double> scan = laser.scan(truth);
    const std::vector<Candidate> c = search.search(scan, laser.beam_angles(), 15.0, truth.theta + deg2rad(2.0),
                                                   deg2rad(3.0), 10);
    ASSERT_FALSE(c.empty());
    EXPECT_LT(distance(c[0].pose, truth), 0.15) << truth.x << ", " << truth.y;
    EXPECT_LT(std::fabs(angle_diff(c[0].pose.theta, truth.theta)), deg2rad(1.0));
    for (size_t k = 1; k < c.size(); ++k) EXPECT_LE(c[k].score, c[k - 1].score);  // best first
  }
}

TEST(GlobalSearch, BranchAndBoundFindsTheExhaustiveBest) {
  const Map m = test::room_map();
  const auto world = std::make_shared<GridRayCaster>(m, RayCasterOptions{0.3, 15.0});
  const GlobalSearch search(m, options_for(15.0));
  LaserSimulator laser(world, {}, 3);
  const Pose truth{12.2, 6.3, 2.7};
  const std::vector<double> scan = laser.scan(truth);
  const double heading = truth.theta - deg2rad(1.5), half = deg2rad(3.0);
  const std::vector<Candidate> c = search.search(scan, laser.beam_angles(), 15.0, heading, half, 5);
  ASSERT_EQ(c.size(), 5u);
  // Every cell centre of the room clear of walls, at the search's 7 headings.
  const DistanceField& f = search.field();
  const FreeSpace free_space(m);
  double best = -1e300;
  for (int iy = 0; iy < f.height(); ++iy)
    for (int ix = 0; ix < f.width(); ++ix) {
      const Point p = f.centre(ix, iy);
      if (!m.border.rect().contains(p) || f.distance(p) < search.options().clearance || !free_space.contains(p))
        continue;
      for (int k = 0; k < 7; ++k)
        best = std::max(best, search.score({p.x, p.y, heading - half + k * half / 3}, scan, laser.beam_angles(), 15.0));
    }
  EXPECT_NEAR(c[0].score, best, 1e-3);
  EXPECT_NEAR(search.score(c[0].pose, scan, laser.beam_angles(), 15.0), c[0].score, 1e-3);
}

// The coarse level only prunes: with it and without, the same K blocks, each with the
// same best pose. A coarse bound below some pose's score would lose candidates.
TEST(GlobalSearch, CoarseLevelKeepsTheSameCandidates) {
  const Map map = read_amrl_file(std::string(FLEETMAP_REAL_MAPS) + "/GDC1.vectormap.txt", AmrlOptions{});
  const auto world = std::make_shared<GridRayCaster>(map, RayCasterOptions{0.3, 15.0});
  GlobalSearchOptions flat = options_for(15.0), coarse = options_for(15.0);
  flat.coarse = 1;
  coarse.coarse = 4;
  const GlobalSearch a(map, flat), b(map, coarse);
  const FreeSpace free_space(map);
  std::mt19937_64 rng(41);
  LaserSimulator laser(world, {}, rng());
  for (int t = 0; t < 3; ++t) {
    const Pose truth = pick_start_pose(free_space, *world, laser.beam_angles(), 0.5, 0.5, rng);
    const std::vector<double> scan = laser.scan(truth);
    const std::vector<Candidate> ca = a.search(scan, laser.beam_angles(), 15.0, truth.theta, deg2rad(3.0), 300);
    const std::vector<Candidate> cb = b.search(scan, laser.beam_angles(), 15.0, truth.theta, deg2rad(3.0), 300);
    ASSERT_EQ(ca.size(), 300u);
    ASSERT_EQ(cb.size(), ca.size());
    for (size_t k = 0; k < ca.size(); ++k) {
      EXPECT_NEAR(cb[k].score, ca[k].score, 1e-3) << "trial " << t << ", candidate " << k;
      EXPECT_LT(distance(cb[k].pose, ca[k].pose), 1e-9) << "trial " << t << ", candidate " << k;
    }
    EXPECT_LT(b.last_expanded(), a.last_expanded() + 1);  // no block scored that the flat search would not
  }
}

TEST(GlobalSearch, NoReturnsNoCandidates) {
  const Map m = test::room_map();
  const GlobalSearch search(m, options_for(15.0));
  const std::vector<double> beams = evenly_spread_angles(131, kPi), nothing(131, 15.0);
  EXPECT_TRUE(search.search(nothing, beams, 15.0, 0.0, deg2rad(3.0), 10).empty());
}

// Seeded scans from start poses as bench-localization draws them; the compass within
// +-3 degrees. The filter keeps 2000 candidates (ParticleFilterOptions::search_candidates).
void expect_truth_among_candidates(const std::string& name, size_t k, int within_top, int of_top) {
  const Map map = read_amrl_file(std::string(FLEETMAP_REAL_MAPS) + "/" + name + ".vectormap.txt", AmrlOptions{});
  const auto world = std::make_shared<GridRayCaster>(map, RayCasterOptions{0.3, 15.0});
  const GlobalSearch search(map, options_for(15.0));
  const FreeSpace free_space(map);
  int found = 0, top = 0;
  const int trials = 8;
  for (int t = 0; t < trials; ++t) {
    std::mt19937_64 rng(100 + t);
    LaserSimulator laser(world, {}, rng());
    const Pose truth = pick_start_pose(free_space, *world, laser.beam_angles(), 0.5, 0.5, rng);
    std::normal_distribution<double> n(0.0, deg2rad(1.0));
    const double compass = truth.theta + std::clamp(n(rng), -deg2rad(3.0), deg2rad(3.0));
    const std::vector<Candidate> c = search.search(laser.scan(truth), laser.beam_angles(), 15.0, compass,
                                                   deg2rad(3.0), k);
    const auto hit = std::find_if(c.begin(), c.end(), [&](const Candidate& x) {
      return distance(x.pose, truth) < 0.6 && std::fabs(angle_diff(x.pose.theta, truth.theta)) < deg2rad(2.0);
    });
    found += hit != c.end();
    top += hit != c.end() && hit - c.begin() < of_top;
  }
  EXPECT_EQ(found, trials) << name << ": the true place among the " << k << " candidates";
  EXPECT_GE(top, within_top) << name << ": the true place among the first " << of_top;
}

TEST(GlobalSearch, FindsTheTruePlaceOnGdc1) { expect_truth_among_candidates("GDC1", 2000, 7, 50); }

TEST(GlobalSearch, FindsTheTruePlaceOnTheCampus) { expect_truth_among_candidates("UT_Campus", 2000, 5, 10); }

}  // namespace
}  // namespace fleetmap::localization
