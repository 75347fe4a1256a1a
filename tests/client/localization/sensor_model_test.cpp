// SensorModel (client/localization/sensor_model.h) against numbers computed by hand from
// seed 000 eq. (5)-(6) with the seed's parameters: alpha 1, beta 0.1, sigma_m 0.5 m,
// RMAX 15 m. N peak = 1 / (sqrt(2 pi) 0.5) = 0.79788456..., uniform = 0.1 / 15.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <vector>

#include "client/localization/particle_filter.h"
#include "client/localization/sensor_model.h"

namespace fleetmap::localization {
namespace {

constexpr double kPeak = 0.79788456080286541;  // 1 / (sqrt(2 pi) * 0.5)
constexpr double kUniform = 0.1 / 15;

TEST(SensorModel, BeamLikelihoodMatchesEquation5) {
  const SensorModel m;
  // delta = 0: both terms, the normal at its peak.
  EXPECT_NEAR(m.likelihood(0.0), 0.8045512274695321, 1e-12);
  EXPECT_NEAR(m.likelihood(0.0), kPeak + kUniform, 1e-12);
  // Measured longer than synthetic (delta > 0): the normal term only.
  EXPECT_NEAR(m.likelihood(0.5), 0.48394144903828673, 1e-12);
  EXPECT_NEAR(m.likelihood(3.0), 1.2151765699646572e-08, 1e-20);
  // Measured shorter (an unmodelled obstacle): the uniform term adds 0.1 / 15.
  EXPECT_NEAR(m.likelihood(-0.5), 0.4906081157049534, 1e-12);
  EXPECT_NEAR(m.likelihood(-1.0), 0.1146485996930428, 1e-12);
  EXPECT_NEAR(m.likelihood(-3.0), 0.006666678818432367, 1e-15);
  // Beyond -RMAX the uniform is 0 again.
  EXPECT_LT(m.likelihood(-16.0), 1e-200);
}

TEST(SensorModel, UniformTermFloorsShortReadingsOnly) {
  const SensorModel m;
  for (double d = -15.0; d <= -4.0; d += 0.5) EXPECT_NEAR(m.likelihood(d), kUniform, 1e-12) << d;
  for (double d = 4.0; d <= 15.0; d += 0.5) EXPECT_LT(m.likelihood(d), 1e-12) << d;
}

TEST(SensorModel, LogLikelihoodIsExactWhereTheLikelihoodUnderflows) {
  const SensorModel m;
  for (double d : {-3.0, -1.0, -0.5, 0.0, 0.5, 3.0}) EXPECT_NEAR(m.log_likelihood(d), std::log(m.likelihood(d)), 1e-12);
  // exp(-800) underflows; its logarithm does not.
  EXPECT_NEAR(m.log_likelihood(20.0), std::log(kPeak) - 800, 1e-9);
  EXPECT_NEAR(m.log_likelihood(-16.0), std::log(kPeak) - 512, 1e-9);
}

TEST(SensorModel, WeightIsInverseOfSumOfInverses) {
  const SensorModel m;
  // seed 000 eq. (6) for deltas {0, -1}: 1 / (1 / 0.80455 + 1 / 0.11465).
  const std::vector<double> measured{5.0, 4.0}, synthetic{5.0, 5.0};
  EXPECT_NEAR(std::exp(m.log_weight(measured.data(), synthetic.data(), 2)), 0.10034887832326189, 1e-12);
  // Three beams, deltas {0, -1, +0.5}.
  const std::vector<double> m3{5.0, 4.0, 2.5}, s3{5.0, 5.0, 2.0};
  EXPECT_NEAR(std::exp(m.log_weight(m3.data(), s3.data(), 3)), 0.0831144711986241, 1e-12);
}

TEST(SensorModel, ProductCombination) {
  SensorModelOptions o;
  o.combination = BeamCombination::Product;
  const SensorModel m(o);
  const std::vector<double> m3{5.0, 4.0, 2.5}, s3{5.0, 5.0, 2.0};
  EXPECT_NEAR(std::exp(m.log_weight(m3.data(), s3.data(), 3)), 0.04463908427954721, 1e-12);
}

TEST(SensorModel, HarmonicWeightFallsBackToLogsWithoutLosingPrecision) {
  SensorModelOptions o;
  o.sigma_m = 0.1;  // exponent (15 m)^2 / (2 * 0.01) = 11250: 1 / L overflows a double
  const SensorModel m(o);
  const std::vector<double> measured{15.0, 5.0}, synthetic{0.0, 5.0};
  const double lw = m.log_weight(measured.data(), synthetic.data(), 2);
  // One beam's 1 / L dominates: log w = log L(15) - log(1 + L(15) / L(0)) ~ log L(15).
  EXPECT_TRUE(std::isfinite(lw));
  EXPECT_NEAR(lw, m.log_likelihood(15.0), 1e-9);
}

TEST(SensorModel, GammaFloorsBothSides) {
  SensorModelOptions o;
  o.gamma = 0.1;  // not in the seed: + 0.1 U(-15, 15), 0.1 / 30 on [-RMAX, RMAX]
  const SensorModel m(o);
  EXPECT_NEAR(m.likelihood(3.0), 1.2151765699646572e-08 + 0.1 / 30, 1e-15);
  EXPECT_NEAR(m.likelihood(-3.0), 0.006666678818432367 + 0.1 / 30, 1e-15);
  EXPECT_NEAR(m.likelihood(0.0), 0.8045512274695321 + 0.1 / 30, 1e-12);
  EXPECT_LT(m.likelihood(16.0), 1e-200);
  EXPECT_NEAR(m.log_likelihood(14.0), std::log(0.1 / 30), 1e-12);
}

TEST(SensorModel, RejectsMeaninglessParameters) {
  SensorModelOptions o;
  o.sigma_m = 0;
  EXPECT_THROW(SensorModel{o}, std::invalid_argument);
  o = {};
  o.alpha = 0;
  o.beta = 0;
  EXPECT_THROW(SensorModel{o}, std::invalid_argument);
  o = {};
  o.rmax = -1;
  EXPECT_THROW(SensorModel{o}, std::invalid_argument);
}

TEST(SensorModel, ShortBeyondFlattensReadingsFarShorterThanExpected) {
  SensorModelOptions o;
  o.short_beyond = 0.5;
  const SensorModel m(o);
  const SensorModel seed;
  // Up to 0.5 m short: eq. (5) as written; farther: the value at 0.5 m short.
  EXPECT_EQ(m.likelihood(-0.3), seed.likelihood(-0.3));
  for (double d : {-0.8, -2.0, -9.0}) EXPECT_NEAR(m.likelihood(d), seed.likelihood(-0.5), 1e-15) << d;
  for (double d : {-0.8, -9.0}) EXPECT_NEAR(m.log_likelihood(d), std::log(seed.likelihood(-0.5)), 1e-12) << d;
  // Longer than expected (through a wall): the full penalty.
  EXPECT_EQ(m.likelihood(2.0), seed.likelihood(2.0));
  // Eq. (6) sees the flattened beams too: deltas {0, -3} weigh as {0, -0.5}.
  const std::vector<double> measured{5.0, 2.0}, synthetic{5.0, 5.0}, flat{5.0, 4.5};
  EXPECT_NEAR(m.log_weight(measured.data(), synthetic.data(), 2), seed.log_weight(flat.data(), synthetic.data(), 2),
              1e-12);
  o.short_beyond = -1;
  EXPECT_THROW(SensorModel{o}, std::invalid_argument);
}

TEST(SensorModel, ShortOnlyForegroundFlattensFlaggedBeamsOnly) {
  SensorModelOptions o;
  o.short_beyond = 0.5;
  o.short_only_foreground = true;
  const SensorModel m(o);
  const SensorModel seed;
  // Two beams 3 m short, the first flagged foreground: it weighs as 0.5 m short, the
  // other as eq. (5) has it. Without a mask neither is flattened.
  const std::vector<double> measured{2.0, 2.0}, synthetic{5.0, 5.0}, half_short{4.5, 2.0};
  const std::vector<uint8_t> front{1, 0};
  EXPECT_NEAR(m.log_weight(measured.data(), synthetic.data(), 2, front.data()),
              seed.log_weight(half_short.data(), synthetic.data(), 2), 1e-12);
  EXPECT_NEAR(m.log_weight(measured.data(), synthetic.data(), 2), seed.log_weight(measured.data(), synthetic.data(), 2),
              1e-12);
  // A flagged beam that passes through the particle's wall keeps the full penalty.
  const std::vector<double> through{7.0, 5.0};
  EXPECT_NEAR(m.log_weight(through.data(), synthetic.data(), 2, front.data()),
              seed.log_weight(through.data(), synthetic.data(), 2), 1e-12);
  // The product combination as well.
  o.combination = BeamCombination::Product;
  const SensorModel p(o);
  SensorModelOptions po;
  po.combination = o.combination;
  const SensorModel plain(po);
  EXPECT_NEAR(p.log_weight(measured.data(), synthetic.data(), 2, front.data()),
              plain.log_weight(half_short.data(), synthetic.data(), 2), 1e-12);
}

// A wall across the view at x = 4 m seen from (x, 0) facing +x, and a crowd lined up
// crowd.gap metres in front of it that hides the beams within crowd.half_angle of the
// axis (no crowd: the map's own ranges).
constexpr double kWallX = 4.0, kRmax = 15.0;

struct Crowd {
  double gap = 1.0;                  // metres in front of the wall
  double half_angle = 40 * kPi / 180;
};

std::vector<double> wall_ranges(double x, const std::vector<double>& beams, const std::optional<Crowd>& crowd) {
  std::vector<double> r;
  for (double a : beams) {
    const double to_wall = std::cos(a) > 0 ? (kWallX - x) / std::cos(a) : kRmax;
    const bool hidden = crowd && std::fabs(a) < crowd->half_angle;
    r.push_back(std::min(kRmax, hidden ? (kWallX - crowd->gap - x) / std::cos(a) : to_wall));
  }
  return r;
}

double crowd_score(const SensorModel& m, double pose_x, const Crowd& crowd = {}) {
  std::vector<double> beams;
  for (int j = 0; j < 131; ++j) beams.push_back(-kPi / 2 + kPi * j / 130);
  const std::vector<double> measured = wall_ranges(0.0, beams, crowd);  // the truth at x = 0
  const std::vector<double> synthetic = wall_ranges(pose_x, beams, std::nullopt);
  return m.log_weight(measured.data(), synthetic.data(), beams.size());
}

TEST(SensorModel, PeopleInFrontOfAWallDoNotPullThePoseOntoThem) {
  // The `fast` preset's model (fast_search()): the true pose
  // must outscore one 0.3 m nearer the wall, which would put the wall where the crowd
  // stands.
  const SensorModel model(ParticleFilterOptions::fast_search().sensor);
  EXPECT_GT(crowd_score(model, 0.0), crowd_score(model, 0.3));
  // The same model without the flat short term lets the crowd decide: this is what the
  // test guards against.
  SensorModelOptions penalised = ParticleFilterOptions::fast_search().sensor;
  penalised.short_beyond = 0;
  const SensorModel before(penalised);
  EXPECT_LT(crowd_score(before, 0.0), crowd_score(before, 0.3));
}

TEST(SensorModel, PeopleAgainstAWallDoNotPullThePoseOntoThem) {
  // People lined up along a wall, hiding it within 60 degrees of the axis. The
  // simulator's people are discs 0.4-0.6 m across, 5 cm clear of walls: their beams stop
  // 0.45 m short and more. The `fast` preset's model: the true pose must outscore one
  // 0.15 m nearer the wall, whose rays would end 0.3 m behind the crowd.
  const Crowd at_the_wall{0.45, 60 * kPi / 180};
  const SensorModel model(ParticleFilterOptions::fast_search().sensor);
  EXPECT_GT(crowd_score(model, 0.0, at_the_wall), crowd_score(model, 0.15, at_the_wall));
  // With the flat term from 0.5 m (the preset's value before), those beams still lie on
  // the normal term's slope: moving nearer gains more on them than it loses on the walls
  // beside the crowd (docs/localization.md, "The flat short term from 0.3 m").
  SensorModelOptions half_metre = ParticleFilterOptions::fast_search().sensor;
  half_metre.short_beyond = 0.5;
  const SensorModel before(half_metre);
  EXPECT_LT(crowd_score(before, 0.0, at_the_wall), crowd_score(before, 0.15, at_the_wall));
}

TEST(SensorModel, BothRobotLocalizersTrackAmongPeople) {
  // What each of fleetmap-robot's localizers weighs with while tracking
  // (ParticleFilterOptions::tracking_sensor(), as the filter builds it): people in front
  // of a wall and people against it must not pull the pose onto them. `search` tracked
  // 1.3 m off among 30 people before it had the flat short term (docs/localization.md,
  // "The search preset tracks among people").
  for (const ParticleFilterOptions& preset :
       {ParticleFilterOptions::fast_search(), ParticleFilterOptions::robust_search()}) {
    const SensorModelOptions tracking = preset.tracking_sensor();
    const SensorModel model(tracking);
    EXPECT_GT(crowd_score(model, 0.0), crowd_score(model, 0.3)) << "crowd 1 m in front, short_beyond "
                                                                  << tracking.short_beyond;
    const Crowd at_the_wall{0.45, 60 * kPi / 180};
    EXPECT_GT(crowd_score(model, 0.0, at_the_wall), crowd_score(model, 0.15, at_the_wall))
        << "people against the wall, short_beyond " << tracking.short_beyond;
  }
}

}  // namespace
}  // namespace fleetmap::localization
