// ZoomMap (client/zoom_map.h): when the robot asks for a new window (seed 002 section
// 3.4: moved a threshold distance from the window's centre, or a time-out), and where
// that window lies (common/map/map_window.h cuts it, clipped to the map's border).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "client/zoom_map.h"
#include "common/map/map_window.h"

namespace fleetmap {
namespace {

using Reason = ZoomMap::Reason;

TEST(ZoomMap, Defaults) {
  const ZoomMapOptions o;
  EXPECT_EQ(o.window_m, 60);
  EXPECT_EQ(o.refresh_distance_m, 15);
  EXPECT_EQ(o.refresh_after_s, 60);
}

TEST(ZoomMap, NoWindowYet) {
  const ZoomMap z;
  EXPECT_FALSE(z.centre());
  EXPECT_EQ(z.needs_refresh({0, 0}, 0), Reason::NoWindow);
  EXPECT_EQ(z.needs_refresh({1e6, -1e6}, 1e9), Reason::NoWindow);  // whatever the pose and time
}

TEST(ZoomMap, WindowIsCentredWhereItWasAskedFor) {
  ZoomMap z;
  z.on_window({12.5, -3}, 100);
  ASSERT_TRUE(z.centre());
  EXPECT_EQ(*z.centre(), (Point{12.5, -3}));
  EXPECT_EQ(z.needs_refresh({12.5, -3}, 100), Reason::None);
}

TEST(ZoomMap, RefreshAtTheDistanceThreshold) {
  ZoomMap z({.window_m = 60, .refresh_distance_m = 15, .refresh_after_s = 60});
  z.on_window({10, 20}, 0);
  EXPECT_EQ(z.needs_refresh({24.9, 20}, 1), Reason::None);
  EXPECT_EQ(z.needs_refresh({25, 20}, 1), Reason::Distance);  // exactly 15 m: refresh
  EXPECT_EQ(z.needs_refresh({10, 5}, 1), Reason::Distance);
  // Euclidean, not per axis: (9, 12) is 15 m away, (9, 11.9) 14.92 m.
  EXPECT_EQ(z.needs_refresh({19, 32}, 1), Reason::Distance);
  EXPECT_EQ(z.needs_refresh({19, 31.9}, 1), Reason::None);
  // Per axis, 14 m each way is 19.8 m: a square rule would miss it.
  EXPECT_EQ(z.needs_refresh({24, 34}, 1), Reason::Distance);
}

TEST(ZoomMap, RefreshAfterTheTimeOut) {
  ZoomMap z({.window_m = 60, .refresh_distance_m = 15, .refresh_after_s = 60});
  z.on_window({0, 0}, 1000);
  EXPECT_EQ(z.needs_refresh({1, 1}, 1059.9), Reason::None);
  EXPECT_EQ(z.needs_refresh({1, 1}, 1060), Reason::Timeout);  // exactly 60 s: refresh
  EXPECT_EQ(z.needs_refresh({1, 1}, 5000), Reason::Timeout);
  // Moved too far and too old: the distance is reported.
  EXPECT_EQ(z.needs_refresh({20, 0}, 5000), Reason::Distance);
  // A clock read before the window (a different clock): not old.
  EXPECT_EQ(z.needs_refresh({1, 1}, 0), Reason::None);
}

TEST(ZoomMap, ANewWindowRestartsBothRules) {
  ZoomMap z;
  z.on_window({0, 0}, 0);
  EXPECT_EQ(z.needs_refresh({16, 0}, 59), Reason::Distance);
  z.on_window({16, 0}, 59);
  EXPECT_EQ(z.needs_refresh({16, 0}, 59), Reason::None);
  EXPECT_EQ(z.needs_refresh({0, 0}, 60), Reason::Distance);  // now far from the new centre
  EXPECT_EQ(z.needs_refresh({20, 0}, 118), Reason::None);    // 4 m, 59 s
  EXPECT_EQ(z.needs_refresh({20, 0}, 119), Reason::Timeout);
}

// While no refresh is due the robot keeps at least window/2 - refresh_distance of the
// window around it on every side (away from the map's border): 60 m windows refreshed
// after 15 m leave 15 m ahead, more than the laser's RMAX (seed 000: 15 m).
TEST(ZoomMap, NoRefreshDueMeansTheRobotIsWellInsideItsWindow) {
  const ZoomMapOptions o{.window_m = 60, .refresh_distance_m = 15, .refresh_after_s = 60};
  ZoomMap z(o);
  const Point c{100, 200};
  z.on_window(c, 0);
  const Rect window = Rect::centred(c, o.window_m, o.window_m);
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> u(-40, 40);
  int inside = 0;
  for (int i = 0; i < 20000; ++i) {
    const Point p{c.x + u(rng), c.y + u(rng)};
    if (z.needs_refresh(p, 1) != Reason::None) continue;
    ++inside;
    const double margin = std::min({p.x - window.xmin, window.xmax - p.x, p.y - window.ymin, window.ymax - p.y});
    EXPECT_GT(margin, 15.0) << p.x << " " << p.y;
  }
  // pi 15^2 / 80^2 of the samples (11 %): the test did look at some.
  EXPECT_NEAR(inside / 20000.0, 3.14159265 * 225 / 6400, 0.01);
}

// The window asked for at the robot's pose (ZoomMapClient: W = H = window_m), cut by
// the server: W along x, H along y, centred on the pose, clipped to the map's border.
TEST(ZoomMap, WindowAtTheMapBorderIsClipped) {
  const Border border = Border::from_rect({0, 0, 200, 100});
  // W x H: 60 along x, 20 along y.
  EXPECT_EQ(window_rect(border, {100, 50}, 60, 20), (Rect{70, 40, 130, 60}));
  // Near the lower-left corner: what is off the map is cut off, the centre stays the pose.
  ZoomMap z;
  z.on_window({10, 5}, 0);
  EXPECT_EQ(window_rect(border, *z.centre(), 60, 60), (Rect{0, 0, 40, 35}));
  // Refreshing goes by the distance from the pose asked for, not from the clipped
  // window's centre (20, 17.5), which is 16 m away.
  EXPECT_EQ(z.needs_refresh({20, 17.5}, 1), Reason::Distance);
  EXPECT_EQ(z.needs_refresh({12, 7}, 1), Reason::None);
  // A window entirely off the map is empty.
  EXPECT_TRUE(window_rect(border, {-100, 50}, 60, 60).empty());
}

}  // namespace
}  // namespace fleetmap
