// CompassPrior (client/localization/compass_prior.h): headings within +-3 degrees of the
// reading (seed 000 section 4.1), across the +-pi cut; the tracking weight term.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "client/localization/compass_prior.h"

namespace fleetmap::localization {
namespace {

TEST(CompassPrior, SamplesWithinHalfWidthOfTheReading) {
  const CompassPrior c;
  EXPECT_NEAR(c.half_width(), deg2rad(3.0), 1e-15);
  std::mt19937_64 rng(1);
  for (double reading : {0.0, 1.0, kPi - 0.01, -kPi + 0.01}) {
    double lo = 1, hi = -1, mean = 0;
    const int n = 20000;
    for (int k = 0; k < n; ++k) {
      const double t = c.sample(reading, rng);
      EXPECT_LE(std::fabs(t), kPi);  // normalized
      const double d = angle_diff(t, reading);
      lo = std::min(lo, d);
      hi = std::max(hi, d);
      mean += d / n;
    }
    EXPECT_GE(lo, -deg2rad(3.0));
    EXPECT_LE(hi, deg2rad(3.0));
    EXPECT_LT(lo, -deg2rad(2.9));  // uniform: the edges are reached
    EXPECT_GT(hi, deg2rad(2.9));
    EXPECT_NEAR(mean, 0.0, deg2rad(0.1));
  }
}

TEST(CompassPrior, WeightTermIsAGaussianOfTheHeadingError) {
  const CompassPrior c(deg2rad(3.0));
  EXPECT_EQ(c.log_likelihood(0.5, 0.5), 0.0);
  EXPECT_NEAR(c.log_likelihood(deg2rad(3.0), 0.0), -0.5, 1e-12);
  EXPECT_NEAR(c.log_likelihood(deg2rad(-6.0), 0.0), -2.0, 1e-12);
  // Across the cut: 179 and -179 degrees are 2 degrees apart.
  EXPECT_NEAR(c.log_likelihood(deg2rad(179.0), deg2rad(-179.0)), -0.5 * (2.0 / 3) * (2.0 / 3), 1e-9);
}

TEST(CompassPrior, RejectsANonPositiveWidth) { EXPECT_THROW(CompassPrior(0.0), std::invalid_argument); }

}  // namespace
}  // namespace fleetmap::localization
