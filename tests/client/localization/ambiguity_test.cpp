// The ambiguity verdict (client/localization/ambiguity.h): on particle sets built by hand
// (the Weight rule's candidates; the Likelihood rule with scores given by hand), and on
// the filter itself in two identical rooms (must say ambiguous, both rooms), in two rooms
// that differ by one wall (must not, and name the true room), and on a cloud split evenly
// between those two rooms (the Weight rule says ambiguous, the scans say the true room).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "client/localization/ambiguity.h"
#include "client/localization/particle_filter.h"
#include "client/sim/drive_simulator.h"
#include "client/sim/laser_simulator.h"
#include "common/raycast/grid_ray_caster.h"
#include "tests/client/test_maps.h"

namespace fleetmap::localization {
namespace {

// n particles around each centre, weights in the given proportions.
void add_cluster(std::vector<Pose>& poses, std::vector<double>& weights, Pose centre, double weight, int n) {
  for (int i = 0; i < n; ++i) {
    poses.push_back({centre.x + 0.02 * (i % 5 - 2), centre.y + 0.02 * (i / 5 % 5 - 2), centre.theta});
    weights.push_back(weight / n);
  }
}

// Two rooms' clusters of 50 particles: A at x 3.2, B at x 18.2, with these weights.
struct Cloud {
  std::vector<Pose> p;
  std::vector<double> w;
};
Cloud rooms_a_b(double weight_a, double weight_b) {
  Cloud c;
  add_cluster(c.p, c.w, {3.2, 2.1, 0}, weight_a, 50);
  add_cluster(c.p, c.w, {18.2, 2.1, 0}, weight_b, 50);
  return c;
}

TEST(Ambiguity, TwoEqualClustersFarApartAreAmbiguous) {
  std::vector<Pose> p;
  std::vector<double> w;
  add_cluster(p, w, {3.2, 2.1, 0.5}, 1, 50);
  add_cluster(p, w, {18.2, 2.1, 0.5}, 1, 50);
  const Ambiguity a = find_ambiguity(p, w);
  ASSERT_TRUE(a.ambiguous());
  ASSERT_EQ(a.places.size(), 2u);
  EXPECT_NEAR(a.weights[0] + a.weights[1], 1.0, 1e-9);
  const double x0 = std::min(a.places[0].x, a.places[1].x), x1 = std::max(a.places[0].x, a.places[1].x);
  EXPECT_NEAR(x0, 3.2, 0.05);
  EXPECT_NEAR(x1, 18.2, 0.05);
  EXPECT_NEAR(a.places[0].theta, 0.5, 1e-9);
}

TEST(Ambiguity, ALightSecondClusterIsNot) {
  std::vector<Pose> p;
  std::vector<double> w;
  add_cluster(p, w, {3.2, 2.1, 0}, 0.95, 50);
  add_cluster(p, w, {18.2, 2.1, 0}, 0.05, 50);  // a nineteenth of the heaviest: below a tenth
  const Ambiguity a = find_ambiguity(p, w);
  EXPECT_FALSE(a.ambiguous());
  ASSERT_EQ(a.places.size(), 1u);
  EXPECT_NEAR(a.places[0].x, 3.2, 0.05);
  EXPECT_NEAR(a.weights[0], 0.95, 1e-9);
}

TEST(Ambiguity, OneCloudAcrossCellBordersIsOnePlace) {
  // A converged cloud straddling a cell corner, and a second lump 0.6 m away: one place.
  std::vector<Pose> p;
  std::vector<double> w;
  add_cluster(p, w, {4.0, 4.0, 0}, 1, 50);
  add_cluster(p, w, {4.6, 4.0, 0}, 1, 50);
  EXPECT_FALSE(find_ambiguity(p, w).ambiguous());
}

TEST(Ambiguity, EmptyOrWeightlessSetsHaveNoPlace) {
  EXPECT_TRUE(find_ambiguity({}, {}).places.empty());
  EXPECT_TRUE(find_ambiguity({{1, 1, 0}, {9, 9, 0}}, {0.0, 0.0}).places.empty());
  EXPECT_TRUE(find_ambiguity({}, {}, {}, [](const Pose&) { return 0.0; }).places.empty());
}

// Scores by hand: -0.2 per beam near x = 3.2 (the scans fit there), `elsewhere` away.
PlaceScore score_fitting_at_a(double elsewhere) {
  return [elsewhere](const Pose& p) { return std::fabs(p.x - 3.2) < 0.5 ? -0.2 : elsewhere; };
}

TEST(AmbiguityByLikelihood, AHeavySecondPlaceThatExplainsTheScansWorseIsNot) {
  // About equal weights, so the Weight rule says ambiguous; B is worse by 0.5 per beam
  // (a wall of the scans missing there), far beyond the margin.
  const auto [p, w] = rooms_a_b(0.52, 0.48);
  ASSERT_TRUE(find_ambiguity(p, w).ambiguous());
  const Ambiguity a = find_ambiguity(p, w, {}, score_fitting_at_a(-0.7));
  EXPECT_FALSE(a.ambiguous());
  ASSERT_EQ(a.places.size(), 1u);
  EXPECT_NEAR(a.places[0].x, 3.2, 0.05);
  EXPECT_NEAR(a.runner_up_gap, 0.5, 1e-9);
}

TEST(AmbiguityByLikelihood, PlacesThatExplainTheScansAlikeAreAmbiguous) {
  // B far lighter (a fifth of A), but within the margin of A's score: both stay.
  const auto [p, w] = rooms_a_b(0.8, 0.2);
  AmbiguityOptions o;
  const Ambiguity a = find_ambiguity(p, w, o, score_fitting_at_a(-0.2 - o.margin_per_beam / 2));
  ASSERT_TRUE(a.ambiguous());
  EXPECT_NEAR(a.places[1].x, 18.2, 0.05);
  // Just beyond the margin: B goes.
  EXPECT_FALSE(find_ambiguity(p, w, o, score_fitting_at_a(-0.2 - o.margin_per_beam * 1.5)).ambiguous());
}

TEST(AmbiguityByLikelihood, AHeaviestPlaceThatExplainsTheScansWorseIsKeptBesideTheBest) {
  // The weight says B, the scans say A: the filter's estimate (B) cannot be reported.
  const auto [p, w] = rooms_a_b(0.3, 0.7);
  const Ambiguity a = find_ambiguity(p, w, {}, score_fitting_at_a(-0.7));
  ASSERT_EQ(a.places.size(), 2u);
  EXPECT_NEAR(a.places[0].x, 18.2, 0.05);
  EXPECT_NEAR(a.places[1].x, 3.2, 0.05);
  EXPECT_NEAR(a.heaviest_gap, 0.5, 1e-9);
}

TEST(AmbiguityByLikelihood, APlaceIsScoredAtItsBestParticle) {
  // B's mean sits 0.5 m off the pose that fits; one of its heaviest particles is on it.
  std::vector<Pose> p;
  std::vector<double> w;
  add_cluster(p, w, {10.0, 2.1, 0}, 0.55, 50);
  add_cluster(p, w, {17.0, 2.1, 0}, 0.4, 50);
  p.push_back({16.7, 2.1, 0});
  w.push_back(0.05);
  const PlaceScore score = [](const Pose& q) {
    return std::fabs(q.x - 16.7) < 0.05 ? -0.2 : std::fabs(q.x - 10.0) < 0.5 ? -0.21 : -1.0;
  };
  EXPECT_TRUE(find_ambiguity(p, w, {}, score).ambiguous());
  AmbiguityOptions mean_only;
  mean_only.refine = 0;
  EXPECT_FALSE(find_ambiguity(p, w, mean_only, score).ambiguous());
}

// Rivals (AmbiguityOptions::rivals): a place the cloud has lost, given by the caller.
// One cluster at A (3.2, 2.1); the residual (higher is better, as PlaceScore) has a well
// at A and one at C (15.2, 6.1), C's worse by c_extra; each well falls off by 1 per
// 0.1 m. The filter's own score is flat: only the residual tells.
PlaceScore two_wells(double c_extra) {
  return [c_extra](const Pose& q) {
    const double da = std::hypot(q.x - 3.2, q.y - 2.1), dc = std::hypot(q.x - 15.2, q.y - 6.1);
    return -1.0 - std::min(100 * da * da, 100 * dc * dc + c_extra);
  };
}
const PlaceScore flat = [](const Pose&) { return -0.2; };
// The cloud: one cluster at A. The rival: given 0.15 m and 0.1 m off C's well.
struct OneClusterAndARival {
  std::vector<Pose> p;
  std::vector<double> w;
  std::vector<Pose> rival{{15.35, 6.0, 0}};
  OneClusterAndARival() { add_cluster(p, w, {3.2, 2.1, 0}, 1.0, 50); }
};

TEST(AmbiguityByLikelihood, ARivalAsGoodAsTheCloudsPlaceIsAPlace) {
  const auto [p, w, rival] = OneClusterAndARival();
  AmbiguityOptions o;
  // Refined onto its well.
  const Ambiguity a = find_ambiguity(p, w, o, flat, rival, two_wells(o.rival_margin_z2 / 2));
  ASSERT_TRUE(a.ambiguous());
  ASSERT_EQ(a.places.size(), 2u);
  EXPECT_NEAR(a.places[0].x, 3.2, 0.05);
  EXPECT_NEAR(a.places[1].x, 15.2, 0.01);
  EXPECT_NEAR(a.places[1].y, 6.1, 0.01);
  EXPECT_EQ(a.weights[1], 0.0);  // no particle there
  // Worse than the cloud's place by twice the margin: not a place.
  EXPECT_FALSE(find_ambiguity(p, w, o, flat, rival, two_wells(2 * o.rival_margin_z2)).ambiguous());
  // Without the rival, or with rivals off, or without a residual: one place.
  EXPECT_FALSE(find_ambiguity(p, w, o, flat, {}, two_wells(0)).ambiguous());
  EXPECT_FALSE(find_ambiguity(p, w, o, flat, rival).ambiguous());
  o.rivals = false;
  EXPECT_FALSE(find_ambiguity(p, w, o, flat, rival, two_wells(0)).ambiguous());
}

// Given, the registered residual (each scan at its own best pose near the stitched one)
// judges the refined places instead of the residual they were refined on.
TEST(AmbiguityByLikelihood, RivalsAreJudgedByTheRegisteredResidualWhenGiven) {
  const auto [p, w, rival] = OneClusterAndARival();
  const AmbiguityOptions o;
  const auto registered = [](double c_extra) {
    return RegisteredResidual([c_extra](const Pose& at) { return RegisteredScans{at, two_wells(c_extra)}; });
  };
  // The residual says alike, registered C is worse by twice the margin.
  EXPECT_FALSE(find_ambiguity(p, w, o, flat, rival, two_wells(0), registered(2 * o.rival_margin_z2)).ambiguous());
  // And the other way round.
  const Ambiguity a = find_ambiguity(p, w, o, flat, rival, two_wells(2 * o.rival_margin_z2), registered(0));
  ASSERT_TRUE(a.ambiguous());
  EXPECT_NEAR(a.places[1].x, 15.2, 0.01);
}

// Registered at the best candidate A, rival C is worse by twice the margin; registered
// at C itself, C fits better than A did: the best candidate may be the wrong one of
// the two, so both are places. If C registered at itself still fits worse, it is not.
TEST(AmbiguityByLikelihood, ARivalThatFitsBetterRegisteredAtItselfIsAPlace) {
  const auto [p, w, rival] = OneClusterAndARival();
  const AmbiguityOptions o;
  const auto registered = [&](double c_extra_at_c) {
    return RegisteredResidual([&o, c_extra_at_c](const Pose& at) {
      return RegisteredScans{at, std::hypot(at.x - 15.2, at.y - 6.1) < 0.5 ? two_wells(c_extra_at_c)
                                                                          : two_wells(2 * o.rival_margin_z2)};
    });
  };
  const Ambiguity a = find_ambiguity(p, w, o, flat, rival, two_wells(0), registered(-0.01));
  ASSERT_TRUE(a.ambiguous());
  EXPECT_NEAR(a.places[1].x, 15.2, 0.01);
  EXPECT_FALSE(find_ambiguity(p, w, o, flat, rival, two_wells(0), registered(0.01)).ambiguous());
  // Beyond the window registering at C is not tried.
  AmbiguityOptions narrow = o;
  narrow.rival_register_window_z2 = o.rival_margin_z2;
  EXPECT_FALSE(find_ambiguity(p, w, narrow, flat, rival, two_wells(0), registered(-0.01)).ambiguous());
}

// The stitched residual puts the cloud's place at A (3.2, 2.1); the scans registered at a
// place q fit best with q at `best`, and lose 0.2 per beam at A. Rival C fits those scans
// twice the margin worse than the scans fit `best`.
RegisteredResidual registered_best_at(Point best, double c_extra) {
  const double k = 0.2 / (std::pow(best.x - 3.2, 2) + std::pow(best.y - 2.1, 2));
  return [best, k, c_extra](const Pose& q) {
    const double pays = k * (std::pow(q.x - best.x, 2) + std::pow(q.y - best.y, 2));
    return RegisteredScans{q, [q, pays, c_extra](const Pose& r) {
                             const double dq = std::hypot(r.x - q.x, r.y - q.y), dc = std::hypot(r.x - 15.2, r.y - 6.1);
                             return -1.0 - std::min(100 * dq * dq + pays, 100 * dc * dc + c_extra);
                           }};
  };
}

// With `best` 0.2 m from A, within the bounds of a localization: judged at A, which pays
// 0.2 itself, C is within the margin; moved first (register_moves_place), the reference
// leaves C out. With `best` 0.5 m away, the move found the cloud's place off, and the
// verdict stays.
TEST(AmbiguityByLikelihood, TheReferenceMovesOntoItsRegisteredScans) {
  const auto [p, w, rival] = OneClusterAndARival();
  AmbiguityOptions o;
  const double c_extra = 2 * o.rival_margin_z2;
  ASSERT_TRUE(o.register_moves_place);
  const Ambiguity moved = find_ambiguity(p, w, o, flat, rival, two_wells(0), registered_best_at({3.4, 2.1}, c_extra));
  EXPECT_FALSE(moved.ambiguous());
  ASSERT_EQ(moved.places.size(), 1u);
  EXPECT_NEAR(moved.places[0].x, 3.2, 0.05);  // the cloud's place is what it reports
  const Ambiguity far = find_ambiguity(p, w, o, flat, rival, two_wells(0), registered_best_at({3.7, 2.1}, c_extra));
  ASSERT_TRUE(far.ambiguous());
  AmbiguityOptions wide = o;
  wide.move_max_shift = 1.0;  // the guard is what kept it: without it, C is out
  EXPECT_FALSE(find_ambiguity(p, w, wide, flat, rival, two_wells(0), registered_best_at({3.7, 2.1}, c_extra)).ambiguous());
  o.register_moves_place = false;
  const Ambiguity kept = find_ambiguity(p, w, o, flat, rival, two_wells(0), registered_best_at({3.4, 2.1}, c_extra));
  ASSERT_TRUE(kept.ambiguous());
  EXPECT_NEAR(kept.places[1].x, 15.2, 0.01);
}

// The cloud's own second place, with a residual given, is judged as a rival is: by the
// residual, not by the tempered score's margin (which here calls A and C alike).
TEST(AmbiguityByLikelihood, TheCloudsSecondPlaceIsJudgedByTheResidual) {
  std::vector<Pose> p;
  std::vector<double> w;
  add_cluster(p, w, {3.2, 2.1, 0}, 0.7, 50);
  add_cluster(p, w, {15.2, 6.1, 0}, 0.3, 50);
  AmbiguityOptions o;
  ASSERT_TRUE(find_ambiguity(p, w, o, flat).ambiguous());  // no residual: the margin's rule
  // C worse by twice the residual's margin: one place, A.
  const Ambiguity one = find_ambiguity(p, w, o, flat, {}, two_wells(2 * o.rival_margin_z2));
  ASSERT_EQ(one.places.size(), 1u);
  EXPECT_NEAR(one.places[0].x, 3.2, 0.05);
  // Within it: both, C with its weight.
  const Ambiguity two = find_ambiguity(p, w, o, flat, {}, two_wells(o.rival_margin_z2 / 2));
  ASSERT_EQ(two.places.size(), 2u);
  EXPECT_NEAR(two.places[1].x, 15.2, 0.05);
  EXPECT_NEAR(two.weights[1], 0.3, 1e-9);
  // Off: the margin's rule again, whatever the residual.
  o.candidates_by_residual = false;
  EXPECT_TRUE(find_ambiguity(p, w, o, flat, {}, two_wells(2 * o.rival_margin_z2)).ambiguous());
}

// The tempered score puts the lighter C first; the residual decides between it and the
// heaviest A (what the filter reports): A far better, one place; C better, both, the
// heaviest first.
TEST(AmbiguityByLikelihood, TheResidualDecidesBetweenTheHeaviestAndTheBestScored) {
  std::vector<Pose> p;
  std::vector<double> w;
  add_cluster(p, w, {3.2, 2.1, 0}, 0.7, 50);
  add_cluster(p, w, {15.2, 6.1, 0}, 0.3, 50);
  const PlaceScore c_first = [](const Pose& q) { return std::fabs(q.x - 15.2) < 0.5 ? -0.19 : -0.2; };
  AmbiguityOptions o;
  const Ambiguity a = find_ambiguity(p, w, o, c_first, {}, two_wells(2 * o.rival_margin_z2));
  ASSERT_EQ(a.places.size(), 1u);
  EXPECT_NEAR(a.places[0].x, 3.2, 0.05);
  // A worse by the residual: the filter's estimate cannot be reported.
  const PlaceScore a_worse = [](const Pose& q) { return two_wells(0)(q) - (std::hypot(q.x - 3.2, q.y - 2.1) < 0.5 ? 0.5 : 0); };
  const Ambiguity b = find_ambiguity(p, w, o, c_first, {}, a_worse);
  ASSERT_EQ(b.places.size(), 2u);
  EXPECT_NEAR(b.places[0].x, 3.2, 0.05);
  EXPECT_NEAR(b.places[1].x, 15.2, 0.05);
  // The margin's rule keeps both whatever the residual.
  o.candidates_by_residual = false;
  EXPECT_EQ(find_ambiguity(p, w, o, c_first, {}, two_wells(2 * o.rival_margin_z2)).places.size(), 2u);
}

TEST(AmbiguityByLikelihood, ARivalThatRefinesOntoTheCloudsPlaceIsThatPlace) {
  std::vector<Pose> p;
  std::vector<double> w;
  add_cluster(p, w, {3.2, 2.1, 0}, 1.0, 50);
  // 1.1 m from A, whose well is the only one near: refinement walks it back onto A.
  const PlaceScore one_well = [](const Pose& q) {
    const double d = std::hypot(q.x - 3.2, q.y - 2.1);
    return -1.0 - 0.5 * d * d;
  };
  const Ambiguity a = find_ambiguity(p, w, {}, flat, {{4.3, 2.1, 0}}, one_well);
  EXPECT_FALSE(a.ambiguous());
}

TEST(AmbiguityByLikelihood, ADiffuseCloudIsAmbiguousWhateverTheScores) {
  // 400 equal particles on a 20 m x 20 m grid (a cloud just after init_global).
  std::vector<Pose> p;
  std::vector<double> w;
  for (int i = 0; i < 400; ++i) {
    p.push_back({0.5 + i % 20, 0.5 + i / 20, 0});
    w.push_back(1);
  }
  EXPECT_TRUE(find_ambiguity(p, w, {}, [](const Pose& q) { return q.x < 3 ? 0.0 : -5.0; }).ambiguous());
}

// Global localization (robust preset, uniform cloud, compass) in room A for 8 updates;
// settle_after: ParticleFilterOptions::settle_after.
std::unique_ptr<ParticleFilter> localize_in_room_a(const Map& m, Pose& truth, size_t settle_after = 0) {
  const auto world = std::make_shared<GridRayCaster>(m, RayCasterOptions{0.3, 15.0});
  LaserSimulator laser(world, {}, 21);
  WanderDriver driver(world, {5.5, 1.5, 0.4}, {}, 22);
  ParticleFilterOptions o = ParticleFilterOptions::robust();
  o.particles = 4000;
  o.seed = 23;
  o.settle_after = settle_after;
  auto f = std::make_unique<ParticleFilter>(m, o);
  truth = driver.pose();
  f->init_global(truth.theta);
  for (int u = 1; u <= 8; ++u) {
    if (u > 1) {
      const DriveStep s = driver.step();
      truth = s.truth;
      f->predict(s.odometry);
    }
    f->update(laser.scan(truth), truth.theta);
  }
  return f;
}

// The filter drifts towards one of identical rooms (the weight of room A fell from 0.56
// to 0.21 in 8 updates on this seed: the room whose particles happen to sit nearer the
// true relative pose wins each scan), so "comparable" is a tenth, not a half.
TEST(Ambiguity, IdenticalRoomsAreAmbiguous) {
  Pose truth;
  const Ambiguity a = localize_in_room_a(test::two_rooms(true), truth)->ambiguity();
  ASSERT_TRUE(a.ambiguous());
  // The two places are the truth and its copy in room B, not two lumps of one room.
  bool at_truth = false, at_copy = false;
  for (const Pose& p : a.places) {
    at_truth = at_truth || distance(p, truth) < 0.3;
    at_copy = at_copy || distance(p, {truth.x + 12, truth.y, truth.theta}) < 0.3;
  }
  EXPECT_TRUE(at_truth);
  EXPECT_TRUE(at_copy);
}

// Settling on the eight scans keeps both identical rooms (they explain the scans alike),
// each at the truth's pose in it, and the verdict says so.
TEST(Ambiguity, SettlingKeepsIdenticalRoomsBoth) {
  Pose truth;
  const auto f = localize_in_room_a(test::two_rooms(true), truth, 8);
  const Ambiguity a = f->ambiguity();
  ASSERT_TRUE(a.ambiguous());
  bool at_truth = false, at_copy = false;
  for (const Pose& p : a.places) {
    at_truth = at_truth || distance(p, truth) < 0.1;
    at_copy = at_copy || distance(p, {truth.x + 12, truth.y, truth.theta}) < 0.1;
  }
  EXPECT_TRUE(at_truth);
  EXPECT_TRUE(at_copy);
  for (double w : a.weights) EXPECT_GT(w, 0.3);  // shared, not one room's lucky lump
}

// Where room B's short wall is elsewhere, settling leaves one place, the true one, and
// a cloud already converged on it.
TEST(Ambiguity, SettlingLeavesOnePlaceWhereRoomsDiffer) {
  Pose truth;
  const auto f = localize_in_room_a(test::two_rooms(false), truth, 8);
  const Ambiguity a = f->ambiguity();
  EXPECT_FALSE(a.ambiguous());
  const PoseEstimate e = f->estimate();
  EXPECT_LT(distance(e.pose, truth), 0.1);
  EXPECT_LT(std::fabs(angle_diff(e.pose.theta, truth.theta)), deg2rad(1.0));
  EXPECT_LT(e.spread_xy, 0.1);
}

TEST(Ambiguity, RoomsThatDifferAreNot) {
  Pose truth;
  const Ambiguity a = localize_in_room_a(test::two_rooms(false), truth)->ambiguity();
  EXPECT_FALSE(a.ambiguous());
  ASSERT_FALSE(a.places.empty());
  EXPECT_LT(distance(a.places[0], truth), 0.3);
}

// The weight share is not the evidence: the filter's cloud replaced by one split evenly
// between the truth and its copy in room B (B's short wall elsewhere). The Weight rule
// calls it ambiguous; the last scans, seen from B, miss the short wall: one place, the
// true one.
TEST(Ambiguity, AnEvenSplitBetweenRoomsThatDifferIsNot) {
  Pose truth;
  const auto f = localize_in_room_a(test::two_rooms(false), truth);
  const Pose copy{truth.x + 12, truth.y, truth.theta};
  const auto split = [&](double at_truth) {
    std::vector<Pose> p;
    std::vector<double> w;
    add_cluster(p, w, truth, at_truth, 50);
    add_cluster(p, w, copy, 1 - at_truth, 50);
    f->set_particles(p, w);
  };
  split(0.55);
  ASSERT_TRUE(f->ambiguity(AmbiguityRule::Weight).ambiguous());
  const Ambiguity a = f->ambiguity();
  EXPECT_FALSE(a.ambiguous());
  ASSERT_EQ(a.places.size(), 1u);
  EXPECT_LT(distance(a.places[0], truth), 0.3);
  EXPECT_GT(a.runner_up_gap, f->options().ambiguity.margin_per_beam);
  // The copy heavier: the weight and the scans disagree; both kept, the truth second.
  split(0.45);
  const Ambiguity b = f->ambiguity();
  ASSERT_EQ(b.places.size(), 2u);
  EXPECT_LT(distance(b.places[0], copy), 0.3);
  EXPECT_LT(distance(b.places[1], truth), 0.3);
}

// Rooms that differ by one short wall, seen only facing it: the robot looks around in
// room A, faces A's short wall for ten more scans, then turns to face the bottom wall,
// where both rooms look alike, and stays there ten scans. The window of recent scans then
// holds only look-alike scans. A rival ruled out while the scans showed the difference
// stays out (AmbiguityOptions::drop_ruled_out_rivals); judged anew on the window alone,
// room B comes back. At the first full window B's residual is 0.46 per beam worse than
// A's (0.37 registered at itself): dropped at a margin of 0.2, kept at 1.
std::unique_ptr<ParticleFilter> look_then_face_the_bottom(bool drop, double margin, Pose& truth) {
  const Map m = test::two_rooms(false);
  const auto world = std::make_shared<GridRayCaster>(m, RayCasterOptions{0.3, 15.0});
  LaserSimulator laser(world, {}, 31);
  ParticleFilterOptions o = ParticleFilterOptions::fast_search();
  o.particles = 1000;
  o.seed = 32;
  o.threads = 1;
  o.ambiguity.drop_ruled_out_rivals = drop;
  o.ambiguity.rival_drop_margin_z2 = margin;
  auto f = std::make_unique<ParticleFilter>(m, world, o);
  truth = {5, 2.5, deg2rad(45.0)};
  f->init_global(truth.theta);
  f->update(laser.scan(truth), truth.theta);
  const auto turn = [&](double by, int scans) {
    for (int k = 0; k < scans; ++k) {
      const Odometry u{0, 0, k == 0 ? by : 0.0};
      truth = compose(truth, u);
      f->predict(u);
      f->update(laser.scan(truth), truth.theta);
    }
  };
  for (int k = 0; k < 6; ++k) turn(deg2rad(60.0), 1);  // the look around: seven scans
  turn(0, 10);                                          // facing A's short wall: a full window of it
  turn(deg2rad(-135.0), 10);                            // facing the bottom wall
  return f;
}

TEST(Ambiguity, ARivalRuledOutStaysOutOnceTheWindowForgetsWhy) {
  const Pose copy_offset{12, 0, 0};
  Pose truth;
  const auto judged_anew = look_then_face_the_bottom(false, 0.2, truth);
  // The premise: room B is a rival, and on the look-alike window alone it is a place.
  const auto near_copy = [&](const Pose& p) { return distance(p, {truth.x + copy_offset.x, truth.y, truth.theta}) < 0.5; };
  ASSERT_TRUE(std::any_of(judged_anew->rivals().begin(), judged_anew->rivals().end(), near_copy));
  const Ambiguity anew = judged_anew->ambiguity();
  ASSERT_TRUE(anew.ambiguous());
  EXPECT_TRUE(std::any_of(anew.places.begin(), anew.places.end(), near_copy));

  const auto dropped = look_then_face_the_bottom(true, 0.2, truth);
  EXPECT_FALSE(std::any_of(dropped->rivals().begin(), dropped->rivals().end(), near_copy));
  const Ambiguity a = dropped->ambiguity();
  EXPECT_FALSE(a.ambiguous());
  ASSERT_FALSE(a.places.empty());
  EXPECT_LT(distance(a.places[0], truth), 0.3);

  // A margin wider than the difference the scans showed keeps the rival.
  const auto kept = look_then_face_the_bottom(true, 1.0, truth);
  EXPECT_TRUE(std::any_of(kept->rivals().begin(), kept->rivals().end(), near_copy));
  EXPECT_TRUE(kept->ambiguity().ambiguous());
}

}  // namespace
}  // namespace fleetmap::localization
