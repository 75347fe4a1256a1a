// The ray/segment test every RayCaster shares (common/raycast/ray_segment.h): ordinary hits and
// the degenerate cases it decides once for all (parallel, collinear, ends, origin on it).
#include <gtest/gtest.h>

#include <cmath>

#include "common/raycast/ray_caster.h"
#include "common/raycast/ray_segment.h"

namespace fleetmap {
namespace {

constexpr double kPi = 3.14159265358979323846;

double hit(Point a, Point b, Point o, double angle) { return ray_segment_distance(a, b, o, ray_direction(angle)); }

TEST(RaySegment, PerpendicularHitAndMiss) {
  EXPECT_DOUBLE_EQ(hit({5, -1}, {5, 1}, {0, 0}, 0), 5);
  EXPECT_EQ(hit({5, -1}, {5, 1}, {0, 0}, kPi), kNoHit);      // behind
  EXPECT_EQ(hit({5, -1}, {5, 1}, {0, 0}, kPi / 2), kNoHit);  // beside
  EXPECT_EQ(hit({5, 1}, {5, 3}, {0, 0}, 0), kNoHit);         // passes below its start
  // Orientation of the segment does not matter.
  EXPECT_DOUBLE_EQ(hit({5, 1}, {5, -1}, {0, 0}, 0), 5);
}

TEST(RaySegment, ObliqueHit) {
  // Ray at 45 degrees meets x = 5 at (5, 5): distance 5 sqrt 2.
  EXPECT_NEAR(hit({5, -10}, {5, 10}, {0, 0}, kPi / 4), 5 * std::sqrt(2.0), 1e-12);
}

TEST(RaySegment, ThroughAnEndIsAHit) {
  // Exactly through the end (5, 1) and through the shared vertex of two segments.
  const double angle = std::atan2(1.0, 5.0);
  EXPECT_NEAR(hit({5, -1}, {5, 1}, {0, 0}, angle), std::sqrt(26.0), 1e-12);
  EXPECT_NEAR(hit({5, 1}, {8, 1}, {0, 0}, angle), std::sqrt(26.0), 1e-12);
  // A hair (1e-7 m) past the end: a miss.
  EXPECT_EQ(hit({5, -1}, {5, 1 - 1e-7}, {0, 0}, angle), kNoHit);
}

TEST(RaySegment, ParallelOffTheLineNeverHits) {
  EXPECT_EQ(hit({0, 1}, {10, 1}, {-5, 0}, 0), kNoHit);
  EXPECT_EQ(hit({0, 1}, {10, 1}, {-5, 1 + 1e-6}, 0), kNoHit);
  EXPECT_EQ(hit({0, 1}, {10, 1}, {-5, 0}, kPi), kNoHit);
}

TEST(RaySegment, AlongTheLineHitsTheNearerEnd) {
  EXPECT_DOUBLE_EQ(hit({0, 1}, {10, 1}, {-5, 1}, 0), 5);
  EXPECT_DOUBLE_EQ(hit({10, 1}, {0, 1}, {-5, 1}, 0), 5);    // either orientation
  EXPECT_EQ(hit({0, 1}, {10, 1}, {-5, 1}, kPi), kNoHit);    // pointing away
  EXPECT_DOUBLE_EQ(hit({0, 1}, {10, 1}, {15, 1}, kPi), 5);  // from the other side
}

TEST(RaySegment, OriginOnTheSegmentIsZeroInEveryDirection) {
  for (double a : {0.0, 0.3, kPi / 2, kPi, -kPi / 2, 2.0}) {
    EXPECT_EQ(hit({5, -1}, {5, 1}, {5, 0}, a), 0) << a;            // inside the segment
    EXPECT_EQ(hit({5, -1}, {5, 1}, {5, 1}, a), 0) << a;            // on its end
    EXPECT_EQ(hit({5, -1}, {5, 1}, {5 + 1e-10, 0.5}, a), 0) << a;  // within tolerance
  }
}

TEST(RaySegment, NearlyParallelStillExact) {
  // A ray at 1e-6 rad to a 10 km wall 1 m away meets it 1e6 m on: a hit far past any
  // rmax, computed without dividing by zero.
  const double t = hit({-1e4, 1}, {1e4, 1}, {0, 0}, 1e-6);
  EXPECT_EQ(t, kNoHit);  // the crossing (x = 1e6) is past the wall's end
  const double t2 = hit({-1e7, 1}, {1e7, 1}, {0, 0}, 1e-6);
  EXPECT_NEAR(t2, 1 / std::sin(1e-6), 1e-3);
}

TEST(RaySegment, ZeroLengthSegmentIsAPoint) {
  EXPECT_DOUBLE_EQ(hit({3, 0}, {3, 0}, {0, 0}, 0), 3);
  EXPECT_EQ(hit({3, 0}, {3, 0}, {0, 0}, 0.1), kNoHit);
}

}  // namespace
}  // namespace fleetmap
