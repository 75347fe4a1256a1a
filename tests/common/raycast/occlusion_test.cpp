// The one-occluder test of the candidate lists' culling (common/raycast/occlusion.h):
// a wall may be dropped from a cell's list only when the occluder hides all of it from
// every point of the cell. The expected answers come from the lines drawn by hand below.
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace fleetmap
