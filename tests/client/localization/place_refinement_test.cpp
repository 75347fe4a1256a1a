// refine_place (client/localization/place_refinement.h): coordinate ascent to the best
// pose near a start, on scores whose peak is known.
#include <gtest/gtest.h>

#include <cmath>

#include "client/localization/place_refinement.h"

namespace fleetmap::localization {
namespace {

// A smooth peak at `top`, narrower in heading than in position, as a scan's likelihood is.
auto peak_at(const Pose& top) {
  return [top](const Pose& p) {
    const double dx = p.x - top.x, dy = p.y - top.y, dt = angle_diff(p.theta, top.theta);
    return -(dx * dx + dy * dy) / (2 * 0.05 * 0.05) - dt * dt / (2 * deg2rad(0.5) * deg2rad(0.5));
  };
}

TEST(PlaceRefinement, ClimbsFromTheSearchGridToAPeakBetweenItsSteps) {
  const Pose top{3.037, -1.262, 0.4123};
  const RefinedPlace r = refine_place({3.1, -1.2, 0.4123 + deg2rad(1.0)}, peak_at(top));
  EXPECT_NEAR(r.pose.x, top.x, 0.0125);
  EXPECT_NEAR(r.pose.y, top.y, 0.0125);
  EXPECT_NEAR(angle_diff(r.pose.theta, top.theta), 0.0, deg2rad(0.125));
  EXPECT_DOUBLE_EQ(r.score, peak_at(top)(r.pose));
  EXPECT_GT(r.score, peak_at(top)({3.1, -1.2, 0.4123 + deg2rad(1.0)}));
}

TEST(PlaceRefinement, StaysAtAPeakAndCrossesThePiBoundary) {
  const Pose top{0, 0, kPi - deg2rad(0.2)};
  const RefinedPlace stay = refine_place(top, peak_at(top));
  EXPECT_EQ(stay.pose.x, top.x);
  EXPECT_EQ(stay.pose.theta, top.theta);
  const RefinedPlace across = refine_place({0, 0, -kPi + deg2rad(0.6)}, peak_at(top));
  EXPECT_NEAR(angle_diff(across.pose.theta, top.theta), 0.0, deg2rad(0.125));
}

TEST(PlaceRefinement, BoundsItsMoves) {
  RefineOptions o;
  o.max_moves = 3;
  const RefinedPlace r = refine_place({0, 0, 0}, peak_at({5, 5, 0}), o);
  EXPECT_NEAR(r.pose.x + r.pose.y, 0.3, 1e-9);  // three steps of 0.1 m towards the peak
  EXPECT_LE(r.evaluations, 1 + 3 * 6);
}

}  // namespace
}  // namespace fleetmap::localization
