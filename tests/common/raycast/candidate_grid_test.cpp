// The candidate lists' cell sizes and memory (common/raycast/candidate_grid.h): cells
// finer than CandidateGrid::kRootCell are halved level by level only while the lists are
// known to fit, and the default picks small cells on the dense floor only.
#include "common/raycast/candidate_grid.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "common/io/amrl_import.h"
#include "common/raycast/sweep_ray_caster.h"

namespace fleetmap {
namespace {

const std::string kMaps = FLEETMAP_REAL_MAPS;
const RayCasterOptions kSeedLaser{0.3, 15.0};

const Map& gdc1() {
  static const Map m = read_amrl_file(kMaps + "/GDC1.vectormap.txt", AmrlOptions{});
  return m;
}

TEST(CandidateGrid, DefaultCellsFollowTheDensity) {
  EXPECT_EQ(SweepRayCaster(gdc1(), kSeedLaser).candidates().cell(), SweepOptions::kDenseCell);
  const Map campus = read_amrl_file(kMaps + "/UT_Campus.vectormap.txt", AmrlOptions{});
  EXPECT_EQ(SweepRayCaster(campus, kSeedLaser).candidates().cell(), SweepOptions::kSparseCell);
}

TEST(CandidateGrid, HalvingStopsWhereTheListsMightNotFit) {
  const LaserObstacles obstacles = prepare_laser_obstacles(gdc1(), kSeedLaser.laser_height);
  const CandidateGrid fine(obstacles, 0.5, kSeedLaser.rmax, 64u << 20, 32);
  EXPECT_EQ(fine.cell(), 0.5);
  // A budget below what 0.5 m takes: the grid stops at a coarser level, within it.
  const size_t budget = fine.memory_bytes() / 2;
  const CandidateGrid coarser(obstacles, 0.5, kSeedLaser.rmax, budget, 32);
  EXPECT_GT(coarser.cell(), 0.5);
  EXPECT_LE(coarser.memory_bytes(), budget);
}

// A 0.5 m list is taken from its 1 m parent's (the same levels from the same 4 m root):
// it names no obstacle the parent left out.
TEST(CandidateGrid, HalvedListsArePartOfTheirParents) {
  const LaserObstacles obstacles = prepare_laser_obstacles(gdc1(), kSeedLaser.laser_height);
  const CandidateGrid fine(obstacles, 0.5, kSeedLaser.rmax, 64u << 20, 32);
  const CandidateGrid parent(obstacles, 1.0, kSeedLaser.rmax, 64u << 20, 32);
  ASSERT_EQ(fine.cell(), 0.5);
  ASSERT_EQ(parent.cell(), 1.0);
  const Rect r = gdc1().border.rect();
  size_t shorter = 0;
  for (double y = r.ymin + 0.1; y < r.ymax; y += 0.7)
    for (double x = r.xmin + 0.1; x < r.xmax; x += 0.7) {
      std::set<uint32_t> ids;
      for (const CandidateGrid::Candidate& c : parent.near({x, y})) ids.insert(c.id);
      for (const CandidateGrid::Candidate& c : fine.near({x, y})) ASSERT_TRUE(ids.count(c.id)) << x << ", " << y;
      shorter += fine.near({x, y}).size() < ids.size();
    }
  EXPECT_GT(shorter, 0u);
}

}  // namespace
}  // namespace fleetmap
