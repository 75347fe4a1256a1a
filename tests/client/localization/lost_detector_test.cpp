// The lost detector (client/localization/lost_detector.h): scan agreement on a known room,
// the averages' verdicts, and kidnappings on the room detected and not confused with
// people in the scans.
#include "client/localization/lost_detector.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "client/sim/drive_simulator.h"
#include "client/sim/laser_simulator.h"
#include "client/sim/localization_trials.h"
#include "common/raycast/grid_ray_caster.h"
#include "common/raycast/sweep_ray_caster.h"
#include "tests/client/test_maps.h"

namespace fleetmap::localization {
namespace {

// The room, a laser of 131 beams over 180 degrees at (10, 3), and its noiseless scan.
struct RoomScan {
  const Map room = test::room_map();
  const GridRayCaster caster{room, {0.3, 15.0}};
  const std::vector<double> beams = evenly_spread_angles(131, kPi);
  const Pose at{10, 3, 0};
  std::vector<double> ranges = std::vector<double>(beams.size());
  RoomScan() { caster.cast_scan(at.point(), at.theta, beams, ranges.data()); }
  // The scan with a straight front `metres` ahead (a wall the map lacks, or a row of
  // people) across the beams within 1 rad of ahead, where it is nearer than the room.
  std::vector<double> with_front_at(double metres) const {
    std::vector<double> s = ranges;
    for (size_t j = 0; j < beams.size(); ++j)
      if (std::fabs(beams[j]) < 1.0) s[j] = std::min(s[j], metres / std::cos(beams[j]));
    return s;
  }
};

// Evidence of beam counts alone: no pieces nor scan kept, as from a detector that does
// not compare scans.
ScanEvidence counts(size_t agree, size_t open, size_t against) {
  ScanEvidence e;
  e.agree = agree;
  e.open = open;
  e.against = against;
  return e;
}

// The share the detector takes from a scan (LostDetector::update).
double scan_agreement(const RayCaster& caster, const Pose& pose, const std::vector<double>& beams,
                      const std::vector<double>& ranges, const LostDetectorOptions& options = {}) {
  return scan_evidence(caster, pose, beams, ranges, options).share(options.open_beam_weight);
}

TEST(ScanAgreement, CountsTheBeamsWithinTheTolerance) {
  auto [room, caster, beams, at, ranges] = RoomScan();
  EXPECT_DOUBLE_EQ(scan_agreement(caster, at, beams, ranges), 1.0);
  // Ten beams shortened by 2 m (people in front of the wall) are left out: the map does
  // not hold people. Ten beams 2 m longer than the walls allow disagree.
  for (size_t j = 0; j < 10; ++j) ranges[j * 13] -= 2.0;
  EXPECT_DOUBLE_EQ(scan_agreement(caster, at, beams, ranges), 1.0);
  for (size_t j = 0; j < 10; ++j) ranges[j * 13 + 1] += 2.0;
  EXPECT_NEAR(scan_agreement(caster, at, beams, ranges), 111.0 / 121.0, 1e-12);
  // Within the tolerance is agreement.
  ranges[5] += 0.4;
  EXPECT_NEAR(scan_agreement(caster, at, beams, ranges), 111.0 / 121.0, 1e-12);
  // Every beam blocked right in front of the laser: nothing contradicts the pose.
  EXPECT_DOUBLE_EQ(scan_agreement(caster, at, beams, std::vector<double>(beams.size(), 0.2)), 1.0);
  // The same scan seen from elsewhere, turned around, fits far worse.
  EXPECT_LT(scan_agreement(caster, {17, 7, 3.0}, beams, ranges), 0.5);
  EXPECT_THROW(scan_agreement(caster, at, beams, std::vector<double>(3, 1.0)), std::invalid_argument);
}

// By default a beam stopped short on a straight piece longer than people counts against
// the pose (unmapped_walls.h): a wall 2 m ahead that the map does not hold (the end of a
// look-alike corridor) does; a person, or the same wall when the option is off, does not.
TEST(ScanAgreement, AWallTheMapLacksCountsAgainstThePose) {
  const RoomScan r;
  const auto& [room, caster, beams, at, ranges] = r;
  const std::vector<double> wall = r.with_front_at(2.0);
  EXPECT_LT(scan_agreement(caster, at, beams, wall), 0.7);
  LostDetectorOptions off;
  off.count_unmapped_walls = false;
  EXPECT_DOUBLE_EQ(scan_agreement(caster, at, beams, wall, off), 1.0);
  std::vector<double> person = ranges;
  // A person is round: their returns bulge towards the laser.
  for (size_t j = 55; j < 75; ++j) {
    const double u = (static_cast<double>(j) - 64.5) / 10.0;  // -1 .. 1 across the person
    person[j] = 1.5 - 0.25 * std::sqrt(std::max(0.0, 1 - u * u));
  }
  EXPECT_DOUBLE_EQ(scan_agreement(caster, at, beams, person), 1.0);
}

// The wall's returns come back in the laser's frame, one piece, with the scan as it was
// read: what the detector looks through at the next scans' pieces
// (unmapped_wall_seen_through), and only for it.
TEST(ScanEvidence, PlacesTheReturnsOnAWallTheMapLacks) {
  const RoomScan r;
  const auto& [room, caster, beams, at, ranges] = r;
  const std::vector<double> wall = r.with_front_at(2.0);
  LostDetectorOptions o;
  o.unmapped_wall_seen_through = 0.3;
  const ScanEvidence e = scan_evidence(caster, at, beams, wall, o);
  ASSERT_EQ(e.unmapped_walls.size(), 1u);
  EXPECT_EQ(e.unmapped_walls[0].size(), e.against);
  for (const Point& p : e.unmapped_walls[0]) {  // in the laser's frame: 2 m ahead
    EXPECT_NEAR(p.x, 2.0, 1e-9);
    EXPECT_LT(std::fabs(p.y), 2.0 * std::tan(1.0) + 1e-9);
  }
  EXPECT_TRUE(scan_evidence(caster, at, beams, ranges, o).unmapped_walls.empty());
  // A detector that does not compare them is not handed them, nor the scan.
  LostDetectorOptions off;
  off.unmapped_wall_seen_through = 0;
  const ScanEvidence plain = scan_evidence(caster, at, beams, wall, off);
  EXPECT_TRUE(plain.unmapped_walls.empty());
  EXPECT_TRUE(plain.beams.empty() && plain.ranges.empty());
  // One that looks through earlier scans keeps this one as it was read.
  EXPECT_EQ(e.beams, beams);
  EXPECT_EQ(e.ranges, wall);
}

// People step into beams that passed their place a moment before; a wall stops every beam
// that meets it. With unmapped_wall_seen_through 0.3 m, a row walking towards the laser
// (0.2 m a scan) never says lost, as the earlier scans' beams read past its place. A wall
// that stands says lost once no remembered scan saw past it: 5 scans (the memory) after it
// appeared where the room's far wall was seen, or at once, as without the option, when
// the scans before it were blind (a robot walled in by a crowd).
TEST(LostDetector, AWallTheMapLacksDoesNotCountWhereAnEarlierScanSawThroughIt) {
  const RoomScan r;
  for (double seen_through : {0.3, 0.0}) {
    LostDetectorOptions o;
    o.unmapped_wall_seen_through = seen_through;
    const auto scan_with_front_at = [&r, &o](double metres) {
      return scan_evidence(r.caster, r.at, r.beams, r.with_front_at(metres), o);
    };
    const ScanEvidence good = scan_evidence(r.caster, r.at, r.beams, r.ranges, o);
    const ScanEvidence blind = scan_evidence(r.caster, r.at, r.beams, std::vector<double>(r.beams.size(), 0.3), o);
    ASSERT_EQ(good.against, 0u);
    ASSERT_EQ(blind.against + blind.agree, 0u);
    LostDetector standing(o), walking(o), approached(o), walled_in(o);
    for (int i = 0; i < 30; ++i)
      for (LostDetector* d : {&standing, &walking, &approached, &walled_in}) d->update(good);
    int said_standing = -1, said_walking = -1, said_approached = -1, said_walled_in = -1;
    for (int k = 0; k < 12; ++k) {
      if (standing.update(scan_with_front_at(2.0)) && said_standing < 0) said_standing = k;
      if (walking.update(scan_with_front_at(3.0 - 0.2 * k)) && said_walking < 0) said_walking = k;
      // The row's scans, but the odometry says the robot drove towards what it sees.
      if (approached.update(scan_with_front_at(3.0 - 0.2 * k), Odometry{0.2, 0, 0}) && said_approached < 0)
        said_approached = k;
      if (walled_in.update(k < 5 ? blind : scan_with_front_at(2.0)) && said_walled_in < 0) said_walled_in = k;
    }
    const int memory = static_cast<int>(o.unmapped_wall_memory);
    EXPECT_EQ(said_standing, seen_through > 0 ? memory + o.hold - 1 : o.hold - 1) << seen_through;
    EXPECT_EQ(said_approached, seen_through > 0 ? memory + o.hold - 1 : o.hold - 1) << seen_through;
    EXPECT_EQ(said_walking, seen_through > 0 ? -1 : o.hold - 1) << seen_through;
    EXPECT_EQ(said_walled_in, 5 + o.hold - 1) << seen_through;
  }
}

// Evidence built by hand whose readings do not match its beams is no scan to look
// through: the next wall counts as from a detector that remembers nothing, and nothing is
// read past the readings' end.
TEST(LostDetector, EvidenceWithReadingsThatDoNotMatchItsBeamsIsNotLookedThrough) {
  const RoomScan r;
  LostDetectorOptions o;
  ASSERT_GT(o.unmapped_wall_seen_through, 0);
  ScanEvidence broken = scan_evidence(r.caster, r.at, r.beams, r.ranges, o);
  broken.ranges.resize(3, 20.0);  // three readings far beyond any wall, for 131 beams
  const ScanEvidence wall = scan_evidence(r.caster, r.at, r.beams, r.with_front_at(2.0), o);
  ASSERT_GT(wall.against, 0u);
  LostDetector d(o);
  for (int i = 0; i < 30; ++i) d.update(broken);
  int said = -1;
  for (int k = 0; k < 8 && said < 0; ++k)
    if (d.update(wall)) said = k;
  EXPECT_EQ(said, o.hold - 1);
}

// Beams that read nothing where the map has nothing within range are counted apart: with
// a laser whose range is the median wall's in the room, every beam whose wall lies beyond
// it (less the tolerance). The count comes from a caster of 15 m, not from the one scored.
TEST(ScanEvidence, CountsTheOpenBeamsApartAndLeavesThemOutOnRequest) {
  const RoomScan far;
  std::vector<double> sorted = far.ranges;
  std::sort(sorted.begin(), sorted.end());
  const double reach = sorted[sorted.size() / 2];
  const GridRayCaster near(far.room, {0.3, reach});
  std::vector<double> ranges(far.beams.size());
  near.cast_scan(far.at.point(), far.at.theta, far.beams, ranges.data());
  // A person in front on ten beams: stopped short, neither agreeing nor against.
  for (size_t j = 0; j < 10; ++j) ranges[j] = 0.9;
  const ScanEvidence e = scan_evidence(near, far.at, far.beams, ranges);
  size_t open_left = 0;
  for (size_t j = 10; j < far.beams.size(); ++j) open_left += far.ranges[j] >= reach - 0.5 ? 1 : 0;
  ASSERT_GT(open_left, 10u);
  ASSERT_LT(open_left, far.beams.size() - 20);
  EXPECT_EQ(e.agree, far.beams.size() - 10);
  EXPECT_EQ(e.open, open_left);
  EXPECT_EQ(e.against, 0u);
  EXPECT_DOUBLE_EQ(e.telling(1.0), static_cast<double>(far.beams.size() - 10));
  EXPECT_DOUBLE_EQ(e.telling(0.0), static_cast<double>(far.beams.size() - 10 - open_left));
  // The share: with the open beams and without them.
  const ScanEvidence mixed = counts(10, 6, 4);
  EXPECT_DOUBLE_EQ(mixed.share(1.0), 10.0 / 14.0);
  EXPECT_DOUBLE_EQ(mixed.share(0.0), 4.0 / 8.0);
  EXPECT_DOUBLE_EQ(ScanEvidence{}.share(1.0), 1.0);
  // At a quarter of a beam each: 4 + 4 + 1.5 telling, 5.5 agreeing.
  EXPECT_DOUBLE_EQ(mixed.telling(0.25), 9.5);
  EXPECT_DOUBLE_EQ(mixed.share(0.25), 5.5 / 9.5);
}

// A kidnapped robot whose estimate stands on open ground (the campus among 30 people,
// docs/localization.md "Open beams at a quarter"): most beams that agree are open ones,
// and a few per scan pass through walls of the map. Open beams counted whole outweigh
// those; counted at a quarter they do not, while tracking right, with walls in view,
// stays found either way.
TEST(LostDetector, OpenGroundDoesNotOutweighBeamsAgainstTheEstimate) {
  const ScanEvidence tracking = counts(60, 40, 1), kidnapped = counts(30, 29, 4);
  for (double weight : {1.0, 0.25}) {
    LostDetectorOptions o;
    o.open_beam_weight = weight;
    LostDetector d(o);
    for (int i = 0; i < 100; ++i) EXPECT_FALSE(d.update(tracking)) << weight;
    bool lost = false;
    for (int i = 0; i < 10; ++i) lost = d.update(kidnapped) || lost;
    EXPECT_EQ(lost, weight < 1.0) << "open beams weighing " << weight;
  }
}

// A blind scan (no beam tells) leaves the averages as they are but counts towards hold:
// a scan that told the pose wrong, then scans a crowd blocks whole, are lost. Counted as
// full agreement (min_telling_beams 0, as before), the blocked scans lift the fast average
// back over the bounds and the loss goes unsaid.
TEST(LostDetector, BlindScansKeepTheAveragesAndLetTimeRun) {
  const ScanEvidence good = counts(100, 0, 2), wrong = counts(0, 0, 20), blind{};
  for (size_t min_telling : {size_t{1}, size_t{0}}) {
    LostDetectorOptions o;
    o.min_telling_beams = min_telling;
    ASSERT_EQ(o.hold_against, 1);  // one scan against the pose, then blind ones (the next test: 2)
    o.ratio = 0.8;
    o.floor = 0.75;
    LostDetector d(o);
    for (int i = 0; i < 30; ++i) d.update(good);
    d.update(wrong);  // the fast average falls to 0.49, below both bounds
    const double fast = d.fast();
    ASSERT_LT(fast, o.floor);
    ASSERT_LT(fast, o.ratio * d.slow());
    ASSERT_FALSE(d.lost());
    bool lost = false;
    for (int i = 0; i < 10; ++i) lost = d.update(blind) || lost;
    if (min_telling == 1) {
      EXPECT_TRUE(lost);
      EXPECT_DOUBLE_EQ(d.fast(), fast);
    } else {
      EXPECT_FALSE(lost);
      EXPECT_GT(d.fast(), o.floor);
    }
  }
  // Blind from the start: nothing to judge, never lost.
  LostDetector d;
  for (int i = 0; i < 50; ++i) EXPECT_FALSE(d.update(blind));
}

// With hold_against 2, one scan against the pose (a crowd in a row read as a wall), then
// blind ones, is not enough; a second scan against it is, though a good scan came between.
TEST(LostDetector, OneScanAgainstThePoseThenBlindOnesIsNotEnough) {
  const ScanEvidence good = counts(100, 0, 2), wrong = counts(0, 0, 20), blind{};
  LostDetectorOptions o;
  o.hold_against = 2;
  LostDetector d(o);
  for (int i = 0; i < 30; ++i) d.update(good);
  d.update(wrong);
  for (int i = 0; i < 10; ++i) EXPECT_FALSE(d.update(blind)) << i;
  ASSERT_LT(d.fast(), o.floor);
  // A good scan lifts the fast average to 0.735, still below the floor: low, but not
  // against the pose itself.
  EXPECT_FALSE(d.update(good));
  ASSERT_LT(d.fast(), o.floor);
  EXPECT_TRUE(d.update(wrong));

  // Once the fast average is back over the floor, the count starts again.
  LostDetector e(o);
  for (int i = 0; i < 30; ++i) e.update(good);
  e.update(wrong);
  for (int i = 0; i < 3; ++i) e.update(good);
  ASSERT_GT(e.fast(), o.floor);
  EXPECT_FALSE(e.update(wrong));
  for (int i = 0; i < 10; ++i) EXPECT_FALSE(e.update(blind)) << i;
}

TEST(LostDetector, StaysFoundOnAGoodOrMerelyHarderPlace) {
  LostDetector d;
  for (int i = 0; i < 100; ++i) EXPECT_FALSE(d.update(i % 5 == 0 ? 0.8 : 0.95)) << i;
  // A harder stretch (glass walls): the fit drops to 0.78 and stays there. Above the
  // floor: not lost.
  for (int i = 0; i < 100; ++i) EXPECT_FALSE(d.update(0.78)) << i;
  // Lower still, where the slow average has learnt the place: not lost either, as the
  // fast one stays above ratio x the slow.
  for (int i = 0; i < 300; ++i) EXPECT_FALSE(d.update(i < 100 ? 0.74 : 0.66)) << i;
}

TEST(LostDetector, ALookAlikeCorridorIsLostWithinSixScans) {
  // The agreement traced on GDC1 after a robot was carried 17.6 m along a corridor whose
  // other stretch looks alike (docs/localization.md, "The floor at 0.7"): half the beams
  // that tell agree at once, more as both places run alike. A floor at 0.6 waited for
  // the places to part, 3.8 s later.
  LostDetector d;
  for (int i = 0; i < 100; ++i) d.update(1.0);  // tracking on a bare corridor: every beam agrees
  const double after_kidnap[] = {0.50, 0.52, 0.56, 0.59, 0.62, 0.65};
  for (double a : after_kidnap) d.update(a);
  EXPECT_TRUE(d.lost());
  // The fast average following about the last two scans says it at the fourth; about
  // the last three (alpha 0.3, before "A faster average"), a scan later.
  for (double alpha : {LostDetectorOptions{}.fast_alpha, 0.3}) {
    LostDetectorOptions o;
    o.fast_alpha = alpha;
    LostDetector f(o);
    for (int i = 0; i < 100; ++i) f.update(1.0);
    int scans = 0;
    while (scans < 6 && !f.update(after_kidnap[scans])) ++scans;
    EXPECT_EQ(scans + 1, alpha == 0.3 ? 5 : 4) << "alpha " << alpha;
  }
  LostDetectorOptions old_floor;
  old_floor.floor = 0.6;
  LostDetector e(old_floor);
  for (int i = 0; i < 100; ++i) e.update(1.0);
  for (double a : after_kidnap) e.update(a);
  EXPECT_FALSE(e.lost());
}

TEST(LostDetector, ALastingDropIsLostAfterHoldUpdatesAndResetForgetsIt) {
  LostDetectorOptions o;
  LostDetector d(o);
  for (int i = 0; i < 30; ++i) d.update(0.95);
  // One bad scan (a door opening in front of the laser) is not enough.
  EXPECT_FALSE(d.update(0.2));
  for (int i = 0; i < 5; ++i) d.update(0.95);
  EXPECT_FALSE(d.lost());
  int n = 0;
  while (!d.update(0.2) && n < 20) ++n;
  EXPECT_TRUE(d.lost());
  // The fast average needs a scan or two to fall under the bounds, then hold more.
  EXPECT_GE(n + 1, o.hold);
  EXPECT_LE(n + 1, o.hold + 3);
  // Lost stays lost while the scans do not fit, and while they fit again: the filter's
  // cloud is still wrong until it is initialised anew.
  for (int i = 0; i < 10; ++i) EXPECT_TRUE(d.update(0.95));
  d.reset();
  EXPECT_FALSE(d.lost());
  for (int i = 0; i < 20; ++i) EXPECT_FALSE(d.update(0.9));
}

// One scan that fits nothing (the laser's frame garbled, a truck passing close) where
// the usual fit is 0.9: the fast average falls far below both bounds and needs two good
// scans to climb back. Three scans to say lost ride it out; two would not (measured
// with the bench as an alternative to a faster average, docs/localization.md, "A faster
// average").
TEST(LostDetector, OneScanThatFitsNothingIsNotLost) {
  for (int hold : {3, 2}) {
    LostDetectorOptions o;
    o.hold = hold;  // hold alone decides here (hold_against 1)
    LostDetector d(o);
    for (int i = 0; i < 100; ++i) d.update(0.9);
    bool lost = d.update(0.0);
    for (int i = 0; i < 20; ++i) lost = d.update(0.9) || lost;
    EXPECT_EQ(lost, hold < 3) << "hold " << hold;
  }
}

TEST(LostDetector, TheSlowAverageDoesNotLearnALoss) {
  LostDetector d;
  for (int i = 0; i < 30; ++i) d.update(0.9);
  for (int i = 0; i < 200; ++i) d.update(0.3);
  EXPECT_TRUE(d.lost());
  EXPECT_GT(d.slow(), 0.8);
}

// The room, its caster, and trials of the `robust` filter at 300 particles, detection only
// (recovery is global localization, tested on its own).
struct RoomTrials {
  Map room = test::room_map();
  std::shared_ptr<const RayCaster> world = make_fast_ray_caster(room, RayCasterOptions{0.3, 15.0});
  TrialSettings s = [] {
    TrialSettings t;
    t.filter = *preset("robust");
    t.filter.particles = 300;
    t.recover_updates = 0;
    return t;
  }();
};

TEST(KidnapTrials, OnTheRoomEveryKidnapIsDetectedAndNoDriveRaisesAFalseAlarm) {
  RoomTrials t;
  TrialSettings& s = t.s;
  s.kidnaps = 4;
  s.kidnap_after = 5;
  s.false_alarm_drive = 40;
  s.laser.people = 3;
  s.seed = 3;
  const KidnapResult k = run_kidnap_trials(t.room, t.world, s);
  EXPECT_EQ(k.trials, 4);
  EXPECT_EQ(k.detected, 4);
  EXPECT_EQ(k.false_alarms, 0);
  ASSERT_EQ(k.detect_updates.size(), 4u);
  for (int u : k.detect_updates) EXPECT_LE(u * s.scan_period_s, 3.0);  // within 3 s
  EXPECT_GE(k.driven_without_kidnap, 4 * 5 + 40);
}

// A detector that cries wolf (both bounds above any fit) says "lost" every few scans of a
// filter that tracks right: each cry is a false alarm of a right pose, none of a lost
// filter, and the drive has no slip left unsaid.
TEST(KidnapTrials, ADetectorThatCriesWolfIsCountedAsFalseAlarmsOfARightPose) {
  RoomTrials t;
  TrialSettings& s = t.s;
  s.false_alarm_drive = 20;
  s.lost.floor = 1.1;
  s.lost.ratio = 2.0;
  s.seed = 5;
  const KidnapResult k = run_kidnap_trials(t.room, t.world, s);
  const int scans = static_cast<int>(20 / DriveOptions{}.step);
  EXPECT_GE(k.false_alarms, scans / (s.lost.warmup + s.lost.hold) / 2);
  EXPECT_EQ(k.alarms_of_right_pose, k.false_alarms);
  EXPECT_EQ(k.alarms_while_off, 0);
  EXPECT_EQ(k.slips_unsaid, 0);
  EXPECT_GE(k.scans_without_kidnap, scans);
  EXPECT_EQ(k.blind_scans, 0);  // a closed room: every scan sees walls
}

}  // namespace
}  // namespace fleetmap::localization
