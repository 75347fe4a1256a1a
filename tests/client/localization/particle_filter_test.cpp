// ParticleFilter (client/localization/particle_filter.h) on a small room built in code:
// reproducibility, the map switch, the estimate, tempering, KLD, global localization
// and tracking. The real maps: particle_filter_real_maps_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <stdexcept>
#include <vector>

#include "client/sim/drive_simulator.h"
#include "client/sim/laser_simulator.h"
#include "client/localization/particle_filter.h"
#include "client/localization/sensor_model.h"
#include "common/raycast/grid_ray_caster.h"
#include "common/map/map_window.h"
#include "tests/client/test_maps.h"

namespace fleetmap::localization {
namespace {

ParticleFilterOptions small(size_t particles, uint64_t seed = 1) {
  ParticleFilterOptions o;  // the seed's model
  o.particles = particles;
  o.seed = seed;
  return o;
}

// A RayCaster that sees a wall at the same range in every direction.
class ConstantCaster : public RayCaster {
 public:
  double cast_direction(Point, Point) const override { return 5.0; }
  const RayCasterOptions& options() const override { return options_; }

 private:
  RayCasterOptions options_{0.3, 15.0};
};

TEST(ParticleFilter, SameSeedSameParticles) {
  const Map m = test::room_map();
  const auto world = std::make_shared<GridRayCaster>(m, RayCasterOptions{0.3, 15.0});
  LaserSimulator laser(world, {}, 7);
  const std::vector<double> scan = laser.scan({3, 8, 0});
  ParticleFilter a(m, small(500, 42)), b(m, small(500, 42)), c(m, small(500, 43));
  for (ParticleFilter* f : {&a, &b, &c}) {
    f->init_global(0.0);
    f->predict({0.2, 0, 0.05});
    f->update(scan, 0.0);
    f->predict({0.2, 0, 0.05});
    f->update(scan, 0.0);
  }
  ASSERT_EQ(a.poses().size(), b.poses().size());
  for (size_t i = 0; i < a.poses().size(); ++i) {
    EXPECT_EQ(a.poses()[i], b.poses()[i]);
    EXPECT_EQ(a.weights()[i], b.weights()[i]);
  }
  EXPECT_NE(a.poses()[0], c.poses()[0]);
}

TEST(ParticleFilter, GlobalInitIsFreeAndFollowsTheCompass) {
  const Map m = test::room_map();
  ParticleFilter f(m, small(3000));
  f.init_global(kPi - 0.01);
  const FreeSpace fs(m);
  for (const Pose& p : f.poses()) {
    EXPECT_TRUE(fs.contains(p.point()));
    EXPECT_LE(std::fabs(angle_diff(p.theta, kPi - 0.01)), deg2rad(3.0) + 1e-12);
  }
  f.init_global(std::nullopt);  // no compass: any heading
  double c = 0, s = 0;
  for (const Pose& p : f.poses()) {
    c += std::cos(p.theta);
    s += std::sin(p.theta);
  }
  EXPECT_LT(std::hypot(c, s) / f.poses().size(), 0.05);
}

TEST(ParticleFilter, EstimateUsesTheCircularMean) {
  const Map m = test::room_map();
  ParticleFilter f(m, small(4000));
  f.init_pose({10, 3, kPi}, 0.1, 0.05);
  const PoseEstimate e = f.estimate();
  EXPECT_NEAR(e.pose.x, 10, 0.01);
  EXPECT_NEAR(e.pose.y, 3, 0.01);
  EXPECT_LT(std::fabs(angle_diff(e.pose.theta, kPi)), 0.005);  // not 0, the naive mean
  EXPECT_NEAR(e.spread_xy, 0.1 * std::sqrt(2.0), 0.01);
  EXPECT_NEAR(e.spread_theta, 0.05, 0.005);
  EXPECT_NEAR(e.n_eff, 4000, 1e-6);
  EXPECT_TRUE(e.converged);
  EXPECT_NEAR(e.cluster_weight, 1.0, 1e-9);
}

TEST(ParticleFilter, EstimateReportsTheHeaviestCluster) {
  const Map m = test::room_map();
  ParticleFilter f(m, small(1000));
  f.init_pose({2, 2, 0}, 0.05, 0.01);
  // Two hypotheses 10 m apart: the mean lies between them, the pose on the heavier.
  std::vector<Pose> poses = f.poses();
  for (size_t i = 0; i < 400; ++i) poses[i].x += 10;
  f.set_particles(poses, std::vector<double>(poses.size(), 2.0));
  EXPECT_NEAR(f.weights()[0], 1.0 / 1000, 1e-15);  // normalized
  const PoseEstimate e = f.estimate();
  EXPECT_NEAR(e.mean.x, 6, 0.05);
  EXPECT_NEAR(e.pose.x, 2, 0.05);
  EXPECT_NEAR(e.cluster_weight, 0.6, 1e-9);
  EXPECT_FALSE(e.converged);
  EXPECT_THROW(f.set_particles(poses, std::vector<double>(3, 1.0)), std::invalid_argument);
  EXPECT_THROW(f.set_particles(poses, std::vector<double>(poses.size(), 0.0)), std::invalid_argument);
}

TEST(ParticleFilter, EstimateReportsTheWeightedCovariance) {
  // Worked by hand: weights 1, 1, 2 -> mean (3.5, 2.5); var x = var y = 3/4, cov xy = 1/4.
  const Map m = test::room_map();
  ParticleFilter f(m, small(3));
  f.set_particles({{2, 2, 0}, {4, 4, 0}, {4, 2, 0}}, {1, 1, 2});
  const PoseEstimate e = f.estimate();
  EXPECT_NEAR(e.covariance(0, 0), 0.75, 1e-12);
  EXPECT_NEAR(e.covariance(1, 1), 0.75, 1e-12);
  EXPECT_NEAR(e.covariance(0, 1), 0.25, 1e-12);
  EXPECT_NEAR(e.covariance(1, 0), 0.25, 1e-12);
  EXPECT_NEAR(e.spread_xy, std::sqrt(1.5), 1e-12);
}

TEST(ParticleFilter, SetMapKeepsParticlesAndWeights) {
  const Map m = test::room_map();
  const auto world = std::make_shared<GridRayCaster>(m, RayCasterOptions{0.3, 15.0});
  LaserSimulator laser(world, {}, 8);
  ParticleFilter f(m, small(800));
  f.init_pose({10, 3, 0.5}, 0.3, 0.05);
  ParticleFilterOptions o = f.options();
  o.resample_threshold = 0;  // keep the weights of this update
  ParticleFilter g(m, o);
  g.init_pose({10, 3, 0.5}, 0.3, 0.05);
  g.update(laser.scan({10, 3, 0.5}), 0.5);
  const std::vector<Pose> poses = g.poses();
  const std::vector<double> weights = g.weights();
  const PoseEstimate before = g.estimate();
  g.set_map(clip_map(m, window_rect(m.border, {10, 3}, 12, 8)));
  EXPECT_EQ(g.poses(), poses);
  EXPECT_EQ(g.weights(), weights);
  EXPECT_EQ(g.estimate().pose, before.pose);
  EXPECT_THROW(g.set_map(m, nullptr), std::invalid_argument);
}

TEST(ParticleFilter, UpdateChecksItsInput) {
  const Map m = test::room_map();
  ParticleFilter f(m, small(100));
  EXPECT_THROW(f.update(std::vector<double>(131, 5.0)), std::logic_error);  // no particles yet
  f.init_pose({10, 3, 0}, 0.1, 0.1);
  EXPECT_THROW(f.update(std::vector<double>(130, 5.0)), std::invalid_argument);
}

// The room, its caster, the fast preset at 300 particles on one thread, and a robot at
// (16.5, 7) facing the east wall, 3.5 m away.
struct FastInTheRoom {
  Map m = test::room_map();
  std::shared_ptr<const RayCaster> world = std::make_shared<GridRayCaster>(m, RayCasterOptions{0.3, 15.0});
  ParticleFilterOptions o = [] {
    ParticleFilterOptions f = ParticleFilterOptions::fast_search();
    f.particles = 300;
    f.threads = 1;
    return f;
  }();
  Pose truth{16.5, 7, 0};
};

// Another detector (a leg tracker, a camera) may know which returns are people. Here a
// crowd 1.7 m wide stands 1.5 m in front of the robot: wider than two people, so
// foreground.h's guess keeps it, and the verdict's residual charges the true pose for it.
// Named as foreground, it is left out as the guessed people are.
TEST(ParticleFilter, AGivenForegroundReplacesTheGuess) {
  const FastInTheRoom r;
  const auto& [m, world, o, truth] = r;
  LaserSimulator laser(world, {}, 3);
  std::vector<double> scan = laser.true_scan(truth);
  std::vector<uint8_t> crowd(scan.size(), 0);
  for (size_t j = 40; j <= 90; ++j) {
    ASSERT_GT(scan[j], 3.0) << j;  // the wall behind the crowd
    scan[j] = 1.5;
    crowd[j] = 1;
  }
  ParticleFilter guessed(m, world, o), told(m, world, o);
  guessed.init_pose(truth, 0.05, 0.02);
  told.init_pose(truth, 0.05, 0.02);
  guessed.update(scan, truth.theta);
  told.update(scan, truth.theta, crowd);

  EXPECT_EQ(told.last_foreground(), crowd);
  // The premise: too wide for the guess.
  const std::vector<uint8_t> guess = foreground_returns(scan, told.beam_angles(), 15.0, o.foreground);
  ASSERT_EQ(guess.size(), scan.size());
  EXPECT_EQ(std::count(guess.begin() + 40, guess.begin() + 91, 1), 0);
  // The noiseless scan fits the truth exactly but for the crowd.
  EXPECT_LT(-told.recent_residual()(truth), 1e-6);
  EXPECT_GT(-guessed.recent_residual()(truth), 1.0);
}

// The fast preset weighs with the flat short term from 0.5 m while it localizes globally
// and from 0.3 m once tracking (ParticleFilterOptions::global_short_beyond). A crowd
// against the wall ahead stops 51 beams 0.4 m short: the two models score that scan
// apart, and the verdict's figure for the true place must come from the phase's own.
TEST(ParticleFilter, TheGlobalPhaseWeighsWithItsOwnShortTerm) {
  const FastInTheRoom r;
  const auto& [m, world, o, truth] = r;
  ASSERT_GT(o.global_short_beyond, o.sensor.short_beyond);
  LaserSimulator laser(world, {}, 3);
  const std::vector<double> wall = laser.true_scan(truth);
  std::vector<double> scan = wall;
  for (size_t j = 40; j <= 90; ++j) scan[j] -= 0.4;
  // The scan's log-likelihood at the truth under the flat term from `beyond`.
  // r.o, not o: Debian 12's clang cannot capture a structured binding in a lambda.
  const auto scored = [&](double beyond, const std::vector<uint8_t>& front, double sigma_m) {
    SensorModelOptions so = r.o.sensor;
    so.rmax = r.o.laser.rmax;
    so.short_beyond = beyond;
    if (sigma_m > 0) so.sigma_m = sigma_m;
    return SensorModel(so).log_weight(scan.data(), wall.data(), scan.size(), front.empty() ? nullptr : front.data());
  };
  ParticleFilter f(m, world, o);
  f.init_global(truth.theta);
  f.update(scan, truth.theta);
  const double global_phase = f.recent_log_likelihood(truth);
  EXPECT_NEAR(global_phase, scored(o.global_short_beyond, f.last_foreground(), -1), 1e-9);
  f.init_pose(truth, 0.05, 0.02);
  f.update(scan, truth.theta);
  const double tracking = f.recent_log_likelihood(truth);
  EXPECT_NEAR(tracking, scored(o.sensor.short_beyond, f.last_foreground(), o.tracking_sigma_m), 1e-9);
  EXPECT_GT(std::fabs(global_phase - tracking), 1.0);  // the premise: the two models differ on it
}

TEST(ParticleFilter, AGivenForegroundOfTheWrongSizeIsRefusedAndChangesNothing) {
  const Map m = test::room_map();
  ParticleFilterOptions o = ParticleFilterOptions::fast_search();
  o.particles = 300;
  ParticleFilter f(m, o);
  f.init_pose({16.5, 7, 0}, 0.1, 0.05);
  const std::vector<Pose> before = f.poses();
  const std::vector<double> scan(131, 5.0);
  EXPECT_THROW(f.update(scan, 0.0, std::vector<uint8_t>(130, 0)), std::invalid_argument);
  EXPECT_THROW(f.update(std::vector<double>(130, 5.0), 0.0, std::vector<uint8_t>(131, 0)), std::invalid_argument);
  EXPECT_TRUE(f.last_foreground().empty());
  ASSERT_EQ(f.poses().size(), before.size());
  for (size_t i = 0; i < before.size(); ++i) EXPECT_EQ(f.poses()[i].x, before[i].x);
}

TEST(ParticleFilter, RefusesAStageDecayOutsideZeroToOne) {
  const Map m = test::room_map();
  for (double decay : {-0.5, 1.5, std::nan("")}) {
    ParticleFilterOptions o = small(100);
    o.roughening_stage_decay = decay;
    EXPECT_THROW(ParticleFilter(m, o), std::invalid_argument) << decay;
  }
  ParticleFilterOptions o = small(100);
  o.roughening_stage_decay = 0;  // no jitter after a scan's first stage: allowed
  EXPECT_NO_THROW(ParticleFilter(m, o));
}

TEST(ParticleFilter, UninformativeScanLeavesWeightsEqual) {
  const Map m = test::room_map();
  ParticleFilter f(m, std::make_shared<ConstantCaster>(), small(300));
  f.init_global(std::nullopt);
  f.update(std::vector<double>(131, 5.0));
  for (double w : f.weights()) EXPECT_NEAR(w, 1.0 / 300, 1e-15);
  EXPECT_EQ(f.resamplings(), 0u);
}

// The robust options: with the seed's eq. (6) the first update leaves a single particle
// (one grazing ray is enough to rule out the others), 0.8 m off here, and the motion
// noise alone brings it only to 0.5 m in ten updates (bench-localization measures it).
TEST(ParticleFilter, GlobalLocalizationInTheRoom) {
  const Map m = test::room_map();
  const auto world = std::make_shared<GridRayCaster>(m, RayCasterOptions{0.3, 15.0});
  LaserSimulator laser(world, {}, 9);
  WanderDriver driver(world, {6.5, 8.0, -0.4}, {}, 10);
  ParticleFilterOptions o = ParticleFilterOptions::robust();
  o.particles = 2000;
  o.seed = 11;
  ParticleFilter f(m, o);
  Pose truth = driver.pose();
  f.init_global(truth.theta);
  int within_since = -1;
  for (int u = 1; u <= 10; ++u) {
    if (u > 1) {
      const DriveStep s = driver.step();
      truth = s.truth;
      f.predict(s.odometry);
    }
    f.update(laser.scan(truth), truth.theta);
    const PoseEstimate e = f.estimate();
    const bool within = distance(e.pose, truth) < 0.3 && std::fabs(angle_diff(e.pose.theta, truth.theta)) < deg2rad(3);
    if (!within) within_since = -1;
    else if (within_since < 0) within_since = u;
  }
  EXPECT_GT(within_since, 0);
  EXPECT_TRUE(f.estimate().converged);
}

// Settling (settle_after 1): a uniform cloud of the robust preset has not converged
// after its first scan; the same filter settling at that update searches the scan and
// leaves a tight cloud at the truth. A settle that placed the scan wrongly would leave
// it elsewhere.
TEST(ParticleFilter, SettlingConvergesAtItsUpdate) {
  const Map m = test::room_map();
  const auto world = std::make_shared<GridRayCaster>(m, RayCasterOptions{0.3, 15.0});
  const Pose truth{6.5, 8.0, -0.4};
  for (const size_t settle : {0, 1}) {
    LaserSimulator laser(world, {}, 9);
    ParticleFilterOptions o = ParticleFilterOptions::robust();
    o.particles = 300;
    o.global_density = 0;  // 1.5 particles per square metre: none within 0.1 m of the truth
    o.seed = 11;
    o.settle_after = settle;
    ParticleFilter f(m, o);
    f.init_global(truth.theta);
    f.update(laser.scan(truth), truth.theta);
    const PoseEstimate e = f.estimate();
    if (settle == 0) {
      EXPECT_GT(std::max(distance(e.pose, truth), e.spread_xy), 0.1) << "without settling, not yet";
      EXPECT_TRUE(f.last_settle().empty());
      continue;
    }
    EXPECT_LT(distance(e.pose, truth), 0.1);
    EXPECT_LT(std::fabs(angle_diff(e.pose.theta, truth.theta)), deg2rad(1.0));
    EXPECT_LT(e.spread_xy, 0.1);
    EXPECT_FALSE(f.ambiguity().ambiguous());
    ASSERT_FALSE(f.last_settle().empty());
    EXPECT_LT(distance(f.last_settle()[0].pose, truth), 0.05);
  }
}

// The fast preset with 800 particles, seeded: the look-around tests on the room.
ParticleFilterOptions small_fast() {
  ParticleFilterOptions o = ParticleFilterOptions::fast_search();
  o.particles = 800;
  o.kld.max_particles = 800;
  o.seed = 5;
  return o;
}

// defer_look_around: the turns in place only collect scans; the last turn (the 7th scan
// with look_around_searches 6), or the first step driven, searches once on all of them.
// Searching at every turn (or never) would show candidates before the end, or none.
TEST(ParticleFilter, DeferredLookAroundSearchesOnceAtItsEnd) {
  const Map m = test::room_map();
  const auto world = std::make_shared<GridRayCaster>(m, RayCasterOptions{0.3, 15.0});
  for (const int turns : {6, 2}) {
    LaserSimulator laser(world, {}, 9);
    ParticleFilter f(m, world, small_fast());
    Pose truth{6.5, 8.0, -0.4};
    f.init_global(truth.theta);
    const std::vector<double> before = f.weights();
    for (int u = 1; u <= turns + 1; ++u) {
      if (u > 1) {
        const Odometry turn{0, 0, deg2rad(60.0)};
        truth = compose(truth, turn);
        f.predict(turn);
      }
      f.update(laser.scan(truth), truth.theta);
      if (u < 7) {
        EXPECT_TRUE(f.last_candidates().empty()) << turns << " turns, update " << u;
        EXPECT_TRUE(f.searching());
        EXPECT_TRUE(f.awaiting_search());
        EXPECT_EQ(f.weights(), before) << "the cloud waits for the search";
      }
    }
    if (turns == 6) {
      EXPECT_FALSE(f.last_candidates().empty());
      EXPECT_FALSE(f.searching());
      EXPECT_FALSE(f.awaiting_search());
    } else {  // drives after two turns: the step searches on the three turns' scans and itself
      const Odometry ahead{0.5, 0, 0};
      truth = compose(truth, ahead);
      f.predict(ahead);
      f.update(laser.scan(truth), truth.theta);
      EXPECT_FALSE(f.last_candidates().empty());
      EXPECT_FALSE(f.searching());
    }
    const PoseEstimate e = f.estimate();
    EXPECT_LT(distance(e.pose, truth), 0.3) << turns << " turns";
    EXPECT_LT(std::fabs(angle_diff(e.pose.theta, truth.theta)), deg2rad(3.0)) << turns << " turns";
  }
}

// Odometry reports a few centimetres of translation on a turn in place (its noise grows
// with the turn); a look around must not end there (ParticleFilterOptions::turn_in_place_sds,
// docs/localization.md "The search's misses on the campus"): with the option the six 60
// degree turns, each reported 8 cm ahead, keep their scans for one search at the last; with
// 5 cm alone the first turn is taken for driving and the filter searches at once.
TEST(ParticleFilter, ALookAroundsTurnsStayTurnsDespiteOdometrysDrift) {
  const Map m = test::room_map();
  const auto world = std::make_shared<GridRayCaster>(m, RayCasterOptions{0.3, 15.0});
  for (const double sds : {3.0, 0.0}) {
    LaserSimulator laser(world, {}, 9);
    ParticleFilterOptions o = small_fast();
    o.turn_in_place_sds = sds;
    ParticleFilter f(m, world, o);
    Pose truth{6.5, 8.0, -0.4};
    f.init_global(truth.theta);
    int searched_at = 0;
    for (int u = 1; u <= 7; ++u) {
      if (u > 1) {
        const Odometry turn{0, 0, deg2rad(60.0)};
        truth = compose(truth, turn);
        f.predict({0.08, 0.02 * std::sin(u), turn.dtheta});  // as reported: 8 cm ahead
      }
      f.update(laser.scan(truth), truth.theta);
      if (searched_at == 0 && !f.last_candidates().empty()) searched_at = u;
    }
    if (sds > 0) {
      EXPECT_EQ(searched_at, 7) << "one search, at the last turn";
      const PoseEstimate e = f.estimate();
      EXPECT_LT(distance(e.pose, truth), 0.3);
      EXPECT_LT(std::fabs(angle_diff(e.pose.theta, truth.theta)), deg2rad(3.0));
    } else {
      EXPECT_EQ(searched_at, 2) << "without the option the first turn ends the look around";
    }
  }
}

// A cloud of places far apart (a searched cloud) is spread over metres, and roughening
// jitters it by its cap at each resampling, several per scan while tempering: with a cap
// of 0.05 m (ParticleFilterOptions::roughening_max_xy) each place stays as sharp as the
// scans make it; with the default 0.2 m the place the robot is at blurs (on the campus a
// wrong place tolerant of the blur then won the next scans: docs/localization.md, "The
// search's misses on the campus"). Two identical rooms 12 m apart keep the cloud two
// places; the robot stands in room A.
// A cloud split between two identical rooms, as a search leaves it (0.1 m and 0.7
// degrees around each place), the robot standing in one: the place's RMS error after
// three scans, and the other room's share of the weight.
struct SplitCloud {
  double rms_at_truth;
  double twin_share;
};

SplitCloud three_scans_on_a_split_cloud(double cap, double stage_decay) {
  const Map m = test::two_rooms(true);
  const auto world = std::make_shared<GridRayCaster>(m, RayCasterOptions{0.3, 15.0});
  const Pose truth{5.5, 1.8, 2.4};
  ParticleFilterOptions o = ParticleFilterOptions::fast_search();
  o.particles = 400;
  o.kld.max_particles = 400;
  o.seed = 31;
  o.roughening_max_xy = cap;
  o.roughening_stage_decay = stage_decay;
  o.tracking_sigma_m = -1;  // set_particles stands in for the search: the global phase's model
  ParticleFilter f(m, world, o);
  LaserSimulator laser(world, {}, 32);
  std::mt19937_64 rng(33);
  std::normal_distribution<double> n01(0.0, 1.0);
  std::vector<Pose> poses;
  for (int i = 0; i < 400; ++i) {
    const double ox = i % 2 ? 12.0 : 0.0;
    poses.push_back({truth.x + ox + 0.1 * n01(rng), truth.y + 0.1 * n01(rng), truth.theta + deg2rad(0.7) * n01(rng)});
  }
  f.set_particles(poses, std::vector<double>(poses.size(), 1.0));
  for (int u = 0; u < 3; ++u) f.update(laser.scan(truth), truth.theta);  // standing still
  double sum = 0, w = 0, in_b = 0;
  for (size_t i = 0; i < f.poses().size(); ++i) {
    if (f.poses()[i].x > 10) {
      in_b += f.weights()[i];
      continue;
    }
    sum += f.weights()[i] * std::pow(distance(f.poses()[i], truth), 2);
    w += f.weights()[i];
  }
  return {std::sqrt(sum / w), in_b};
}

TEST(ParticleFilter, PlacesFarApartStaySharpUnderRoughening) {
  const SplitCloud sharp = three_scans_on_a_split_cloud(0.05, 1), blurred = three_scans_on_a_split_cloud(0.2, 1);
  EXPECT_GT(sharp.twin_share, 0.1) << "the twin room keeps its share: the cloud stays two places";
  EXPECT_GT(blurred.twin_share, 0.1);
  EXPECT_LT(sharp.rms_at_truth, 0.1) << "a cap of 0.05 m";
  EXPECT_GT(blurred.rms_at_truth, 1.5 * sharp.rms_at_truth) << "the default cap blurs the place the robot is at";
}

// Annealing's diffusion shrinking stage by stage keeps the default cap at a scan's first
// stage and blurs the place far less over its six.
TEST(ParticleFilter, AnnealingsDiffusionShrinksByStage) {
  const SplitCloud blurred = three_scans_on_a_split_cloud(0.2, 1), decayed = three_scans_on_a_split_cloud(0.2, 0.5);
  EXPECT_GT(decayed.twin_share, 0.1) << "the twin room keeps its share: the cloud stays two places";
  EXPECT_LT(decayed.rms_at_truth, 0.1);
  EXPECT_GT(blurred.rms_at_truth, 1.5 * decayed.rms_at_truth);
}

// The ambiguity verdict's residual (AmbiguityOptions::rivals) of the recent scans, each
// placed from the latest by the stitched odometry. Here the odometry under-reports every
// 0.5 m step by 4 % and each 5 degree turn by 0.3 degrees, so the earlier scans sit up
// to 0.2 m off their true poses. Registered (each scan at its best pose near the
// stitched one), the truth's residual is what the true poses give; stitched, it is
// well above, by more than places that differ would be.
TEST(ParticleFilter, TheRegisteredResidualForgivesTheStitchingsError) {
  const Map m = test::room_map();
  const auto world = std::make_shared<GridRayCaster>(m, RayCasterOptions{0.3, 15.0});
  LaserSimulator laser(world, {}, 9);
  ParticleFilterOptions o = ParticleFilterOptions::fast_search();
  o.particles = 500;
  o.seed = 5;
  ParticleFilter f(m, world, o);
  Pose truth{6.5, 8.0, -0.4};
  f.init_pose(truth, 0.05, 0.02);
  std::vector<Pose> path;
  std::vector<std::vector<double>> scans;
  for (size_t u = 0; u < o.ambiguity.scans; ++u) {
    if (u > 0) {
      truth = compose(truth, Odometry{0.5, 0, deg2rad(5.0)});
      f.predict(Odometry{0.48, 0, deg2rad(4.7)});
    }
    path.push_back(truth);
    scans.push_back(laser.scan(truth));
    f.update(scans.back(), truth.theta);
  }
  // The residual at the true poses, as the verdict computes it.
  const std::vector<double> beams = f.beam_angles();
  double sum = 0, n = 0;
  std::vector<double> cast(beams.size());
  for (size_t k = 0; k < path.size(); ++k) {
    world->cast_scan(path[k].point(), path[k].theta, beams, cast.data());
    for (size_t j = 0; j < beams.size(); ++j, ++n) {
      const double z = (scans[k][j] - cast[j]) / o.ambiguity.rival_sigma;
      sum += std::min(z * z, o.ambiguity.rival_max_z2);
    }
  }
  const double at_true_poses = sum / n;
  const double stitched = -f.recent_residual()(truth);
  const RegisteredScans at_truth = f.registered_residual()(truth);
  const double registered = -at_truth.score(at_truth.place);
  EXPECT_GT(stitched, at_true_poses + 0.5);
  EXPECT_NEAR(registered, at_true_poses, 0.1);
  // The window does not let a place 1 m off slide onto the truth's scans.
  const Pose aside = compose(truth, Odometry{0, 1.0, 0});
  const RegisteredScans at_aside = f.registered_residual()(aside);
  const double off = -at_aside.score(at_aside.place);
  EXPECT_GT(off, registered + 0.5);
}

TEST(ParticleFilter, TrackingInTheRoomStaysWithinBounds) {
  const Map m = test::room_map();
  const auto world = std::make_shared<GridRayCaster>(m, RayCasterOptions{0.3, 15.0});
  LaserSimulator laser(world, {}, 12);
  WanderDriver driver(world, {2, 2, 0.3}, {}, 13);
  ParticleFilter f(m, small(500, 14));
  f.init_pose(driver.pose(), 0.1, deg2rad(2));
  double worst = 0, driven = 0;
  while (driven < 40) {
    const DriveStep s = driver.step();
    driven += s.driven;
    f.predict(s.odometry);
    f.update(laser.scan(s.truth), s.truth.theta);
    worst = std::max(worst, distance(f.estimate().pose, s.truth));
  }
  EXPECT_LT(worst, 0.3);
}

TEST(ParticleFilter, TemperingSpendsTheWholeScanOnceConverged) {
  const Map m = test::room_map();
  const auto world = std::make_shared<GridRayCaster>(m, RayCasterOptions{0.3, 15.0});
  LaserSimulator laser(world, {}, 15);
  ParticleFilterOptions o = ParticleFilterOptions::robust();
  o.particles = 2000;
  o.global_density = 0;
  ParticleFilter f(m, o);
  const Pose truth{6.5, 8.0, -0.4};
  f.init_global(truth.theta);
  f.update(laser.scan(truth), truth.theta);
  EXPECT_LT(f.last_tempering(), 1.0);  // a global cloud: the scan is tempered
  EXPECT_GT(f.last_tempering(), 0.0);
  f.init_pose(truth, 0.05, 0.01);
  f.update(laser.scan(truth), truth.theta);
  EXPECT_EQ(f.last_tempering(), 1.0);
}

TEST(ParticleFilter, KldShrinksATrackingCloud) {
  const Map m = test::room_map();
  const auto world = std::make_shared<GridRayCaster>(m, RayCasterOptions{0.3, 15.0});
  LaserSimulator laser(world, {}, 16);
  WanderDriver driver(world, {2, 2, 0.3}, {}, 17);
  ParticleFilterOptions o = small(3000, 18);
  o.adaptive = true;
  o.resample_threshold = 1.0;  // resample at every update
  o.kld.min_particles = 200;
  o.kld.max_particles = 3000;
  ParticleFilter f(m, o);
  f.init_pose(driver.pose(), 0.1, deg2rad(2));
  double worst = 0;
  for (int k = 0; k < 60; ++k) {
    const DriveStep s = driver.step();
    f.predict(s.odometry);
    f.update(laser.scan(s.truth), s.truth.theta);
    worst = std::max(worst, distance(f.estimate().pose, s.truth));
  }
  EXPECT_LT(f.poses().size(), 1500u);
  EXPECT_GE(f.poses().size(), 200u);
  EXPECT_LT(worst, 0.3);
}

// The tracking floor holds from a known pose on; a cloud from init_global keeps
// kld.min_particles even once it has collapsed on one place (ParticleFilterOptions::
// tracking_min_particles).
TEST(ParticleFilter, KldKeepsTheTrackingFloorFromAKnownPoseOnly) {
  const Map m = test::room_map();
  const auto world = std::make_shared<GridRayCaster>(m, RayCasterOptions{0.3, 15.0});
  ParticleFilterOptions o = small(3000, 19);
  o.adaptive = true;
  o.resample_threshold = 1.0;  // resample at every update
  o.kld.min_particles = 200;
  o.kld.max_particles = 3000;
  o.tracking_min_particles = 1200;
  const auto drive = [&](ParticleFilter& f, WanderDriver& driver, LaserSimulator& laser) {
    double worst = 0;
    for (int k = 0; k < 60; ++k) {
      const DriveStep s = driver.step();
      f.predict(s.odometry);
      f.update(laser.scan(s.truth), s.truth.theta);
      if (k >= 30) worst = std::max(worst, distance(f.estimate().pose, s.truth));
    }
    return worst;
  };
  {
    LaserSimulator laser(world, {}, 20);
    WanderDriver driver(world, {2, 2, 0.3}, {}, 21);
    ParticleFilter f(m, o);
    f.init_pose(driver.pose(), 0.1, deg2rad(2));
    EXPECT_LT(drive(f, driver, laser), 0.3);
    EXPECT_EQ(f.poses().size(), 1200u);  // collapsed, held at the tracking floor
  }
  {
    LaserSimulator laser(world, {}, 20);
    WanderDriver driver(world, {2, 2, 0.3}, {}, 21);
    ParticleFilter f(m, o);
    f.init_global(driver.pose().theta);
    EXPECT_LT(drive(f, driver, laser), 0.3);  // found, and collapsed on it
    EXPECT_LT(f.poses().size(), 1200u);
    EXPECT_GE(f.poses().size(), 200u);
  }
}

// tracking_sigma_m sharpens the sensor model from a known pose on; the global phase keeps
// sensor.sigma_m, particle for particle.
TEST(ParticleFilter, TrackingSigmaSharpensTrackingOnly) {
  const Map m = test::room_map();
  const auto world = std::make_shared<GridRayCaster>(m, RayCasterOptions{0.3, 15.0});
  LaserSimulator laser(world, {}, 22);
  const Pose truth{6.5, 8.0, -0.4};
  const std::vector<double> scan = laser.scan(truth);
  ParticleFilterOptions broad = small(2000, 23);
  broad.resample_threshold = 0;  // keep the weights: the spread is theirs
  ParticleFilterOptions sharp = broad;
  sharp.tracking_sigma_m = 0.15;
  ParticleFilter a(m, broad), b(m, sharp);
  a.init_pose(truth, 0.3, 0.05);
  b.init_pose(truth, 0.3, 0.05);
  a.update(scan, truth.theta);
  b.update(scan, truth.theta);
  EXPECT_LT(b.estimate().spread_xy, 0.7 * a.estimate().spread_xy);
  ParticleFilter c(m, broad), d(m, sharp);
  c.init_global(truth.theta);
  d.init_global(truth.theta);
  c.update(scan, truth.theta);
  d.update(scan, truth.theta);
  EXPECT_EQ(c.weights(), d.weights());
}

}  // namespace
}  // namespace fleetmap::localization
