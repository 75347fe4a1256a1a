// The twin oracle of the localization trials (client/sim/twin_places.h): in a hall of
// pillars on an 8 m grid, a start whose 15 m of view holds only pillars has a twin one
// grid step away (the same scans, whatever the turns), and a start that sees two walls
// of the hall has none.
#include "client/sim/twin_places.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "client/sim/localization_trials.h"
#include "common/raycast/sweep_ray_caster.h"

namespace fleetmap::localization {
namespace {

struct Hall {
  Map map = load_map_file("gen:hall");  // 60 m x 40 m, pillars at x 6 + 8i, y 4 + 8j
  std::unique_ptr<RayCaster> world = make_fast_ray_caster(map, RayCasterOptions{});
  GlobalSearch search{map, [] {
                        GlobalSearchOptions o;
                        o.field.margin = 15;
                        return o;
                      }()};
  std::vector<double> beams = evenly_spread_angles(131, kPi);

  // A look around as the trials make it: six turns of 60 degrees in place.
  static std::vector<Pose> look_around(const Pose& start) {
    std::vector<Pose> path{start};
    for (int k = 1; k <= 6; ++k) path.push_back({start.x, start.y, normalize_angle(start.theta + k * deg2rad(60.0))});
    return path;
  }
  TwinCheck check(const Pose& start) const { return find_twin(*world, search, look_around(start), beams, deg2rad(3.0)); }
};

TEST(TwinPlaces, AStartAmongPillarsOnlyHasATwinOneGridStepAway) {
  const Hall h;
  // Every wall of the hall is 16 m or more away; the pillars repeat every 8 m.
  const Pose start{26.3, 16.2, deg2rad(20.0)};
  const TwinCheck t = h.check(start);
  ASSERT_TRUE(t.twin);
  EXPECT_LT(t.mean_z2, 0.1);
  // The twin is the start moved by a step of the pillars' grid, same heading.
  const double dx = t.place.x - start.x, dy = t.place.y - start.y;
  EXPECT_NEAR(dx, 8 * std::round(dx / 8), 0.02);
  EXPECT_NEAR(dy, 8 * std::round(dy / 8), 0.02);
  EXPECT_GE(std::hypot(dx, dy), 7.9);
  EXPECT_LT(std::fabs(angle_diff(t.place.theta, start.theta)), deg2rad(0.2));
}

TEST(TwinPlaces, AStartThatSeesTheHallsCornerHasNone) {
  const Hall h;
  // 3 m from the west wall and 2 m from the south one: a step of the grid moves both.
  const Pose start{3.0, 2.0, deg2rad(35.0)};
  const TwinCheck t = h.check(start);
  EXPECT_FALSE(t.twin);
  EXPECT_GT(t.tried, 0);
  EXPECT_GT(t.mean_z2, 0.3);  // the best other place differs by more than half the noise, RMS
}

// Places named by the caller (a verdict's) are checked alone when the search is off:
// one grid step away, 0.1 m and 0.5 degrees off, is refined onto the twin; half a step
// away is not a twin.
TEST(TwinPlaces, APlaceTheCallerNamesIsCheckedLikeTheSearchs) {
  const Hall h;
  const Pose start{26.3, 16.2, deg2rad(20.0)};
  TwinOptions only;
  only.candidates = 0;
  const auto path = Hall::look_around(start);
  const TwinCheck named = find_twin(*h.world, h.search, path, h.beams, deg2rad(3.0), only,
                                    {{start.x + 8.1, start.y - 0.05, start.theta + deg2rad(0.5)}});
  ASSERT_TRUE(named.twin);
  EXPECT_EQ(named.tried, 1);
  EXPECT_NEAR(named.place.x, start.x + 8, 0.02);
  EXPECT_NEAR(named.place.y, start.y, 0.02);
  const TwinCheck half = find_twin(*h.world, h.search, path, h.beams, deg2rad(3.0), only, {{start.x + 4, start.y, start.theta}});
  EXPECT_FALSE(half.twin);
  EXPECT_EQ(half.tried, 1);
  EXPECT_FALSE(find_twin(*h.world, h.search, path, h.beams, deg2rad(3.0), only).twin);  // nothing to try
}

// People hide the walls behind them, so a place told from the start only by what they
// hide is a twin among them; a place whose own walls or pillars would stand in front of
// them is not.
TEST(TwinPlaces, AmongPeopleOnlyWhatTheyLeaveToSeeTellsAPlace) {
  const Hall h;
  const Pose start{3.0, 2.0, deg2rad(35.0)};  // it sees the hall's corner: no twin on the map alone
  const auto path = Hall::look_around(start);
  TwinOptions only;
  only.candidates = 0;
  // One step of the pillars' grid along the diagonal: the same pillars around it, but the
  // hall's walls 10 m and more away instead of 2-3 m.
  const Pose diagonal{start.x + 8, start.y + 8, start.theta};
  const Pose half{start.x + 4, start.y, start.theta};  // a pillar 2.2 m from it, none there from the start
  ASSERT_FALSE(find_twin(*h.world, h.search, path, h.beams, deg2rad(3.0), only, {diagonal}).twin);
  // A crowd 0.5 m in front of whatever each beam of the start meets, on every beam.
  PeopleInPath crowd;
  for (const Pose& p : path) {
    std::vector<double> ranges(h.beams.size());
    h.world->cast_scan(p.point(), p.theta, h.beams, ranges.data());
    for (double& r : ranges) r -= 0.5;
    crowd.ranges.push_back(ranges);
    crowd.stopped.emplace_back(h.beams.size(), 1);
  }
  const TwinCheck hidden = find_twin(*h.world, h.search, path, h.beams, deg2rad(3.0), only, {diagonal}, &crowd);
  EXPECT_TRUE(hidden.twin);
  EXPECT_LT(hidden.mean_z2, 0.01);
  const TwinCheck in_front = find_twin(*h.world, h.search, path, h.beams, deg2rad(3.0), only, {half}, &crowd);
  EXPECT_FALSE(in_front.twin);
  EXPECT_GT(in_front.mean_z2, 0.3);
  // A record missing a scan of the path is left out: the map alone decides, and nothing
  // is read past its end.
  PeopleInPath short_record = crowd;
  short_record.ranges.pop_back();
  EXPECT_FALSE(find_twin(*h.world, h.search, path, h.beams, deg2rad(3.0), only, {diagonal}, &short_record).twin);
  // People on no beam: the map alone decides, as without them.
  for (auto& s : crowd.stopped) std::fill(s.begin(), s.end(), 0);
  EXPECT_FALSE(find_twin(*h.world, h.search, path, h.beams, deg2rad(3.0), only, {diagonal}, &crowd).twin);
}

TEST(TwinPlaces, NoPathOrNoBeamsHasNoTwin) {
  const Hall h;
  EXPECT_FALSE(find_twin(*h.world, h.search, {}, h.beams, deg2rad(3.0)).twin);
  EXPECT_FALSE(find_twin(*h.world, h.search, {{26.3, 16.2, 0}}, {}, deg2rad(3.0)).twin);
}

}  // namespace
}  // namespace fleetmap::localization
