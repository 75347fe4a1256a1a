#pragma once
// Resampling of the particle set (seed 000 Fig. 4, the step after the weight update).
//
//  * low_variance_resample: Thrun, Burgard & Fox 2005, table 4.4. One random offset and
//    a comb of n evenly spaced teeth over the cumulative weights: particle i gets
//    floor(n w_i) or ceil(n w_i) copies, so a set of equal weights is kept as it is and
//    the sampling adds no variance of its own.
//  * kld_resample: KLD sampling (Fox, "Adapting the sample size in particle filters
//    through KLD-sampling", IJRR 2003), for tracking. Particles are drawn one at a time
//    (multinomially, as in the paper: the comb needs n in advance) and binned on a grid
//    in (x, y, theta); drawing stops once the count reaches the number that bounds, with
//    probability 1 - delta, the Kullback-Leibler distance between the sample-based and
//    the true posterior by epsilon, given the k bins occupied so far (Fox 2003, eq. 12).
#include <cstddef>
#include <random>
#include <vector>

#include "client/localization/pose.h"

namespace fleetmap::localization {

// Indices of the n particles drawn; weights need not be normalized, must not all be 0.
std::vector<size_t> low_variance_resample(const std::vector<double>& weights, size_t n, std::mt19937_64& rng);

// The defaults are Nav2 AMCL's (kld_err, kld_z 0.99, its k-d tree's cells, min_particles),
// with the seed's NP as the maximum.
struct KldOptions {
  double epsilon = 0.05;             // bound on the K-L distance
  double delta = 0.01;               // probability that the bound does not hold
  double bin_xy = 0.5;               // metres
  double bin_theta = deg2rad(10.0);  // radians
  size_t min_particles = 500;
  size_t max_particles = 6000;
};

// Fox 2003, eq. (12): particles needed for k occupied bins (Wilson-Hilferty
// approximation of the chi-square quantile); z is the upper 1 - delta quantile of N(0,1).
double kld_required_count(size_t k, double epsilon, double z);

// The upper quantile z with P(N(0,1) > z) = p, for 0 < p < 1.
double normal_upper_quantile(double p);

// Indices of the particles drawn by KLD sampling, between min and max particles.
std::vector<size_t> kld_resample(const std::vector<Pose>& poses, const std::vector<double>& weights,
                                 const KldOptions& options, std::mt19937_64& rng);

}  // namespace fleetmap::localization
