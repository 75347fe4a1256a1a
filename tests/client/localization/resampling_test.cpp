// Low-variance resampling and KLD sampling (client/localization/resampling.h).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>
#include <stdexcept>
#include <vector>

#include "client/localization/resampling.h"

namespace fleetmap::localization {
namespace {

std::vector<size_t> counts(const std::vector<size_t>& idx, size_t n) {
  std::vector<size_t> c(n, 0);
  for (size_t i : idx) ++c.at(i);
  return c;
}

TEST(LowVarianceResample, KeepsTheSingleHeavyParticle) {
  std::mt19937_64 rng(1);
  const std::vector<double> w{0, 0, 1, 0, 0};
  for (int r = 0; r < 20; ++r)
    for (size_t i : low_variance_resample(w, 100, rng)) EXPECT_EQ(i, 2u);
  // Nearly alone: a particle with 1e-9 of the weight does not survive a set of 100.
  const std::vector<double> w2{1e-9, 1, 1e-9};
  for (size_t i : low_variance_resample(w2, 100, rng)) EXPECT_EQ(i, 1u);
}

TEST(LowVarianceResample, CopiesAreFloorOrCeilOfNw) {
  std::mt19937_64 rng(2);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int r = 0; r < 50; ++r) {
    std::vector<double> w(37);
    double total = 0;
    for (double& x : w) total += (x = u(rng) * u(rng));
    const size_t n = 500;
    const std::vector<size_t> idx = low_variance_resample(w, n, rng);
    ASSERT_EQ(idx.size(), n);
    const std::vector<size_t> c = counts(idx, w.size());
    for (size_t i = 0; i < w.size(); ++i) {
      const double expected = n * w[i] / total;
      EXPECT_GE(static_cast<double>(c[i]), std::floor(expected) - 1e-9) << i;
      EXPECT_LE(static_cast<double>(c[i]), std::ceil(expected) + 1e-9) << i;
    }
  }
}

TEST(LowVarianceResample, EqualWeightsKeepEveryParticleOnce) {
  std::mt19937_64 rng(3);
  const std::vector<double> w(1000, 1.0);
  const std::vector<size_t> c = counts(low_variance_resample(w, 1000, rng), 1000);
  for (size_t k : c) EXPECT_EQ(k, 1u);
  // Exact proportions: 100, 200, 300, 400.
  const std::vector<size_t> c4 = counts(low_variance_resample({0.1, 0.2, 0.3, 0.4}, 1000, rng), 4);
  EXPECT_NEAR(c4[0], 100, 1);
  EXPECT_NEAR(c4[1], 200, 1);
  EXPECT_NEAR(c4[2], 300, 1);
  EXPECT_NEAR(c4[3], 400, 1);
}

TEST(LowVarianceResample, RejectsZeroWeights) {
  std::mt19937_64 rng(4);
  EXPECT_THROW(low_variance_resample({0, 0}, 10, rng), std::invalid_argument);
  EXPECT_THROW(low_variance_resample({}, 10, rng), std::invalid_argument);
}

TEST(Kld, RequiredCountMatchesFox2003) {
  // z_{0.99} = 2.3263478740408408; eq. (12) with epsilon 0.05.
  EXPECT_NEAR(normal_upper_quantile(0.01), 2.3263478740408408, 1e-9);
  EXPECT_NEAR(normal_upper_quantile(0.5), 0.0, 1e-9);
  const double z = normal_upper_quantile(0.01);
  EXPECT_NEAR(kld_required_count(2, 0.05, z), 65.85773096926759, 1e-6);
  EXPECT_NEAR(kld_required_count(100, 0.05, z), 1346.5503645393544, 1e-6);
  EXPECT_NEAR(kld_required_count(1000, 0.05, z), 11059.214873125933, 1e-5);
}

TEST(Kld, ConcentratedCloudShrinksToTheMinimum) {
  std::mt19937_64 rng(5);
  KldOptions o;
  o.min_particles = 300;
  o.max_particles = 6000;
  const std::vector<Pose> poses(6000, Pose{1.2, 3.4, 0.5});
  const std::vector<double> w(6000, 1.0);
  EXPECT_EQ(kld_resample(poses, w, o, rng).size(), 300u);
}

TEST(Kld, SpreadCloudKeepsMoreParticles) {
  std::mt19937_64 rng(6);
  KldOptions o;
  o.min_particles = 300;
  o.max_particles = 6000;
  std::uniform_real_distribution<double> u(-10, 10), a(-kPi, kPi);
  std::vector<Pose> wide(6000), narrow(6000);
  for (Pose& p : wide) p = {u(rng), u(rng), a(rng)};
  for (Pose& p : narrow) p = {u(rng) / 10, u(rng) / 10, a(rng) / 20};
  const std::vector<double> w(6000, 1.0);
  const size_t n_wide = kld_resample(wide, w, o, rng).size();
  const size_t n_narrow = kld_resample(narrow, w, o, rng).size();
  EXPECT_EQ(n_wide, 6000u);  // 20 x 20 m x 360 degrees: far more bins than particles
  EXPECT_GT(n_narrow, 300u);
  EXPECT_LT(n_narrow, n_wide);
  // Only particles with weight are drawn.
  std::vector<double> one(6000, 0.0);
  one[17] = 1;
  for (size_t i : kld_resample(wide, one, o, rng)) EXPECT_EQ(i, 17u);
}

}  // namespace
}  // namespace fleetmap::localization
