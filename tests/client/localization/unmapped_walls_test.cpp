// Straight pieces among the returns stopped short (client/localization/unmapped_walls.h):
// a wall is found, people are not, however they stand.
#include "client/localization/unmapped_walls.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "client/localization/pose.h"
#include "common/raycast/ray_caster.h"

namespace fleetmap::localization {
namespace {

// 131 beams over 180 degrees, each reading the nearest of the discs (people) and walls
// along it, or 15 m (no return). Every return is one stopped short: the map holds none.
struct Scan {
  std::vector<double> beams = evenly_spread_angles(131, kPi);
  std::vector<double> ranges = std::vector<double>(beams.size(), 15.0);

  std::vector<uint8_t> stopped_short() const {
    std::vector<uint8_t> f(ranges.size());
    for (size_t j = 0; j < ranges.size(); ++j) f[j] = ranges[j] < 15.0 ? 1 : 0;
    return f;
  }

  void disc(double cx, double cy, double r) {
    for (size_t j = 0; j < beams.size(); ++j) {
      const double dx = std::cos(beams[j]), dy = std::sin(beams[j]);
      const double b = dx * cx + dy * cy, c = cx * cx + cy * cy - r * r, disc = b * b - c;
      if (disc < 0) continue;
      const double t = b - std::sqrt(disc);
      if (t > 0) ranges[j] = std::min(ranges[j], t);
    }
  }
  // The line x = x0 (a wall across the laser's view, x0 ahead) from y0 to y1.
  void wall(double x0, double y0, double y1) {
    for (size_t j = 0; j < beams.size(); ++j) {
      const double dx = std::cos(beams[j]);
      if (dx <= 1e-9) continue;
      const double t = x0 / dx, y = t * std::sin(beams[j]);
      if (y >= y0 && y <= y1) ranges[j] = std::min(ranges[j], t);
    }
  }
  size_t flagged(const UnmappedWallOptions& o = {}) const {
    const std::vector<uint8_t> f = unmapped_wall_returns(ranges, beams, stopped_short(), o);
    return static_cast<size_t>(std::count(f.begin(), f.end(), 1));
  }
};

// Two walls at different depths are two pieces: each return carries its own wall's
// number, the same on all of one wall, and unmapped_wall_returns flags exactly those.
TEST(UnmappedWalls, EachPieceHasItsNumber) {
  Scan s;
  s.wall(2.0, -3.0, -0.5);
  s.wall(4.0, 0.5, 4.0);
  const std::vector<int> pieces = unmapped_wall_pieces(s.ranges, s.beams, s.stopped_short());
  const std::vector<uint8_t> flags = unmapped_wall_returns(s.ranges, s.beams, s.stopped_short());
  int right = -1, left = -1;
  for (size_t j = 0; j < s.beams.size(); ++j) {
    EXPECT_EQ(flags[j], pieces[j] > 0 ? 1 : 0) << j;
    if (pieces[j] == 0) continue;
    int& mine = s.beams[j] < 0 ? right : left;
    if (mine < 0) mine = pieces[j];
    EXPECT_EQ(pieces[j], mine) << j;
  }
  EXPECT_GT(right, 0);
  EXPECT_GT(left, 0);
  EXPECT_NE(right, left);
  EXPECT_THROW(unmapped_wall_pieces(s.ranges, s.beams, std::vector<uint8_t>(3, 1)), std::invalid_argument);
}

TEST(UnmappedWalls, AWallAcrossTheScanIsFound) {
  Scan s;
  s.wall(2.0, -3.0, 3.0);  // 6 m of wall 2 m ahead: the beams meet it within 56 degrees of head on
  const std::vector<uint8_t> f = unmapped_wall_returns(s.ranges, s.beams, s.stopped_short());
  size_t on_wall = 0;
  for (size_t j = 0; j < s.beams.size(); ++j) {
    const bool hits = s.ranges[j] < 15.0;
    ASSERT_EQ(hits, std::fabs(s.beams[j]) < std::atan(1.5)) << j;
    on_wall += hits ? 1 : 0;
    EXPECT_EQ(f[j], hits ? 1 : 0) << j;
  }
  EXPECT_GT(on_wall, 70u);
  // Where the beams graze a wall (beyond 75 degrees), they do not count: a wall along
  // the laser's left, 0.5 m away, 12 m long, is found only from 0 to 1.9 m ahead.
  Scan side;
  for (size_t j = 0; j < side.beams.size(); ++j) {
    const double dy = std::sin(side.beams[j]);
    if (dy > 1e-9 && 0.5 / dy * std::cos(side.beams[j]) <= 12.0) side.ranges[j] = 0.5 / dy;
  }
  const std::vector<uint8_t> g = unmapped_wall_returns(side.ranges, side.beams, side.stopped_short());
  for (size_t j = 0; j < side.beams.size(); ++j) {
    if (side.ranges[j] >= 15.0) continue;
    const double incidence = kPi / 2 - side.beams[j];
    if (incidence < 0.99 * 5 * kPi / 12) {
      EXPECT_EQ(g[j], 1) << j;
    }
    if (incidence > 1.01 * 5 * kPi / 12) {
      EXPECT_EQ(g[j], 0) << j;
    }
  }
  // With the laser's noise (5 cm) it still is.
  std::mt19937_64 rng(7);
  std::normal_distribution<double> noise(0, 0.05);
  Scan noisy = s;
  for (double& r : noisy.ranges)
    if (r < 15.0) r += noise(rng);
  EXPECT_GE(noisy.flagged(), on_wall - 4);
  // A few lone returns well off it (0.25 m; one in ten or fewer) do not break it.
  for (size_t j : {50u, 65u, 80u}) noisy.ranges[j] -= 0.25;
  EXPECT_GE(noisy.flagged(), on_wall - 8);
}

TEST(UnmappedWalls, AShortPieceIsNoWall) {
  Scan s;
  s.wall(2.0, -0.5, 0.5);  // 1 m: a cart, a door leaf
  EXPECT_GT(std::count_if(s.ranges.begin(), s.ranges.end(), [](double r) { return r < 15.0; }), 5);
  EXPECT_EQ(s.flagged(), 0u);
  UnmappedWallOptions shorter;
  shorter.min_length = 0.8;
  EXPECT_GT(s.flagged(shorter), 5u);
}

TEST(UnmappedWalls, PeopleSideBySideAreNoWall) {
  // Six people shoulder to shoulder, 2 m ahead, each a step before or behind the next
  // (0.15 m): 3 m of returns, but round ones. Six at exactly one depth would read as a
  // wall (their fronts within 0.15 m of one line, the gaps between them one beam each):
  // no rule on one scan tells them apart, and the detector waits for 3 scans of them.
  Scan row;
  for (int i = 0; i < 6; ++i) row.disc(2.0 + (i % 2 ? 0.15 : 0.0), -1.25 + 0.5 * i, 0.25);
  EXPECT_GT(std::count_if(row.ranges.begin(), row.ranges.end(), [](double r) { return r < 15.0; }), 40);
  EXPECT_EQ(row.flagged(), 0u);
  // The narrowest people (0.4 m across), close together at 1.5 m, in a slanted row.
  Scan slanted;
  for (int i = 0; i < 8; ++i) slanted.disc(1.5 + 0.1 * i, -1.6 + 0.42 * i, 0.2);
  EXPECT_EQ(slanted.flagged(), 0u);
  // A crowd at random, many draws: never a straight piece of 1.5 m.
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> x(0.8, 5), y(-4, 4), r(0.2, 0.3);
  for (int draw = 0; draw < 200; ++draw) {
    Scan crowd;
    for (int i = 0; i < 30; ++i) crowd.disc(x(rng), y(rng), r(rng));
    EXPECT_EQ(crowd.flagged(), 0u) << draw;
  }
}

TEST(UnmappedWalls, OnlyBeamsStoppedShortCountAndRunsBreakAtGaps) {
  Scan s;
  s.wall(2.0, -3.0, 3.0);
  // The middle beam is not stopped short: it splits the wall into two halves, each still
  // longer than 1.5 m; it is never flagged itself.
  std::vector<uint8_t> flags = s.stopped_short();
  const size_t mid = s.beams.size() / 2;
  flags[mid] = 0;
  std::vector<uint8_t> f = unmapped_wall_returns(s.ranges, s.beams, flags);
  EXPECT_EQ(f[mid], 0);
  EXPECT_EQ(f[mid - 1], 1);
  EXPECT_EQ(f[mid + 1], 1);
  // Every fourth beam missing: no run is 5 beams long.
  for (size_t j = 0; j < flags.size(); j += 4) flags[j] = 0;
  ASSERT_GT(std::count(flags.begin(), flags.end(), 1), 30);
  f = unmapped_wall_returns(s.ranges, s.beams, flags);
  EXPECT_EQ(std::count(f.begin(), f.end(), 1), 0);
  // Two walls at different depths side by side are two runs: the jump breaks them.
  Scan two;
  two.wall(2.0, -3.0, 0.0);
  two.wall(4.0, 0.0, 6.0);
  EXPECT_GT(two.flagged(), 40u);
  const std::vector<uint8_t> three(3, 1);
  EXPECT_THROW(unmapped_wall_returns(s.ranges, s.beams, three), std::invalid_argument);
}

}  // namespace
}  // namespace fleetmap::localization
