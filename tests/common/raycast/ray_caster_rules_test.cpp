// Hand-computed rays (SPEC 6, seed 000 section 4.1 and Fig. 6) through every RayCaster:
// walls, walls lower than the laser, stairs from below and above, ramps, rmax, and the
// degenerate rays (origin on a segment, rays along walls and grid lines).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "common/raycast/grid_ray_caster.h"
#include "common/map/ramp.h"
#include "common/io/seed_format.h"
#include "common/raycast/seed_ray_caster.h"
#include "common/raycast/sweep_ray_caster.h"

namespace fleetmap {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kEps = 1e-9;

Obstacle make_obstacle(int id, ShapeType type, std::vector<std::array<double, 5>> segs, std::string semantic = "test") {
  Obstacle o;
  o.id = id;
  o.type = type;
  o.semantic = std::move(semantic);
  for (const auto& s : segs) o.segments.push_back({{s[0], s[1]}, {s[2], s[3]}, s[4], 1, "s", ""});
  o.compute_bound();
  return o;
}

Map make_map(std::vector<Obstacle> obstacles) {
  Map m;
  m.border = {-100, 100, 100, -100};
  m.obstacles = std::move(obstacles);
  return m;
}

// The example map's stairs (docs/map-format.md): steps at y = 18.5 + 0.3 k, k = 0..4,
// 0.15 m each, x from 44 to 50, closing segment at y = 20.
Obstacle example_stairs() {
  std::vector<std::array<double, 5>> segs;
  for (int k = 0; k < 5; ++k) segs.push_back({44, 18.5 + 0.3 * k, 50, 18.5 + 0.3 * k, 0.15 * (k + 1)});
  segs.push_back({50, 20, 44, 20, 0});
  return make_obstacle(6, ShapeType::Stairs, segs);
}

// The example map's ramp: (8,10)-(12,12), rising 0.125 m per metre along +x from x = 8.
Obstacle example_ramp() {
  return make_obstacle(7, ShapeType::Ramp,
                       {{8, 10, 12, 10, 0}, {12, 10, 12, 12, 0}, {12, 12, 8, 12, 0}, {8, 12, 8, 10, 0}},
                       "ramp,concrete," + ramp_tokens(-0.125, 0, 1, {8, 10}));
}

using Factory = std::function<std::unique_ptr<RayCaster>(const Map&, RayCasterOptions)>;
struct Kind {
  std::string name;
  Factory make;
};

std::vector<Kind> kinds() {
  return {
      {"seed", [](const Map& m, RayCasterOptions o) { return std::make_unique<SeedRayCaster>(m, o); }},
      {"grid", [](const Map& m, RayCasterOptions o) { return std::make_unique<GridRayCaster>(m, o); }},
      {"grid_plain",
       [](const Map& m, RayCasterOptions o) {
         return std::make_unique<GridRayCaster>(m, o, GridOptions{1.0, false});
       }},
      {"grid_fine",
       [](const Map& m, RayCasterOptions o) {
         return std::make_unique<GridRayCaster>(m, o, GridOptions{0.25, true});
       }},
      {"grid_coarse",
       [](const Map& m, RayCasterOptions o) {
         return std::make_unique<GridRayCaster>(m, o, GridOptions{7.0, true});
       }},
      {"sweep", [](const Map& m, RayCasterOptions o) { return std::make_unique<SweepRayCaster>(m, o); }},
      {"sweep_fine",
       [](const Map& m, RayCasterOptions o) { return std::make_unique<SweepRayCaster>(m, o, SweepOptions{0.25}); }},
      {"sweep_coarse",
       [](const Map& m, RayCasterOptions o) { return std::make_unique<SweepRayCaster>(m, o, SweepOptions{7.0}); }},
      {"fast", [](const Map& m, RayCasterOptions o) { return make_fast_ray_caster(m, o); }},
  };
}

class RayRules : public ::testing::TestWithParam<Kind> {
 protected:
  std::unique_ptr<RayCaster> make(const Map& m, double laser_height, double rmax = 15) {
    return GetParam().make(m, {laser_height, rmax});
  }
};

TEST_P(RayRules, WallAtKnownDistance) {
  const auto rc = make(make_map({make_obstacle(1, ShapeType::OpenPolygon, {{5, -10, 5, 10, 2}})}), 0.3);
  EXPECT_NEAR(rc->cast({0, 0}, 0), 5, kEps);
  EXPECT_NEAR(rc->cast({0, 0}, kPi / 4), 5 * std::sqrt(2.0), kEps);
  EXPECT_NEAR(rc->cast({2, 3}, std::atan2(-4.0, 3.0)), 5, kEps);  // 3-4-5 triangle: hits (5, -1)
  EXPECT_EQ(rc->cast({0, 0}, kPi), 15);                           // nothing behind
  EXPECT_NEAR(rc->cast({9, 0}, kPi), 4, kEps);                    // from the other side
}

TEST_P(RayRules, WallLowerThanTheLaserIsPassed) {
  const Map m = make_map({make_obstacle(1, ShapeType::OpenPolygon, {{5, -10, 5, 10, 0.2}}),
                          make_obstacle(2, ShapeType::OpenPolygon, {{8, -10, 8, 10, 2}})});
  EXPECT_NEAR(make(m, 0.3)->cast({0, 0}, 0), 8, kEps);  // 0.2 m wall passed
  EXPECT_NEAR(make(m, 0.2)->cast({0, 0}, 0), 5, kEps);  // h = hL stops (h >= hL)
  EXPECT_NEAR(make(m, 0.1)->cast({0, 0}, 0), 5, kEps);
  EXPECT_EQ(make(m, 2.5)->cast({0, 0}, 0), 15);  // laser over both
}

TEST_P(RayRules, StairsFromDownstairsStopAtTheFirstStepHigherThanTheLaser) {
  const Map m = make_map({example_stairs()});
  // Straight up from below: steps at y = 18.5 (0.15 m), 18.8 (0.3), 19.1 (0.45) ...
  EXPECT_NEAR(make(m, 0.3)->cast({47, 15}, kPi / 2), 4.1, kEps);  // 0.15 and 0.3 passed
  EXPECT_NEAR(make(m, 0.1)->cast({47, 15}, kPi / 2), 3.5, kEps);  // first step
  EXPECT_NEAR(make(m, 0.5)->cast({47, 15}, kPi / 2), 4.4, kEps);  // 0.6 m step
  EXPECT_NEAR(make(m, 0.7)->cast({47, 15}, kPi / 2), 4.7, kEps);  // 0.75 m step
  EXPECT_EQ(make(m, 0.75)->cast({47, 15}, kPi / 2), 15);          // no step higher: passes
  // Obliquely from below-left: 30 degrees over +x from (40, 17): meets y = 19.1 at
  // t = 2.1 / sin 30 = 4.2, x = 40 + 4.2 cos 30 = 43.64 < 44: outside. The 0.6 m step
  // y = 19.4: t = 4.8, x = 44.157, inside.
  EXPECT_NEAR(make(m, 0.5)->cast({40, 17}, kPi / 6), 4.8, kEps);
}

TEST_P(RayRules, StairsFromUpstairsAreCrossedWhole) {
  const Map m = make_map({example_stairs(), make_obstacle(2, ShapeType::OpenPolygon, {{30, 10, 60, 10, 2}})});
  // From the top landing down: the closing segment (y = 20) comes first, every step is
  // crossed, and the wall at y = 10 stops the ray 12 m on.
  for (double hl : {0.1, 0.3, 0.5}) EXPECT_NEAR(make(m, hl)->cast({47, 22}, -kPi / 2), 12, kEps) << hl;
  // From below the same ray up stops on a step.
  EXPECT_NEAR(make(m, 0.1)->cast({47, 12}, kPi / 2), 6.5, kEps);
  // Standing on the stairs (between y = 19.1 and 19.4), the first segment met in
  // either direction is a step: the rule stops the ray at the nearest step over hL.
  EXPECT_NEAR(make(m, 0.3)->cast({47, 19.25}, kPi / 2), 0.15, kEps);   // 0.6 m step above
  EXPECT_NEAR(make(m, 0.3)->cast({47, 19.25}, -kPi / 2), 0.15, kEps);  // 0.45 m step below
  EXPECT_NEAR(make(m, 0.5)->cast({47, 19.25}, -kPi / 2), 9.25, kEps);  // 0.45, 0.3, 0.15 passed
}

TEST_P(RayRules, RampHitWhereTheSurfaceReachesTheLaser) {
  const Map m = make_map({example_ramp()});
  // Along +x at y = 11: enters at x = 8 (z = 0), z = 0.125 (x - 8) reaches 0.3 at
  // x = 10.4: 10.4 m from x = 0.
  EXPECT_NEAR(make(m, 0.3)->cast({0, 11}, 0), 10.4, kEps);
  EXPECT_NEAR(make(m, 0.1)->cast({0, 11}, 0), 8.8, kEps);
  EXPECT_NEAR(make(m, 0.5)->cast({0, 11}, 0), 12, kEps);  // reaches 0.5 m at the top edge
  EXPECT_EQ(make(m, 0.6)->cast({0, 11}, 0), 15);          // never that high: passes
  // Obliquely, rising 1 in 4 from (6, 10.5): enters at (8, 11), reaches 0.3 m at
  // x = 10.4, y = 11.6 (inside): t = sqrt(4.4^2 + 1.1^2).
  EXPECT_NEAR(make(m, 0.3)->cast({6, 10.5}, std::atan2(1.0, 4.0)), std::hypot(4.4, 1.1), kEps);
  // Across the slope (along +y) at x = 9.6, z = 0.2 < 0.3 everywhere on the ray: passes.
  EXPECT_EQ(make(m, 0.3)->cast({9.6, 0}, kPi / 2), 15);
}

TEST_P(RayRules, RampSideHit) {
  const Map m = make_map({example_ramp()});
  // From the high end: the top edge x = 12 is at 0.5 m >= 0.3: stops on the side.
  EXPECT_NEAR(make(m, 0.3)->cast({20, 11}, kPi), 8, kEps);
  // From below at x = 11 the side y = 10 is at 0.375 m.
  EXPECT_NEAR(make(m, 0.3)->cast({11, 0}, kPi / 2), 10, kEps);
  EXPECT_NEAR(make(m, 0.3)->cast({11, 20}, -kPi / 2), 8, kEps);  // and from above
}

TEST_P(RayRules, RayFromInsideARampIgnoresIt) {
  const Map m = make_map({example_ramp(), make_obstacle(2, ShapeType::OpenPolygon, {{14, 0, 14, 20, 2}})});
  // A robot on the ramp: its laser rides parallel to the surface.
  EXPECT_NEAR(make(m, 0.1)->cast({10, 11}, 0), 4, kEps);
  EXPECT_NEAR(make(m, 0.1)->cast({8, 11}, 0), 6, kEps);  // on the outline counts as on it
  EXPECT_EQ(make(m, 0.1)->cast({10, 11}, kPi), 15);
}

TEST_P(RayRules, RangeIsCappedAtRmax) {
  const Map m = make_map({make_obstacle(1, ShapeType::OpenPolygon, {{20, -10, 20, 10, 2}})});
  EXPECT_EQ(make(m, 0.3)->cast({0, 0}, 0), 15);
  EXPECT_NEAR(make(m, 0.3, 25)->cast({0, 0}, 0), 20, kEps);
  EXPECT_EQ(make(m, 0.3, 20)->cast({0, 0}, 0), 20);               // exactly at rmax
  EXPECT_EQ(make(make_map({}), 0.3)->cast({0, 0}, 1), 15);        // empty map
  EXPECT_EQ(make(m, 0.3)->cast({500, 500}, 0), 15);               // far outside everything
  EXPECT_NEAR(make(m, 0.3, 200)->cast({-100, 0}, 0), 120, kEps);  // from far outside
}

TEST_P(RayRules, RayStartingOnASegment) {
  const auto rc = make(make_map({make_obstacle(1, ShapeType::OpenPolygon, {{5, -10, 5, 10, 2}})}), 0.3);
  for (double a : {0.0, kPi, kPi / 2, -kPi / 2, 1.0}) {
    EXPECT_EQ(rc->cast({5, 0}, a), 0) << a;
    EXPECT_EQ(rc->cast({5, 10}, a), 0) << a;  // on its end
  }
}

TEST_P(RayRules, RaysParallelToWalls) {
  const Map m = make_map({make_obstacle(1, ShapeType::OpenPolygon, {{0, 1, 30, 1, 2}}),
                          make_obstacle(2, ShapeType::OpenPolygon, {{0, -1, 30, -1, 2}}),
                          make_obstacle(3, ShapeType::OpenPolygon, {{3, 7, 6, 7, 2}, {6, 7, 6, 9, 2}})});
  const auto rc = make(m, 0.3);
  EXPECT_EQ(rc->cast({0, 0}, 0), 15);          // down a corridor
  EXPECT_EQ(rc->cast({-5, 1.5}, 0), 15);       // beside a wall
  EXPECT_NEAR(rc->cast({-5, 1}, 0), 5, kEps);  // along a wall's line: its end
  EXPECT_NEAR(rc->cast({40, -1}, kPi), 10, kEps);
  // Along grid lines (integer coordinates) and through a wall's end.
  EXPECT_NEAR(rc->cast({3, 2}, kPi / 2), 5, kEps);
  EXPECT_NEAR(rc->cast({6, 2}, kPi / 2), 5, kEps);
  EXPECT_NEAR(rc->cast({0, 7}, 0), 3, kEps);     // along y = 7 into the wall's end
  EXPECT_NEAR(rc->cast({10, 8}, kPi), 4, kEps);  // meets x = 6 at y = 8
}

TEST_P(RayRules, ClosedPolygonDoesNotLeakAtItsVertices) {
  const Map m = make_map({make_obstacle(
      1, ShapeType::ClosedPolygon, {{10, -1, 12, -1, 2}, {12, -1, 12, 1, 2}, {12, 1, 10, 1, 2}, {10, 1, 10, -1, 2}})});
  const auto rc = make(m, 0.3);
  EXPECT_NEAR(rc->cast({0, 0}, std::atan2(-1.0, 10.0)), std::hypot(10.0, 1.0), kEps);
  EXPECT_NEAR(rc->cast({0, 0}, std::atan2(1.0, 10.0)), std::hypot(10.0, 1.0), kEps);
  EXPECT_NEAR(rc->cast({0, -3}, std::atan2(2.0, 10.0)), std::hypot(10.0, 2.0), kEps);
}

TEST_P(RayRules, ScanMatchesSingleRays) {
  const Map m = read_seed_file(FLEETMAP_SOURCE_DIR "/maps/example-campus.map");
  const auto rc = make(m, 0.3);
  const std::vector<double> rel = evenly_spread_angles(131, kPi);
  std::vector<double> ranges(rel.size());
  for (Point o : {Point{30, 30}, Point{47, 15}, Point{10, 5}, Point{25, 10}}) {
    rc->cast_scan(o, 0.7, rel, ranges.data());
    for (size_t i = 0; i < rel.size(); ++i) EXPECT_NEAR(ranges[i], rc->cast(o, 0.7 + rel[i]), 1e-9);
  }
  // Known rays of the example map: the library's west wall (x = 20, 12 m) from (30, 30).
  EXPECT_NEAR(rc->cast({30, 30}, kPi), 10, kEps);
  EXPECT_NEAR(rc->cast({47, 15}, kPi / 2), 4.1, kEps);  // the lab's stairs
}

INSTANTIATE_TEST_SUITE_P(AllCasters, RayRules, ::testing::ValuesIn(kinds()),
                         [](const ::testing::TestParamInfo<Kind>& info) { return info.param.name; });

}  // namespace
}  // namespace fleetmap
