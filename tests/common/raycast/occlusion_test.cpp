// The one-occluder test of the candidate lists' culling (common/raycast/occlusion.h):
// a wall may be dropped from a cell's list only when the occluder hides all of it from
// every point of the cell. The expected answers come from the lines drawn by hand below.
#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>
#include <utility>

#include "common/raycast/occlusion.h"

namespace fleetmap {
namespace {

const Rect kCell{0, 0, 1, 1};

bool hidden(Point o1, Point o2, Point w1, Point w2) {
  return hides(prepare_segment(o1, o2), prepare_segment(w1, w2), kCell);
}

TEST(Occlusion, LongWallInFrontHidesAShortOneBehind) {
  // Every line from the cell to x = 6, y in [0, 1] crosses x = 3 within y in [0, 1].
  EXPECT_TRUE(hidden({3, -5}, {3, 6}, {6, 0}, {6, 1}));
  EXPECT_TRUE(hidden({3, 6}, {3, -5}, {6, 1}, {6, 0}));  // either orientation
}

TEST(Occlusion, WallReachingPastTheOccludersShadowIsKept) {
  // From (0, 1) to (6, 20) the line crosses x = 3 at y = 10.5, past the occluder's end.
  EXPECT_FALSE(hidden({3, -5}, {3, 6}, {6, 0}, {6, 20}));
}

TEST(Occlusion, HiddenFromTheCentreButSeenFromACorner) {
  // From the centre (0.5, 0.5) the lines to (6, 0) and (6, 1) cross x = 3 at y = 0.27 and
  // 0.73, inside [0.2, 0.8]; from the corner (1, 0) the line to (6, 0) passes at y = 0.
  EXPECT_FALSE(hidden({3, 0.2}, {3, 0.8}, {6, 0}, {6, 1}));
}

TEST(Occlusion, OccluderOnTheWrongSideOrThroughTheCell) {
  EXPECT_FALSE(hidden({8, -5}, {8, 6}, {6, 0}, {6, 1}));      // behind the wall
  EXPECT_FALSE(hidden({0.5, -5}, {0.5, 6}, {6, 0}, {6, 1}));  // through the cell
  EXPECT_FALSE(hidden({-3, -5}, {-3, 6}, {6, 0}, {6, 1}));    // behind the cell
}

TEST(Occlusion, WallTouchingTheOccluderIsKept) {
  // The wall's end lies on the occluder's line: no margin, so no proof.
  EXPECT_FALSE(hidden({3, -5}, {3, 6}, {3, 0}, {6, 1}));
}

// Two walls that meet, as one occluder (hides_joint). Each "seen" case also casts the
// ray that reaches the wall first, so a rule that dropped it would change a range.
bool hidden_by_joint(Point a, Point b, Point b2, Point c, Point w1, Point w2) {
  return hides_joint(prepare_segment(a, b), prepare_segment(b2, c), prepare_segment(w1, w2), kCell);
}

// Whether the ray from o towards q meets the wall before either occluder.
bool wall_seen(Point o, Point q, Point w1, Point w2, std::initializer_list<std::pair<Point, Point>> occluders) {
  const Point v = q - o;
  const Point d = (1 / std::sqrt(dot(v, v))) * v;
  const double to_wall = ray_segment_distance(w1, w2, o, d);
  for (const auto& [a, b] : occluders)
    if (ray_segment_distance(a, b, o, d) <= to_wall) return false;
  return to_wall < kNoHit;
}

TEST(Occlusion, WallDrawnInTwoPiecesHidesWhatNeitherPieceHides) {
  // x = 3 from y = -5 to 6, drawn as two segments meeting at (3, 0.5): each piece alone
  // lets the lines from some corner past its end at y = 0.5.
  EXPECT_FALSE(hidden({3, -5}, {3, 0.5}, {6, 0}, {6, 1}));
  EXPECT_FALSE(hidden({3, 0.5}, {3, 6}, {6, 0}, {6, 1}));
  EXPECT_TRUE(hidden_by_joint({3, -5}, {3, 0.5}, {3, 0.5}, {3, 6}, {6, 0}, {6, 1}));
  EXPECT_TRUE(hidden_by_joint({3, 6}, {3, 0.5}, {3, 0.5}, {3, -5}, {6, 0}, {6, 1}));  // either orientation
}

TEST(Occlusion, WallSeenThroughTheGapBetweenPiecesIsKept) {
  // The pieces stop 1e-5 m apart: the ray through the gap reaches the wall.
  EXPECT_TRUE(wall_seen({0.5, 0.5}, {3, 0.500005}, {6, 0}, {6, 1}, {{{3, -5}, {3, 0.5}}, {{3, 0.50001}, {3, 6}}}));
  EXPECT_FALSE(hidden_by_joint({3, -5}, {3, 0.5}, {3, 0.50001}, {3, 6}, {6, 0}, {6, 1}));
}

TEST(Occlusion, WallBehindACornerIsHidden) {
  // Up x = 3 to (3, 0.5), then on to (4, 6): the cell faces the corner; every line from
  // the cell to x = 6, y in [0, 1], crosses one of the two sides.
  EXPECT_FALSE(hidden({3, -5}, {3, 0.5}, {6, 0}, {6, 1}));
  EXPECT_FALSE(hidden({3, 0.5}, {4, 6}, {6, 0}, {6, 1}));
  EXPECT_TRUE(hidden_by_joint({3, -5}, {3, 0.5}, {3, 0.5}, {4, 6}, {6, 0}, {6, 1}));
}

TEST(Occlusion, WallPastTheCornersFarEndIsKept) {
  // From (0, 1) to (6, 19) the line passes x = 3 at y = 10 and x = 4 at y = 13, above
  // both sides (the corner ends at (4, 6)).
  EXPECT_TRUE(wall_seen({0, 1}, {6, 19}, {6, 0}, {6, 20}, {{{3, -5}, {3, 0.5}}, {{3, 0.5}, {4, 6}}}));
  EXPECT_FALSE(hidden_by_joint({3, -5}, {3, 0.5}, {3, 0.5}, {4, 6}, {6, 0}, {6, 20}));
}

TEST(Occlusion, WallInsideTheCornersTriangleIsKept) {
  // A V opening towards the cell, (3, -5) to (8, 0.5) to (3, 6): its chord x = 3 hides
  // x = 6, y in [0, 1] from the cell, but the wall stands inside the V, in plain sight.
  EXPECT_TRUE(wall_seen({0.5, 0.5}, {6, 0.5}, {6, 0}, {6, 1}, {{{3, -5}, {8, 0.5}}, {{8, 0.5}, {3, 6}}}));
  EXPECT_TRUE(hidden({3, -5}, {3, 6}, {6, 0}, {6, 1}));  // the chord alone
  EXPECT_FALSE(hidden_by_joint({3, -5}, {8, 0.5}, {8, 0.5}, {3, 6}, {6, 0}, {6, 1}));
}

TEST(Occlusion, CellOnTheLineOfASideIsRefused) {
  // The cell straddles the line y = 0.5 of the second side: rays from it graze that side.
  EXPECT_FALSE(hidden_by_joint({3, -5}, {3, 0.5}, {3, 0.5}, {4, 0.5}, {6, 0}, {6, 1}));
}

}  // namespace
}  // namespace fleetmap
