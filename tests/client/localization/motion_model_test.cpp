// MotionModel (client/localization/motion_model.h): the odometry model of Probabilistic
// Robotics table 5.6. Sample means equal the increment; sample spreads equal the
// standard deviations the alphas give; pose composition round-trips.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "client/localization/motion_model.h"

namespace fleetmap::localization {
namespace {

constexpr int kSamples = 40000;

struct Stats {
  double mean_dx = 0, mean_dy = 0, mean_dtheta = 0, sd_dx = 0, sd_dy = 0, sd_dtheta = 0;
};

Stats sample_stats(const MotionModel& m, const Odometry& u, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<Odometry> v(kSamples);
  Stats s;
  for (Odometry& o : v) {
    o = m.sample(u, rng);
    s.mean_dx += o.dx / kSamples;
    s.mean_dy += o.dy / kSamples;
    s.mean_dtheta += angle_diff(o.dtheta, u.dtheta) / kSamples;  // around u's turn
  }
  s.mean_dtheta += u.dtheta;
  for (const Odometry& o : v) {
    s.sd_dx += (o.dx - s.mean_dx) * (o.dx - s.mean_dx) / kSamples;
    s.sd_dy += (o.dy - s.mean_dy) * (o.dy - s.mean_dy) / kSamples;
    const double d = angle_diff(o.dtheta, s.mean_dtheta);
    s.sd_dtheta += d * d / kSamples;
  }
  s.sd_dx = std::sqrt(s.sd_dx);
  s.sd_dy = std::sqrt(s.sd_dy);
  s.sd_dtheta = std::sqrt(s.sd_dtheta);
  return s;
}

TEST(Pose, ComposeAndBetweenRoundTrip) {
  const Pose a{1.5, -2.0, 2.8}, b{-3.0, 4.0, -2.9};
  const Pose c = compose(a, between(a, b));
  EXPECT_NEAR(c.x, b.x, 1e-12);
  EXPECT_NEAR(c.y, b.y, 1e-12);
  EXPECT_NEAR(angle_diff(c.theta, b.theta), 0.0, 1e-12);
  // One metre forward while facing +y.
  const Pose d = compose({0, 0, kPi / 2}, {1, 0, 0});
  EXPECT_NEAR(d.x, 0.0, 1e-12);
  EXPECT_NEAR(d.y, 1.0, 1e-12);
  EXPECT_NEAR(angle_diff(kPi - 0.1, -kPi + 0.1), -0.2, 1e-12);
}

TEST(MotionModel, DecompositionRebuildsTheIncrement) {
  const MotionModel m;
  for (const Odometry u : {Odometry{1, 0, 0}, Odometry{0.3, 0.2, 0.5}, Odometry{-0.5, 0.1, -0.2}, Odometry{0, 0, 1.0},
                           Odometry{-0.2, -0.3, 3.0}}) {
    const OdometryDecomposition d = m.decompose(u);
    EXPECT_LE(std::fabs(d.rot1), kPi / 2 + 1e-12);  // backwards is a negative trans
    EXPECT_NEAR(d.trans * std::cos(d.rot1), u.dx, 1e-12);
    EXPECT_NEAR(d.trans * std::sin(d.rot1), u.dy, 1e-12);
    EXPECT_NEAR(angle_diff(d.rot1 + d.rot2, u.dtheta), 0.0, 1e-12);
  }
}

TEST(MotionModel, StraightMotionMeanAndSpread) {
  const MotionNoise a{0.02, 0.002, 0.01, 0.001};
  const MotionModel m(a);
  const Stats s = sample_stats(m, {1, 0, 0}, 1);
  // rot1 = rot2 = 0, trans = 1: sd(trans) = sqrt(alpha3), sd(rot1) = sd(rot2) = sqrt(alpha2).
  EXPECT_NEAR(s.mean_dx, 1.0, 0.003);
  EXPECT_NEAR(s.mean_dy, 0.0, 0.002);
  EXPECT_NEAR(s.mean_dtheta, 0.0, 0.002);
  EXPECT_NEAR(s.sd_dx, std::sqrt(a.alpha3), 0.05 * std::sqrt(a.alpha3));
  EXPECT_NEAR(s.sd_dy, std::sqrt(a.alpha2), 0.05 * std::sqrt(a.alpha2));           // trans * rot1
  EXPECT_NEAR(s.sd_dtheta, std::sqrt(2 * a.alpha2), 0.05 * std::sqrt(2 * a.alpha2));  // rot1 + rot2
}

TEST(MotionModel, RotationInPlaceMeanAndSpread) {
  const MotionNoise a{0.02, 0.002, 0.01, 0.001};
  const MotionModel m(a);
  const double turn = kPi / 2;
  const Stats s = sample_stats(m, {0, 0, turn}, 2);
  EXPECT_NEAR(s.mean_dtheta, turn, 0.004);
  EXPECT_NEAR(s.mean_dx, 0.0, 0.002);
  EXPECT_NEAR(s.sd_dtheta, std::sqrt(a.alpha1) * turn, 0.05 * std::sqrt(a.alpha1) * turn);
  EXPECT_NEAR(s.sd_dx, std::sqrt(a.alpha4) * turn, 0.05 * std::sqrt(a.alpha4) * turn);
  EXPECT_NEAR(s.sd_dy, 0.0, 1e-12);  // rot1 is exactly 0
}

TEST(MotionModel, BackwardsIsNotTwoHalfTurns) {
  const MotionModel m;
  const Stats s = sample_stats(m, {-1, 0, 0}, 3);
  EXPECT_NEAR(s.mean_dx, -1.0, 0.003);
  EXPECT_NEAR(s.mean_dtheta, 0.0, 0.002);
  EXPECT_LT(s.sd_dtheta, 0.1);  // two half turns would spread it by sqrt(alpha1) * pi
}

TEST(MotionModel, NoMotionNoNoise) {
  const MotionModel m;
  std::mt19937_64 rng(4);
  const Odometry o = m.sample({0, 0, 0}, rng);
  EXPECT_EQ(o.dx, 0.0);
  EXPECT_EQ(o.dy, 0.0);
  EXPECT_EQ(o.dtheta, 0.0);
}

TEST(MotionModel, PoseSampleComposes) {
  const MotionModel m(MotionNoise{0, 0, 0, 0});
  std::mt19937_64 rng(5);
  const Pose p = m.sample(Pose{1, 1, kPi}, {2, 0, 0}, rng);
  EXPECT_NEAR(p.x, -1.0, 1e-12);
  EXPECT_NEAR(p.y, 1.0, 1e-12);
}

}  // namespace
}  // namespace fleetmap::localization
